/*
 * plane_crossing.c - where a ray's line crosses a facet's plane, in
 * double-double arithmetic with a running error bound (plane_crossing.h).
 *
 * Every value is a pair hi + lo (|lo| <= ulp(hi) / 2) carrying a bound on
 * its distance from the exact value.  The products and sums are Joldes,
 * Muller and Popescu's "Tight and rigorous error bounds for basic building
 * blocks of double-word arithmetic" (ACM TOMS 44(2), 2017): DWTimesDW3
 * (relative error at most 4u^2 with an FMA) and AccurateDWPlusDW (at most
 * 3u^2 + 13u^3), u = 2^-53; the bound below takes 8u^2 for both.  Those
 * bounds hold without underflow: the coordinates are first scaled by
 * powers of two (exact) so that the largest is about 1, and every
 * operation adds 2^-1000 to the bound for what an underflow could lose.
 * Nothing here is on a hot path: the kernel calls it only for hits whose
 * plain computation cannot tell whether the facet lies in front of the ray.
 */
#include "kernel/plane_crossing.h"

#include <float.h>
#include <math.h>

#define U (DBL_EPSILON / 2)
#define DD_RELATIVE (8 * U * U)     /* per operation, see above */
#define DD_UNDERFLOW 0x1p-1000      /* per operation, absolute */
#define MAGNITUDE_UP (1 + 8 * U)    /* the bounds' own rounding */

/* A double-double value with a bound on its error. */
typedef struct dd {
    double hi, lo;
    double err;
} dd;

static dd fast_two_sum(double a, double b)
{
    double s = a + b;
    return (dd){s, b - (s - a), 0};
}

static dd two_sum(double a, double b)
{
    double s = a + b;
    double bb = s - a;
    return (dd){s, (a - (s - bb)) + (b - bb), 0};
}

/* a - b, exactly (for finite a, b whose difference does not overflow). */
static dd exact_difference(double a, double b)
{
    return two_sum(a, -b);
}

static dd exact(double a)
{
    return (dd){a, 0, 0};
}

static double magnitude(dd x)
{
    return fabs(x.hi) * (1 + 2 * U);    /* >= |hi + lo| */
}

/* AccurateDWPlusDW. */
static dd add(dd x, dd y)
{
    dd s = two_sum(x.hi, y.hi), t = two_sum(x.lo, y.lo);
    dd v = fast_two_sum(s.hi, s.lo + t.hi);
    dd z = fast_two_sum(v.hi, t.lo + v.lo);
    z.err = (DD_RELATIVE * (magnitude(x) + magnitude(y)) + x.err + y.err) *
                MAGNITUDE_UP +
            DD_UNDERFLOW;
    return z;
}

static dd negate(dd x)
{
    return (dd){-x.hi, -x.lo, x.err};
}

/* DWTimesDW3. */
static dd multiply(dd x, dd y)
{
    double ch = x.hi * y.hi;
    double cl1 = fma(x.hi, y.hi, -ch);
    double tl1 = fma(x.hi, y.lo, x.lo * y.lo);
    double cl2 = fma(x.lo, y.hi, tl1);
    dd z = fast_two_sum(ch, cl1 + cl2);
    double mx = magnitude(x), my = magnitude(y);
    z.err = (DD_RELATIVE * mx * my + mx * y.err + my * x.err +
             x.err * y.err) *
                MAGNITUDE_UP +
            DD_UNDERFLOW;
    return z;
}

static dd scaled(dd x, int exponent)
{
    /* exact but for an underflow of lo, which DD_UNDERFLOW covers */
    return (dd){ldexp(x.hi, exponent), ldexp(x.lo, exponent),
                ldexp(x.err, exponent) + DD_UNDERFLOW};
}

/* p.q for vectors of three. */
static dd dot3(const dd p[3], const dd q[3])
{
    return add(add(multiply(p[0], q[0]), multiply(p[1], q[1])),
               multiply(p[2], q[2]));
}

/* The component i of p x q + q x r + r x p, which is (q - p) x (r - p). */
static dd cross_sum(const dd p[3], const dd q[3], const dd r[3], int i)
{
    int j = (i + 1) % 3, k = (i + 2) % 3;
    dd pq = add(multiply(p[j], q[k]), negate(multiply(p[k], q[j])));
    dd qr = add(multiply(q[j], r[k]), negate(multiply(q[k], r[j])));
    dd rp = add(multiply(r[j], p[k]), negate(multiply(r[k], p[j])));
    return add(add(pq, qr), rp);
}

/* The exponent e with |x| < 2^e for the largest |x| of the values (0 when
 * all are zero). */
static int exponent_above(const dd *values, int n)
{
    double largest = 0;
    for (int i = 0; i < n; i++)
        largest = fmax(largest, fabs(values[i].hi));
    int e = 0;
    if (largest > 0)
        frexp(largest, &e);
    return e;
}

/* Certain sign, with room to spare: hi + lo is farther than its error
 * plus `margin` from 0. */
static int sign_certain(dd x, double margin)
{
    return fabs(x.hi) - fabs(x.lo) > x.err + margin;
}

/* An upper bound on |n| (the value, not its rounding). */
static double length_above(const dd n[3])
{
    double squares = 0, errors = 0;
    for (int i = 0; i < 3; i++) {
        double m = fabs(n[i].hi) * (1 + 2 * U) + n[i].err;
        squares += m * m;
        errors += n[i].err;
    }
    return sqrt(squares) * (1 + 8 * U) + errors;
}

/* The plane's normal n = (b - a) x (c - a) and n.(a - o), both from the
 * corners relative to o scaled by 2^-e (returned): n scaled by 2^-2e,
 * n.(a - o) by 2^-3e. */
static int plane_terms(const double a[3], const double b[3],
                       const double c[3], const double o[3], dd n[3],
                       dd *along)
{
    dd corner[3][3];
    const double *vertex[3] = {a, b, c};
    for (int v = 0; v < 3; v++)
        for (int i = 0; i < 3; i++)
            corner[v][i] = exact_difference(vertex[v][i], o[i]);
    int e = exponent_above(&corner[0][0], 9);
    for (int v = 0; v < 3; v++)
        for (int i = 0; i < 3; i++)
            corner[v][i] = scaled(corner[v][i], -e);
    for (int i = 0; i < 3; i++)
        n[i] = cross_sum(corner[0], corner[1], corner[2], i);
    *along = dot3(n, corner[0]);
    return e;
}

int rt__plane_side(const double a[3], const double b[3], const double c[3],
                   const double o[3])
{
    dd n[3], along;
    plane_terms(a, b, c, o, n, &along);
    if (!sign_certain(along, 0))
        return 0;
    return along.hi > 0 ? 1 : -1;
}

int rt__plane_crossing(const double a[3], const double b[3],
                       const double c[3], const double o[3],
                       const double d[3], double origin_error, double *t,
                       double *error)
{
    /* t = n.(a - o) / n.d, both scaled: t = (N / D) 2^(e - f). */
    dd n[3], along, direction[3];
    int e = plane_terms(a, b, c, o, n, &along);
    for (int i = 0; i < 3; i++)
        direction[i] = exact(d[i]);
    int f = exponent_above(direction, 3);
    for (int i = 0; i < 3; i++)
        direction[i] = scaled(direction[i], -f);
    dd across = dot3(n, direction);
    /* |along| / |n| is the origin's distance from the plane (scaled) */
    double room = ldexp(origin_error, -e) * length_above(n) * (1 + 8 * U);
    if (!sign_certain(along, room) || !sign_certain(across, 0))
        return 0;
    double rel_along = (along.err + fabs(along.lo)) / fabs(along.hi);
    double rel_across = (across.err + fabs(across.lo)) / fabs(across.hi);
    double q = along.hi / across.hi;
    double relative = ((rel_along + rel_across) / (1 - rel_across) + 2 * U) *
                      MAGNITUDE_UP;
    *t = ldexp(q, e - f);
    *error = ldexp(fabs(q) * relative, e - f) + DBL_TRUE_MIN;
    return 1;
}
