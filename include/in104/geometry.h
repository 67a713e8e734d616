/*
 * geometry.h - the data types of the IN 104 course handout (compatibility
 * layer of libraytrace, library raytrace-in104).
 *
 * Programs written for the course include this header and intersection.h /
 * raytracer.h exactly as the handout's skeleton did; the names, field order
 * and layout below are the handout's (docs/in104.md), so such programs
 * build unchanged.  libraytrace's own API is the rt_-prefixed one in
 * <raytrace/raytrace.h>; these unprefixed names exist only in this layer.
 *
 * All types are plain values: a scene filled by parse() owns its `points` and
 * `facets` arrays until freeScene() (see raytracer.h).
 *
 * Build:   cc -Wall -Wextra -I<prefix>/include/in104 prog.c \
 *             -lraytrace-in104 -lraytrace -lm -lpthread
 *     or   cc prog.c $(pkg-config --cflags --libs raytrace-in104)
 */
#ifndef IN104_GEOMETRY_H
#define IN104_GEOMETRY_H

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The handout's tolerance: an absolute distance in scene units.  isInFacet()
 * accepts points whose distance to the triangle is at most EPSILON (see
 * intersection.h).
 */
#define EPSILON (1e-5)

/* An RGB colour, each component in 0..255. */
typedef struct scolor {
    unsigned char r, g, b;
} color;

/* A point and a vector are the same type (x, y, z), so one can be passed
 * where the other is expected, as in the handout. */
typedef struct spoint {
    double x, y, z;
} point, vector;

/*
 * A triangle a, b, c with its reflection coefficient k (0..1), its colour cp
 * and its unit normal n = (b - a) x (c - a) / |(b - a) x (c - a)|, the zero
 * vector for a zero-area facet.  createFacet() and parse() fill n.
 */
typedef struct sfacet {
    point a, b, c;
    double k;
    color cp;
    vector n;
} facet;

/* The half-line o + t.v, t >= 0; v need not be unit length. */
typedef struct sray {
    point o;
    vector v;
} ray;

/* A point light p of colour cp. */
typedef struct ssource {
    point p;
    color cp;
} source;

/*
 * A whole scene, as parse() fills it (docs/scene-format.md):
 *   back               background colour;
 *   width, height      image size in pixels;
 *   nbPoints, points   the vertices of the file (points[0] is vertex 1);
 *   nbFacets, facets   the facets, with vertex coordinates copied in;
 *   obs                the observer O;
 *   screenA            the centre A of the screen;
 *   screenB            the middle B of its right edge, already projected onto
 *                      the plane through A perpendicular to AO;
 *   s                  the light source.
 */
typedef struct sscene {
    color back;
    int width, height, nbPoints, nbFacets;
    point obs, screenA, screenB, *points;
    facet *facets;
    source s;
} scene;

#ifdef __cplusplus
}
#endif

#endif /* IN104_GEOMETRY_H */
