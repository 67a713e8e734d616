#ifndef GEOMETRY_H
#define GEOMETRY_H

/* The handout's data types (its field names and order). */

#define EPSILON 1e-5

typedef struct scolor {
    unsigned char r, g, b;
} color;

typedef struct spoint {
    double x, y, z;
} point, vector;

typedef struct sfacet {
    point a, b, c;
    double k;
    color cp;
    vector n;
} facet;

typedef struct sray {
    point o;
    vector v;
} ray;

typedef struct ssource {
    point p;
    color cp;
} source;

typedef struct sscene {
    color back;
    int width, height, nbPoints, nbFacets;
    point obs, screenA, screenB, *points;
    facet *facets;
    source s;
} scene;

/* Vector helpers (geometry.c). */
vector vadd(vector a, vector b);
vector vsub(vector a, vector b);
vector vscale(vector a, double s);
double vdot(vector a, vector b);
vector vcross(vector a, vector b);
/* a / |a| through util.h's fastInvSqrt; the zero vector stays zero. */
vector vnormalize(vector a);

facet createFacet(point a, point b, point c);

#endif
