/* render.c - the ray tracer of the handout (part 2): one ray a pixel,
 * shadows from the point light, mirror reflections up to MAX_DEPTH, the
 * colour formula C = k.CR + E.(1 - k).(N.S).CS.CF / 255; directions are
 * normalised with util.h's fastInvSqrt. */
#include <math.h>
#include <stdio.h>

#include "intersection.h"
#include "render.h"

typedef struct srgb {
    double r, g, b;
} rgb;

/* The facet nearest along o + t.d, t > tiny, other than `skip`; its index
 * or -1, and the parameter in *tHit.  With limit > 0 only t < limit
 * counts. */
static int nearest(const scene *s, point o, vector d, int skip, double limit,
                   double *tHit)
{
    ray r = {o, d};
    double dd = vdot(d, d), best = limit > 0 ? limit : INFINITY;
    int found = -1;

    for (int i = 0; i < s->nbFacets; i++) {
        point p;
        double t;
        if (i == skip)
            continue;
        p = computeIntersection(r, s->facets[i]);
        if (isnan(p.x))
            continue;
        t = vdot(vsub(p, o), d) / dd;
        if (t > 1e-9 && t < best && isInFacet(p, s->facets[i])) {
            best = t;
            found = i;
        }
    }
    *tHit = best;
    return found;
}

static rgb trace(const scene *s, point o, vector d, int level, int skip)
{
    double t, ns, e;
    int i = nearest(s, o, d, skip, 0, &t);
    rgb c = {s->back.r, s->back.g, s->back.b}, reflected = {0, 0, 0};
    const facet *f;
    vector in, n, toLight;
    point p;

    if (i < 0)
        return c;
    f = &s->facets[i];
    p = vadd(o, vscale(d, t));
    in = vnormalize(d);
    n = f->n;
    if (vdot(n, in) > 0)
        n = vscale(n, -1);
    toLight = vsub(s->s.p, p);
    ns = vdot(n, vnormalize(toLight));
    e = ns > 0 && nearest(s, p, toLight, i, 1, &t) < 0 ? 1 : 0;
    if (f->k > 0 && level < MAX_DEPTH)
        reflected = trace(s, p, vsub(in, vscale(n, 2 * vdot(in, n))),
                          level + 1, i);
    c.r = f->k * reflected.r + e * (1 - f->k) * ns * s->s.cp.r * f->cp.r / 255;
    c.g = f->k * reflected.g + e * (1 - f->k) * ns * s->s.cp.g * f->cp.g / 255;
    c.b = f->k * reflected.b + e * (1 - f->k) * ns * s->s.cp.b * f->cp.b / 255;
    return c;
}

static unsigned char toByte(double v)
{
    if (!(v > 0))
        return 0;
    if (v >= 255)
        return 255;
    return (unsigned char)(int)(v + 0.5);
}

color pixelColor(const scene *s, int i, int j)
{
    vector ab = vsub(s->screenB, s->screenA);
    vector ao = vsub(s->obs, s->screenA);
    vector up = vcross(ao, ab);
    vector ac = vscale(up, sqrt(vdot(ab, ab) / vdot(up, up)));
    double x = 2 * (i + 0.5) / s->width - 1;
    double y = (1 - 2 * (j + 0.5) / s->height) * s->height / s->width;
    point screen = vadd(s->screenA, vadd(vscale(ab, x), vscale(ac, y)));
    rgb c = trace(s, s->obs, vsub(screen, s->obs), 0, -1);
    color result = {toByte(c.r), toByte(c.g), toByte(c.b)};
    return result;
}

int writeP3(const scene *s, const char *ppmFile)
{
    FILE *file = fopen(ppmFile, "w");
    int failed;

    if (NULL == file) {
        perror(ppmFile);
        return 1;
    }
    fprintf(file, "P3\n%d %d\n255\n", s->width, s->height);
    for (int j = 0; j < s->height; j++)
        for (int i = 0; i < s->width; i++) {
            color c = pixelColor(s, i, j);
            fprintf(file, "%d %d %d\n", c.r, c.g, c.b);
        }
    failed = ferror(file);
    if (0 != fclose(file) || failed) {
        perror(ppmFile);
        return 1;
    }
    return 0;
}
