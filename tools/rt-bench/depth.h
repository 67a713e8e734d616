/*
 * depth.h - the reflection depth rt-bench's reference needs, and how the
 * truncation of a shallower render compares with its bound
 * (docs/accuracy.md, bench_truncation_bound in metrics.h): the bound's
 * constants found from the scene's facets and lights, then each depth up
 * to the reference's rendered at one ray a pixel in double and measured
 * against it, as a table on stdout and a CSV.
 */
#ifndef RT_BENCH_DEPTH_H
#define RT_BENCH_DEPTH_H

#include <stdio.h>

#include "measure.h"
#include "metrics.h"

/* The constants of the truncation bound of `scene`'s facets. */
bench_depth_bound bench_find_depth_bound(const rt_scene *scene);

/*
 * Depth truncation measured against its bound, at one ray per pixel in
 * double: each depth d against the reference depth `ref_depth`, printed
 * and written to `csv`.  Also finds the first depth whose image one more
 * bounce leaves unchanged (*converged_at, -1: none), and whether
 * ref_depth + 1 leaves ref_depth's image unchanged (*reference_stable).
 * Uses im->depth_reference and im->scratch.  Returns 0 if a render failed.
 */
int bench_analyse_depth(const rt_scene *scene, const rt_render_options *base,
                        const bench_depth_bound *b, int ref_depth,
                        bench_images *im, FILE *csv, int *converged_at,
                        int *reference_stable);

#endif /* RT_BENCH_DEPTH_H */
