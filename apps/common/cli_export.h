/*
 * cli_export.h - the one export pipeline of rt-export and rt-export-mpi:
 * load the scene the command line names (a file, or standard input read
 * whole), check the options and the output against it, render the bands
 * of the image, save it and report.  The programs differ only in how the
 * scene's bytes are read and who renders the bands (c-ray's thin driver
 * over one library; mgba's front-ends over one core): rt-export renders
 * every band itself on its threads, rt-export-mpi's farm hands them out
 * to the ranks of a job.  A cli_export_config names those two hooks
 * (NULL: rt-export's own way) and the rest is decided here, once:
 *
 *   1. before the load: a scene from standard input needs -o; with
 *      `check_output`, an image format this build cannot write and a
 *      binary image to a terminal are refused;
 *   2. the load, timed (its warnings: cli_export_print_warnings);
 *   3. before the render: the output (-o, else the scene's name with .ppm
 *      or .png in the current folder) is none of the files the scene was
 *      read from (cli_output.h), the size and region fit the image, the
 *      precision can hold the scene, the output can be written (a bad one
 *      fails now, not after hours of rendering);
 *   4. the bands, with the progress line on stderr (on a terminal, unless
 *      -q; or --progress) and the counters;
 *   5. the save: the same output check again, then the library's safe save
 *      (rt_image_save), or the image streamed to standard output (-o -);
 *      when that late save fails the image is kept under another name
 *      (cli_keep_image), unless a signal asked to stop;
 *   6. the reports: --stats (text or JSON) on stderr, then the path written
 *      on stdout (unless the image went there).
 *
 * Every message is "PROGRAM: ..." on stderr, the program's name taken from
 * its cli_program.  Exit statuses: 0 success, 1 bad input or a failed
 * write, 2 bad usage.  Not thread-safe: the calling thread owns the
 * pipeline (the band hook may use threads, or ranks).
 *
 * Typical use (rt-export):
 *
 *     cli_export ex;
 *     cli_export_init(&ex, &program, &settings, NULL);
 *     int code = cli_export_load(&ex, 1);
 *     if (code == CLI_CONTINUE) {
 *         cli_export_print_warnings(&ex);
 *         code = cli_export_render(&ex);
 *     }
 *     cli_export_release(&ex);
 */
#ifndef RAYTRACE_CLI_EXPORT_H
#define RAYTRACE_CLI_EXPORT_H

#include <stdio.h>

#include "cli.h"
#include "cli_report.h"
#include "raytrace/raytrace.h"

typedef struct cli_export cli_export;

/* Reads the scene `ex` names (ex->operand; ex->from_stdin for "-", then
 * named ex->name, "<stdin>") with ex->settings->load.  Returns RT_OK with
 * *scene set, or a status with *error filled: the pipeline prints
 * "PROGRAM: MESSAGE". */
typedef rt_status (*cli_export_load_func)(void *user, const cli_export *ex,
                                          rt_scene **scene, rt_error *error);

/*
 * Renders the bands of the image: all of ex->settings->render's image
 * (its region's, when it has one) into `image`, whose size it has, with
 * ex->settings->render as parsed (no row callback, no stats).  `progress`
 * is NULL, or the progress line to count each finished row on
 * (cli_progress_row); *stats (zeroed) receives the counters and the
 * render's seconds.  Called once every check has passed.  Returns
 * CLI_CONTINUE, or an exit status after saying why itself.
 */
typedef int (*cli_export_bands_func)(void *user, const cli_export *ex,
                                     cli_progress *progress, rt_image *image,
                                     rt_render_stats *stats);

/* With --stats, after a successful save and before the statistics: more
 * lines on `out` (rt-export-mpi: a line a rank). */
typedef void (*cli_export_report_func)(void *user, FILE *out);

/* What a program does its own way; NULL fields: rt-export's way. */
typedef struct cli_export_config {
    cli_export_load_func load;      /* NULL: rt_scene_load, or the
                                       whole of standard input parsed */
    cli_export_bands_func bands;    /* NULL: rt_render (or rt_render_view
                                       for --view) on this process's
                                       threads */
    cli_export_report_func report;  /* NULL: nothing more */
    void *user;                     /* passed to the three */
    int no_stdout;                  /* 1: -o - was refused before (the
                                       usage message for standard input
                                       does not offer it) */
} cli_export_config;

/* One export: what the command line asked, and what was found out. */
struct cli_export {
    const cli_program *program;
    cli_settings *settings;         /* the parsed command line */
    cli_export_config config;
    const char *operand;            /* the scene as given; "-": stdin */
    const char *name;               /* as messages name it ("<stdin>") */
    int from_stdin, to_stdout;      /* SCENE `-', -o - */
    rt_scene *scene;                /* after cli_export_load; owned */
    const char *output;             /* after cli_export_render's checks */
    char *default_output;           /* owned, when -o was not given */
    rt_image_float *linear;         /* during cli_export_render with a
                                       float format (pfm, exr): the linear
                                       image rendered with the bytes */
    cli_render_report report;       /* the times and sizes --stats shows */
};

/* Sets up an export of settings->operands[0]; `config` NULL: rt-export's
 * way (the config is copied). */
void cli_export_init(cli_export *ex, const cli_program *program,
                     cli_settings *settings, const cli_export_config *config);

/* Steps 1 and 2: the checks that need no scene (those of the output only
 * with `check_output`: rt-export --check writes nothing), then the load.
 * Returns CLI_CONTINUE with ex->scene set, or an exit status. */
int cli_export_load(cli_export *ex, int check_output);

/* The scene's warnings, "PROGRAM: WARNING" a line on stderr. */
void cli_export_print_warnings(const cli_export *ex);

/* Steps 3 to 6.  Returns the exit status. */
int cli_export_render(cli_export *ex);

/* Frees the scene and the names; the settings stay the caller's. */
void cli_export_release(cli_export *ex);

/*
 * The output rt-export writes when -o is not given: the file name of
 * `scene` (the operand as given) without its folder and its extension,
 * whatever that is ("dir/balls-s2.nff" -> "balls-s2"; a name with no dot,
 * or whose only dot starts it, is kept whole), then ".png" for PNG, else
 * ".ppm".  rt-view's S saves beside the scene under the same name,
 * numbered.  A new string (free it), NULL when out of memory.
 * Thread-safe.
 */
char *cli_export_default_output(const char *scene, rt_image_format format);

/*
 * Reads the whole of `in` (a scene: at most a little more than
 * RT_MAX_SCENE_BYTES, or up to a chunk holding a NUL byte unless `binary`,
 * a PLY's body, so that the parser names what is wrong) into a new buffer
 * *text (free() it) of *length bytes and a NUL after them.  Returns RT_OK,
 * or RT_ERR_NOMEM ("NAME: out of memory reading the scene") or RT_ERR_IO
 * ("NAME: cannot read: REASON") with *error filled and nothing allocated.
 * `name` is escaped in messages.
 */
rt_status cli_read_scene_text(FILE *in, const char *name, int binary,
                              char **text, size_t *length, rt_error *error);

#endif /* RAYTRACE_CLI_EXPORT_H */
