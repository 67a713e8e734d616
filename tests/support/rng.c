/*
 * rng.c - splitmix64 (Steele, Lea and Flood, "Fast splittable pseudorandom
 * number generators", OOPSLA 2014; constants as Vigna publishes them); see
 * rng.h.
 */
#include "rng.h"

uint64_t rt_test_rng_next(rt_test_rng *rng)
{
    uint64_t z = (rng->state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

double rt_test_rng_uniform(rt_test_rng *rng)
{
    return (double)(rt_test_rng_next(rng) >> 11) * 0x1p-53;
}

double rt_test_rng_range(rt_test_rng *rng, double lo, double hi)
{
    return lo + (hi - lo) * rt_test_rng_uniform(rng);
}

int rt_test_rng_below(rt_test_rng *rng, int n)
{
    return (int)(rt_test_rng_uniform(rng) * n) % n;
}
