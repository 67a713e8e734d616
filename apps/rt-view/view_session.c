/*
 * view_session.c - a scene rendered by a worker thread, row by row, for the
 * viewer (see view_session.h).  The library's row callback records finished
 * rows under a mutex; the main thread collects them; the library's
 * cancellation flag, polled before every pixel, stops the render at once.
 */
#include "view_session.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_clock.h"

struct view_session {
    rt_scene *scene;
    rt_image image;
    view_session_options options;
    /* placeholder until r-prog merges: the camera of the render under
     * way (the worker reads it), and the one the next start takes */
    rt_camera camera, next_camera;
    int camera_given, next_camera_given;

    pthread_t worker;
    int worker_joinable;        /* controlling thread only */
    rt_cancel *cancel;          /* raised to stop the worker's render */
    atomic_int wake_pending;    /* notify sent, rows not yet taken */

    pthread_mutex_t lock;       /* guards everything below */
    unsigned char *done;        /* per row: finished */
    unsigned char *fresh;       /* per row: finished, not yet taken */
    int rows_done;
    int fresh_count;
    view_state state;
    rt_status status;
    unsigned generation;
    double started;             /* monotonic seconds */
    double finished;
};

static void notify(view_session *session)
{
    if (session->options.notify)
        session->options.notify(session->options.notify_user);
}

/* The library's row callback: runs on rendering threads, serialised. */
static int on_row(void *user, int row)
{
    view_session *session = user;
    pthread_mutex_lock(&session->lock);
    if (row >= 0 && row < session->image.height && !session->done[row]) {
        session->done[row] = 1;
        session->fresh[row] = 1;
        session->rows_done++;
        session->fresh_count++;
    }
    pthread_mutex_unlock(&session->lock);
    if (!atomic_exchange(&session->wake_pending, 1))
        notify(session);
    return !rt_cancel_requested(session->cancel);
}

static void *worker_main(void *arg)
{
    view_session *session = arg;
    rt_render_options options = session->options.render;
    options.stats = NULL;
    options.on_row = on_row;
    options.user = session;
    options.cancel = session->cancel;
    options.camera = session->camera_given ? &session->camera : NULL;
    rt_status status = rt_render_rows(session->scene, &options, 0,
                                      session->image.height, &session->image,
                                      NULL);

    pthread_mutex_lock(&session->lock);
    session->status = status;
    session->finished = cli_clock_seconds();
    if (status == RT_OK)
        session->state = VIEW_DONE;
    else if (status == RT_ERR_CANCELLED)
        session->state = VIEW_CANCELLED;
    else
        session->state = VIEW_FAILED;
    pthread_mutex_unlock(&session->lock);
    notify(session);
    return NULL;
}

void view_session_options_init(view_session_options *options)
{
    memset(options, 0, sizeof *options);
    rt_render_options_init(&options->render);
}

rt_status view_session_create(rt_scene *scene,
                              const view_session_options *options,
                              view_session **out, rt_error *error)
{
    *out = NULL;
    view_session_options defaults;
    if (options == NULL) {
        view_session_options_init(&defaults);
        options = &defaults;
    }
    int width, height;
    rt_status status = rt_render_image_size(scene, &options->render, &width,
                                            &height, error);
    if (status == RT_OK && (options->render.max_depth < 0 ||
                            options->render.max_depth > VIEW_MAX_DEPTH ||
                            options->render.threads < 0)) {
        status = RT_ERR_ARGUMENT;
        if (error) {
            memset(error, 0, sizeof *error);
            error->status = status;
            snprintf(error->message, sizeof error->message,
                     "depth or threads out of range");
        }
    }
    if (status != RT_OK) {
        rt_scene_destroy(scene);
        return status;
    }
    view_session *session = calloc(1, sizeof *session);
    if (session == NULL) {
        rt_scene_destroy(scene);
        return RT_ERR_NOMEM;
    }
    session->scene = scene;
    session->options = *options;
    session->state = VIEW_IDLE;
    session->status = RT_OK;
    atomic_init(&session->wake_pending, 0);

    status = rt_cancel_create(&session->cancel, NULL);
    if (status == RT_OK)
        status = rt_image_init(&session->image, width, height, NULL);
    if (status == RT_OK) {
        session->done = calloc((size_t)height, 1);
        session->fresh = calloc((size_t)height, 1);
        if (session->done == NULL || session->fresh == NULL)
            status = RT_ERR_NOMEM;
    }
    if (status == RT_OK && session->cancel == NULL)
        status = RT_ERR_NOMEM;
    if (status == RT_OK && pthread_mutex_init(&session->lock, NULL) != 0)
        status = RT_ERR_NOMEM;
    if (status != RT_OK) {
        rt_cancel_destroy(session->cancel);
        free(session->done);
        free(session->fresh);
        rt_image_release(&session->image);
        rt_scene_destroy(scene);
        free(session);
        return status;
    }
    *out = session;
    return RT_OK;
}

void view_session_destroy(view_session *session)
{
    if (session == NULL)
        return;
    view_session_cancel(session);
    pthread_mutex_destroy(&session->lock);
    rt_cancel_destroy(session->cancel);
    free(session->done);
    free(session->fresh);
    rt_image_release(&session->image);
    rt_scene_destroy(session->scene);
    free(session);
}

void view_session_request_cancel(view_session *session)
{
    rt_cancel_request(session->cancel);
}

void view_session_cancel(view_session *session)
{
    if (!session->worker_joinable)
        return;
    rt_cancel_request(session->cancel);
    pthread_join(session->worker, NULL);
    session->worker_joinable = 0;
}

rt_status view_session_start(view_session *session)
{
    view_session_cancel(session);
    session->camera = session->next_camera;  /* placeholder until r-prog */
    session->camera_given = session->next_camera_given;
    int height = session->image.height;
    memset(session->image.pixels, 0, session->image.stride * (size_t)height);

    pthread_mutex_lock(&session->lock);
    memset(session->done, 0, (size_t)height);
    memset(session->fresh, 0, (size_t)height);
    session->rows_done = 0;
    session->fresh_count = 0;
    session->generation++;
    session->state = VIEW_RENDERING;
    session->status = RT_OK;
    session->started = cli_clock_seconds();
    session->finished = session->started;
    pthread_mutex_unlock(&session->lock);
    rt_cancel_reset(session->cancel);
    atomic_store(&session->wake_pending, 0);

    if (pthread_create(&session->worker, NULL, worker_main, session) != 0) {
        pthread_mutex_lock(&session->lock);
        session->state = VIEW_FAILED;
        session->status = RT_ERR_NOMEM;
        pthread_mutex_unlock(&session->lock);
        return RT_ERR_NOMEM;
    }
    session->worker_joinable = 1;
    return RT_OK;
}

rt_status view_session_set_depth(view_session *session, int max_depth)
{
    if (max_depth < 0 || max_depth > VIEW_MAX_DEPTH)
        return RT_ERR_ARGUMENT;
    session->options.render.max_depth = max_depth;
    return RT_OK;
}

/* Placeholder until r-prog merges. */
rt_status view_session_set_camera(view_session *session,
                                  const rt_camera *camera)
{
    session->next_camera_given = camera != NULL;
    if (camera)
        session->next_camera = *camera;
    return RT_OK;
}

int view_session_take_finished_rows(view_session *session, int *rows,
                                    int capacity, unsigned *generation)
{
    int count = 0;
    atomic_store(&session->wake_pending, 0);
    pthread_mutex_lock(&session->lock);
    for (int row = 0; row < session->image.height && count < capacity &&
                      session->fresh_count > 0;
         row++) {
        if (session->fresh[row]) {
            session->fresh[row] = 0;
            session->fresh_count--;
            rows[count++] = row;
        }
    }
    if (generation)
        *generation = session->generation;
    pthread_mutex_unlock(&session->lock);
    return count;
}

int view_session_row_done(view_session *session, int row)
{
    if (row < 0 || row >= session->image.height)
        return 0;
    pthread_mutex_lock(&session->lock);
    int done = session->done[row];
    pthread_mutex_unlock(&session->lock);
    return done;
}

void view_session_get_progress(view_session *session,
                               view_progress *progress)
{
    pthread_mutex_lock(&session->lock);
    progress->state = session->state;
    progress->rows_done = session->rows_done;
    progress->rows_total = session->image.height;
    progress->max_depth = session->options.render.max_depth;
    progress->status = session->status;
    progress->generation = session->generation;
    double end = session->state == VIEW_RENDERING ? cli_clock_seconds()
                                                  : session->finished;
    progress->seconds = session->state == VIEW_IDLE
                            ? 0.0 : end - session->started;
    pthread_mutex_unlock(&session->lock);
}

const rt_image *view_session_image(const view_session *session)
{
    return &session->image;
}

const rt_scene *view_session_scene(const view_session *session)
{
    return session->scene;
}

void view_progress_describe(const view_progress *progress, char *buffer,
                            size_t size)
{
    int percent = progress->rows_total > 0
                      ? (int)(100.0 * progress->rows_done /
                              progress->rows_total)
                      : 0;
    switch (progress->state) {
    case VIEW_IDLE:
        snprintf(buffer, size, "not started");
        break;
    case VIEW_RENDERING:
        snprintf(buffer, size, "%d%% - %.1f s", percent, progress->seconds);
        break;
    case VIEW_DONE:
        snprintf(buffer, size, "done in %.2f s", progress->seconds);
        break;
    case VIEW_CANCELLED:
        snprintf(buffer, size, "cancelled at %d%% after %.1f s", percent,
                 progress->seconds);
        break;
    case VIEW_FAILED:
        snprintf(buffer, size, "failed: %s",
                 rt_status_string(progress->status));
        break;
    }
}
