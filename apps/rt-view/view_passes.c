/*
 * view_passes.c - what the session's renders are made of, without a
 * session (see view_session.h): the plan of passes coarse to fine, the
 * camera of a coarse pass, and the words the title and --stats use for
 * passes, progress and a render's report.
 */
#include "view_session.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>

static const char *const view_names[] = {
    "picture", "normal view", "depth view", "facet view", "shadow view",
    "bounces view", "N.S view", "shading normal view",
};

const char *view_session_view_name(int view)
{
    return view >= 0 && view <= RT_VIEW_SHADING_NORMAL ? view_names[view]
                                                       : "";
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
