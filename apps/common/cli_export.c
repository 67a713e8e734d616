/*
 * cli_export.c - the export pipeline of rt-export and rt-export-mpi (see
 * cli_export.h): the checks around the load, the render's bands through
 * the program's hook or on this process's threads, the save that keeps
 * the image when it fails late, and the reports.
 */
#include "cli_export.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_clock.h"
#include "cli_output.h"
#include "cli_text.h"

#define EXIT_BAD_INPUT 1
#define FIRST_CHUNK ((size_t)1 << 16)   /* bytes read at first from a
                                           stream; doubled as it grows */
#define SHOWN_NAME (RT_ERROR_MESSAGE_SIZE / 2) /* a name in a message,
                                               escaped */

void cli_export_init(cli_export *ex, const cli_program *program,
                     cli_settings *settings, const cli_export_config *config)
{
    memset(ex, 0, sizeof *ex);
    ex->program = program;
    ex->settings = settings;
    if (config != NULL)
        ex->config = *config;
    ex->operand = settings->operands[0];
    ex->from_stdin = strcmp(ex->operand, "-") == 0;
    ex->to_stdout = settings->output != NULL &&
                    strcmp(settings->output, "-") == 0;
    ex->name = ex->from_stdin ? "<stdin>" : ex->operand;
}

/* ------------------------------------------------------------------ */
/* Loading                                                             */

rt_status cli_read_scene_text(FILE *in, const char *name, int binary,
                              char **text, size_t *length, rt_error *error)
{
    size_t capacity = FIRST_CHUNK, used = 0;
    char *bytes = malloc(capacity + 1);     /* and a NUL after the bytes */
    while (bytes != NULL) {
        size_t got = fread(bytes + used, 1, capacity - used, in);
        used += got;
        if (used < capacity)
            break;
        /* /dev/zero or a huge binary: the parser's check names it */
        if (used > RT_MAX_SCENE_BYTES ||
            (!binary && memchr(bytes + used - got, 0, got)))
            break;
        char *bigger = capacity < SIZE_MAX / 2
                           ? realloc(bytes, capacity * 2 + 1)
                           : NULL;
        if (bigger == NULL)
            free(bytes);
        bytes = bigger;
        capacity *= 2;
    }
    int failed = bytes != NULL && ferror(in);
    int reason = errno;
    char shown[SHOWN_NAME];
    cli_printable(name, shown, sizeof shown);
    memset(error, 0, sizeof *error);
    if (bytes == NULL || failed) {
        free(bytes);
        error->status = bytes == NULL ? RT_ERR_NOMEM : RT_ERR_IO;
        if (bytes == NULL)
            snprintf(error->message, sizeof error->message,
                     "%s: out of memory reading the scene", shown);
        else
            snprintf(error->message, sizeof error->message,
                     "%s: cannot read: %s", shown, strerror(reason));
        return error->status;
    }
    bytes[used] = '\0';
    *text = bytes;
    *length = used;
    return RT_OK;
}

/* The whole of standard input, parsed as "<stdin>"; the files it names
 * (an OBJ's libraries) are looked for in the current folder, as
 * rt_scene_load looks in the scene's. */
static rt_status load_standard_input(const rt_load_options *given,
                                     rt_scene **scene, rt_error *error)
{
    rt_load_options options = *given;
    if (options.resolve == NULL)
        options.resolve = rt_resolve_in_folder;
    char *text;
    size_t length;
    *scene = NULL;
    rt_status status = cli_read_scene_text(
        stdin, "<stdin>", options.format == RT_SCENE_FORMAT_PLY, &text,
        &length, error);
    if (status != RT_OK)
        return status;
    status = rt_scene_parse(text, length, "<stdin>", &options, scene, error);
    free(text);
    return status;
}

static rt_status load_here(const cli_export *ex, rt_scene **scene,
                           rt_error *error)
{
    if (ex->from_stdin)
        return load_standard_input(&ex->settings->load, scene, error);
    return rt_scene_load(ex->operand, &ex->settings->load, scene, error);
}

/* Refusals that need no scene: an image format this build cannot write,
 * a binary image to a terminal.  Returns CLI_CONTINUE or an exit status. */
static int is_float_format(rt_image_format format)
{
    return format == RT_IMAGE_PFM || format == RT_IMAGE_EXR;
}

static int refuse_output(const cli_export *ex)
{
    const cli_settings *s = ex->settings;
    if (s->format == RT_IMAGE_EXR && !rt_image_format_supported(s->format)) {
        fprintf(stderr, "%s: cannot write %s: this build has no OpenEXR "
                        "support (it was built without libopenexr-dev, or "
                        "with -DRAYTRACE_EXR=OFF); use --format pfm\n",
                ex->program->name, s->output ? s->output : "EXR");
        return EXIT_BAD_INPUT;
    }
    if (is_float_format(s->format) && (s->view != 0 || ex->config.bands)) {
        fprintf(stderr, "%s: cannot write %s: %s no linear colours; use "
                        "--format p6, p3 or png\n", ex->program->name,
                rt_image_format_name(s->format),
                s->view != 0 ? "a debug view (--view) has"
                             : "this program renders");
        return CLI_EXIT_USAGE;
    }
    if (!rt_image_format_supported(s->format)) {
        fprintf(stderr, "%s: cannot write %s: this build has no PNG "
                        "support (it was built without libpng); use --format "
                        "p6 or p3\n", ex->program->name,
                s->output ? s->output : "PNG");
        return EXIT_BAD_INPUT;
    }
    if (ex->to_stdout && s->format != RT_IMAGE_P3 && isatty(STDOUT_FILENO)) {
        fprintf(stderr, "%s: refusing to write a binary image to a "
                        "terminal; redirect standard output, or use "
                        "--format p3\n", ex->program->name);
        return CLI_EXIT_USAGE;
    }
    return CLI_CONTINUE;
}

int cli_export_load(cli_export *ex, int check_output)
{
    if (ex->from_stdin && ex->settings->output == NULL)
        return cli_usage_error(ex->program, "expected -o OUT%s with a scene "
                               "read from standard input",
                               ex->config.no_stdout
                                   ? ""
                                   : " (or -o - for standard output)");
    int code = check_output ? refuse_output(ex) : CLI_CONTINUE;
    if (code != CLI_CONTINUE)
        return code;
    rt_error error;
    double start = cli_clock_seconds();
    rt_status status = ex->config.load
                           ? ex->config.load(ex->config.user, ex, &ex->scene,
                                             &error)
                           : load_here(ex, &ex->scene, &error);
    if (status != RT_OK) {
        ex->scene = NULL;
        fprintf(stderr, "%s: %s\n", ex->program->name, error.message);
        return EXIT_BAD_INPUT;
    }
    ex->report = (cli_render_report){
        .program = ex->program->name, .scene = ex->name,
        .format = ex->settings->format, .settings = ex->settings,
        .load_seconds = cli_seconds_since(start),
        .load_peak_bytes = cli_peak_bytes()};
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(ex->scene, &info);
    ex->report.facet_count = info.facet_count;
    return CLI_CONTINUE;
}

void cli_export_print_warnings(const cli_export *ex)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(ex->scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "%s: %s\n", ex->program->name,
                rt_scene_warning(ex->scene, i)->message);
    if (!ex->settings->quiet)
        cli_print_up_note(stderr, ex->program->name, ex->name, ex->scene);
}

/* ------------------------------------------------------------------ */
/* Before the render                                                   */

char *cli_export_default_output(const char *scene, rt_image_format format)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    const char *dot = strrchr(base, '.');
    size_t length = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    const char *extension = format == RT_IMAGE_PNG   ? ".png"
                            : format == RT_IMAGE_PFM ? ".pfm"
                            : format == RT_IMAGE_EXR ? ".exr"
                                                     : ".ppm";
    char *out = malloc(length + 5);
    if (out != NULL) {
        memcpy(out, base, length);
        memcpy(out + length, extension, 5);
    }
    return out;
}

/* Step 3.  Returns CLI_CONTINUE or an exit status. */
static int check_before_render(cli_export *ex)
{
    const char *program = ex->program->name;
    cli_settings *s = ex->settings;
    if (s->output == NULL)
        ex->default_output = cli_export_default_output(ex->operand,
                                                       s->format);
    ex->output = s->output ? s->output : ex->default_output;
    ex->report.output = ex->output;
    if (ex->output == NULL) {
        fprintf(stderr, "%s: out of memory\n", program);
        return EXIT_BAD_INPUT;
    }
    if (cli_refuse_input_as_output(program, ex->output, ex->scene,
                                   ex->operand, "the image"))
        return EXIT_BAD_INPUT;
    int code = cli_image_size(ex->program, s, ex->scene, &ex->report.width,
                              &ex->report.height);
    if (code != CLI_CONTINUE)
        return code;
    rt_render_options whole = s->render;
    whole.region = (rt_region){0, 0, 0, 0};
    rt_render_image_size(ex->scene, &whole, &ex->report.full_width,
                         &ex->report.full_height, NULL);
    rt_error error;
    rt_save_options save = cli_save_options();
    if (rt_scene_check_precision(ex->scene, s->render.precision, &error) !=
            RT_OK ||
        (!ex->to_stdout &&
         rt_image_save_check(ex->output, &save, &error) != RT_OK)) {
        fprintf(stderr, "%s: %s\n", program, error.message);
        return EXIT_BAD_INPUT;
    }
    return CLI_CONTINUE;
}

/* ------------------------------------------------------------------ */
/* The bands and the save                                              */

/* The bands rendered here: all of them, with this process's threads. */
static int render_here(const cli_export *ex, cli_progress *progress,
                       rt_image *image, rt_render_stats *stats)
{
    const cli_settings *s = ex->settings;
    rt_render_options options = s->render;
    options.stats = stats;
    options.linear = ex->linear;
    if (progress != NULL) {
        options.on_row = cli_progress_row;
        options.user = progress;
    }
    rt_error error;
    rt_status status = s->view != 0
                           ? rt_render_view(ex->scene, &options, s->view,
                                            s->view_light, image, &error)
                           : rt_render(ex->scene, &options, image, &error);
    if (status == RT_OK)
        return CLI_CONTINUE;
    fprintf(stderr, "%s: %s: cannot render: %s\n", ex->program->name,
            ex->name, error.message);
    return EXIT_BAD_INPUT;
}

/* The progress line goes to stderr unless -q; by default only when stderr
 * is a terminal and the image does not go to that terminal too (-o - with
 * --format p3 would interleave them); never for a debug view. */
static int wants_progress(const cli_export *ex)
{
    const cli_settings *s = ex->settings;
    if (s->quiet || s->view != 0)
        return 0;
    if (s->progress)
        return 1;
    return isatty(STDERR_FILENO) &&
           !(ex->to_stdout && isatty(STDOUT_FILENO));
}

static int write_stdout(void *user, const void *data, size_t size)
{
    (void)user;
    return fwrite(data, 1, size, stdout) == size;
}

/* A float image to standard output, flushed. */
static rt_status write_float_stdout(const rt_image_float *linear,
                                    rt_image_format format, rt_error *error)
{
    rt_status status = rt_image_float_write_to(write_stdout, NULL, linear,
                                               format, error);
    if (status == RT_OK && (fflush(stdout) != 0 || ferror(stdout))) {
        snprintf(error->message, sizeof error->message,
                 "cannot write the image: input/output error");
        status = error->status = RT_ERR_IO;
    }
    return status;
}

/* Step 5: writes the image to the output (or standard output).  When that
 * fails, or the output has become an input, the image is kept under
 * another name; a signal is the user's wish to stop, and keeps nothing.
 * Returns RT_OK or the failure. */
static rt_status write_image(const cli_export *ex, const rt_image *image)
{
    const char *program = ex->program->name;
    const char *kept_path = ex->to_stdout ? NULL : ex->output;
    rt_image_format format = ex->settings->format;
    /* a float image that cannot be written is kept as its bytes */
    rt_image_format kept = ex->linear != NULL ? RT_IMAGE_P6 : format;
    if (cli_refuse_input_as_output(program, ex->output, ex->scene,
                                   ex->operand, "the image")) {
        cli_keep_image(program, kept_path, image, kept);
        return RT_ERR_IO;
    }
    rt_error error;
    rt_save_options save = cli_save_options();
    rt_status status;
    if (ex->linear != NULL)
        status = ex->to_stdout
                     ? write_float_stdout(ex->linear, format, &error)
                     : rt_image_float_save(ex->output, ex->linear, format,
                                           &save, &error);
    else
        status = ex->to_stdout
                     ? rt_image_write_file(stdout, image, format, &error)
                     : rt_image_save(ex->output, image, format, &save,
                                     &error);
    if (status == RT_OK || status == RT_ERR_INTERRUPTED)
        return status;
    fprintf(stderr, "%s: %s%s\n", program, ex->to_stdout ? "<stdout>: " : "",
            error.message);
    cli_keep_image(program, kept_path, image, kept);
    return status;
}

/* Non-zero when `path` names the file open as descriptor `fd`
 * (-o /dev/stdout). */
static int same_file_as(const char *path, int fd)
{
    struct stat sp, sf;
    return stat(path, &sp) == 0 && fstat(fd, &sf) == 0 &&
           sp.st_dev == sf.st_dev && sp.st_ino == sf.st_ino;
}

/* Step 6, after a successful save. */
static void report(cli_export *ex, const rt_render_stats *stats)
{
    cli_stats wanted = ex->settings->stats;
    ex->report.peak_bytes = cli_peak_bytes();
    if (wanted != CLI_STATS_NONE && ex->config.report != NULL)
        ex->config.report(ex->config.user, stderr);
    if (wanted == CLI_STATS_TEXT)
        cli_print_stats_text(stderr, stats, &ex->report);
    else if (wanted == CLI_STATS_JSON)
        cli_print_stats_json(stderr, stats, &ex->report);
    /* the path goes to standard output unless the image went there */
    if (!ex->to_stdout && !same_file_as(ex->output, STDOUT_FILENO))
        printf("%s\n", ex->output);
}

int cli_export_render(cli_export *ex)
{
    int code = check_before_render(ex);
    if (code != CLI_CONTINUE)
        return code;
    rt_image image = {0};
    rt_error error;
    if (rt_image_init(&image, ex->report.width, ex->report.height,
                      &error) != RT_OK) {
        fprintf(stderr, "%s: %s\n", ex->program->name, error.message);
        return EXIT_BAD_INPUT;
    }
    rt_image_float linear = {0};
    if (is_float_format(ex->settings->format)) {
        if (rt_image_float_init(&linear, ex->report.width, ex->report.height,
                                &error) != RT_OK) {
            fprintf(stderr, "%s: %s\n", ex->program->name, error.message);
            rt_image_release(&image);
            return EXIT_BAD_INPUT;
        }
        ex->linear = &linear;
    }
    cli_progress progress;
    cli_progress_start(&progress, stderr, isatty(STDERR_FILENO), ex->name,
                       ex->report.height, ex->report.width,
                       ex->settings->render.samples);
    cli_progress *shown = wants_progress(ex) ? &progress : NULL;
    rt_render_stats stats = {.size = sizeof stats};
    code = ex->config.bands
               ? ex->config.bands(ex->config.user, ex, shown, &image, &stats)
               : render_here(ex, shown, &image, &stats);
    cli_progress_end(&progress);
    if (code == CLI_CONTINUE) {
        /* every band is in: only now is anything written */
        double start = cli_clock_seconds();
        code = EXIT_BAD_INPUT;
        if (write_image(ex, &image) == RT_OK) {
            ex->report.write_seconds = cli_seconds_since(start);
            report(ex, &stats);
            code = EXIT_SUCCESS;
        }
    }
    rt_image_release(&image);
    rt_image_float_release(&linear);
    ex->linear = NULL;
    return code;
}

void cli_export_release(cli_export *ex)
{
    rt_scene_destroy(ex->scene);
    free(ex->default_output);
    ex->scene = NULL;
    ex->default_output = NULL;
}
