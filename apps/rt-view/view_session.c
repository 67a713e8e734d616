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

static const char *const view_names[] = {
    "picture", "normal view", "depth view", "facet view", "shadow view",
    "bounces view", "N.S view", "shading normal view",
};

const char *view_session_view_name(int view)
{
    return view >= 0 && view <= RT_VIEW_SHADING_NORMAL ? view_names[view]
                                                       : "";
}

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

void view_pass_camera(const rt_camera *camera, int width, int height,
                      int scale, rt_camera *coarse, int *coarse_width,
                      int *coarse_height)
{
    int w = (width + scale - 1) / scale;
    int h = (height + scale - 1) / scale;
    /* Pixel (i, j) at ((i + 1/2) s, (j + 1/2) s) of the full image: the
     * screen k times as wide and high (k = w s / W, pixels s times as
     * large), its centre moved by (k - 1) AB and (H - h s)/W AC. */
    double k = (double)w * scale / width;
    double down = (double)(height - h * scale) / width;
    const rt_vec3 ab = camera->right, ac = camera->up, a = camera->screen_center;
    *coarse = *camera;
    coarse->right = (rt_vec3){k * ab.x, k * ab.y, k * ab.z};
    coarse->up = (rt_vec3){k * ac.x, k * ac.y, k * ac.z};
    coarse->screen_center = (rt_vec3){a.x + (k - 1) * ab.x + down * ac.x,
                                      a.y + (k - 1) * ab.y + down * ac.y,
                                      a.z + (k - 1) * ab.z + down * ac.z};
    coarse->width = w;
    coarse->height = h;
    *coarse_width = w;
    *coarse_height = h;
}

int view_session_plan(int width, int height, int region, int samples,
                      int view, view_pass passes[VIEW_MAX_PASSES])
{
    int count = 0;
    if (samples < 1)
        samples = 1;
    if (!region && (long long)width * height >= VIEW_COARSE_MIN_PIXELS)
        for (int scale = 8; scale >= 2; scale /= 2)
            if ((width + scale - 1) / scale >= VIEW_COARSE_MIN_SIDE &&
                (height + scale - 1) / scale >= VIEW_COARSE_MIN_SIDE)
                passes[count++] = (view_pass){scale, 1};
    if (view == 0 && samples > 1)
        passes[count++] = (view_pass){1, 1};
    passes[count++] = (view_pass){1, samples};
    return count;
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

const char *view_pass_name(const view_pass *passes, int index, char *buffer,
                           size_t size)
{
    const view_pass *pass = &passes[index];
    if (pass->scale > 1)
        snprintf(buffer, size, "1/%d", pass->scale);
    else if (index > 0 && passes[index - 1].scale == 1)
        snprintf(buffer, size, "%d samples", pass->samples);
    else
        snprintf(buffer, size, "full");
    return buffer;
}

void view_progress_describe(const view_progress *progress, char *buffer,
                            size_t size)
{
    int percent = progress->rows_total > 0
                      ? (int)(100.0 * progress->rows_done /
                              progress->rows_total)
                      : 0;
    char pass[32] = "";
    if (progress->pass_count > 1 && progress->pass >= 0 &&
        progress->pass < progress->pass_count)
        view_pass_name(progress->passes, progress->pass, pass, sizeof pass);
    switch (progress->state) {
    case VIEW_IDLE:
        snprintf(buffer, size, "not started");
        break;
    case VIEW_RENDERING:
        snprintf(buffer, size, "%s%s%d%% - %.1f s", pass, pass[0] ? ": " : "",
                 percent, progress->seconds);
        break;
    case VIEW_DONE:
        snprintf(buffer, size, "done in %.2f s", progress->seconds);
        break;
    case VIEW_CANCELLED:
        snprintf(buffer, size, "cancelled at %d%%%s%s after %.1f s", percent,
                 pass[0] ? " of " : "", pass, progress->seconds);
        break;
    case VIEW_FAILED:
        snprintf(buffer, size, "failed: %s",
                 rt_status_string(progress->status));
        break;
    }
}

/* "6 ms", "0.4 ms", "1.84 s" */
static const char *describe_seconds(double seconds, char *buffer,
                                    size_t size)
{
    if (seconds < 0.01)
        snprintf(buffer, size, "%.1f ms", seconds * 1e3);
    else if (seconds < 1.0)
        snprintf(buffer, size, "%.0f ms", seconds * 1e3);
    else
        snprintf(buffer, size, "%.2f s", seconds);
    return buffer;
}

/* Appends to buffer (of `size`, holding `*used` characters). */
static void append(char *buffer, size_t size, size_t *used,
                   const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static void append(char *buffer, size_t size, size_t *used,
                   const char *format, ...)
{
    if (*used >= size)
        return;
    va_list arguments;
    va_start(arguments, format);
    int written = vsnprintf(buffer + *used, size - *used, format, arguments);
    va_end(arguments);
    if (written > 0)
        *used += (size_t)written;
}

void view_render_report_describe(const view_render_report *report,
                                 char *buffer, size_t size)
{
    size_t used = 0;
    char name[32], time[32];
    buffer[0] = '\0';
    append(buffer, size, &used, "render %u (%s", report->generation,
           view_session_view_name(report->view));
    if (report->view == RT_VIEW_SHADOW || report->view == RT_VIEW_NS)
        append(buffer, size, &used, " of light %d", report->light);
    append(buffer, size, &used, "): ");
    if (report->kept) {
        append(buffer, size, &used,
               "the picture finished before, shown again at once");
        return;
    }
    int done = report->passes_done;
    if (report->state != VIEW_DONE && done < report->pass_count) {
        view_pass_name(report->passes, done, name, sizeof name);
        append(buffer, size, &used, "%s in %s (%d of %d rows) after %s",
               report->state == VIEW_CANCELLED ? "cancelled" : "failed",
               name, report->rows_reached, report->rows_total,
               describe_seconds(report->seconds, time, sizeof time));
        if (report->error[0])
            append(buffer, size, &used, ": %s", report->error);
        if (done > 0)
            append(buffer, size, &used, "; ");
    }
    for (int i = 0; i < done; i++)
        append(buffer, size, &used, "%s%s in %s", i ? ", " : "",
               view_pass_name(report->passes, i, name, sizeof name),
               describe_seconds(report->pass_seconds[i], time, sizeof time));
    if (report->shown_seconds >= 0)
        append(buffer, size, &used, "; first shown at %s",
               describe_seconds(report->shown_seconds, time, sizeof time));
    if (report->rays < 100000)
        append(buffer, size, &used, "; %" PRIu64 " rays", report->rays);
    else
        append(buffer, size, &used, "; %.2f M rays", report->rays / 1e6);
}
