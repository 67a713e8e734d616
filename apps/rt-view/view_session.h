/*
 * view_session.h - one scene being rendered for the viewer, off the main
 * thread.
 *
 * A view_session owns a scene, the image it is rendered into and a worker
 * thread that renders the whole image through rt_render_rows.  The
 * library's row callback marks each finished row; the main thread asks for
 * the rows finished since it last asked (view_session_take_finished_rows)
 * and shows only those, so a row appears exactly when it is complete.
 * Cancelling sets a flag that the row callback returns to the library, then
 * joins the worker, so when view_session_cancel returns no thread of the
 * session is left.  Nothing here knows about SDL: the tests drive a session
 * directly, and rt-view wakes its event loop through the `notify` hook.
 *
 * Threading: every function is for one controlling thread (the main
 * thread), except the `notify` hook, which the session calls from rendering
 * threads.  Pixels of a row may be read by the controlling thread once
 * take_finished_rows has returned that row, until the next start, cancel or
 * destroy.
 */
#ifndef VIEW_SESSION_H
#define VIEW_SESSION_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* Deepest reflection depth the viewer accepts: rt-export's limit
 * (apps/common/cli.h, CLI_MAX_DEPTH); the library itself has none. */
#define VIEW_MAX_DEPTH 1000000

typedef struct view_session view_session;

/* Called from a rendering thread when new rows are finished (at most once
 * until the controlling thread takes them) and when a render ends.  It must
 * not call back into the session; pushing an event or posting a semaphore
 * is what it is for. */
typedef void (*view_notify_func)(void *user);

typedef struct view_session_options {
    rt_render_options render;   /* every render option: depth (at most
                                   VIEW_MAX_DEPTH), threads, samples, size,
                                   region ...; on_row, user and cancel are
                                   the session's own and ignored here */
    view_notify_func notify;    /* optional */
    void *notify_user;
} view_session_options;

typedef enum view_state {
    VIEW_IDLE,                  /* never started */
    VIEW_RENDERING,
    VIEW_DONE,                  /* every row finished */
    VIEW_CANCELLED,
    VIEW_FAILED                 /* the render returned another error */
} view_state;

/* A snapshot of where the render is. */
typedef struct view_progress {
    view_state state;
    int rows_done;
    int rows_total;
    int max_depth;
    double seconds;             /* elapsed while rendering, total after */
    rt_status status;           /* of the last finished render */
    unsigned generation;        /* increases with each start */
} view_progress;

/* Sets the defaults: rt_render_options_init's, no notify. */
void view_session_options_init(view_session_options *options);

/*
 * Creates a session for `scene`, which it takes over (freed by
 * view_session_destroy, also on failure).  The image has the size
 * rt_render_image_size gives for the options, allocated black.  Returns
 * RT_OK, RT_ERR_NOMEM or RT_ERR_ARGUMENT (depth out of range, or a size or
 * region the scene's image cannot have: the reason in *error, which may be
 * NULL); *session is NULL on failure.
 */
rt_status view_session_create(rt_scene *scene,
                              const view_session_options *options,
                              view_session **session, rt_error *error);

/* Cancels any render, joins its thread and frees everything.  NULL is a
 * no-op. */
void view_session_destroy(view_session *session);

/*
 * Starts rendering from scratch: cancels and joins a running render, blacks
 * the image, forgets which rows were finished and starts a new worker.
 * Returns RT_OK, or RT_ERR_NOMEM when the thread could not start (the
 * state is then VIEW_FAILED).
 */
rt_status view_session_start(view_session *session);

/* Asks the render to stop and waits for its thread: when this returns, no
 * thread of the session runs.  The library stops within about one row of
 * each rendering thread's work.  A session not rendering is left alone. */
void view_session_cancel(view_session *session);

/* Only sets the cancel flag (does not wait); safe from any thread,
 * including the notify hook. */
void view_session_request_cancel(view_session *session);

/* Changes the depth used by the next start; 0..VIEW_MAX_DEPTH, else
 * RT_ERR_ARGUMENT. */
rt_status view_session_set_depth(view_session *session, int max_depth);

/* Placeholder until r-prog merges: the camera the next start renders with
 * (copied; NULL: the scene's own).  RT_OK. */
rt_status view_session_set_camera(view_session *session,
                                  const rt_camera *camera);

/*
 * Moves the rows finished since the last call into `rows` (at most
 * `capacity` of them, in increasing order; the rest stay for the next call)
 * and returns how many.  *generation (when not NULL) receives the
 * generation those rows belong to.  Also re-arms the notify hook.
 */
int view_session_take_finished_rows(view_session *session, int *rows,
                                    int capacity, unsigned *generation);

/* Non-zero when `row` of the current render is finished. */
int view_session_row_done(view_session *session, int row);

void view_session_get_progress(view_session *session,
                               view_progress *progress);

/* The image being rendered (see the threading rule above). */
const rt_image *view_session_image(const view_session *session);

const rt_scene *view_session_scene(const view_session *session);

/* "42% - 1.3 s", "done in 2.41 s", "cancelled at 42%", "failed: ..." */
void view_progress_describe(const view_progress *progress, char *buffer,
                            size_t size);

#endif /* VIEW_SESSION_H */
