/*
 * view_app_internal.h - what the files of rt-view's app share; not API
 * (main.c and the tests use view_app.h).  The app is split by job:
 *   - view_app.c: creating and destroying it, the title and the messages,
 *     starting a render, the termination signals and the event loop;
 *   - view_reload.c: opening a scene on the load's worker, showing it in a
 *     new session when it is read, R and --watch;
 *   - view_save.c: S, the image saved by the rules of view_app.h;
 *   - view_navigation.c: the keys, a click's explanation and its overlay,
 *     the debug views, the depth and the help;
 *   - view_move.c: moving the camera with the mouse and the keys (the
 *     arithmetic in view_camera.c), and C, the camera as text.
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

union SDL_Event;

/* The camera moves (view_move.c): the camera shown and the input the event
 * loop has not applied yet (applied once a turn: view_app__apply_moves). */
typedef struct view_move {
    const rt_scene *scene;      /* the scene the fields below are of */
    char path[4096];            /* its file (a reload of it keeps the view) */
    rt_vec3 world_up;           /* unit: orbits turn about it */
    double extent;              /* the scene's size, scene units */
    int moved;                  /* 0: the file's camera */
    rt_look look;               /* when moved: the view shown */
    rt_camera camera;           /* when moved: rt_scene_look's of `look` */
    /* the mouse button held */
    int button;                 /* SDL's button number; 0: none */
    int pan;                    /* its drag pans (else it orbits) */
    int dragging;               /* it went past the click's slop */
    int picked;                 /* a double-click: no explanation */
    int press_x, press_y;       /* where it was pressed, window points */
    int last_x, last_y;         /* the last motion's place */
    double pixels_per_point;    /* image pixels per window point */
    /* input since the last turn */
    int pending;
    double drag_x, drag_y;      /* window points */
    double wheel, fov_wheel;    /* notches (fov_wheel: with Ctrl) */
    double fly_forward, fly_right, fly_rise; /* in fly steps */
    int fov_steps;              /* ] +1, [ -1 */
    int pick, pick_i, pick_j;   /* a double-click's image pixel */
} view_move;

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
    view_move move;             /* the camera's moves (view_move.c) */
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
 * giving the size when --size did not, and the moved camera (pointing
 * into app->move: valid until the next move) once the camera moved. */
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

/* Takes an event that moves the camera or belongs to a drag (mouse
 * buttons, motion, wheel; the keys of view_app_keys_help's "Camera"
 * lines, C included): returns 1 when it was one of them (the loop then
 * does nothing else with it), else 0.  A button released without motion
 * (within a few points) explains the pixel (left) or clears the
 * explanation (right), as a click did before. */
int view_app__move_event(view_app *app, const union SDL_Event *event);

/* Applies the moves taken since the last call, at most one new camera a
 * turn of the event loop (the session restarted once), and follows a new
 * scene (a reload of the same file keeps the view, another file starts
 * from its own camera). */
void view_app__apply_moves(view_app *app);

/* Back to the file's camera (Home). */
void view_app__camera_home(view_app *app);

/* C: prints the camera as rt-export options and .scn records on stdout
 * and writes the same text beside the scene, STEM-camera.txt (or the
 * first free STEM-camera-N.txt); the path in `path` (may be NULL).
 * Returns 1 when written. */
int view_app__print_camera(view_app *app, char *path, size_t size);

#endif /* VIEW_APP_INTERNAL_H */
