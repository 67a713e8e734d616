/*
 * rt-export - render a `.scn` scene to a PPM or PNG image, headless.
 *
 * A thin command-line client of libraytrace: parse the arguments, load the
 * scene (from a file or standard input), check that the output can be
 * written and is none of the files the scene was read from, render on all
 * cores with a progress line on a terminal, save the image with the
 * library's safe save (or stream it to standard output) - after the same
 * check again, and keeping the image under another name when the save
 * fails (apps/common/cli_output.h) - and print the path.  Exit status: 0
 * success, 1 bad input or a failed write, 2 bad usage; a signal during the
 * save ends it killed by that signal, the previous file intact.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "cli_explain.h"
#include "cli_output.h"
#include "cli_report.h"
#include "cli_text.h"
#include "raytrace/raytrace.h"

#define EXIT_BAD_INPUT 1

static int check_only; /* --check */

static const cli_option export_options[] = {
    {"check", 0, NULL, CLI_FLAG, 0, 0, &check_only,
     "validate the scene and print what it holds; do not render"},
    {NULL, 0, NULL, CLI_FLAG, 0, 0, NULL, NULL},
};

static const cli_program program = {
    "rt-export", "SCENE",
    "Renders SCENE (a .scn scene, an NFF file or a Wavefront OBJ model, by\n"
    "its extension) to an image and prints the path it wrote.  SCENE `-'\n"
    "reads the scene from standard input (then -o is needed).  The image\n"
    "goes to OUT (default: the scene's name with .ppm, or .png with\n"
    "--format png, in the current directory; `-o -' writes it to standard\n"
    "output and nothing else there); a device, FIFO or socket is\n"
    "written directly, a file is replaced atomically, keeping its mode,\n"
    "owner and links.  The progress line (stderr, on a terminal) shows the\n"
    "time left and the camera rays per second; --stats=json prints one\n"
    "JSON object on one line, the last line on stderr.  --explain X,Y\n"
    "prints why pixel X,Y has its colour instead of writing the image;\n"
    "--view writes a debug view in its place (docs/teaching.md).",
    "Exit status: 0 success, 1 bad scene or failed write, 2 bad usage.\n"
    "A signal during the save leaves the previous file intact.",
    CLI_GROUP_RENDER | CLI_GROUP_LOAD | CLI_GROUP_OUTPUT | CLI_GROUP_REPORT |
        CLI_GROUP_QUIET | CLI_GROUP_EXPLAIN | CLI_GROUP_VIEW,
    export_options, 1, 1, "expected a scene file"};

/* "dir/name.scn" -> "name.ppm", or "name.png" for PNG (in the current
 * directory). */
static char *default_output(const char *scene, rt_image_format format)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    const char *dot = strrchr(base, '.');
    size_t length = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    const char *extension = format == RT_IMAGE_PNG ? ".png" : ".ppm";
    char *out = malloc(length + 5);
    if (out != NULL) {
        memcpy(out, base, length);
        memcpy(out + length, extension, 5);
    }
    return out;
}

/* Reads the whole scene from standard input and parses it as "<stdin>";
 * the files it names (an OBJ's libraries) are looked for in the current
 * folder, as rt_scene_load_with looks in the scene's. */
static rt_status load_standard_input(const rt_load_options *given,
                                     rt_scene **scene, rt_error *error)
{
    rt_load_options resolved = *given;
    const rt_load_options *options = &resolved;
    if (resolved.resolve == NULL)
        resolved.resolve = rt_resolve_in_folder;
    size_t capacity = 1 << 16, used = 0;
    char *text = malloc(capacity);
    while (text != NULL) {
        size_t got = fread(text + used, 1, capacity - used, stdin);
        used += got;
        if (used < capacity)
            break;
        /* /dev/zero or a huge binary: the loader's check names it */
        if (used > RT_MAX_SCENE_BYTES || memchr(text + used - got, 0, got))
            break;
        char *bigger = capacity <= SIZE_MAX / 2 ? realloc(text, capacity * 2)
                                                : NULL;
        if (bigger == NULL)
            free(text);
        text = bigger;
        capacity *= 2;
    }
    if (text == NULL) {
        *scene = NULL;
        snprintf(error->message, sizeof error->message,
                 "<stdin>: out of memory reading the scene");
        return RT_ERR_NOMEM;
    }
    if (ferror(stdin)) {
        free(text);
        *scene = NULL;
        snprintf(error->message, sizeof error->message,
                 "<stdin>: cannot read: %s", strerror(errno));
        return RT_ERR_IO;
    }
    rt_status status = rt_scene_parse_with(text, used, "<stdin>", options,
                                           scene, error);
    free(text);
    return status;
}

static void print_check(const char *path, const rt_scene *scene)
{
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    printf("%s: valid scene\n", path);
    printf("  image      %d x %d\n", info.width, info.height);
    printf("  vertices   %d\n", info.vertex_count);
    printf("  facets     %d (%d can be hit, %d reflective, %d "
           "transparent)\n",
           info.facet_count, info.live_facet_count,
           info.reflective_facet_count, info.transparent_facet_count);
    printf("  camera     O (%g, %g, %g), A (%g, %g, %g)%s\n",
           info.camera.observer.x, info.camera.observer.y,
           info.camera.observer.z, info.camera.screen_center.x,
           info.camera.screen_center.y, info.camera.screen_center.z,
           info.camera.b_was_projected
               ? ", B projected onto the screen plane"
               : "");
    if (info.camera.aperture > 0.0)
        printf("  lens       aperture %g, focal distance %g\n",
               info.camera.aperture, info.camera.focal_distance);
    for (int i = 0; i < info.light_count; i++) {
        rt_light light;
        rt_scene_light(scene, i, &light);
        printf("  light      (%g, %g, %g), colour %d %d %d\n",
               light.position.x, light.position.y, light.position.z,
               light.color.r, light.color.g, light.color.b);
    }
    printf("  background %d %d %d\n", info.background.r, info.background.g,
           info.background.b);
    printf("  warnings   %d\n", info.warning_count);
    for (int i = 0; i < info.warning_count; i++)
        printf("  %s\n", rt_scene_warning(scene, i)->message);
}

/* --explain X,Y: the ray tree of that pixel, as text or JSON.  Returns an
 * exit status. */
static int explain(const rt_scene *scene, const cli_settings *s,
                   const char *scene_name)
{
    rt_ray_tree *tree;
    rt_error error;
    if (rt_explain_pixel(scene, &s->render, s->explain_x, s->explain_y, -1,
                         &tree, &error) != RT_OK) {
        fprintf(stderr, "rt-export: %s: cannot explain: %s\n", scene_name,
                error.message);
        return EXIT_BAD_INPUT;
    }
    if (s->explain_json)
        cli_explain_print_json(stdout, tree, scene_name, s->explain_x,
                               s->explain_y);
    else
        cli_explain_print_text(stdout, tree, scene_name, s->explain_x,
                               s->explain_y, s->render.samples);
    rt_ray_tree_destroy(tree);
    return EXIT_SUCCESS;
}

/* Non-zero when `path` names the file open as descriptor `fd`
 * (-o /dev/stdout). */
static int same_file_as(const char *path, int fd)
{
    struct stat sp, sf;
    return stat(path, &sp) == 0 && fstat(fd, &sf) == 0 &&
           sp.st_dev == sf.st_dev && sp.st_ino == sf.st_ino;
}

/* Refusals that need no scene: an image format this build cannot write,
 * a binary image to a terminal.  Returns CLI_CONTINUE or an exit status. */
static int refuse_early(const cli_settings *s, int to_stdout)
{
    if (check_only)
        return CLI_CONTINUE;
    if (!rt_image_format_supported(s->format)) {
        fprintf(stderr, "rt-export: cannot write %s: this build has no PNG "
                        "support (it was built without libpng); use --format "
                        "p6 or p3\n", s->output ? s->output : "PNG");
        return EXIT_BAD_INPUT;
    }
    if (to_stdout && s->format != RT_IMAGE_P3 && isatty(STDOUT_FILENO)) {
        fprintf(stderr, "rt-export: refusing to write a binary image to a "
                        "terminal; redirect standard output, or use "
                        "--format p3\n");
        return CLI_EXIT_USAGE;
    }
    return CLI_CONTINUE;
}

/* The progress line goes to stderr unless -q; by default only when stderr
 * is a terminal and the image does not go to that terminal too (-o - with
 * --format p3 would interleave them). */
static int wants_progress(const cli_settings *s, int to_stdout)
{
    if (s->quiet)
        return 0;
    if (s->progress)
        return 1;
    return isatty(STDERR_FILENO) && !(to_stdout && isatty(STDOUT_FILENO));
}

/* Writes the rendered image to `path` (`-`: standard output).  When that
 * fails, or the output has become an input, the image is kept under
 * another name (cli_keep_image); a signal is the user's wish to stop, and
 * keeps nothing.  Returns RT_OK or the failure. */
static rt_status write_image(const rt_scene *scene, const cli_settings *s,
                             const char *path, int to_stdout,
                             const rt_image *image)
{
    rt_error error;
    if (cli_refuse_input_as_output("rt-export", path, scene,
                                   s->operands[0], "the image")) {
        cli_keep_image("rt-export", to_stdout ? NULL : path, image,
                       s->format);
        return RT_ERR_IO;
    }
    rt_status status = to_stdout
                           ? rt_image_write_file(stdout, image, s->format,
                                                 &error)
                           : rt_image_save(path, image, s->format, &error);
    if (status == RT_OK || status == RT_ERR_INTERRUPTED)
        return status;
    fprintf(stderr, "rt-export: %s%s\n", to_stdout ? "<stdout>: " : "",
            error.message);
    cli_keep_image("rt-export", to_stdout ? NULL : path, image, s->format);
    return status;
}

/* Renders the image the options describe and writes it to `path`;
 * fills report's times.  Returns an exit status. */
static int render_and_write(const rt_scene *scene, cli_settings *s,
                            const char *path, int to_stdout,
                            cli_render_report *report)
{
    rt_image image = {0};
    rt_error error;
    if (rt_image_init(&image, report->width, report->height, &error) !=
        RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    cli_progress progress;
    cli_progress_start(&progress, stderr, isatty(STDERR_FILENO),
                       report->scene, report->height, report->width,
                       s->render.samples);
    rt_render_stats stats;
    memset(&stats, 0, sizeof stats);
    s->render.stats = &stats;
    if (wants_progress(s, to_stdout) && s->view == 0) {
        s->render.on_row = cli_progress_row;
        s->render.user = &progress;
    }
    rt_status status = s->view != 0
                           ? rt_render_view(scene, &s->render, s->view,
                                            s->view_light, &image, &error)
                           : rt_render(scene, &s->render, &image, &error);
    cli_progress_end(&progress);
    int code = EXIT_BAD_INPUT;
    if (status != RT_OK) {
        fprintf(stderr, "rt-export: %s: cannot render: %s\n", report->scene,
                error.message);
        goto done;
    }
    double write_start = cli_clock_seconds();
    if (write_image(scene, s, path, to_stdout, &image) != RT_OK)
        goto done;
    report->write_seconds = cli_seconds_since(write_start);
    if (s->stats == CLI_STATS_TEXT)
        cli_print_stats_text(stderr, &stats, report);
    else if (s->stats == CLI_STATS_JSON)
        cli_print_stats_json(stderr, &stats, report);
    code = EXIT_SUCCESS;
done:
    rt_image_release(&image);
    return code;
}

/* The checks between loading and rendering: the output is no input,
 * float can hold the scene, the output can be written, the size and
 * region fit the image.  Returns CLI_CONTINUE or an exit status. */
static int check_before_render(const rt_scene *scene, const cli_settings *s,
                               const char *path, int to_stdout,
                               cli_render_report *report)
{
    rt_error error;
    if (path == NULL) {
        fprintf(stderr, "rt-export: out of memory\n");
        return EXIT_BAD_INPUT;
    }
    if (cli_refuse_input_as_output("rt-export", path, scene,
                                   s->operands[0], "the image"))
        return EXIT_BAD_INPUT;
    int code = cli_image_size(&program, s, scene, &report->width,
                              &report->height);
    if (code != CLI_CONTINUE)
        return code;
    rt_render_options whole = s->render;
    whole.region = (rt_region){0, 0, 0, 0};
    rt_render_image_size(scene, &whole, &report->full_width,
                         &report->full_height, NULL);
    if (rt_scene_check_precision(scene, s->render.precision, &error) !=
        RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    /* A bad output fails now, not after the render. */
    if (!to_stdout && rt_image_save_check(path, &error) != RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    return CLI_CONTINUE;
}

int main(int argc, char **argv)
{
    cli_settings s;
    int code = cli_parse(&program, argc, argv, &s);
    if (code != CLI_CONTINUE)
        return code;
    const char *scene_path = s.operands[0];
    int to_stdout = s.output != NULL && !strcmp(s.output, "-");
    int from_stdin = !strcmp(scene_path, "-");
    if (from_stdin && s.output == NULL)
        return cli_usage_error(&program, "expected -o OUT (or -o - for "
                               "standard output) with a scene read from "
                               "standard input");
    code = refuse_early(&s, to_stdout);
    if (code != CLI_CONTINUE)
        return code;

    rt_scene *scene;
    rt_error error;
    double load_start = cli_clock_seconds();
    rt_status loaded = from_stdin
                           ? load_standard_input(&s.load, &scene, &error)
                           : rt_scene_load_with(scene_path, &s.load, &scene,
                                                &error);
    if (loaded != RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    cli_render_report report = {
        .program = "rt-export", .scene = from_stdin ? "<stdin>" : scene_path,
        .format = s.format, .settings = &s,
        .load_seconds = cli_seconds_since(load_start)};
    if (check_only) {
        print_check(report.scene, scene);
        rt_scene_destroy(scene);
        return EXIT_SUCCESS;
    }
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "rt-export: %s\n", rt_scene_warning(scene, i)->message);

    if (s.explain) {
        code = explain(scene, &s, report.scene);
        rt_scene_destroy(scene);
        return code;
    }
    char *output = s.output ? NULL : default_output(scene_path, s.format);
    const char *path = s.output ? s.output : output;
    report.output = path;
    code = check_before_render(scene, &s, path, to_stdout, &report);
    if (code == CLI_CONTINUE)
        code = render_and_write(scene, &s, path, to_stdout, &report);
    /* The path goes to standard output unless the image went there. */
    if (code == EXIT_SUCCESS && !to_stdout &&
        !same_file_as(path, STDOUT_FILENO))
        printf("%s\n", path);
    free(output);
    rt_scene_destroy(scene);
    return code;
}
