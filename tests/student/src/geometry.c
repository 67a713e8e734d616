/* geometry.c - vectors and facets. */
#include "geometry.h"
#include "util.h"

vector vadd(vector a, vector b)
{
    vector r = {a.x + b.x, a.y + b.y, a.z + b.z};
    return r;
}

vector vsub(vector a, vector b)
{
    vector r = {a.x - b.x, a.y - b.y, a.z - b.z};
    return r;
}

vector vscale(vector a, double s)
{
    vector r = {a.x * s, a.y * s, a.z * s};
    return r;
}

double vdot(vector a, vector b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

vector vcross(vector a, vector b)
{
    vector r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                a.x * b.y - a.y * b.x};
    return r;
}

vector vnormalize(vector a)
{
    double n2 = vdot(a, a);
    if (0 == n2)
        return a;
    return vscale(a, fastInvSqrt((float)n2));
}

facet createFacet(point a, point b, point c)
{
    facet f;
    f.a = a;
    f.b = b;
    f.c = c;
    f.k = 0;
    f.cp.r = f.cp.g = f.cp.b = 0;
    f.n = vnormalize(vcross(vsub(b, a), vsub(c, a)));
    return f;
}
