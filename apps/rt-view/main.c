/*
 * rt-view - shows a scene in an SDL window while it renders.
 *
 * This file is the command line (the shared module apps/common/cli, so
 * rt-view takes every render option rt-export takes, with the same limits
 * and words) and the start-up; the rest is in apps/rt-view: view_app (the
 * app and its event loop), view_reload (opening, R and --watch),
 * view_save (S), view_navigation (keys, clicks, debug views), view_load
 * (reads a scene on its own thread, so the window never waits for a file),
 * view_session (renders on its own thread and reports finished rows),
 * view_window (uploads those rows and draws), view_overlay (the click's
 * rays projected), view_explain (a pixel's tree as segments and text) and
 * view_scene (loads, watches and names files).
 */
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "cli.h"
#include "cli_output.h"
#include "raytrace/raytrace.h"
#include "view_app.h"
#include "view_scene.h"
#include "view_window.h"

#define PROGRAM "rt-view"

static double scale = 1.0;      /* --scale */
static int watch;               /* --watch */
static int stats;               /* --stats */

static const cli_option view_options[] = {
    {"scale", 0, "F", CLI_NUMBER_CLOSED, VIEW_MIN_SCALE, VIEW_MAX_SCALE,
     &scale,
     "render at F times the scene's size in pixels (0.01..64): 0.5 for a "
     "quick preview, 2 for detail; the same picture with more or fewer "
     "pixels (a shorthand for --size; not with it)"},
    {"watch", 0, NULL, CLI_FLAG, 0, 0, &watch,
     "reload and render the scene whenever its file changes (looked at "
     "every 250 ms)"},
    {"stats", 0, NULL, CLI_FLAG, 0, 0, &stats,
     "after each render, print on stderr how long it took to the end of "
     "each pass (1/8, 1/4, 1/2 of the resolution, full), when its first "
     "frame was shown, and the rays it cast; for a render cancelled by a "
     "restart, the pass it reached"},
    CLI_OPTIONS_END,
};

#ifdef RAYTRACE_VIEWER_TTF
#define TEXT_IN_WINDOW " and\n          in the window"
#define TEXT_IN_WINDOW_HELP ", in the window"
#else
#define TEXT_IN_WINDOW " (this build has no\n          SDL2_ttf: " \
    "not in the window)"
#define TEXT_IN_WINDOW_HELP ", on stdout (this build has no SDL2_ttf)"
#endif

static const cli_program program = {
    PROGRAM, "[SCENE]",
    "Shows SCENE in a window while it renders, coarse to fine: at 1/8, 1/4\n"
    "and 1/2 of the resolution, then in full (then with --samples), each\n"
    "row appearing as soon as a pass finishes it.  The title shows the\n"
    "scene, the pass, the progress and the elapsed time, then the total\n"
    "time.  Without SCENE the window waits for a scene file\n"
    "dropped on it.  The window needs a display (X11 or Wayland);\n"
    "rt-export renders without one.",
    "\nWithout -o or --format, S saves PNG.  -o OUT is a file (not `-').\n"
    "\nKeys:\n"
    "  S       save the image: the first time to -o OUT when given, else\n"
    "          to the first free numbered name beside the scene, from\n"
    "          its stem (STEM-1.png, STEM-2.png, ...; beside OUT: OUT-1.png\n"
    "          ...),\n"
    "          never over an earlier save; an image still rendering goes to\n"
    "          STEM-partial-N.png (OUT-partial-N.png), never to OUT.  PNG\n"
    "          unless --format or OUT's extension say otherwise (binary PPM\n"
    "          in a build without PNG support).  Prints the path.\n"
    "  R       reload the scene from its file and render it; if it no\n"
    "          longer loads, the picture stays and the error\n"
    "          (FILE:LINE:COLUMN: MESSAGE) goes to stderr and the title.\n"
    "          Scenes are read on a worker thread: the window stays live\n"
    "          and the picture stays until the new scene is ready\n"
    "  + / -   one more / one less reflection, and render again\n"
    "  left click  explain that pixel (the render's options): its ray\n"
    "          tree drawn over the image - camera rays white, shadow rays\n"
    "          yellow to their light or red up to the facet that blocks\n"
    "          them, reflected cyan, refracted magenta, hits marked by a\n"
    "          square - and its text (each ray's facet and file line, t,\n"
    "          N.S, E, the blocker, what each term adds) on stdout"
    TEXT_IN_WINDOW "\n"
    "          (with several samples a pixel: the sample nearest the\n"
    "          click is drawn; Tab / Shift+Tab: the next / previous)\n"
    "  right click, Esc  clear the explanation\n"
    "Moving the camera (each move renders again, coarse to fine; the\n"
    "scene is not read again):\n"
    "  left drag   orbit round the target (no roll)\n"
    "  right or middle drag, Shift + left drag  pan\n"
    "  wheel       dolly towards / away from the target\n"
    "  Ctrl + wheel, [ / ]  narrower / wider field of view\n"
    "  arrows, PgUp / PgDn  fly (Shift: five times as far)\n"
    "  double-click  the surface under the cursor becomes the target\n"
    "  Home        back to the file's camera\n"
    "  C           print the camera as rt-export options and .scn\n"
    "              records, and write them to STEM-camera.txt\n"
    "  N normal, D depth, F facet index, L shadow term E (again: next\n"
    "          light), B bounces, I N.S (again: next light): debug views\n"
    "          of the same render, named in the title, rendered like the\n"
    "          picture (coarse to fine, cancelled by the next key); V or\n"
    "          0: the picture (at once when it had finished)\n"
    "  H, F1   the keys" TEXT_IN_WINDOW_HELP "\n"
    "  Q, Esc  quit at once (Esc when nothing is explained; a render or a\n"
    "          load in progress is cancelled)\n"
    "A scene file dropped on the window is loaded, rendered and watched.\n"
    "\n"
    "Exit status: 0 when the window closes, 1 when a scene was given and\n"
    "never loaded, when there is no display, or -o cannot be written;\n"
    "2 bad usage; 128 + the signal after SIGINT, SIGTERM or SIGHUP (which\n"
    "leave a save under way undone, the file as it was).",
    CLI_GROUP_RENDER | CLI_GROUP_LOAD | CLI_GROUP_OUTPUT | CLI_GROUP_VIEW,
    view_options, 0, 1, NULL};

/*
 * Opens the window, shows `scene` (may be NULL) and runs until it closes;
 * returns the exit status.  Without a display it fails at once: SDL would
 * otherwise pick its invisible "offscreen" driver and run forever.
 */
static int run_viewer(const view_app_options *options, const char *scene)
{
    rt_error error;
    rt_save_options save = cli_save_options();
    if (options->output &&
        rt_image_save_check(options->output, &save, &error) != RT_OK) {
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
    view_app *app = NULL;
    if (started && view_video_init(message, sizeof message)) {
        SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");
        app = view_app_create(options, message, sizeof message);
    }
    if (app == NULL) {
        fprintf(stderr,
                PROGRAM ": cannot open a window: %s; rt-export renders "
                        "without a display\n",
                message);
        SDL_Quit();
        return 1;
    }
    if (scene)
        view_app_open(app, scene);     /* read on a worker: see view_load.h */
    view_app_run(app);
    int status = view_app_exit_status(app);
    view_app_destroy(app);
    SDL_Quit();
    return status;
}

/* The checks cli_parse leaves to rt-view; CLI_CONTINUE or 2. */
static int check_settings(const cli_settings *s)
{
    const rt_render_options *r = &s->render;
    if (scale != 1.0 && (r->width != 0 || r->height != 0))
        return cli_usage_error(&program, "--scale: not with --size, --width "
                                         "or --height");
    if (s->output != NULL && strcmp(s->output, "-") == 0)
        return cli_usage_error(&program, "-o: rt-view saves to a file, not "
                                         "to standard output");
    return CLI_CONTINUE;
}

int main(int argc, char **argv)
{
    cli_settings s;
    int code = cli_parse(&program, argc, argv, &s);
    if (code == CLI_CONTINUE)
        code = check_settings(&s);
    if (code != CLI_CONTINUE)
        return code;
    view_app_options options;
    view_app_options_init(&options);
    options.render = s.render;
    options.scale = scale;
    options.load = &s.load;
    options.output = s.output;
    if (s.output != NULL || s.format_given)
        options.format = s.format;
    options.watch = watch;
    options.view = (int)s.view;
    options.view_light = s.view_light;
    options.stats = stats ? stderr : NULL;
    return run_viewer(&options, s.operand_count ? s.operands[0] : NULL);
}
