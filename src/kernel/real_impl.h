/*
 * real_impl.h - the arithmetic of the kernel in its precision: vectors of
 * REAL, normalisation (exact or the handout's fastInvSqrt), Higham's error
 * bounds and the one-ulp step used by the offsets (part of kernel_impl.h,
 * compiled once per precision; everything here is static).
 */

typedef struct vec {
    REAL x, y, z;
} vec;


static inline vec mk(REAL x, REAL y, REAL z) { return (vec){x, y, z}; }
static inline vec add(vec a, vec b) { return mk(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec sub(vec a, vec b) { return mk(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec scale(vec a, REAL s) { return mk(a.x * s, a.y * s, a.z * s); }
static inline vec neg(vec a) { return mk(-a.x, -a.y, -a.z); }
static inline vec vabs(vec a) { return mk(fabs(a.x), fabs(a.y), fabs(a.z)); }
static inline REAL dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline REAL get(vec a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline vec from_rt(rt_vec3 v) { return mk((REAL)v.x, (REAL)v.y, (REAL)v.z); }
static inline rt_vec3 to_rt(vec v) { return (rt_vec3){v.x, v.y, v.z}; }

/* The handout's fastInvSqrt in this precision (fast_inv_sqrt.h: one
 * definition for the kernel and the course's libraytrace-util). */
static REAL fast_inv_sqrt(REAL x)
{
    if (sizeof(REAL) == sizeof(float))
        return (REAL)rt_fast_inv_sqrtf((float)x);
    return (REAL)rt_fast_inv_sqrt((double)x);
}

/* a / |a| without overflow or underflow; zero stays zero. */
static vec normalize(vec a, int fast)
{
    REAL m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0)
        return a;
    vec s = scale(a, 1 / m);
    REAL n = dot(s, s);
    return scale(s, fast ? fast_inv_sqrt(n) : 1 / sqrt(n));
}


/* Higham's gamma(n) = n u / (1 - n u), u the unit roundoff. */
static REAL gamma_bound(int n)
{
    REAL u = REAL_EPS / 2;
    return n * u / (1 - n * u);
}

static REAL max3(REAL a, REAL b, REAL c)
{
    return fmax(fabs(a), fmax(fabs(b), fabs(c)));
}


static REAL step_away(REAL x, REAL direction)
{
    if (direction > 0)
        return nextafter(x, (REAL)INFINITY);
    if (direction < 0)
        return nextafter(x, -(REAL)INFINITY);
    return x;
}
