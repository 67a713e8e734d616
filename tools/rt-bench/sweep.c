/*
 * sweep.c - the settings rt-bench measures, their labels and their bases
 * (see sweep.h).
 */
#include "sweep.h"

#include <stdio.h>
#include <string.h>

/* The side of a grid of n points: n's root, 0 when n is not a square. */
static int square_root(int n)
{
    int root = 1;
    while (root * root < n)
        root++;
    return root * root == n ? root : 0;
}

/* The smallest regular grid side >= `grid` that contains none of the
 * tested regular grids' points: side m holds side n's centres exactly when
 * m / n is an odd integer. */
static int non_nesting_grid(int grid, const bench_config *configs, int count)
{
    for (int m = grid;; m++) {
        int nests = 0;
        for (int i = 0; i < count; i++) {
            int n = configs[i].s.grid;
            int regular = configs[i].s.sampling == RT_SAMPLING_REGULAR ||
                          n == 1;
            if (regular && m % n == 0 && (m / n) % 2 == 1)
                nests = 1;
        }
        if (!nests || m >= 32)
            return m;
    }
}

int bench_reference_grid(int samples, const bench_config *configs,
                         int count)
{
    return non_nesting_grid(square_root(samples), configs, count);
}

/* The label rt-bench --help explains: "float+fast d2 16s". */
static void make_label(const bench_settings *s, char *label, size_t size)
{
    snprintf(label, size, "%s%s d%d %d%s",
             s->precision == RT_PRECISION_FLOAT ? "float" : "double",
             s->fast_sqrt ? "+fast" : "", s->depth, s->grid * s->grid,
             s->grid == 1 ? ""
             : s->sampling == RT_SAMPLING_STRATIFIED ? "s" : "r");
}

/* Which knobs differ from the default render (the report's "varies"). */
static const char *knobs_varied(const bench_settings *s)
{
    int precision = s->precision != RT_PRECISION_DOUBLE;
    int sqrt_knob = s->fast_sqrt != 0;
    int samples = s->grid != 1;
    int depth = s->depth != RT_DEFAULT_DEPTH;
    switch (precision + sqrt_knob + samples + depth) {
    case 0:
        return "default";
    case 1:
        return precision ? "precision" : sqrt_knob ? "sqrt"
               : samples ? "samples" : "depth";
    default:
        return "combination";
    }
}

/* The same render: the sampling counts only with several rays. */
static int same_settings(const bench_settings *a, const bench_settings *b)
{
    return a->precision == b->precision && a->fast_sqrt == b->fast_sqrt &&
           a->grid == b->grid && a->depth == b->depth &&
           (a->grid == 1 || a->sampling == b->sampling);
}

/* Appends setting `s` unless it has too many rays or is there already. */
static void add_config(bench_config *configs, int *count, bench_settings s,
                       int max_samples)
{
    if (s.grid * s.grid > max_samples || *count >= BENCH_MAX_CONFIGS)
        return;
    if (s.grid == 1)
        s.sampling = RT_SAMPLING_REGULAR;
    for (int i = 0; i < *count; i++) {
        if (same_settings(&configs[i].s, &s))
            return;
    }
    bench_config *c = &configs[(*count)++];
    memset(c, 0, sizeof *c);
    c->s = s;
    make_label(&s, c->row.label, sizeof c->row.label);
    snprintf(c->row.varies, sizeof c->row.varies, "%s", knobs_varied(&s));
    c->row.precision = s.precision;
    c->row.fast_sqrt = s.fast_sqrt;
    c->row.samples = s.grid * s.grid;
    c->row.sampling = s.sampling;
    c->row.depth = s.depth;
}

/*
 * The settings measured (bench_build_configs): every combination of the two numerical knobs with
 * one ray, 4 and 16 stratified rays and depths 2 and 5; then each knob on
 * its own from the default (regular grids, 9 rays, depths 0, 1, 3 and the
 * reference's).
 */
int bench_build_configs(bench_config *configs, int max_samples,
                        int ref_depth)
{
    int count = 0;
    const int depths[] = {2, RT_DEFAULT_DEPTH};
    const int grids[] = {1, 2, 4};
    for (int d = 0; d < 2; d++)
        for (int g = 0; g < 3; g++)
            for (int n = 0; n < 4; n++)
                add_config(configs, &count,
                           (bench_settings){n / 2 ? RT_PRECISION_FLOAT
                                                  : RT_PRECISION_DOUBLE,
                                            n % 2, grids[g],
                                            RT_SAMPLING_STRATIFIED,
                                            depths[d]},
                           max_samples);
    const int alone[][2] = {{2, RT_SAMPLING_REGULAR},
                            {3, RT_SAMPLING_REGULAR},
                            {3, RT_SAMPLING_STRATIFIED},
                            {4, RT_SAMPLING_REGULAR}};
    for (int i = 0; i < 4; i++)
        add_config(configs, &count,
                   (bench_settings){RT_PRECISION_DOUBLE, 0, alone[i][0],
                                    (rt_sampling)alone[i][1],
                                    RT_DEFAULT_DEPTH},
                   max_samples);
    const int depth_alone[] = {0, 1, 3, ref_depth};
    for (int i = 0; i < 4; i++)
        add_config(configs, &count,
                   (bench_settings){RT_PRECISION_DOUBLE, 0, 1,
                                    RT_SAMPLING_REGULAR, depth_alone[i]},
                   max_samples);
    for (int i = 0; i < count; i++) {
        bench_settings base = configs[i].s;
        base.precision = RT_PRECISION_DOUBLE;
        base.fast_sqrt = 0;
        configs[i].base = i;
        for (int j = 0; j < count; j++) {
            if (same_settings(&configs[j].s, &base))
                configs[i].base = j;
        }
    }
    return count;
}

/*
 * The depth-of-field settings: 1, 4, 16 and 64 rays per pixel on regular
 * and stratified grids (each ray also takes its own point of the lens, on
 * the same kind of grid), double, exact square root, the default depth:
 * the only knob is the number of rays.
 */
int bench_build_dof_configs(bench_config *configs, int max_samples)
{
    int count = 0;
    const int grids[] = {1, 2, 4, 8};
    for (int g = 0; g < 4; g++)
        for (int st = 0; st < 2; st++)
            add_config(configs, &count,
                       (bench_settings){RT_PRECISION_DOUBLE, 0, grids[g],
                                        st ? RT_SAMPLING_STRATIFIED
                                           : RT_SAMPLING_REGULAR,
                                        RT_DEFAULT_DEPTH},
                       max_samples);
    for (int i = 0; i < count; i++)
        configs[i].base = i;
    return count;
}
