/*
 * view_app.h - rt-view itself, less its command line: the window, the
 * scene it shows, the keys, reloading (R, --watch), saving (S) and the
 * event loop (view_app.c, view_reload.c, view_save.c and
 * view_navigation.c, one job each: view_app_internal.h).  main.c parses
 * the options and calls this; the tests drive the same functions directly
 * on SDL's dummy driver.
 *
 * The rules it keeps:
 *   - a scene is read on a worker thread (view_load.h): the window stays
 *     live meanwhile, the picture shown before stays until the new scene
 *     is ready, and the title says "loading"; a new load, and quitting,
 *     cancel the one under way without waiting for it;
 *   - a reload reads the file again; when it fails, the picture shown stays
 *     and the error (FILE:LINE:COLUMN: MESSAGE) goes to stderr and the
 *     title;
 *   - S never replaces an image saved before: a complete image goes to
 *     `-o PATH` the first time, else to the first free numbered name
 *     (SCENE-1.png, SCENE-2.png ..., or PATH's stem numbered the same way),
 *     and an image still rendering to SCENE-partial-N.png, so a partial
 *     image can never take a complete one's place;
 *   - the exit status is 128 + the signal after SIGINT, SIGTERM or SIGHUP,
 *     1 when a scene was asked for and none ever loaded, else 0.
 *
 * Threading: main thread only (SDL's rule), after view_video_init.
 */
#ifndef VIEW_APP_H
#define VIEW_APP_H

#include <stddef.h>
#include <stdio.h>

#include "raytrace/raytrace.h"
#include "view_explain.h"
#include "view_load.h"
#include "view_session.h"
#include "view_window.h"

#define VIEW_WATCH_MS 250   /* how often --watch looks at the file */

/* The longest the event loop sleeps: termination signals are blocked (they
 * cannot wake it) and taken at each turn, so one is acted on within this
 * (SIGTERM quits within it whatever a load is doing). */
#define VIEW_SIGNAL_MS 50

typedef struct view_app_options {
    rt_render_options render;   /* every render option; width and height 0
                                   (the scene's) unless --size said */
    double scale;               /* when width and height are 0: the scene's
                                   size times this (1: the scene's) */
    const rt_load_options *load;/* the loader's options, NULL: defaults;
                                   must outlive the app */
    const char *output;         /* -o PATH, or NULL: beside the scene */
    rt_image_format format;     /* of the saves */
    int watch;                  /* --watch: reload when the file changes */
    unsigned window_flags;      /* VIEW_WINDOW_*; the window starts hidden
                                   whatever they say */
    int view;                   /* --view: the rt_debug_view shown first,
                                   0: the picture */
    int view_light;             /* its light (shadow and N.S views) */
    view_load_func load_scene;  /* how a scene is read (on the load's
                                   worker): NULL, view_scene_load; the
                                   tests pass loaders that block */
    FILE *stats;                /* --stats: after each render, a line with
                                   the time of each pass and the rays
                                   (view_session_options.stats); NULL:
                                   none */
} view_app_options;

typedef struct view_app view_app;

/* Defaults: rt_render_options_init's, scale 1, PNG when this build writes
 * it (else binary PPM), no -o, no watch. */
void view_app_options_init(view_app_options *options);

/* Opens the (hidden) window.  SDL's video must be started.  NULL on
 * failure, with the reason in `error`. */
view_app *view_app_create(const view_app_options *options, char *error,
                          size_t error_size);

/* Cancels the render and waits for its threads, lets any load go (never
 * waiting for it), closes the window.  NULL is a no-op. */
void view_app_destroy(view_app *app);

/*
 * Starts loading `path` on a worker thread, to render it in place of the
 * current scene once loaded (the event loop takes it over, or
 * view_app_wait_load); a load under way is cancelled and let go.  `path`
 * becomes the file R and --watch reload.  Returns 1 when the load started,
 * 0 when it could not (out of memory; the error is shown).
 */
int view_app_open(view_app *app, const char *path);

/* Non-zero while a load is under way. */
int view_app_loading(const view_app *app);

/*
 * Waits for the load under way, then does what the event loop does when
 * one ends: renders its scene, or shows its error and keeps the current
 * picture.  Returns 1 when it loaded, 0 when it failed or none was under
 * way.  For the tests (the event loop never waits).
 */
int view_app_wait_load(view_app *app);

/* R: view_app_open on the current file again (0 when there is none). */
int view_app_reload(view_app *app);

/* --watch: starts a reload when the file's stamp differs from the one it
 * had when last read (a stat, which never blocks).  Returns 1 when it
 * started one. */
int view_app_check_watch(view_app *app);

/* S: saves what is rendered so far by the rules above; returns 1 with the
 * path written in `path`, or 0 (the reason shown). */
int view_app_save(view_app *app, char *path, size_t size);

/* Shows the window and runs the event loop until Q, Esc, closing the
 * window or a termination signal (taken within VIEW_SIGNAL_MS).  A load
 * ending meanwhile is shown at once. */
void view_app_run(view_app *app);

/* The exit status the rules above give. */
int view_app_exit_status(const view_app *app);

/* The session shown, or NULL before a scene loaded. */
view_session *view_app_session(view_app *app);

/* The keys, as the help shows them (H, F1) and rt-view --help prints. */
extern const char view_app_keys_help[];

/* A key pressed (an SDL keycode; `repeat` non-zero for a held key's
 * repeats), as the event loop handles it. */
void view_app_key(view_app *app, int key, int repeat);

/* A left click at window point (x, y): explains the image pixel there,
 * drawing the sample nearest the point's place in the pixel
 * (view_app_explain_at), with a panel sized to the picture as it is on
 * screen.  0 outside the picture or on failure. */
int view_app_click(view_app *app, int x, int y);

/* Explains pixel (x, y) of the shown image with the picture's render
 * options: draws its ray tree over the image (of one sample, with
 * several: Tab steps through them), shows its text in the window (with
 * SDL2_ttf; a part of it, at most two fifths of the picture's height) and
 * prints all of it on stdout, as rt-export --explain X,Y does.  Returns 1,
 * or 0 with the reason shown. */
int view_app_explain(view_app *app, int x, int y);

/* Explains the pixel under point (x, y) of the shown image, in image
 * coordinates (pixel (i, j) covers [i, i+1) x [j, j+1)): as
 * view_app_explain, drawing the sample whose point is nearest (x, y)
 * (view_explain_point).  view_app_click maps the window point to such a
 * point; view_app_explain(i, j) is the pixel's centre. */
int view_app_explain_at(view_app *app, double x, double y);

/* Tab (delta 1) and Shift+Tab (-1): draws the explained pixel's next (or
 * previous) sample, cycling, with its text in the panel, and prints which
 * on stdout.  Returns 1, or 0 when no pixel of several samples is
 * explained or on failure (the reason shown). */
int view_app_step_sample(view_app *app, int delta);

/* The explanation shown, or NULL. */
const view_explanation *view_app_explanation(const view_app *app);

/* Shows debug view `view` (an rt_debug_view; 0: the picture) of light
 * `light` (shadow and N.S views).  Returns 1, or 0 (the picture then, the
 * reason shown). */
int view_app_set_view(view_app *app, int view, int light);

/* The window's title, and the window (for the tests to read). */
const char *view_app_title(const view_app *app);
view_window *view_app_window(view_app *app);

/* The last error shown ("" when the last action succeeded). */
const char *view_app_message(const view_app *app);

#endif /* VIEW_APP_H */
