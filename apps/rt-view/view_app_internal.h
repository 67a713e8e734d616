/*
 * view_app_internal.h - what the files of rt-view's app share; not API
 * (main.c and the tests use view_app.h).  The app is split by job:
 *   - view_app.c: creating and destroying it, the title and the messages,
 *     starting a render, the termination signals and the event loop;
 *   - view_reload.c: opening a scene on the load's worker, showing it in a
 *     new session when it is read, R and --watch;
 *   - view_save.c: S, the image saved by the rules of view_app.h;
 *   - view_navigation.c: the keys, a click's explanation and its overlay,
 *     the debug views, the depth and the help.
 * Each file calls the others only through the view_app__ functions below.
 * Threading: main thread only, as view_app.h says (view_app__wake excepted).
 */
#ifndef VIEW_APP_INTERNAL_H
#define VIEW_APP_INTERNAL_H

#include <stdint.h>

#include "raytrace/raytrace.h"
#include "view_app.h"
#include "view_scene.h"

#define VIEW_APP_PROGRAM "rt-view"  /* the prefix of messages, the title */

struct view_app {
    view_app_options options;
    char *path;                 /* the file R and --watch reload; NULL */
    char *shown_path;           /* the file of the session's scene */
    view_file_stamp stamp;      /* of `path` when last read */
    int scene_asked;            /* a scene was asked for */
    int scene_loaded;           /* one loaded at least once */
    int output_written;         /* -o PATH has a complete image */
    view_session *session;
    view_load *load;            /* the load under way, or NULL */
    view_window *window;
    uint32_t wake_event;         /* SDL_RegisterEvents' */
    char message[RT_ERROR_MESSAGE_SIZE + 64]; /* shown in the title */
    char title[RT_ERROR_MESSAGE_SIZE + 256];
    int shown;                  /* the window is on screen */
    int quit;
    int quit_signal;            /* the termination signal, or 0 */
    int redraw;
    int view;                   /* 0: the picture, else an rt_debug_view */
    int view_light;             /* the light of the shadow and N.S views */
    view_explanation explanation; /* of the clicked pixel; text NULL: none */
    int help;                   /* the help is shown in the window */
};

/* Prints "rt-view: MESSAGE" on stderr and shows it in the title until the
 * next render starts. */
void view_app__show_message(view_app *app, const char *message);

/* Sets the window's title from the state: the scene, its size, depth,
 * progress, the view shown, a load under way, the last message. */
void view_app__update_title(view_app *app);

/* Renders the session's scene again (after a load, a depth change); the
 * explanation is cleared, the debug view shown is rendered again. */
void view_app__start_render(view_app *app);

/* The render options of the picture of `scene`: the app's, with --scale
 * giving the size when --size did not. */
rt_render_options view_app__render_options(const view_app *app,
                                           const rt_scene *scene);

/* Takes a pending SIGINT, SIGTERM or SIGHUP, if any, and asks the loop to
 * quit (the exit status then says which). */
void view_app__take_signal(view_app *app);

/* The session's and the load's notify hook (`user`: the app): wakes the
 * event loop.  Any thread. */
void view_app__wake(void *user);

/* The load under way has ended: shows its scene, or its error (the
 * current picture stays).  Returns 1 when it loaded. */
int view_app__finish_load(view_app *app);

/* Clears the explanation and the help, if shown. */
void view_app__clear_explanation(view_app *app);

/* Starts the session on debug view app->view (0: the picture, which
 * shows at once when it finished before with the same depth and camera):
 * rendered on its worker, coarse to fine, as the picture is.  A light
 * the scene does not have falls back to the picture.  Returns 1, or 0
 * with the reason shown. */
int view_app__show_view(view_app *app);

/* "normal view", "depth view", ...: how the title names an rt_debug_view
 * (0, the picture: ""). */
const char *view_app__view_name(int view);

#endif /* VIEW_APP_INTERNAL_H */
