/*
 * viewer.h - what the suites of rt-view's logic share (test_viewer*.c,
 * test_explain_terms.c): SDL on its dummy video driver with the software
 * renderer (no display needed), sessions rendered to their end, windows
 * read back pixel by pixel, apps opened and closed.  A library of its own,
 * raytrace_test_viewer_support, built only with the viewer: it links
 * raytrace_viewer and SDL2, which the other suites must not load.  Part of
 * tests/support/; every function fails the test (Check) when it cannot do
 * its job.
 */
#ifndef RAYTRACE_TEST_VIEWER_H
#define RAYTRACE_TEST_VIEWER_H

#include "probe.h"
#include "raytrace/raytrace.h"
#include "view_app.h"
#include "view_session.h"
#include "view_window.h"

/* Longest a test waits for a render before failing (a guard, not a
 * measure: a render here takes milliseconds; under valgrind, where a
 * 400 x 400 render of 4 samples takes a minute, ten times as long). */
#define RT_TEST_VIEW_WAIT_SECONDS (rt_test_memcheck() ? 600.0 : 60.0)

/* A scene slow to render: `count` small reflective triangles scattered in
 * front of a large floor (slower still with RT_ACCEL_NONE: every ray
 * tests every facet), for a width x height image.  Same camera as
 * scenes/two-facets.scn. */
rt_scene *rt_test_view_heavy_scene(int count, int width, int height);

/* Whether row `y` of `frame` is the placeholder a render starts from. */
int rt_test_view_row_is_placeholder(const rt_image *frame, int y);

/* SDL's video, on the dummy driver unless SDL_VIDEODRIVER says otherwise
 * (tests/viewer.cmake sets it too). */
void rt_test_view_sdl_init(void);

/* A session over `scene` rendering with `threads` threads, calling
 * `notify(user)` (optional) as view_session_options says. */
view_session *rt_test_view_session(rt_scene *scene, int threads,
                                   view_notify_func notify, void *user);

/* Waits while `session` renders; its state then (VIEW_DONE...). */
view_state rt_test_view_wait(view_session *session);

/* A hidden window of that size on the software renderer (SDL initialised
 * here); rt_test_view_window_close destroys it and quits SDL. */
view_window *rt_test_view_window_open(int width, int height);
void rt_test_view_window_close(view_window *window);

/* What the window shows, read back (free with rt_image_release). */
rt_image rt_test_view_window_read(view_window *window);

/* view_app_options_init with the software window: the options an app of
 * the tests starts from. */
void rt_test_view_app_options(view_app_options *options);

/* An app made with `options` (SDL initialised here);
 * rt_test_view_app_close destroys it and quits SDL. */
view_app *rt_test_view_app_open(const view_app_options *options);
void rt_test_view_app_close(view_app *app);

/* An app saving binary PPM to `output` (NULL: beside the scene), watching
 * its scene when `watch`; `samples` > 1 rays a pixel on one thread. */
view_app *rt_test_view_app(const char *output, int watch, int samples);

/* view_app_open, then what the event loop does when the load ends: 1 when
 * the scene loaded. */
int rt_test_view_app_load(view_app *app, const char *path);

/* The finished image of the app's session (waits for the render). */
const rt_image *rt_test_view_app_image(view_app *app);

#endif /* RAYTRACE_TEST_VIEWER_H */
