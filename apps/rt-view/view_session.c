/*
 * view_session.c - a scene rendered by a worker thread, coarse to fine, for
 * the viewer (see view_session.h).  Each pass renders into the session's
 * work image (a coarse pass into a smaller view of the same pixels); the
 * library's row callback copies each finished row, or a coarse row's
 * blocks, into the image shown, under a mutex, and marks it new; the main
 * thread collects the new rows.  The library's cancellation flag, polled
 * before every pixel, stops a pass at once, and the worker then starts no
 * other.
 */
#include "view_session.h"

#include <inttypes.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "cli_clock.h"

struct view_session {
    rt_scene *scene;
    rt_image image;             /* shown; the worker writes it under `lock` */
    rt_image work;              /* where the passes render */
    rt_image kept;              /* the last finished picture, once a view
                                   was started over it; pixels NULL: none */
    view_session_options options; /* width and height resolved; depth of the
                                     next start */
    rt_camera scene_camera;
    rt_camera camera;           /* of the next start, when has_camera */
    int has_camera;
    int light_count;
    int region;                 /* the options have a region */
    int view, light;            /* of the next start */
    unsigned settings;          /* bumped when the depth or camera changes */

    /* The render started last: set by start before the worker runs, then
     * only read. */
    rt_render_options render;
    rt_camera render_camera;    /* the camera its passes start from */
    int render_view, render_light;
    unsigned render_settings;
    view_pass passes[VIEW_MAX_PASSES];
    int pass_count;

    /* What the image holds when no render runs (controlling thread, and
     * the worker before it ends). */
    int image_complete;         /* a render finished into it */
    int image_view;
    unsigned image_settings;
    double image_seconds;       /* what it took */
    int kept_valid;
    unsigned kept_settings;
    double kept_seconds;

    pthread_t worker;
    int worker_joinable;        /* controlling thread only */
    rt_cancel *cancel;          /* raised to stop the worker's render */
    atomic_int wake_pending;    /* notify sent, rows not yet taken */

    pthread_mutex_t lock;       /* guards everything below, and `image` */
    unsigned char *done;        /* per row: final */
    unsigned char *fresh;       /* per row: changed, not yet taken */
    int rows_done;              /* by the current pass */
    int rows_final;
    int fresh_count;
    int pass;                   /* under way */
    rt_image coarse;            /* the view of `work` a coarse pass fills */
    view_state state;
    rt_status status;
    unsigned generation;
    double started;             /* monotonic seconds */
    double took;                /* once ended: the render's time */
    double shown;               /* seconds to the first frame shown; < 0 */
    double pass_seconds[VIEW_MAX_PASSES];
    int passes_done;
    uint64_t rays;
    view_render_report report;  /* of the last render that ended */
};

static void notify(view_session *session)
{
    if (session->options.notify)
        session->options.notify(session->options.notify_user);
}

static void mark_fresh(view_session *session, int row)
{
    if (!session->fresh[row]) {
        session->fresh[row] = 1;
        session->fresh_count++;
    }
}

/* Coarse row `row` of the pass of `scale`: each pixel over its block of
 * the image (the blocks of the last row and column may be cut). */
static void copy_blocks(view_session *session, int row, int scale)
{
    rt_image *image = &session->image;
    int first = row * scale;
    int end = first + scale < image->height ? first + scale : image->height;
    unsigned char *out = rt_image_pixel(image, 0, first);
    const unsigned char *in = rt_image_pixel(&session->coarse, 0, row);
    for (int x = 0; x < image->width; x++)
        memcpy(out + 3 * (size_t)x, in + 3 * (size_t)(x / scale), 3);
    for (int y = first; y < end; y++) {
        if (y > first)
            memcpy(rt_image_pixel(image, 0, y), out,
                   3 * (size_t)image->width);
        mark_fresh(session, y);
    }
    session->rows_done += end - first;
}

/* The library's row callback: runs on rendering threads, serialised. */
static int on_row(void *user, int row)
{
    view_session *session = user;
    pthread_mutex_lock(&session->lock);
    const view_pass *pass = &session->passes[session->pass];
    if (pass->scale > 1) {
        if (row >= 0 && row < session->coarse.height)
            copy_blocks(session, row, pass->scale);
    } else if (row >= 0 && row < session->image.height) {
        memcpy(rt_image_pixel(&session->image, 0, row),
               rt_image_pixel(&session->work, 0, row),
               3 * (size_t)session->image.width);
        mark_fresh(session, row);
        session->rows_done++;
        if (session->pass == session->pass_count - 1 &&
            !session->done[row]) {
            session->done[row] = 1;
            session->rows_final++;
        }
    }
    pthread_mutex_unlock(&session->lock);
    if (!atomic_exchange(&session->wake_pending, 1))
        notify(session);
    return !rt_cancel_requested(session->cancel);
}

/* Renders pass `index` into the work image; its rays added to *rays. */
static rt_status render_pass(view_session *session, int index,
                             uint64_t *rays, rt_error *error)
{
    const view_pass *pass = &session->passes[index];
    rt_render_options options = session->render;
    rt_render_stats stats;
    memset(&stats, 0, sizeof stats);
    stats.size = sizeof stats;
    options.stats = &stats;
    options.on_row = on_row;
    options.user = session;
    options.cancel = session->cancel;
    options.samples = pass->samples;
    rt_camera coarse_camera;
    rt_image target = session->work;
    if (pass->scale > 1) {
        int w, h;
        view_pass_camera(&session->render_camera, session->render.width,
                         session->render.height, pass->scale, &coarse_camera,
                         &w, &h);
        options.camera = &coarse_camera;
        options.width = w;
        options.height = h;
        target = (rt_image){w, h, 3 * (size_t)w, session->work.pixels};
    }
    pthread_mutex_lock(&session->lock);
    session->pass = index;
    session->rows_done = 0;
    session->coarse = target;
    pthread_mutex_unlock(&session->lock);
    rt_status status =
        session->render_view
            ? rt_render_view(session->scene, &options,
                             (rt_debug_view)session->render_view,
                             session->render_light, &target, error)
            : rt_render_rows(session->scene, &options, 0, target.height,
                             &target, error);
    *rays += rt_render_stats_rays(&stats);
    return status;
}

/* The report of the render ending now (with the lock held). */
static void fill_report(view_session *session, view_render_report *report)
{
    memset(report, 0, sizeof *report);
    report->generation = session->generation;
    report->view = session->render_view;
    report->light = session->render_light;
    report->state = session->state;
    report->status = session->status;
    report->pass_count = session->pass_count;
    memcpy(report->passes, session->passes, sizeof report->passes);
    report->passes_done = session->passes_done;
    report->rows_reached = session->rows_done;
    report->rows_total = session->image.height;
    memcpy(report->pass_seconds, session->pass_seconds,
           sizeof report->pass_seconds);
    report->seconds = session->took;
    report->shown_seconds = session->shown;
    report->rays = session->rays;
}

static void print_report(view_session *session,
                         const view_render_report *report)
{
    if (session->options.stats == NULL)
        return;
    char line[1024];
    view_render_report_describe(report, line, sizeof line);
    fprintf(session->options.stats, "rt-view: %s\n", line);
    fflush(session->options.stats);
}

static void *worker_main(void *arg)
{
    view_session *session = arg;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = RT_OK;
    uint64_t rays = 0;
    for (int index = 0; index < session->pass_count && status == RT_OK;
         index++) {
        if (rt_cancel_requested(session->cancel)) {
            pthread_mutex_lock(&session->lock);
            session->pass = index;      /* stopped before it began */
            session->rows_done = 0;
            pthread_mutex_unlock(&session->lock);
            status = RT_ERR_CANCELLED;
            break;
        }
        status = render_pass(session, index, &rays, &error);
        pthread_mutex_lock(&session->lock);
        session->rays = rays;
        if (status == RT_OK) {
            session->passes_done = index + 1;
            session->pass_seconds[index] =
                cli_clock_seconds() - session->started;
        }
        pthread_mutex_unlock(&session->lock);
    }

    pthread_mutex_lock(&session->lock);
    session->status = status;
    session->took = cli_clock_seconds() - session->started;
    if (status == RT_OK)
        session->state = VIEW_DONE;
    else if (status == RT_ERR_CANCELLED)
        session->state = VIEW_CANCELLED;
    else
        session->state = VIEW_FAILED;
    session->image_complete = status == RT_OK;
    session->image_view = session->render_view;
    session->image_settings = session->render_settings;
    session->image_seconds = session->took;
    fill_report(session, &session->report);
    if (status != RT_OK && status != RT_ERR_CANCELLED)
        snprintf(session->report.error, sizeof session->report.error, "%s",
                 error.message[0] ? error.message
                                  : rt_status_string(status));
    view_render_report report = session->report;
    pthread_mutex_unlock(&session->lock);
    print_report(session, &report);
    notify(session);
    return NULL;
}

void view_session_options_init(view_session_options *options)
{
    memset(options, 0, sizeof *options);
    rt_render_options_init(&options->render);
}

static rt_status refuse(rt_error *error, const char *message)
{
    if (error) {
        memset(error, 0, sizeof *error);
        error->status = RT_ERR_ARGUMENT;
        snprintf(error->message, sizeof error->message, "%s", message);
    }
    return RT_ERR_ARGUMENT;
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
    rt_render_options render = options->render;
    render.on_row = NULL;
    render.user = NULL;
    render.cancel = NULL;
    render.stats = NULL;
    render.camera = NULL;
    /* The whole image's size, then the size of what is shown (the
     * region's when one is set). */
    rt_render_options whole = render;
    whole.region = (rt_region){0, 0, 0, 0};
    int width, height;
    rt_status status = rt_render_image_size(scene, &whole, &render.width,
                                            &render.height, error);
    if (status == RT_OK)
        status = rt_render_image_size(scene, &render, &width, &height,
                                      error);
    if (status == RT_OK && (render.max_depth < 0 ||
                            render.max_depth > VIEW_MAX_DEPTH ||
                            render.threads < 0))
        status = refuse(error, "depth or threads out of range");
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
    session->options.render = render;
    session->region = render.region.x0 != 0 || render.region.y0 != 0 ||
                      render.region.x1 != 0 || render.region.y1 != 0;
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    session->scene_camera = info.camera;
    session->light_count = info.light_count;
    session->state = VIEW_IDLE;
    session->status = RT_OK;
    session->shown = -1;
    atomic_init(&session->wake_pending, 0);

    status = rt_cancel_create(&session->cancel, NULL);
    if (status == RT_OK)
        status = rt_image_init(&session->image, width, height, NULL);
    if (status == RT_OK)
        status = rt_image_init(&session->work, width, height, NULL);
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
        rt_image_release(&session->work);
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
    rt_image_release(&session->work);
    rt_image_release(&session->kept);
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

static size_t image_bytes(const rt_image *image)
{
    return image->stride * (size_t)image->height;
}

/* Before a debug view is rendered over the finished picture: a copy of it
 * to show again (the copy made once, then reused). */
static void keep_picture(view_session *session)
{
    if (!session->image_complete || session->image_view != 0 ||
        session->image_settings != session->settings)
        return;
    if (session->kept.pixels == NULL &&
        rt_image_init(&session->kept, session->image.width,
                      session->image.height, NULL) != RT_OK)
        return;     /* no copy: the picture will be rendered again */
    memcpy(session->kept.pixels, session->image.pixels,
           image_bytes(&session->image));
    session->kept_valid = 1;
    session->kept_settings = session->settings;
    session->kept_seconds = session->image_seconds;
}

/* Shows the finished picture of the current settings again, if there is
 * one (in the image, or kept): every row final and new.  1 when it did. */
static int show_kept_picture(view_session *session)
{
    int in_image = session->image_complete && session->image_view == 0 &&
                   session->image_settings == session->settings;
    int kept = session->kept_valid &&
               session->kept_settings == session->settings;
    if (session->view != 0 || (!in_image && !kept))
        return 0;
    double seconds = in_image ? session->image_seconds
                              : session->kept_seconds;
    if (!in_image)
        memcpy(session->image.pixels, session->kept.pixels,
               image_bytes(&session->image));
    int height = session->image.height;
    pthread_mutex_lock(&session->lock);
    memset(session->done, 1, (size_t)height);
    memset(session->fresh, 1, (size_t)height);
    session->rows_done = height;
    session->rows_final = height;
    session->fresh_count = height;
    session->generation++;
    session->render = session->options.render;
    session->render_view = 0;
    session->render_light = 0;
    session->render_settings = session->settings;
    session->pass_count = 0;
    session->pass = 0;
    session->passes_done = 0;
    session->rays = 0;
    session->state = VIEW_DONE;
    session->status = RT_OK;
    session->started = cli_clock_seconds();
    session->took = seconds;
    session->shown = -1;
    fill_report(session, &session->report);
    session->report.kept = 1;
    view_render_report report = session->report;
    pthread_mutex_unlock(&session->lock);
    session->image_complete = 1;
    session->image_view = 0;
    session->image_settings = session->settings;
    session->image_seconds = seconds;
    print_report(session, &report);
    return 1;
}

rt_status view_session_start(view_session *session)
{
    view_session_cancel(session);
    if (session->view != 0)
        keep_picture(session);
    if (show_kept_picture(session))
        return RT_OK;
    session->image_complete = 0;
    int height = session->image.height;

    pthread_mutex_lock(&session->lock);
    memset(session->done, 0, (size_t)height);
    memset(session->fresh, 0, (size_t)height);
    session->rows_done = 0;
    session->rows_final = 0;
    session->fresh_count = 0;
    session->generation++;
    session->render = session->options.render;
    session->render_camera = session->has_camera ? session->camera
                                                 : session->scene_camera;
    session->render.camera = session->has_camera ? &session->render_camera
                                                 : NULL;
    session->render_view = session->view;
    session->render_light = session->light;
    session->render_settings = session->settings;
    session->pass_count = view_session_plan(
        session->image.width, height, session->region,
        session->render.samples, session->view, session->passes);
    session->pass = 0;
    session->passes_done = 0;
    session->rays = 0;
    memset(session->pass_seconds, 0, sizeof session->pass_seconds);
    session->state = VIEW_RENDERING;
    session->status = RT_OK;
    session->started = cli_clock_seconds();
    session->took = 0;
    session->shown = -1;
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
    if (max_depth != session->options.render.max_depth) {
        session->options.render.max_depth = max_depth;
        session->settings++;
    }
    return RT_OK;
}

rt_status view_session_set_camera(view_session *session,
                                  const rt_camera *camera)
{
    session->has_camera = camera != NULL;
    if (camera)
        session->camera = *camera;
    session->settings++;
    return RT_OK;
}

rt_status view_session_set_view(view_session *session, int view, int light)
{
    if (view < 0 || view > RT_VIEW_SHADING_NORMAL)
        return RT_ERR_ARGUMENT;
    int per_light = view == RT_VIEW_SHADOW || view == RT_VIEW_NS;
    if (per_light && (light < 0 || light >= session->light_count))
        return RT_ERR_ARGUMENT;
    session->view = view;
    session->light = per_light ? light : 0;
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

int view_session_copy_rows(view_session *session, int first, int count,
                           unsigned char *out, size_t stride)
{
    const rt_image *image = &session->image;
    if (first < 0 || count < 0 || first > image->height - count)
        return 0;
    size_t bytes = 3 * (size_t)image->width;
    pthread_mutex_lock(&session->lock);
    for (int k = 0; k < count; k++)
        memcpy(out + (size_t)k * stride, rt_image_pixel(image, 0, first + k),
               bytes);
    pthread_mutex_unlock(&session->lock);
    return 1;
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
    memset(progress, 0, sizeof *progress);
    pthread_mutex_lock(&session->lock);
    progress->state = session->state;
    progress->rows_done = session->rows_done;
    progress->rows_total = session->image.height;
    progress->max_depth = session->generation > 0
                              ? session->render.max_depth
                              : session->options.render.max_depth;
    progress->status = session->status;
    progress->generation = session->generation;
    progress->seconds =
        session->state == VIEW_IDLE ? 0.0
        : session->state == VIEW_RENDERING
            ? cli_clock_seconds() - session->started
            : session->took;
    progress->pass = session->pass;
    progress->pass_count = session->pass_count;
    memcpy(progress->passes, session->passes, sizeof progress->passes);
    progress->rows_final = session->rows_final;
    progress->view = session->render_view;
    progress->light = session->render_light;
    pthread_mutex_unlock(&session->lock);
}

void view_session_note_shown(view_session *session, unsigned generation)
{
    pthread_mutex_lock(&session->lock);
    if (generation == session->generation && session->shown < 0 &&
        session->state != VIEW_IDLE)
        session->shown = cli_clock_seconds() - session->started;
    if (generation == session->report.generation &&
        session->report.shown_seconds < 0)
        session->report.shown_seconds = session->shown;
    pthread_mutex_unlock(&session->lock);
}

void view_session_last_report(view_session *session,
                              view_render_report *report)
{
    pthread_mutex_lock(&session->lock);
    *report = session->report;
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
