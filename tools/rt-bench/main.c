/*
 * rt-bench - error against run time for the renderer's accuracy knobs.
 *
 * Renders a converged reference of one scene (double precision, exact
 * square root, a depth whose truncation is provably negligible, many rays
 * per pixel on a grid that does not nest the tested grids), then every
 * useful setting of precision, square root, samples per pixel and depth.
 * Each setting is timed (the median of several runs in this process, with
 * the spread) and its image compared with the reference (total error: what
 * depth and sampling cost) and with the same setting computed in double
 * with the exact square root (numerical error: what float and fastInvSqrt
 * cost).  Prints the table and writes a CSV and an SVG plot of error
 * against time with the Pareto front (docs/accuracy.md explains them).
 * With --dof it measures depth of field instead: 1, 4, 16 and 64 rays per
 * pixel (regular and stratified grids, which also sample the thin lens)
 * against a reference of 1024 rays, on a scene whose camera has a lens.
 * Exit status: 0 success, 1 bad input, failed render or write, or a
 * comparison (--compare) that found different errors, 2 bad usage.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/raytrace.h"
#include "cli.h"
#include "cli_clock.h"
#include "metrics.h"
#include "output_file.h"
#include "plot.h"
#include "report.h"

#define EXIT_BAD_INPUT 1

#define MAX_RUNS 99
#define MAX_CONFIGS 64
#define DEPTH_CAP 64            /* deepest reference the bound may ask for */
#define DEPTH_TOLERANCE 1e-3    /* truncation bound of the reference, levels */

static const char description[] =
    "Measures what the accuracy knobs of the renderer cost and buy on one\n"
    "scene: prints a table and writes DIR/accuracy-NAME-WxH.csv (every\n"
    "setting), DIR/accuracy-NAME-WxH-depth.csv (depth truncation against\n"
    "its bound) and DIR/accuracy-NAME-WxH.svg (error against time, log\n"
    "axes, Pareto front).  docs/accuracy.md explains how to read them.\n"
    "With --dof it measures depth of field instead (the camera needs a\n"
    "lens: the scene's, or --aperture).  The size, the lens and the\n"
    "threads are the render options every program takes; the precision,\n"
    "square root, samples and depth are what it sweeps.";

static const char epilogue[] =
    "Settings are named 'PRECISION[+fast] dDEPTH SAMPLES[r|s]': float+fast\n"
    "d2 16s is float arithmetic, fastInvSqrt, depth 2, 16 rays per pixel\n"
    "on a stratified 4x4 grid (r: regular grid; no letter: one ray through\n"
    "the pixel centre).  Exit status: 0 success, 1 bad scene, failed render\n"
    "or write, or errors that differ from --compare's, 2 bad usage.";

typedef struct arguments {
    cli_settings cli;           /* size, lens, threads, quiet, the scene */
    const char *scene;
    const char *out;
    const char *compare;
    int runs;
    int ref_samples;
    int max_samples;
    int dof;                    /* the depth-of-field sweep */
} arguments;

/* The knobs of one render. */
typedef struct settings {
    rt_precision precision;
    int fast_sqrt;
    int grid;                   /* samples per side of a pixel */
    rt_sampling sampling;
    int depth;
} settings;

typedef struct config {
    settings s;
    bench_row row;
    double times[MAX_RUNS];
    unsigned long long hash;    /* of the first render's image */
    int base;                   /* the double/exact config with the same
                                   sampling and depth (may be itself) */
} config;

/* What bounds the contribution of the bounces past a depth (see
 * docs/accuracy.md and bench_depth_bound in bench/metrics.h). */
typedef bench_depth_bound depth_bound;

static int square_root(int n)
{
    int root = 1;
    while (root * root < n)
        root++;
    return root * root == n ? root : 0;
}

/* Returns CLI_CONTINUE to go on, or an exit status. */
static int parse_arguments(int argc, char **argv, arguments *a)
{
    a->out = ".";
    a->compare = NULL;
    a->runs = 5;
    a->ref_samples = 0;
    a->max_samples = 0;
    a->dof = 0;
    const cli_option own[] = {
        {"out", 0, "DIR", CLI_STRING, 0, 0, &a->out,
         "where to write the files (default .)"},
        {"runs", 0, "N", CLI_INT, 5, MAX_RUNS, &a->runs,
         "timed renders per setting (default 5)"},
        {"ref-samples", 0, "N", CLI_SQUARE, 1, CLI_MAX_SAMPLES,
         &a->ref_samples,
         "rays per pixel of the reference, a square (default 256, 1024 "
         "with --dof; raised if its grid would nest a tested one)"},
        {"max-samples", 0, "N", CLI_INT, 1, CLI_MAX_SAMPLES, &a->max_samples,
         "leave out settings with more rays per pixel (default 16; 64 with "
         "--dof)"},
        {"compare", 0, "CSV", CLI_STRING, 0, 0, &a->compare,
         "compare with the CSV of an earlier run: errors must be equal, "
         "times within the spread"},
        {"dof", 0, NULL, CLI_FLAG, 0, 0, &a->dof,
         "depth of field instead: double, depth 5, 1, 4, 16, 64 rays per "
         "pixel on regular and stratified grids (they sample the lens too) "
         "against a reference of 1024 (--ref-samples); writes "
         "DIR/accuracy-dof-NAME-WxH.{csv,svg}"},
        {NULL, 0, NULL, CLI_FLAG, 0, 0, NULL, NULL},
    };
    const cli_program program = {
        "rt-bench", "SCENE", description, epilogue,
        CLI_GROUP_THREADS | CLI_GROUP_LENS | CLI_GROUP_SIZE | CLI_GROUP_QUIET,
        own, 1, 1, "expected a scene file"};
    int code = cli_parse(&program, argc, argv, &a->cli);
    if (code != CLI_CONTINUE)
        return code;
    a->scene = a->cli.operands[0];
    if (a->ref_samples == 0)
        a->ref_samples = a->dof ? 1024 : 256;
    if (a->max_samples == 0)
        a->max_samples = a->dof ? 64 : 16;
    return CLI_CONTINUE;
}

/* Renders with the options the user gave (size, lens, threads) and the
 * knobs `s`; *seconds is the wall-clock time of the call. */
static rt_status render(const rt_scene *scene, const settings *s,
                        const rt_render_options *base, rt_image *image,
                        double *seconds, rt_error *error)
{
    rt_render_options options = *base;
    options.precision = s->precision;
    options.fast_inv_sqrt = s->fast_sqrt;
    options.samples = s->grid * s->grid;
    options.sampling = s->sampling;
    options.max_depth = s->depth;
    double start = cli_clock_seconds();
    rt_status status = rt_render(scene, &options, image, error);
    *seconds = cli_seconds_since(start);
    return status;
}

static double distance_to_plane(rt_vec3 p, rt_vec3 a, rt_vec3 normal)
{
    return fabs((p.x - a.x) * normal.x + (p.y - a.y) * normal.y +
                (p.z - a.z) * normal.z);
}

static double max3(double a, double b, double c)
{
    return fmax(a, fmax(b, c));
}

/*
 * The constants of the truncation bound of the scene's facets.  A hit's
 * colour is (k + t) times what its two rays carry (at most peak) plus
 * d times its local term (at most the sum over the lights of C_S C_F / 255
 * per channel), so peak >= local d / (1 - k - t) keeps every colour within
 * peak; a facet with k + t = 1 and d > 0 bounds nothing (peak infinite, so
 * the bound is the 255 levels of the format).
 */
static depth_bound find_depth_bound(const rt_scene *scene)
{
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    depth_bound b = {max3(info.background.r, info.background.g,
                          info.background.b), 0.0, 0.0};
    double light[3] = {0.0, 0.0, 0.0};
    for (int l = 0; l < info.light_count; l++) {
        rt_light s;
        rt_scene_light(scene, l, &s);
        light[0] += s.color.r, light[1] += s.color.g, light[2] += s.color.b;
    }
    double extent = 0.0;
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        extent = fmax(extent, max3(fabs(v.x), fabs(v.y), fabs(v.z)));
    }
    int top = -1;
    rt_facet_info f, g;
    for (int i = 0; i < info.facet_count; i++) {
        rt_scene_facet(scene, i, &f);
        if (f.degenerate)
            continue;
        double carried = f.k + f.t;
        double local = f.d * max3(light[0] * f.color.r, light[1] * f.color.g,
                                  light[2] * f.color.b) / 255.0;
        b.peak = fmax(b.peak, bench_peak_needed(local, carried));
        if (top < 0 || carried > b.k_max) {
            top = i;
            b.k_max = carried;
        }
    }
    if (top < 0)
        return b;
    /* The best pair holds a facet of largest k + t: any facet coplanar
     * with the other member of a better pair would be coplanar with it
     * too. */
    rt_scene_facet(scene, top, &f);
    rt_vec3 a = rt_scene_vertex(scene, f.vertex[0]);
    double tolerance = 1e-9 * fmax(extent, 1e-300);
    for (int i = 0; i < info.facet_count; i++) {
        rt_scene_facet(scene, i, &g);
        if (g.degenerate)
            continue;
        int coplanar = 1;
        for (int v = 0; v < 3; v++)
            coplanar &= distance_to_plane(rt_scene_vertex(scene, g.vertex[v]),
                                          a, f.normal) <= tolerance;
        if (!coplanar)
            b.pair = fmax(b.pair, (f.k + f.t) * (g.k + g.t));
    }
    return b;
}

/* Largest colour error of stopping after `depth` reflections, in levels. */
static double truncation_bound(const depth_bound *b, int depth)
{
    return bench_truncation_bound(b, depth);
}

/* The smallest regular grid side >= `grid` that contains none of the
 * tested regular grids' points: side m holds side n's centres exactly when
 * m / n is an odd integer. */
static int non_nesting_grid(int grid, const config *configs, int count)
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

static void make_label(const settings *s, char *label, size_t size)
{
    snprintf(label, size, "%s%s d%d %d%s",
             s->precision == RT_PRECISION_FLOAT ? "float" : "double",
             s->fast_sqrt ? "+fast" : "", s->depth, s->grid * s->grid,
             s->grid == 1 ? ""
             : s->sampling == RT_SAMPLING_STRATIFIED ? "s" : "r");
}

static const char *knobs_varied(const settings *s)
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

static int same_settings(const settings *a, const settings *b)
{
    return a->precision == b->precision && a->fast_sqrt == b->fast_sqrt &&
           a->grid == b->grid && a->depth == b->depth &&
           (a->grid == 1 || a->sampling == b->sampling);
}

static void add_config(config *configs, int *count, settings s,
                       int max_samples)
{
    if (s.grid * s.grid > max_samples || *count >= MAX_CONFIGS)
        return;
    if (s.grid == 1)
        s.sampling = RT_SAMPLING_REGULAR;
    for (int i = 0; i < *count; i++) {
        if (same_settings(&configs[i].s, &s))
            return;
    }
    config *c = &configs[(*count)++];
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
 * The settings measured: every combination of the two numerical knobs with
 * one ray, 4 and 16 stratified rays and depths 2 and 5; then each knob on
 * its own from the default (regular grids, 9 rays, depths 0, 1, 3 and the
 * reference's).
 */
static int build_configs(config *configs, int max_samples, int ref_depth)
{
    int count = 0;
    const int depths[] = {2, RT_DEFAULT_DEPTH};
    const int grids[] = {1, 2, 4};
    for (int d = 0; d < 2; d++)
        for (int g = 0; g < 3; g++)
            for (int n = 0; n < 4; n++)
                add_config(configs, &count,
                           (settings){n / 2 ? RT_PRECISION_FLOAT
                                            : RT_PRECISION_DOUBLE,
                                      n % 2, grids[g], RT_SAMPLING_STRATIFIED,
                                      depths[d]},
                           max_samples);
    const int alone[][2] = {{2, RT_SAMPLING_REGULAR},
                            {3, RT_SAMPLING_REGULAR},
                            {3, RT_SAMPLING_STRATIFIED},
                            {4, RT_SAMPLING_REGULAR}};
    for (int i = 0; i < 4; i++)
        add_config(configs, &count,
                   (settings){RT_PRECISION_DOUBLE, 0, alone[i][0],
                              (rt_sampling)alone[i][1], RT_DEFAULT_DEPTH},
                   max_samples);
    const int depth_alone[] = {0, 1, 3, ref_depth};
    for (int i = 0; i < 4; i++)
        add_config(configs, &count,
                   (settings){RT_PRECISION_DOUBLE, 0, 1, RT_SAMPLING_REGULAR,
                              depth_alone[i]},
                   max_samples);
    for (int i = 0; i < count; i++) {
        settings base = configs[i].s;
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
static int build_dof_configs(config *configs, int max_samples)
{
    int count = 0;
    const int grids[] = {1, 2, 4, 8};
    for (int g = 0; g < 4; g++)
        for (int st = 0; st < 2; st++)
            add_config(configs, &count,
                       (settings){RT_PRECISION_DOUBLE, 0, grids[g],
                                  st ? RT_SAMPLING_STRATIFIED
                                     : RT_SAMPLING_REGULAR,
                                  RT_DEFAULT_DEPTH},
                       max_samples);
    for (int i = 0; i < count; i++)
        configs[i].base = i;
    return count;
}

/* Images of the run, freed together. */
typedef struct images {
    rt_image reference, scratch, depth_reference;
    rt_image kept[MAX_CONFIGS];     /* round one's double/exact images */
} images;

static void free_images(images *im)
{
    rt_image_release(&im->reference);
    rt_image_release(&im->scratch);
    rt_image_release(&im->depth_reference);
    for (int i = 0; i < MAX_CONFIGS; i++)
        rt_image_release(&im->kept[i]);
}

static int render_or_complain(const rt_scene *scene, const settings *s,
                              const rt_render_options *base, rt_image *image,
                              double *seconds)
{
    rt_error error;
    rt_status status = render(scene, s, base, image, seconds, &error);
    if (status != RT_OK)
        fprintf(stderr, "rt-bench: cannot render: %s\n", error.message);
    return status == RT_OK;
}

/*
 * Depth truncation measured against its bound, at one ray per pixel in
 * double: depth d against the reference depth D.  Also finds the first
 * depth whose image one more bounce leaves unchanged, and whether D + 1
 * changes D's.  Returns 0 if a render failed.
 */
static int analyse_depth(const rt_scene *scene, const rt_render_options *base,
                         const depth_bound *b, int ref_depth, images *im,
                         FILE *csv, int *converged_at, int *reference_stable)
{
    settings s = {RT_PRECISION_DOUBLE, 0, 1, RT_SAMPLING_REGULAR, ref_depth};
    double seconds;
    if (!render_or_complain(scene, &s, base, &im->depth_reference,
                            &seconds))
        return 0;
    s.depth = ref_depth + 1;
    if (!render_or_complain(scene, &s, base, &im->scratch, &seconds))
        return 0;
    bench_error e;
    bench_compare(&im->scratch, &im->depth_reference, &e);
    *reference_stable = e.differing == 0;
    unsigned long long reference_hash = bench_image_hash(&im->depth_reference);
    unsigned long long previous_hash = 0;
    *converged_at = -1;
    printf("\ndepth truncation, 1 ray per pixel in double, against depth %d "
           "(bound: docs/accuracy.md)\n"
           "%5s %14s %11s | %12s %8s %8s\n",
           ref_depth, "depth", "bound levels", "allowed max", "measured max",
           "RMSE", "%diff");
    fprintf(csv, "depth,bound_levels,allowed_max,measured_max,rmse,"
                 "differing,differing_pct,within_bound\n");
    int all_within = 1;
    for (int d = 0; d <= ref_depth; d++) {
        s.depth = d;
        if (d < ref_depth &&
            !render_or_complain(scene, &s, base, &im->scratch, &seconds))
            return 0;
        const rt_image *image = d < ref_depth ? &im->scratch
                                              : &im->depth_reference;
        unsigned long long hash = d < ref_depth ? bench_image_hash(image)
                                                : reference_hash;
        if (d > 0 && *converged_at < 0 && hash == previous_hash)
            *converged_at = d - 1;
        previous_hash = hash;
        bench_compare(image, &im->depth_reference, &e);
        double bound = truncation_bound(b, d);
        int allowed = (int)ceil(bound);
        int within = e.max_error <= allowed;
        all_within &= within;
        printf("%5d %14.6g %11d | %12d %8.4f %8.4f%s\n", d, bound, allowed,
               e.max_error, e.rmse, bench_percent(e.differing, e.pixels),
               within ? "" : "  EXCEEDS THE BOUND");
        fprintf(csv, "%d,%.6g,%d,%d,%.6g,%ld,%.6g,%d\n", d, bound, allowed,
                e.max_error, e.rmse, e.differing,
                bench_percent(e.differing, e.pixels), within);
    }
    if (*converged_at < 0 && *reference_stable)
        *converged_at = ref_depth;
    printf("measured within the bound at every depth: %s; first depth that "
           "one more bounce leaves byte-identical: %d; depth %d vs %d: %s\n",
           all_within ? "yes" : "NO", *converged_at, ref_depth + 1,
           ref_depth, *reference_stable ? "byte-identical" : "DIFFERENT");
    return 1;
}

static void progress(const arguments *a, int round, int i, int count,
                     const char *label)
{
    if (!a->cli.quiet)
        fprintf(stderr, "rt-bench: run %d/%d, setting %d/%d: %s\n",
                round + 1, a->runs, i + 1, count, label);
}

/* Renders every setting `runs` times, in rounds (so that a slow period of
 * the machine spreads over all settings), measuring the errors in the
 * first round.  Returns 0 if a render failed or a repeat differed. */
static int measure(const rt_scene *scene, const arguments *a,
                   config *configs, int count, images *im)
{
    for (int round = 0; round < a->runs; round++) {
        /* double/exact settings first: the others' numerical error needs
         * their images */
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < count; i++) {
                config *c = &configs[i];
                int is_base = c->base == i;
                if ((pass == 0) != is_base)
                    continue;
                progress(a, round, i, count, c->row.label);
                rt_image *image = round == 0 && is_base ? &im->kept[i]
                                                        : &im->scratch;
                if (image->pixels == NULL &&
                    rt_image_init(image, im->reference.width,
                                    im->reference.height, NULL) != RT_OK) {
                    fprintf(stderr, "rt-bench: out of memory\n");
                    return 0;
                }
                if (!render_or_complain(scene, &c->s, &a->cli.render, image,
                                        &c->times[round]))
                    return 0;
                unsigned long long hash = bench_image_hash(image);
                if (round == 0) {
                    c->hash = hash;
                    bench_compare(image, &im->reference, &c->row.total);
                    bench_compare(image, &im->kept[c->base],
                                  &c->row.numerical);
                } else if (hash != c->hash) {
                    fprintf(stderr, "rt-bench: %s: run %d gave a different "
                                    "image from run 1\n",
                            c->row.label, round + 1);
                    return 0;
                }
            }
        }
    }
    for (int i = 0; i < count; i++) {
        double sorted[MAX_RUNS];
        memcpy(sorted, configs[i].times, sizeof sorted);
        configs[i].row.runs = a->runs;
        bench_summarize(sorted, a->runs, &configs[i].row.median,
                        &configs[i].row.minimum, &configs[i].row.maximum);
    }
    return 1;
}

static int by_time(const void *a, const void *b)
{
    const bench_row *x = a, *y = b;
    return (x->median > y->median) - (x->median < y->median);
}

static int write_plot(const char *path, const char *title,
                      const char *subtitle, const bench_row *rows, int count,
                      int dof)
{
    static const char *const colours[] = {
        "double, exact sqrt (reference arithmetic)", "double, fastInvSqrt",
        "float, exact sqrt", "float, fastInvSqrt"};
    static const char *const shapes[] = {
        "1 ray through the pixel centre", "regular n x n grid",
        "stratified n x n grid"};
    static const char *const dof_colours[] = {
        "double, exact sqrt, depth 5"};
    static const char *const dof_shapes[] = {
        "1 ray: lens centre (pinhole)", "regular n x n, pixel + lens",
        "stratified n x n, pixel + lens"};
    bench_plot_point points[MAX_CONFIGS];
    char tooltips[MAX_CONFIGS][256];
    for (int i = 0; i < count; i++) {
        const bench_row *r = &rows[i];
        snprintf(tooltips[i], sizeof tooltips[i],
                 "%.47s: %.2f ms (%.2f-%.2f), total RMSE %.4g, numerical RMSE "
                 "%.4g, max %d",
                 r->label, 1e3 * r->median, 1e3 * r->minimum,
                 1e3 * r->maximum, r->total.rmse, r->numerical.rmse,
                 r->total.max_error);
        points[i] = (bench_plot_point){
            r->median, r->minimum, r->maximum, r->total.rmse,
            2 * (r->precision == RT_PRECISION_FLOAT) + (r->fast_sqrt != 0),
            r->samples == 1 ? BENCH_SHAPE_CIRCLE
            : r->sampling == RT_SAMPLING_STRATIFIED ? BENCH_SHAPE_TRIANGLE
                                                    : BENCH_SHAPE_SQUARE,
            r->on_front, r->label, tooltips[i]};
    }
    bench_plot plot = {title, subtitle, "median render time (s), log scale",
                       "RMSE against the converged reference (levels of "
                       "255), log scale",
                       dof ? dof_colours : colours, dof ? 1 : 4,
                       dof ? dof_shapes : shapes, 3, points, count};
    output_file out;
    int ok = output_file_open(&out, path);
    ok = output_file_close(&out, ok && bench_plot_write_svg(out.file, &plot));
    if (!ok)
        fprintf(stderr, "rt-bench: %s: cannot write: %s\n", path,
                strerror(errno));
    return ok;
}

static int write_csv(const char *path, const char *scene, int width,
                     int height, const bench_row *rows, int count)
{
    output_file out;
    int ok = output_file_open(&out, path);
    ok = output_file_close(&out, ok && bench_write_csv(out.file, scene, width,
                                                       height, rows, count));
    if (!ok)
        fprintf(stderr, "rt-bench: %s: cannot write: %s\n", path,
                strerror(errno));
    return ok;
}

/* "dir/name.scn" -> "name". */
static void scene_name(const char *path, char *name, size_t size)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *dot = strrchr(base, '.');
    int length = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    snprintf(name, size, "%.*s", length, base);
}

static int compare_with(const char *path, const bench_row *rows, int count)
{
    bench_row *before;
    char message[512];
    int before_count = bench_read_csv(path, &before, message, sizeof message);
    if (before_count < 0) {
        fprintf(stderr, "rt-bench: %s\n", message);
        return 0;
    }
    printf("\ncomparison with %s:\n", path);
    int ok = bench_compare_runs(stdout, rows, count, before, before_count);
    free(before);
    return ok;
}

int main(int argc, char **argv)
{
    arguments a;
    int code = parse_arguments(argc, argv, &a);
    if (code != CLI_CONTINUE)
        return code;
    const rt_render_options *options = &a.cli.render;
    rt_scene *scene;
    rt_error error;
    if (rt_scene_load(a.scene, &scene, &error) != RT_OK) {
        fprintf(stderr, "rt-bench: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    int width, height;
    if (rt_render_image_size(scene, options, &width, &height, &error) !=
        RT_OK) {
        fprintf(stderr, "rt-bench: --size: %s\n", error.message);
        rt_scene_destroy(scene);
        return CLI_EXIT_USAGE;
    }
    /* the lens the renders use: the options', else the scene's */
    double aperture = options->aperture >= 0.0 ? options->aperture
                                               : info.camera.aperture;
    double focus = options->focal_distance > 0.0
                       ? options->focal_distance
                       : info.camera.focal_distance;
    if (a.dof && !(aperture > 0.0)) {
        fprintf(stderr, "rt-bench: %s: the camera has no lens (aperture "
                        "0): give --aperture A (and --focus F) to measure "
                        "depth of field\n", a.scene);
        rt_scene_destroy(scene);
        return EXIT_BAD_INPUT;
    }
    int threads = options->threads;

    depth_bound bound = find_depth_bound(scene);
    int ref_depth = 0;
    while (truncation_bound(&bound, ref_depth) >= DEPTH_TOLERANCE &&
           ref_depth < DEPTH_CAP)
        ref_depth++;
    static config configs[MAX_CONFIGS];
    int count = a.dof ? build_dof_configs(configs, a.max_samples)
                      : build_configs(configs, a.max_samples, ref_depth);
    int ref_grid = non_nesting_grid(square_root(a.ref_samples), configs,
                                    count);

    char name[256], base[4096], path[4200];
    scene_name(a.scene, name, sizeof name);
    snprintf(base, sizeof base, "%s/accuracy-%s%s-%dx%d", a.out,
             a.dof ? "dof-" : "", name, width, height);
    if (mkdir(a.out, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "rt-bench: %s: cannot create: %s\n", a.out,
                strerror(errno));
        rt_scene_destroy(scene);
        return EXIT_BAD_INPUT;
    }
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    printf("rt-bench (libraytrace %s): %s at %d x %d, %d facets; %d runs per "
           "setting on %d thread%s\n",
           rt_version_string(), a.scene, width, height,
           info.facet_count, a.runs, threads ? threads : (int)cores,
           (threads ? threads : cores) == 1 ? "" : "s");
    if (aperture > 0.0)
        printf("lens: aperture radius a = %g, focal distance f = %g (scene "
               "units)\n", aperture, focus);
    printf("depth bound: every colour <= %g, largest k + t %g, largest "
           "(k+t)_i (k+t)_j of facets not coplanar %g\n",
           bound.peak, bound.k_max, bound.pair);
    if (truncation_bound(&bound, ref_depth) >= DEPTH_TOLERANCE)
        printf("warning: the bound does not reach %g levels by depth %d "
               "(reflective or transparent facets facing each other); the "
               "reference stops there\n",
               DEPTH_TOLERANCE, DEPTH_CAP);

    images im = {0};
    code = EXIT_BAD_INPUT;
    output_file depth_out = {0};
    if (rt_image_init(&im.reference, width, height, NULL) != RT_OK ||
        rt_image_init(&im.scratch, width, height, NULL) != RT_OK ||
        rt_image_init(&im.depth_reference, width, height, NULL) !=
            RT_OK) {
        fprintf(stderr, "rt-bench: out of memory\n");
        goto done;
    }
    snprintf(path, sizeof path, "%s-depth.csv", base);
    if (!output_file_open(&depth_out, path)) {
        fprintf(stderr, "rt-bench: %s: cannot write: %s\n", path,
                strerror(errno));
        goto done;
    }
    int converged_at, reference_stable;
    if (!analyse_depth(scene, options, &bound, ref_depth, &im,
                       depth_out.file, &converged_at, &reference_stable))
        goto done;
    if (!output_file_close(&depth_out, 1)) {
        fprintf(stderr, "rt-bench: %s: cannot write: %s\n", path,
                strerror(errno));
        goto done;
    }

    settings reference = {RT_PRECISION_DOUBLE, 0, ref_grid,
                          RT_SAMPLING_STRATIFIED, ref_depth};
    double ref_seconds, check_seconds;
    if (!a.cli.quiet)
        fprintf(stderr, "rt-bench: rendering the reference\n");
    if (!render_or_complain(scene, &reference, options, &im.reference,
                            &ref_seconds))
        goto done;
    reference.sampling = RT_SAMPLING_REGULAR;
    if (!render_or_complain(scene, &reference, options, &im.scratch,
                            &check_seconds))
        goto done;
    bench_error floor;
    bench_compare(&im.scratch, &im.reference, &floor);
    printf("\nreference: double, exact sqrt, depth %d (truncation <= %.3g "
           "levels), %d x %d stratified = %d rays per pixel, %.2f s\n"
           "its own uncertainty, against a %d x %d regular grid (%.2f s): "
           "RMSE %.4f, max %d, %.3f%% of pixels differ, %.3f%% by > %d\n",
           ref_depth, truncation_bound(&bound, ref_depth), ref_grid,
           ref_grid, ref_grid * ref_grid, ref_seconds, ref_grid, ref_grid,
           check_seconds, floor.rmse, floor.max_error,
           bench_percent(floor.differing, floor.pixels),
           bench_percent(floor.differing_much, floor.pixels),
           BENCH_MUCH_LEVELS);
    if (a.dof && ref_grid % 2 == 0) {
        /* Its convergence: half the grid side, a quarter of the rays. */
        settings quarter = {RT_PRECISION_DOUBLE, 0, ref_grid / 2,
                            RT_SAMPLING_STRATIFIED, ref_depth};
        if (!render_or_complain(scene, &quarter, options, &im.scratch,
                                &check_seconds))
            goto done;
        bench_compare(&im.scratch, &im.reference, &floor);
        printf("its convergence, %d x %d stratified = %d rays (%.2f s) "
               "against it: RMSE %.4f, max %d, %.3f%% of pixels differ, "
               "%.3f%% by > %d\n",
               ref_grid / 2, ref_grid / 2, ref_grid * ref_grid / 4,
               check_seconds, floor.rmse, floor.max_error,
               bench_percent(floor.differing, floor.pixels),
               bench_percent(floor.differing_much, floor.pixels),
               BENCH_MUCH_LEVELS);
    }

    if (!measure(scene, &a, configs, count, &im))
        goto done;
    bench_row rows[MAX_CONFIGS];
    double x[MAX_CONFIGS], y[MAX_CONFIGS];
    int front[MAX_CONFIGS];
    for (int i = 0; i < count; i++) {
        rows[i] = configs[i].row;
        x[i] = rows[i].median;
        y[i] = rows[i].total.rmse;
    }
    bench_pareto_front(x, y, count, front);
    for (int i = 0; i < count; i++)
        rows[i].on_front = front[i];
    qsort(rows, (size_t)count, sizeof rows[0], by_time);
    printf("\nsettings by median time (%d runs; * = Pareto front of time "
           "and total RMSE)\n", a.runs);
    bench_print_table(stdout, rows, count);

    char title[512], subtitle[512];
    if (a.dof)
        snprintf(title, sizeof title, "%s at %d x %d, depth of field (a = "
                 "%g, f = %g): error against render time", name, width,
                 height, aperture,
                 focus);
    else
        snprintf(title, sizeof title, "%s at %d x %d: error against render "
                 "time", name, width, height);
    snprintf(subtitle, sizeof subtitle,
             "reference: double, exact sqrt, depth %d, %d x %d stratified; "
             "median of %d runs on %d threads; libraytrace %s",
             ref_depth, ref_grid, ref_grid, a.runs,
             threads ? threads : (int)cores, rt_version_string());
    snprintf(path, sizeof path, "%s.csv", base);
    if (!write_csv(path, name, width, height, rows, count))
        goto done;
    printf("\nwrote %s\n", path);
    snprintf(path, sizeof path, "%s.svg", base);
    if (!write_plot(path, title, subtitle, rows, count, a.dof))
        goto done;
    printf("wrote %s\nwrote %s-depth.csv\n", path, base);
    code = EXIT_SUCCESS;
    if (a.compare != NULL && !compare_with(a.compare, rows, count))
        code = EXIT_BAD_INPUT;
done:
    output_file_close(&depth_out, 0);
    free_images(&im);
    rt_scene_destroy(scene);
    return code;
}
