/*
 * rt-view - shows a scene in an SDL window while it renders.
 *
 * This file is the command line and the start-up; the rest is in
 * apps/viewer: view_app (the window, keys, reloads, saves and event loop),
 * view_session (renders on its own thread and reports finished rows),
 * view_window (uploads those rows and draws) and view_scene (loads, watches
 * and names files).
 */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "cli_values.h"
#include "raytrace/raytrace.h"
#include "view_app.h"
#include "view_scene.h"
#include "view_session.h"
#include "view_window.h"

#define PROGRAM "rt-view"

static const char usage_text[] =
    "Usage: " PROGRAM " [OPTION]... [SCENE.scn]\n"
    "Show SCENE.scn in a window while it renders; each finished row appears\n"
    "at once.  The title shows the scene, the progress and the elapsed time,\n"
    "then the total time.\n"
    "\n"
    "Options:\n"
    "  --depth N     reflections followed after a primary ray, 0.."
    "100 (default 5)\n"
    "  --scale F     render at F times the scene's size in pixels, e.g. 0.5\n"
    "                for a quick preview or 2 for detail (default 1; the\n"
    "                window is scaled down to fit the screen either way)\n"
    "  --threads N   rendering threads, 0 for one per core (default 0)\n"
    "  --samples N   rays per pixel, a square (1, 4, 9, ...; default 1)\n"
    "  --aperture A  lens radius in scene units (default: the scene's; 0 for\n"
    "                a pinhole); depth of field needs several samples\n"
    "  --focus F     distance in focus, in scene units along the view axis\n"
    "                (default: the scene's, else the screen's distance)\n"
    "  --input-format F, --tessellate T, --look-from X,Y,Z, --look-at X,Y,Z,\n"
    "  --up X,Y,Z, --fov DEGREES, --light X,Y,Z[,R,G,B] (repeatable)\n"
    "                as in rt-export: the scene's format, the tolerance of\n"
    "                NFF's curved shapes, a view and lights that replace the\n"
    "                scene's\n"
    "  --help        show this help and exit\n"
    "  --version     show the version and exit\n"
    "\n"
    "Keys:\n"
    "  S             save the image next to the scene, as SCENE.png (or\n"
    "                SCENE.ppm in a build without PNG support); rows not\n"
    "                rendered yet are black; prints the path\n"
    "  R             render again\n"
    "  + / -         one more / one less reflection, and render again\n"
    "  Q, Esc        quit (a render in progress is cancelled)\n"
    "\n"
    "Drop a .scn file on the window to load and render it.  A scene with\n"
    "errors is reported as FILE:LINE:COLUMN: MESSAGE on stderr and in the\n"
    "title; the picture shown before stays.  The window can be moved,\n"
    "resized or closed at any time.  SIGINT, SIGTERM or SIGHUP cancel the\n"
    "render (and a save under way, leaving the file as it was) and end\n"
    "rt-view with 128 + the signal's number.\n";

typedef struct viewer {
    view_app_options app;
    rt_load_options load;       /* format, tessellation, view, lights */
    rt_light lights[16];        /* --light, in order */
} viewer;

static int parse_int(const char *text, int low, int high, int *value)
{
    char *end;
    errno = 0;
    long number = strtol(text, &end, 10);
    if (errno || end == text || *end || number < low || number > high)
        return 0;
    *value = (int)number;
    return 1;
}

static int parse_scale(const char *text, double *value)
{
    char *end;
    errno = 0;
    double number = strtod(text, &end);
    if (errno || end == text || *end || !(number >= VIEW_MIN_SCALE) ||
        !(number <= VIEW_MAX_SCALE))
        return 0;
    *value = number;
    return 1;
}

/* One of the loader's options (shared with rt-export); returns NULL, or
 * what was expected. */
static const char *load_option(viewer *v, const char *arg, const char *text)
{
    rt_load_options *o = &v->load;
    if (strcmp(arg, "--input-format") == 0)
        return cli_parse_scene_format(text, &o->format)
                   ? NULL
                   : "--input-format expects scn, nff or obj, not";
    if (strcmp(arg, "--tessellate") == 0)
        return cli_parse_length(text, 1, &o->tessellation) &&
                       o->tessellation < 1
                   ? NULL
                   : "--tessellate expects a tolerance in (0, 1), not";
    if (strcmp(arg, "--fov") == 0) {
        if (!cli_parse_length(text, 1, &o->fov) || !(o->fov < 180))
            return "--fov expects degrees in (0, 180), not";
        o->fov_given = 1;
        return NULL;
    }
    if (strcmp(arg, "--light") == 0) {
        if (o->light_count == 16)
            return "at most 16 --light options; one more:";
        if (!cli_parse_light(text, &v->lights[o->light_count]))
            return "--light expects x,y,z or x,y,z,r,g,b (0..255), not";
        o->lights = v->lights;
        o->light_count++;
        return NULL;
    }
    int *given = strcmp(arg, "--look-from") == 0 ? &o->look_from_given
                 : strcmp(arg, "--look-at") == 0 ? &o->look_at_given
                                                  : &o->up_given;
    rt_vec3 *point = strcmp(arg, "--look-from") == 0 ? &o->look_from
                     : strcmp(arg, "--look-at") == 0 ? &o->look_at
                                                      : &o->up;
    if (!cli_parse_point(text, point))
        return "expected x,y,z after the option, not";
    *given = 1;
    return NULL;
}

static int usage_error(const char *message, const char *argument)
{
    fprintf(stderr, PROGRAM ": %s '%s'\nTry '" PROGRAM " --help'.\n",
            message, argument);
    return 2;
}

/* Fills v from the command line; returns -1 to go on, else an exit code. */
static int parse_arguments(int argc, char **argv, viewer *v,
                           const char **scene)
{
    *scene = NULL;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            fputs(usage_text, stdout);
            return 0;
        } else if (strcmp(arg, "--version") == 0) {
            printf(PROGRAM " (libraytrace) %s\n", rt_version_string());
            return 0;
        } else if (strcmp(arg, "--input-format") == 0 ||
                   strcmp(arg, "--tessellate") == 0 ||
                   strcmp(arg, "--look-from") == 0 ||
                   strcmp(arg, "--look-at") == 0 ||
                   strcmp(arg, "--up") == 0 || strcmp(arg, "--fov") == 0 ||
                   strcmp(arg, "--light") == 0) {
            if (next == NULL)
                return usage_error("missing value after", arg);
            i++;
            const char *wrong = load_option(v, arg, next);
            if (wrong != NULL)
                return usage_error(wrong, next);
        } else if (strcmp(arg, "--samples") == 0 ||
                   strcmp(arg, "--aperture") == 0 ||
                   strcmp(arg, "--focus") == 0) {
            if (next == NULL)
                return usage_error("missing value after", arg);
            i++;
            if (strcmp(arg, "--samples") == 0) {
                int root = 1;
                if (!parse_int(next, 1, 1024, &v->app.render.samples))
                    return usage_error("--samples expects a square in "
                                       "1..1024, not", next);
                while (root * root < v->app.render.samples)
                    root++;
                if (root * root != v->app.render.samples)
                    return usage_error("--samples expects a square (1, 4, "
                                       "9, 16, ...), not", next);
            } else if (!cli_parse_length(next, strcmp(arg, "--focus") == 0,
                                     strcmp(arg, "--focus") == 0
                                         ? &v->app.render.focal_distance
                                         : &v->app.render.aperture)) {
                return usage_error(strcmp(arg, "--focus") == 0
                                       ? "--focus expects a distance > 0, not"
                                       : "--aperture expects a radius >= 0, "
                                         "not",
                                   next);
            }
        } else if (strcmp(arg, "--depth") == 0 ||
                   strcmp(arg, "--threads") == 0 ||
                   strcmp(arg, "--scale") == 0) {
            if (next == NULL)
                return usage_error("missing value after", arg);
            i++;
            int ok = strcmp(arg, "--scale") == 0
                         ? parse_scale(next, &v->app.scale)
                     : strcmp(arg, "--depth") == 0
                         ? parse_int(next, 0, VIEW_MAX_DEPTH, &v->app.render.max_depth)
                         : parse_int(next, 0, 1024, &v->app.render.threads);
            if (!ok)
                return usage_error(
                    strcmp(arg, "--scale") == 0
                        ? "--scale expects a number in 0.01..64, not"
                    : strcmp(arg, "--depth") == 0
                        ? "--depth expects an integer in 0..1000000, not"
                        : "--threads expects an integer in 0..1024, not",
                    next);
        } else if (strcmp(arg, "--watch") == 0) {
            v->app.watch = 1;
        } else if (strcmp(arg, "-o") == 0 || strcmp(arg, "--output") == 0) {
            if (next == NULL)
                return usage_error("missing value after", arg);
            i++;
            if (rt_image_format_from_path(next, &v->app.format) != RT_OK)
                return usage_error("-o expects a .png, .ppm or .pnm path, "
                                   "not", next);
            v->app.output = next;
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return usage_error("unknown option", arg);
        } else if (*scene != NULL) {
            return usage_error("only one scene, extra argument", arg);
        } else {
            *scene = arg;
        }
    }
    return -1;
}

/*
 * Opens the window, shows `scene` (may be NULL) and runs until it closes;
 * returns the exit status.  Without a display it fails at once: SDL would
 * otherwise pick its invisible "offscreen" driver and run forever.
 */
static int run_viewer(const view_app_options *options, const char *scene)
{
    rt_error error;
    if (options->output && rt_image_save_check(options->output, &error) !=
                               RT_OK) {
        fprintf(stderr, PROGRAM ": %s\n", error.message);
        return 1;
    }
    /* Before any thread exists, so that every thread inherits the mask;
     * view_app takes these signals in its event loop. */
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &signals, NULL);
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    SDL_SetMainReady();

    char message[512];
    int started = SDL_Init(0) == 0;
    if (!started)
        snprintf(message, sizeof message, "%s", SDL_GetError());
    if (!started || !view_video_init(message, sizeof message)) {
        fprintf(stderr,
                PROGRAM ": cannot open a window: %s; rt-export renders "
                        "without a display\n",
                message);
        SDL_Quit();
        return 1;
    }
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");
    view_app *app = view_app_create(options, message, sizeof message);
    if (app == NULL) {
        fprintf(stderr,
                PROGRAM ": cannot open a window: %s; rt-export renders "
                        "without a display\n",
                message);
        SDL_Quit();
        return 1;
    }
    if (scene)
        view_app_open(app, scene);
    view_app_run(app);
    int status = view_app_exit_status(app);
    view_app_destroy(app);
    SDL_Quit();
    return status;
}

int main(int argc, char **argv)
{
    viewer v;
    memset(&v, 0, sizeof v);
    view_app_options_init(&v.app);
    rt_load_options_init(&v.load);
    v.app.load = &v.load;
    const char *scene;
    int code = parse_arguments(argc, argv, &v, &scene);
    if (code >= 0)
        return code;
    return run_viewer(&v.app, scene);
}
