/*
 * sweep.h - the settings rt-bench measures (docs/accuracy.md): every
 * combination of the two numerical knobs (precision, square root) with a
 * few samplings and depths, then each knob alone from the default; or,
 * with --dof, 1 to 64 rays per pixel on regular and stratified grids.
 * Each setting carries its label ("float+fast d2 16s", rt-bench --help
 * says how to read it), its row of the report and the double/exact
 * setting whose image its numerical error is measured against.  No state;
 * thread-safe on distinct arrays.
 */
#ifndef RT_BENCH_SWEEP_H
#define RT_BENCH_SWEEP_H

#include "raytrace/raytrace.h"
#include "report.h"

#define BENCH_MAX_RUNS 99       /* timed renders of one setting, at most */
#define BENCH_MAX_CONFIGS 64    /* settings of one sweep, at most */

/* The knobs of one render. */
typedef struct bench_settings {
    rt_precision precision;
    int fast_sqrt;
    int grid;                   /* samples per side of a pixel */
    rt_sampling sampling;
    int depth;
} bench_settings;

/* One setting of the sweep and what was measured of it. */
typedef struct bench_config {
    bench_settings s;
    bench_row row;
    double times[BENCH_MAX_RUNS];
    unsigned long long hash;    /* of the first render's image */
    int base;                   /* the double/exact config with the same
                                   sampling and depth (may be itself) */
} bench_config;

/* The accuracy sweep, settings with more than `max_samples` rays a pixel
 * left out; `ref_depth` is the reference's depth, measured alone too.
 * Fills configs[0..BENCH_MAX_CONFIGS) and returns how many. */
int bench_build_configs(bench_config *configs, int max_samples,
                        int ref_depth);

/* The depth-of-field sweep (double, exact square root, the default depth:
 * the only knob is the number of rays); each config is its own base. */
int bench_build_dof_configs(bench_config *configs, int max_samples);

/* The reference's grid side for `samples` rays a pixel (a square): the
 * smallest side from its root up that contains none of the tested
 * regular grids' points (side m holds side n's centres exactly when m / n
 * is an odd integer), at most 32. */
int bench_reference_grid(int samples, const bench_config *configs,
                         int count);

#endif /* RT_BENCH_SWEEP_H */
