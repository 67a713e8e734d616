/*
 * reader.c - what every scene reader shares (reader.h): the end of every
 * read (the options' view and lights applied, the scene built, a refusal
 * of the builder mapped to the token the reader kept for it), and the poll
 * of a load's cancellation flag.
 */
#include "formats/reader.h"

#include <math.h>

#include "base/error.h"
#include "base/vecmath.h"
#include "formats/framing.h"
#include "raytrace/render.h"

rt_status rt__parse_arguments(const char *text, size_t length,
                              const char *name, rt_scene **scene,
                              rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected a pointer to fill with the scene");
    *scene = NULL;
    if (text == NULL && length > 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected scene text");
    return RT_OK;
}

int rt__load_cancelled(const rt_load_options *options)
{
    return options != NULL && options->cancel != NULL &&
           rt_cancel_requested(options->cancel);
}

rt_status rt__load_cancel(rt_error *error, const char *name)
{
    return rt__error_set(error, RT_ERR_CANCELLED, name ? name : "<memory>",
                         0, 0, "the load was cancelled");
}

#define PI 3.14159265358979323846

/*
 * The view of `options` applied to the camera of `d`: what is not given
 * keeps the file's value (observer O, look-at A, horizontal field of view
 * 2 atan(|AB| / |AO|); up: the file's AC, or, when the direction of view
 * changes, the coordinate axis nearest to it).  Returns NULL, or what is
 * wrong.
 */
static const char *apply_view(rt_scene_desc *d, const rt_load_options *o)
{
    rt_vec3 from = d->observer, at = d->screen_center;
    rt_vec3 ao = v3_sub(d->observer, d->screen_center);
    rt_vec3 ab = v3_sub(d->screen_right, d->screen_center);
    rt_vec3 up = v3_cross(ao, ab);
    double fov = 2 * atan(v3_length(ab) / v3_length(ao)) * 180 / PI;
    if (o->look_from_given)
        from = o->look_from;
    if (o->look_at_given)
        at = o->look_at;
    if (o->up_given) {
        up = o->up;
    } else if (o->look_from_given || o->look_at_given) {
        /* A new direction of view: the file's up leans with the file's
         * view, so take the axis nearest to it (the scene's vertical,
         * for a camera that looked down at it). */
        rt_vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        rt_vec3 unit = v3_normalize(up), best = axes[2];
        double best_dot = 0;
        for (int i = 0; i < 3; i++) {
            double along = v3_dot(unit, axes[i]);
            if (fabs(along) > fabs(best_dot)) {
                best_dot = along;
                best = axes[i];
            }
        }
        up = best_dot < 0 ? v3_scale(best, -1) : best;
    }
    if (o->fov_given)
        fov = o->fov;
    rt_view view = {from, at, up, fov, d->width, 0};
    switch (rt__frame_view(&view, &d->observer, &d->screen_center,
                           &d->screen_right)) {
    case RT_FRAME_OK:
        return NULL;
    case RT_FRAME_FOV:
        return "the field of view is not in (0, 180) degrees";
    case RT_FRAME_SAME_POINT:
        return "the look-from point is the look-at point";
    case RT_FRAME_UP_ALONG_VIEW:
        return "the up direction is along the view";
    }
    return NULL;
}

/* Whether the options replace the file's camera. */
static int replaces_view(const rt_load_options *options)
{
    return options != NULL &&
           (options->look_from_given || options->look_at_given ||
            options->up_given || options->fov_given);
}

static int replaces_lights(const rt_load_options *options)
{
    return options != NULL && options->light_count > 0;
}

/* Whether the item a refusal names came from `options`, not the file:
 * the reader kept no token for it. */
static int from_options(const rt_refusal *refusal,
                        const rt_load_options *options)
{
    return (refusal->item == RT_ITEM_CAMERA && replaces_view(options)) ||
           (refusal->item == RT_ITEM_LIGHT && replaces_lights(options));
}

/* A refusal of an item of the file, at the token the reader kept for it
 * (when it kept one); `status` and *error otherwise stand. */
static rt_status report(const rt_reading *reading, rt_status status,
                        const rt_refusal *refusal, rt_error *error)
{
    rt_token token;
    if (refusal->status == RT_OK || reading->locate == NULL ||
        !reading->locate(reading->user, refusal, &token))
        return status;
    if (refusal->found[0] != '\0')
        return rt__error_set(error, status, reading->name, token.line,
                             token.column, "expected %s, found %s",
                             refusal->expected, refusal->found);
    return rt__token_refuse(error, status, reading->name, &token, "%s",
                            refusal->expected);
}

rt_status rt__reader_finish(rt_scene_desc *desc, const rt_reading *reading,
                            rt_scene **scene, rt_error *error)
{
    const char *name = reading->name;
    const rt_load_options *options = reading->options;
    rt_refusal refusal;
    rt_status status;
    /* The file's own description is judged first, as the options take
     * its place only once it is read: its errors are named in it. */
    if ((replaces_view(options) || replaces_lights(options)) &&
        (status = rt__scene_check(desc, name, error, &refusal)) != RT_OK)
        return report(reading, status, &refusal, error);
    if (replaces_view(options)) {
        const char *wrong = apply_view(desc, options);
        if (wrong != NULL)
            return rt__error_set(error, RT_ERR_CAMERA, name, 0, 0,
                                 "expected a view, found that %s", wrong);
    }
    if (replaces_lights(options)) {
        desc->lights = options->lights;
        desc->light_count = options->light_count;
    }
    rt_scene_release release = {reading->release, reading->release_user};
    status = rt__scene_build_releasing(
        desc, name, reading->facet_lines, reading->notes,
        options != NULL ? options->cancel : NULL, &release, scene, error,
        &refusal);
    if (status == RT_OK || from_options(&refusal, options))
        return status;
    return report(reading, status, &refusal, error);
}
