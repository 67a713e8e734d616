/*
 * view_session.h - one scene being rendered for the viewer, off the main
 * thread, coarse to fine.
 *
 * A view_session owns a scene, the image it shows (the session's image)
 * and a worker thread that renders it in passes: first at 1/8, 1/4 and
 * 1/2 of the resolution (each coarse pixel copied over the s x s block of
 * image pixels it stands for), then at full resolution with one sample a
 * pixel, then, when the options ask for more samples, with those
 * (view_session_plan says which passes a render gets).  The last pass is
 * exactly the library's render of the options: rt_render's bytes for the
 * picture, rt_render_view's for a debug view (view_session_set_view).
 * The library's row callback copies each row a pass finishes into the
 * image and marks it new; the main thread asks for the rows changed since
 * it last asked (view_session_take_finished_rows) and shows only those.
 * A row is final (view_session_row_done) once the last pass has finished
 * it; earlier passes only stand in for it.
 *
 * Starting again (a move, a depth, a view) cancels the render under way
 * within a pixel's work and starts from the coarsest pass; the image keeps
 * what it held until the new passes replace it.  Cancelling sets a flag
 * that the library polls, then joins the worker, so when
 * view_session_cancel returns no thread of the session is left.  Nothing
 * here knows about SDL: the tests drive a session directly, and rt-view
 * wakes its event loop through the `notify` hook.
 *
 * Threading: every function is for one controlling thread (the main
 * thread), except the `notify` hook, which the session calls from rendering
 * threads, and view_session_request_cancel.  The worker writes the image
 * under the session's lock: the controlling thread reads rows that are not
 * final with view_session_copy_rows; final rows (view_session_row_done) are
 * not written again until the next start, so it may read those directly
 * through view_session_image until the next start, cancel or destroy.
 */
#ifndef VIEW_SESSION_H
#define VIEW_SESSION_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "raytrace/raytrace.h"

/* Deepest reflection depth the viewer accepts: rt-export's limit
 * (apps/common/cli.h, CLI_MAX_DEPTH); the library itself has none. */
#define VIEW_MAX_DEPTH 1000000

/* The most passes a render has: 1/8, 1/4, 1/2, full, full with samples. */
#define VIEW_MAX_PASSES 5

/* No coarse pass for an image of fewer pixels than this (under 128 x 128
 * its full pass is as quick as a frame), nor for a region. */
#define VIEW_COARSE_MIN_PIXELS (128 * 128)

/* Nor a coarse pass whose image would be narrower or lower than this. */
#define VIEW_COARSE_MIN_SIDE 8

typedef struct view_session view_session;

/* Called from a rendering thread when new rows are ready (at most once
 * until the controlling thread takes them) and when a render ends.  It must
 * not call back into the session; pushing an event or posting a semaphore
 * is what it is for. */
typedef void (*view_notify_func)(void *user);

typedef struct view_session_options {
    rt_render_options render;   /* every render option: depth (at most
                                   VIEW_MAX_DEPTH), threads, samples, size,
                                   region ...; on_row, user, cancel, stats
                                   and camera are the session's own and
                                   ignored here (view_session_set_camera) */
    view_notify_func notify;    /* optional */
    void *notify_user;
    FILE *stats;                /* optional (rt-view --stats): one line per
                                   render when it ends, the time of each
                                   pass and the rays
                                   (view_render_report_describe) */
} view_session_options;

typedef enum view_state {
    VIEW_IDLE,                  /* never started */
    VIEW_RENDERING,
    VIEW_DONE,                  /* every pass finished: every row final */
    VIEW_CANCELLED,
    VIEW_FAILED                 /* the render returned another error */
} view_state;

/* One pass of a render. */
typedef struct view_pass {
    int scale;                  /* 8, 4 or 2: a coarse pass of
                                   ceil(W/scale) x ceil(H/scale) pixels,
                                   each shown as a scale x scale block;
                                   1: the full resolution */
    int samples;                /* rays per pixel (1 but in the last pass) */
} view_pass;

/* A snapshot of where the render is. */
typedef struct view_progress {
    view_state state;
    int rows_done;              /* rows of the image the current pass has
                                   finished (a coarse row counts for the
                                   rows of its blocks) */
    int rows_total;
    int max_depth;
    double seconds;             /* elapsed while rendering, total after */
    rt_status status;           /* of the last finished render */
    unsigned generation;        /* increases with each start */
    int pass;                   /* the pass under way (or last run), from 0 */
    int pass_count;             /* passes of this render; 0 before any */
    view_pass passes[VIEW_MAX_PASSES];
    int rows_final;             /* rows view_session_row_done says are
                                   final */
    int view, light;            /* what is rendered: 0 the picture, else an
                                   rt_debug_view and its light */
} view_progress;

/* What one render did, for --stats and the tests: kept by the session for
 * the last render that ended (view_session_last_report). */
typedef struct view_render_report {
    unsigned generation;        /* 0: no render has ended yet */
    int view, light;
    view_state state;           /* VIEW_DONE, VIEW_CANCELLED, VIEW_FAILED */
    rt_status status;
    int pass_count;
    view_pass passes[VIEW_MAX_PASSES];
    int passes_done;            /* passes that finished; the one it stopped
                                   in is passes[passes_done] */
    int rows_reached;           /* rows that pass had finished then */
    int rows_total;             /* of the image */
    double pass_seconds[VIEW_MAX_PASSES]; /* from the start to the end of
                                   each finished pass */
    double seconds;             /* from the start to the end */
    double shown_seconds;       /* from the start to the first frame a
                                   window showed of it
                                   (view_session_note_shown); < 0: none */
    uint64_t rays;              /* rt_render_stats_rays summed over the
                                   passes */
    int kept;                   /* 1: nothing rendered, the picture
                                   finished before was shown again */
    char error[RT_ERROR_MESSAGE_SIZE]; /* why it failed ("" otherwise) */
} view_render_report;

/* Sets the defaults: rt_render_options_init's, no notify, no stats. */
void view_session_options_init(view_session_options *options);

/*
 * Creates a session for `scene`, which it takes over (freed by
 * view_session_destroy, also on failure).  The image has the size
 * rt_render_image_size gives for the options, allocated black; it shows
 * the picture (view 0) with the scene's camera until told otherwise.
 * Returns RT_OK, RT_ERR_NOMEM or RT_ERR_ARGUMENT (depth out of range, or a
 * size or region the scene's image cannot have: the reason in *error,
 * which may be NULL); *session is NULL on failure.
 */
rt_status view_session_create(rt_scene *scene,
                              const view_session_options *options,
                              view_session **session, rt_error *error);

/* Cancels any render, joins its thread and frees everything.  NULL is a
 * no-op. */
void view_session_destroy(view_session *session);

/*
 * Starts rendering from scratch with the current depth, camera and view:
 * cancels and joins a running render, forgets which rows were finished and
 * starts a new worker on the passes view_session_plan gives; the image
 * keeps its pixels until they are replaced.  The picture with the depth
 * and camera of the last picture that finished (before a debug view was
 * started over it, say) is shown again at once without rendering: every
 * row final, the state VIEW_DONE when this returns.  Returns RT_OK, or
 * RT_ERR_NOMEM when the thread could not start (the state is then
 * VIEW_FAILED).
 */
rt_status view_session_start(view_session *session);

/* Asks the render to stop and waits for its thread: when this returns, no
 * thread of the session runs.  The library stops within about one pixel of
 * each rendering thread's work.  A session not rendering is left alone. */
void view_session_cancel(view_session *session);

/* Only sets the cancel flag (does not wait); safe from any thread,
 * including the notify hook. */
void view_session_request_cancel(view_session *session);

/* Changes the depth used by the next start; 0..VIEW_MAX_DEPTH, else
 * RT_ERR_ARGUMENT. */
rt_status view_session_set_depth(view_session *session, int max_depth);

/* The camera of the next start: `camera` copied (rt_scene_look makes one;
 * the library checks it when it renders: a bad one fails the render), or
 * NULL for the scene's.  Its width and height do not matter: the image
 * keeps the session's size.  RT_OK. */
rt_status view_session_set_camera(view_session *session,
                                  const rt_camera *camera);

/* What the next start renders: `view` 0, the picture, or an rt_debug_view
 * with `light` (RT_VIEW_SHADOW and RT_VIEW_NS; ignored by the others).
 * RT_ERR_ARGUMENT (nothing changed) for a view rt_debug_view does not
 * name or a light outside 0..light_count-1; else RT_OK. */
rt_status view_session_set_view(view_session *session, int view, int light);

/*
 * The passes of a render of a width x height image (the region's when
 * `region` is non-zero) with `samples` rays a pixel, of the picture
 * (`view` 0) or of a debug view, into `passes`; returns their number, 1 to
 * VIEW_MAX_PASSES.  Coarse passes 1/8, 1/4, 1/2 unless a region is set or
 * the image has fewer than VIEW_COARSE_MIN_PIXELS pixels, each skipped when
 * its image would have a side under VIEW_COARSE_MIN_SIDE; they have one
 * sample.  Then the full resolution: for the picture with `samples` > 1
 * first with one sample, then with `samples`; otherwise once with
 * `samples` (a view reads only each pixel's first sample: one pass with
 * the samples asked gives rt_render_view's bytes).  Thread-safe.
 */
int view_session_plan(int width, int height, int region, int samples,
                      int view, view_pass passes[VIEW_MAX_PASSES]);

/*
 * The camera of a coarse pass of scale `scale` of a width x height image
 * seen by `camera`: its image is ceil(width/scale) x ceil(height/scale),
 * and its pixel (i, j) is seen through the screen point that `camera`'s
 * pixel coordinates ((i + 1/2) scale, (j + 1/2) scale) give in the
 * width x height image (docs/rendering-model.md's formula), the centre of
 * the block it stands for, even where the blocks overhang the image.
 * Fills *coarse (its width and height those of the coarse image) and
 * *coarse_width, *coarse_height.  Thread-safe.
 */
void view_pass_camera(const rt_camera *camera, int width, int height,
                      int scale, rt_camera *coarse, int *coarse_width,
                      int *coarse_height);

/*
 * Moves the rows changed since the last call (by any pass) into `rows` (at
 * most `capacity` of them, in increasing order; the rest stay for the next
 * call) and returns how many.  *generation (when not NULL) receives the
 * generation those rows belong to.  Also re-arms the notify hook.
 */
int view_session_take_finished_rows(view_session *session, int *rows,
                                    int capacity, unsigned *generation);

/* Copies rows [first, first + count) of the image, as they are now, to
 * `out` (`stride` bytes from one row to the next), under the session's
 * lock; 0 when the rows are outside the image. */
int view_session_copy_rows(view_session *session, int first, int count,
                           unsigned char *out, size_t stride);

/* Non-zero when `row` of the current render is final: the last pass
 * finished it. */
int view_session_row_done(view_session *session, int row);

void view_session_get_progress(view_session *session,
                               view_progress *progress);

/* A window showed a first frame with rows of render `generation`: noted
 * in that render's report (shown_seconds) when it is the current one and
 * none was noted before. */
void view_session_note_shown(view_session *session, unsigned generation);

/* The report of the last render that ended (generation 0: none yet). */
void view_session_last_report(view_session *session,
                              view_render_report *report);

/* The image shown (see the threading rule above). */
const rt_image *view_session_image(const view_session *session);

const rt_scene *view_session_scene(const view_session *session);

/* "picture", "normal view", "depth view", ...: how rt-view names what a
 * session renders (an rt_debug_view, or 0).  "" for an unknown view. */
const char *view_session_view_name(int view);

/* How the title and --stats name pass `index` of `passes`: "1/8", "1/4",
 * "1/2", "full", or "16 samples" for a full pass after a full one. */
const char *view_pass_name(const view_pass *passes, int index, char *buffer,
                           size_t size);

/* "42% - 1.3 s", "1/4: 42% - 0.1 s", "done in 2.41 s", "cancelled at 42%
 * of 1/4 after 0.1 s", "failed: ..." */
void view_progress_describe(const view_progress *progress, char *buffer,
                            size_t size);

/* The --stats line of a render, without the program's name or a newline:
 * the time from its start to the end of each pass (under 10 ms to 0.1 ms,
 * under 1 s in ms, else in s with two decimals), to the first frame shown,
 * and the rays (in millions from 100,000 on, else exactly):
 * "render 3 (picture): 1/8 in 6.0 ms, 1/4 in 18 ms, 1/2 in 61 ms, full in
 * 840 ms; first shown at 9.0 ms; 1.23 M rays"; for a cancelled render
 * "render 4 (normal view): cancelled in 1/4 (41 of 480 rows) after 25 ms;
 * 1/8 in 6.0 ms; ...", a failed one "failed in ...: REASON". */
void view_render_report_describe(const view_render_report *report,
                                 char *buffer, size_t size);

#endif /* VIEW_SESSION_H */
