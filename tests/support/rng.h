/*
 * rng.h - the one random number generator of the tests: splitmix64 over a
 * state the caller holds (no global state), so that a seed gives the same
 * numbers on every machine, in every suite, forked or not.  Part of the
 * support library (tests/support/).
 */
#ifndef RAYTRACE_TEST_RNG_H
#define RAYTRACE_TEST_RNG_H

#include <stdint.h>

/* The generator; seed it by setting `state` (`rt_test_rng rng = {42};`). */
typedef struct rt_test_rng {
    uint64_t state;
} rt_test_rng;

/* The next 64 random bits. */
uint64_t rt_test_rng_next(rt_test_rng *rng);

/* Uniform in [0, 1), 53 random bits. */
double rt_test_rng_uniform(rt_test_rng *rng);

/* Uniform in [lo, hi). */
double rt_test_rng_range(rt_test_rng *rng, double lo, double hi);

/* Uniform in 0 .. n - 1 (n > 0). */
int rt_test_rng_below(rt_test_rng *rng, int n);

#endif /* RAYTRACE_TEST_RNG_H */
