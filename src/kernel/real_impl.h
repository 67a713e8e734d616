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

/* fmax(a, b) for a, b >= 0 or NaN, without libm's call: NaN only when
 * both are (fmax's rule); no signed zeros to order among magnitudes. */
static inline REAL larger(REAL a, REAL b)
{
    return b > a || a != a ? b : a;
}

/* a / |a| without overflow or underflow; zero stays zero. */
static inline vec normalize(vec a, int fast)
{
    REAL m = larger(fabs(a.x), larger(fabs(a.y), fabs(a.z)));
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

static inline REAL max3(REAL a, REAL b, REAL c)
{
    return larger(fabs(a), larger(fabs(b), fabs(c)));
}

/* The unsigned integer of REAL's width, for next_toward. */
#if REAL_IS_FLOAT
typedef uint32_t real_bits;
#else
typedef uint64_t real_bits;
#endif

/* nextafter(x, up ? +inf : -inf), bit for bit, without libm's call: the
 * neighbour of x in the representation; a zero of either sign steps to the
 * smallest subnormal, NaN and the infinity met stay. */
static inline REAL next_toward(REAL x, int up)
{
    if (x != x || x == (up ? (REAL)INFINITY : -(REAL)INFINITY))
        return x;
    real_bits bits, sign = (real_bits)1 << (8 * sizeof bits - 1);
    memcpy(&bits, &x, sizeof bits);
    if (x == 0)
        bits = up ? 0 : sign;
    int grow = x == 0 || (x > 0) == (up != 0);     /* magnitude up? */
    bits = grow ? bits + 1 : bits - 1;
    memcpy(&x, &bits, sizeof x);
    return x;
}

static inline REAL step_away(REAL x, REAL direction)
{
    if (direction > 0)
        return next_toward(x, 1);
    if (direction < 0)
        return next_toward(x, 0);
    return x;
}
