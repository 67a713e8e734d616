/*
 * exact.c - orientation and cross products with exact signs (exact.h),
 * from error-free transformations: a product of two doubles is exactly
 * the sum of its rounded value and the error an FMA recovers, a sum of two
 * doubles that of its rounded value and the error two more sums recover
 * (Dekker, Knuth), and a sum of many such terms is kept exactly as a
 * nonoverlapping expansion (Shewchuk, "Adaptive Precision Floating-Point
 * Arithmetic and Fast Robust Geometric Predicates", 1997).
 */
#include "exact.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "vecmath.h"

/* a*b = hi + lo and a+b = s + e, exactly, barring underflow. */
static void two_product(double a, double b, double *hi, double *lo)
{
    *hi = a * b;
    *lo = fma(a, b, -*hi);
}

static void two_sum(double a, double b, double *s, double *e)
{
    *s = a + b;
    double bb = *s - a;
    *e = (a - (*s - bb)) + (b - bb);
}

/* The sum of n doubles, rounded once (to within an ulp): the terms are
 * accumulated into a nonoverlapping expansion (Shewchuk's grow-expansion),
 * whose components are then added from the smallest up.  Its sign is
 * exact, and it is zero only when the exact sum is. */
static double expansion_sum(const double *terms, int n)
{
    double expansion[16];
    int length = 0;
    for (int i = 0; i < n; i++) {
        double q = terms[i];
        int kept = 0;
        for (int j = 0; j < length; j++) {
            double s, e;
            two_sum(q, expansion[j], &s, &e);
            if (e != 0.0)
                expansion[kept++] = e;
            q = s;
        }
        if (q != 0.0)
            expansion[kept++] = q;
        length = kept;
    }
    double sum = 0.0;
    for (int j = 0; j < length; j++)
        sum += expansion[j];
    return sum;
}

/* The orientation from exact products: the value to within an ulp, the
 * sign exactly. */
static double orient2d_exact(double ax, double ay, double bx, double by,
                             double cx, double cy)
{
    double t[12];
    two_product(ax, by, &t[0], &t[1]);
    two_product(-ay, bx, &t[2], &t[3]);
    two_product(bx, cy, &t[4], &t[5]);
    two_product(-by, cx, &t[6], &t[7]);
    two_product(cx, ay, &t[8], &t[9]);
    two_product(-cy, ax, &t[10], &t[11]);
    return expansion_sum(t, 12);
}

/* The larger of two magnitudes, as fmax gives it (a NaN loses) without a
 * call into libm: for magnitudes (never -0) the same double, bit for bit. */
static double larger(double x, double y)
{
    return x > y || isnan(y) ? x : y;
}

static double max_abs(rt_vec3 a)
{
    return larger(fabs(a.x), larger(fabs(a.y), fabs(a.z)));
}

/* x 2^-e, as ldexp(x, -e) gives it: a multiplication by 2^-e when that is
 * a normal double (the exact product rounded once, as ldexp rounds it),
 * ldexp otherwise. */
static double times_two_to_minus(double x, int e)
{
    if (e < -1023 || e > 1022)
        return ldexp(x, -e);
    uint64_t bits = (uint64_t)(1023 - e) << 52;
    double factor;
    memcpy(&factor, &bits, sizeof factor);
    return x * factor;
}

/* The triangle scaled by the power of two that brings its largest
 * coordinate into [0.5, 1): an exact operation, after which products
 * neither overflow nor underflow.  (Once a third of an OBJ's parse in
 * libm calls: its exponent is read from the bits of a normal double.) */
static void scale(rt_vec3 *a, rt_vec3 *b, rt_vec3 *c)
{
    double largest = larger(max_abs(*a), larger(max_abs(*b), max_abs(*c)));
    int exponent = 0;
    if (largest > 0.0) {
        uint64_t bits;
        memcpy(&bits, &largest, sizeof bits);
        int biased = (int)(bits >> 52) & 0x7ff;
        if (biased > 0 && biased < 0x7ff)
            exponent = biased - 1022;   /* frexp's, for a normal double */
        else
            frexp(largest, &exponent);
    }
    *a = v3(times_two_to_minus(a->x, exponent),
            times_two_to_minus(a->y, exponent),
            times_two_to_minus(a->z, exponent));
    *b = v3(times_two_to_minus(b->x, exponent),
            times_two_to_minus(b->y, exponent),
            times_two_to_minus(b->z, exponent));
    *c = v3(times_two_to_minus(c->x, exponent),
            times_two_to_minus(c->y, exponent),
            times_two_to_minus(c->z, exponent));
}

rt_vec3 rt__exact_cross(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    scale(&a, &b, &c);
    return v3(orient2d_exact(a.y, a.z, b.y, b.z, c.y, c.z),
              orient2d_exact(a.z, a.x, b.z, b.x, c.z, c.x),
              orient2d_exact(a.x, a.y, b.x, b.y, c.x, c.y));
}

rt_vec3 rt__facet_normal(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    return v3_normalize(rt__exact_cross(a, b, c));
}

int rt__triangle_has_area(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    /* First a filter on the coordinates as they are (the scaling's frexp
     * and ldexp cost more than the rest, and a mesh's triangles nearly all
     * pass here): with M the largest magnitude, the floating-point cross
     * product is within 32 eps M^2 (3.6e-15 M^2) of the exact one, barring
     * underflow and overflow, which the range of M rules out; a component
     * beyond 1e-12 M^2 proves an area, as the exact test would find. */
    const double coordinates[9] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y,
                                   c.z};
    double m = 0.0;
    for (int i = 0; i < 9; i++)
        m = fabs(coordinates[i]) > m ? fabs(coordinates[i]) : m;
    rt_vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
    double proof = 1e-12 * m * m;
    if (m >= 1e-100 && m <= 1e100 &&
        (fabs(n.x) > proof || fabs(n.y) > proof || fabs(n.z) > proof))
        return 1;
    scale(&a, &b, &c);
    /* With coordinates below 1 in magnitude, the floating-point cross
     * product is within 32 eps (3.6e-15) of the exact one: a component
     * beyond 1e-13 proves an area, and the exact evaluation, rounded once,
     * is not zero either.  Otherwise decide as rt__exact_cross does, on
     * the same scaled coordinates (scaling them again changes nothing). */
    if (max_abs(v3_cross(v3_sub(b, a), v3_sub(c, a))) > 1e-13)
        return 1;
    return orient2d_exact(a.y, a.z, b.y, b.z, c.y, c.z) != 0.0 ||
           orient2d_exact(a.z, a.x, b.z, b.x, c.z, c.x) != 0.0 ||
           orient2d_exact(a.x, a.y, b.x, b.y, c.x, c.y) != 0.0;
}
