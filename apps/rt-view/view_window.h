/*
 * view_window.h - the viewer's presenter: an SDL window showing a
 * view_session's image as it is rendered.
 *
 * The window keeps a texture of the image's size.  When attached to a
 * session it fills the texture with a dark checker (the placeholder for
 * rows not rendered yet); view_window_sync then uploads only the rows the
 * session reports changed since the last sync, by any pass of its render
 * (copied out under the session's lock, one SDL_UpdateTexture per run of
 * adjacent rows).  A restart of the session keeps what the texture shows
 * until the new render's passes replace it: the checker is only seen
 * before a session's first pass.  Drawing scales the texture to the
 * window, keeping the image's aspect ratio (letterboxed), so the window
 * may be resized freely.  The first frame presented with rows of a render
 * is reported to the session (view_session_note_shown, for --stats).
 *
 * Threading: SDL rendering is main-thread only, so every function here is
 * for the thread that initialised SDL's video subsystem.
 */
#ifndef VIEW_WINDOW_H
#define VIEW_WINDOW_H

#include <stddef.h>

#include "raytrace/raytrace.h"
#include "view_overlay.h"
#include "view_session.h"

typedef struct view_window view_window;

enum {
    VIEW_WINDOW_SOFTWARE = 1,   /* SDL's software renderer (exact, for tests) */
    VIEW_WINDOW_HIDDEN = 2      /* do not show the window */
};

/* Side of the placeholder checker's squares, in image pixels. */
#define VIEW_CHECKER_SIZE 8

/*
 * Starts SDL's video on a display a person can see, or fails with the
 * reason in `error` and SDL not started.  When SDL_VIDEODRIVER names a
 * driver, that one is used, whatever it is (the tests ask for "dummy").
 * Otherwise every compiled-in driver but the headless ones is tried in
 * SDL's order: SDL would otherwise fall back to "offscreen" when there is
 * no display, and a window nobody can see or close would never end.
 * Wayland is not tried without XDG_RUNTIME_DIR (its client library only
 * prints an error then).  Returns 1 on success.
 */
int view_video_init(char *error, size_t error_size);

/*
 * Opens a resizable window of width x height pixels with a renderer.
 * `flags` combines VIEW_WINDOW_*.  Returns NULL on failure with SDL's
 * reason in `error` ("cannot create window: ...").
 */
view_window *view_window_create(const char *title, int width, int height,
                                unsigned flags, char *error,
                                size_t error_size);

/* Closes the window.  NULL is a no-op.  Does not touch the session. */
void view_window_destroy(view_window *window);

/*
 * Shows `session` from now on (NULL: nothing, only the background), with
 * its image all placeholder.  Returns 0 and fills `error` when the texture
 * cannot be created (too large for the renderer, say); the window then shows
 * nothing.
 */
int view_window_attach(view_window *window, view_session *session,
                       char *error, size_t error_size);

/* Uploads the rows changed since the last sync; returns non-zero when the
 * picture changed (draw it). */
int view_window_sync(view_window *window);

/* Draws the picture and presents it. */
void view_window_draw(view_window *window);

/*
 * Draws the picture and reads back what the window shows into `out`, a new
 * image of the window's drawable size (free it with rt_image_release).
 * Returns 0 on failure.
 */
int view_window_read(view_window *window, rt_image *out);

void view_window_set_title(view_window *window, const char *title);

/* Resizes the window (its content is redrawn by the next draw) and centres
 * it in `bounds` {x, y, width, height} when `center` is non-zero or it
 * would reach past them. */
void view_window_place(view_window *window, int width, int height,
                       const int bounds[4], int center);

void view_window_show(view_window *window);

/* Hides the window (before a slow shutdown, say). */
void view_window_hide(view_window *window);

/* Index of the display the window is on (0 when unknown). */
int view_window_display(const view_window *window);

/* The largest size, within max_width x max_height, of a window showing a
 * width x height image: the image's size when it fits, else scaled down
 * keeping the aspect ratio (each side at least 1). */
void view_fit_size(int width, int height, int max_width, int max_height,
                   int *out_width, int *out_height);

/* The rays drawn over the picture (copied; count 0 or segments NULL: none),
 * projected with `projection`.  Returns 0 when out of memory (none then). */
int view_window_set_overlay(view_window *window,
                            const view_projection *projection,
                            const view_segment *segments, int count);

/* The text shown in a panel at the window's top left (NULL or "": none),
 * with SDL2_ttf and DejaVu Sans Mono.  Returns 0 when it cannot be shown
 * (a build without SDL2_ttf, no font found): the caller prints it. */
int view_window_set_text(view_window *window, const char *text);

/* Puts the text panel at the window's bottom (non-zero) or top (0, the
 * default): away from what it would hide. */
void view_window_set_text_place(view_window *window, int bottom);

/* Non-zero when this window can show text (SDL2_ttf and a font). */
int view_window_has_text(const view_window *window);

/* The image pixel (*i, *j) under window point (x, y) (SDL's mouse
 * coordinates), given the scaling and letterboxing of the picture; 0 when
 * the point is outside the picture or nothing is shown. */
int view_window_pixel_at(view_window *window, int x, int y, int *i, int *j);

/* The placeholder's colour at image pixel (x, y). */
void view_placeholder_color(int x, int y, unsigned char rgb[3]);

#endif /* VIEW_WINDOW_H */
