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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "depth.h"
#include "measure.h"
#include "metrics.h"
#include "output_file.h"
#include "plot.h"
#include "raytrace/raytrace.h"
#include "report.h"
#include "sweep.h"

#define EXIT_BAD_INPUT 1

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
        {"runs", 0, "N", CLI_INT, 5, BENCH_MAX_RUNS, &a->runs,
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
        CLI_OPTIONS_END,
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
    bench_plot_point points[BENCH_MAX_CONFIGS];
    char tooltips[BENCH_MAX_CONFIGS][256];
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
    if (rt_scene_load(a.scene, NULL, &scene, &error) != RT_OK) {
        fprintf(stderr, "rt-bench: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    rt_scene_info info = {.size = sizeof info};
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

    bench_depth_bound bound = bench_find_depth_bound(scene);
    int ref_depth = 0;
    while (bench_truncation_bound(&bound, ref_depth) >= DEPTH_TOLERANCE &&
           ref_depth < DEPTH_CAP)
        ref_depth++;
    static bench_config configs[BENCH_MAX_CONFIGS];
    int count = a.dof ? bench_build_dof_configs(configs, a.max_samples)
                      : bench_build_configs(configs, a.max_samples, ref_depth);
    int ref_grid = bench_reference_grid(a.ref_samples, configs, count);

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
    if (bench_truncation_bound(&bound, ref_depth) >= DEPTH_TOLERANCE)
        printf("warning: the bound does not reach %g levels by depth %d "
               "(reflective or transparent facets facing each other); the "
               "reference stops there\n",
               DEPTH_TOLERANCE, DEPTH_CAP);

    bench_images im = {0};
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
    if (!bench_analyse_depth(scene, options, &bound, ref_depth, &im,
                             depth_out.file, &converged_at,
                             &reference_stable))
        goto done;
    if (!output_file_close(&depth_out, 1)) {
        fprintf(stderr, "rt-bench: %s: cannot write: %s\n", path,
                strerror(errno));
        goto done;
    }

    bench_settings reference = {RT_PRECISION_DOUBLE, 0, ref_grid,
                                RT_SAMPLING_STRATIFIED, ref_depth};
    double ref_seconds, check_seconds;
    if (!a.cli.quiet)
        fprintf(stderr, "rt-bench: rendering the reference\n");
    if (!bench_render(scene, &reference, options, &im.reference,
                      &ref_seconds))
        goto done;
    reference.sampling = RT_SAMPLING_REGULAR;
    if (!bench_render(scene, &reference, options, &im.scratch,
                      &check_seconds))
        goto done;
    bench_error floor;
    bench_compare(&im.scratch, &im.reference, &floor);
    printf("\nreference: double, exact sqrt, depth %d (truncation <= %.3g "
           "levels), %d x %d stratified = %d rays per pixel, %.2f s\n"
           "its own uncertainty, against a %d x %d regular grid (%.2f s): "
           "RMSE %.4f, max %d, %.3f%% of pixels differ, %.3f%% by > %d\n",
           ref_depth, bench_truncation_bound(&bound, ref_depth), ref_grid,
           ref_grid, ref_grid * ref_grid, ref_seconds, ref_grid, ref_grid,
           check_seconds, floor.rmse, floor.max_error,
           bench_percent(floor.differing, floor.pixels),
           bench_percent(floor.differing_much, floor.pixels),
           BENCH_MUCH_LEVELS);
    if (a.dof && ref_grid % 2 == 0) {
        /* Its convergence: half the grid side, a quarter of the rays. */
        bench_settings quarter = {RT_PRECISION_DOUBLE, 0, ref_grid / 2,
                                  RT_SAMPLING_STRATIFIED, ref_depth};
        if (!bench_render(scene, &quarter, options, &im.scratch,
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

    if (!bench_measure(scene, options, a.runs, a.cli.quiet, configs, count,
                       &im))
        goto done;
    bench_row rows[BENCH_MAX_CONFIGS];
    double x[BENCH_MAX_CONFIGS], y[BENCH_MAX_CONFIGS];
    int front[BENCH_MAX_CONFIGS];
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
    bench_images_release(&im);
    rt_scene_destroy(scene);
    return code;
}
