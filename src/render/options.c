/*
 * options.c - a render's options (raytrace/render.h): their defaults, how
 * a render takes the caller's struct (as far as its size reaches), the
 * image size they give and the check of every field, so that a bad value
 * is refused with a message naming it before any work starts.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "base/error.h"
#include "base/sized.h"
#include "base/vecmath.h"
#include "render_internal.h"
#include "scene/scene_internal.h"

void rt_render_options_init(rt_render_options *options)
{
    if (options == NULL)
        return;
    memset(options, 0, sizeof *options);
    options->size = sizeof *options;
    options->max_depth = RT_DEFAULT_DEPTH;
    options->threads = 0;
    options->precision = RT_PRECISION_DOUBLE;
    options->samples = 1;
    options->sampling = RT_SAMPLING_REGULAR;
    options->accel = RT_ACCEL_AUTO;
    options->aperture = -1.0;           /* the scene's */
    options->focal_distance = 0.0;      /* the scene's */
}

/*
 * Copies the caller's options into *out, field by field, as far as the
 * caller's size reaches; the fields beyond keep their defaults (the rule of
 * raytrace/render.h for growing option structs).  NULL: the defaults.
 */
static rt_status take_options(const rt_render_options *in,
                              rt_render_options *out, rt_error *error)
{
    rt_render_options_init(out);
    if (in == NULL)
        return RT_OK;
    rt_status status = rt__options_size_check(in->size, sizeof *out,
                                              "render", NULL, error);
    if (status != RT_OK)
        return status;
#define TAKE(field) RT__TAKE_FIELD(rt_render_options, in, out, field)
    TAKE(max_depth) TAKE(threads) TAKE(precision) TAKE(fast_inv_sqrt)
    TAKE(samples) TAKE(sampling) TAKE(on_row) TAKE(cancel) TAKE(user)
    TAKE(stats) TAKE(kernel) TAKE(accel) TAKE(aperture) TAKE(focal_distance)
    TAKE(width) TAKE(height) TAKE(region) TAKE(camera) TAKE(linear)
#undef TAKE
    return RT_OK;
}

/* The checks of rt_render_image_size; fills the whole image's size too. */
static rt_status image_size(const rt_scene *scene,
                            const rt_render_options *options, int *full_width,
                            int *full_height, int *width, int *height,
                            rt_error *error)
{
    *width = *height = *full_width = *full_height = 0;
    if (scene == NULL || options == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene or no render options");
    const rt_camera *camera =
        options->camera != NULL ? options->camera : &scene->camera;
    int w = options->width != 0 ? options->width : camera->width;
    int h = options->height != 0 ? options->height : camera->height;
    if (w < 1 || w > RT_MAX_IMAGE_SIDE || h < 1 || h > RT_MAX_IMAGE_SIDE)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "an image of %d x %d pixels: each side must be "
                             "in 1..%d", w, h, RT_MAX_IMAGE_SIDE);
    *full_width = w;
    *full_height = h;
    rt_region r = options->region;
    if (r.x0 == 0 && r.y0 == 0 && r.x1 == 0 && r.y1 == 0) {
        *width = w;
        *height = h;
        return RT_OK;
    }
    if (r.x0 < 0 || r.y0 < 0 || r.x1 > w || r.y1 > h || r.x0 >= r.x1 ||
        r.y0 >= r.y1)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the region %d,%d,%d,%d is %s of the %d x %d "
                             "image (columns x0 <= x < x1, rows y0 <= y < "
                             "y1)", r.x0, r.y0, r.x1, r.y1,
                             r.x0 >= r.x1 || r.y0 >= r.y1 ? "an empty part"
                                                          : "not inside",
                             w, h);
    *width = r.x1 - r.x0;
    *height = r.y1 - r.y0;
    return RT_OK;
}

rt_status rt_render_image_size(const rt_scene *scene,
                               const rt_render_options *options, int *width,
                               int *height, rt_error *error)
{
    rt_render_options taken;
    int full_width, full_height;
    if (width == NULL || height == NULL) {
        if (width != NULL)
            *width = 0;
        if (height != NULL)
            *height = 0;
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a width and a height to fill");
    }
    *width = *height = 0;
    rt_status status = take_options(options, &taken, error);
    if (status != RT_OK)
        return status;
    return image_size(scene, &taken, &full_width, &full_height, width,
                      height, error);
}

rt_status rt__render_out_of_memory(rt_error *error)
{
    return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                         "out of memory while preparing or running the "
                         "render");
}

/* The checks of the options alone: every field in its domain (the image
 * size and region are image_size's, the samples sample_grid's). */
static rt_status check_options(const rt_render_options *options,
                               rt_error *error)
{
    if (options->max_depth < 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a depth of %d: expected 0 or more",
                             options->max_depth);
    if (options->threads < 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "%d threads: expected 0 (one per core) or more",
                             options->threads);
    rt_status status = rt__precision_check(options->precision, error);
    if (status != RT_OK)
        return status;
    if (options->sampling != RT_SAMPLING_REGULAR &&
        options->sampling != RT_SAMPLING_STRATIFIED)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a sampling of %d: expected RT_SAMPLING_REGULAR "
                             "or RT_SAMPLING_STRATIFIED",
                             (int)options->sampling);
    if (options->kernel != RT_KERNEL_AUTO &&
        options->kernel != RT_KERNEL_SCALAR)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a kernel of %d: expected RT_KERNEL_AUTO or "
                             "RT_KERNEL_SCALAR", (int)options->kernel);
    if (options->accel != RT_ACCEL_AUTO && options->accel != RT_ACCEL_NONE &&
        options->accel != RT_ACCEL_OCTREE &&
        options->accel != RT_ACCEL_KDTREE)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "an accel of %d: expected RT_ACCEL_AUTO, "
                             "RT_ACCEL_NONE, RT_ACCEL_OCTREE or "
                             "RT_ACCEL_KDTREE",
                             (int)options->accel);
    if (!isfinite(options->aperture))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "an aperture of %g: expected a finite lens "
                             "radius >= 0 (negative: the scene's)",
                             options->aperture);
    if (!(options->focal_distance >= 0.0) ||
        !isfinite(options->focal_distance))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a focal distance of %g: expected a finite "
                             "distance > 0 (0: the scene's)",
                             options->focal_distance);
    if (options->stats != NULL &&
        options->stats->size < RT__RENDER_STATS_SIZE_0_3)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "render stats of %zu bytes: expected %zu or "
                             "more (sizeof(rt_render_stats))",
                             options->stats->size,
                             (size_t)RT__RENDER_STATS_SIZE_0_3);
    return RT_OK;
}

/* The number of samples per side for `samples`, or 0 when it is not a
 * square in 1..1024 (with the message in *error). */
static int sample_grid(int samples, rt_error *error)
{
    int grid = 1;
    while (grid * grid < samples && grid < 32)
        grid++;
    if (grid * grid != samples) {
        rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                      "%d samples per pixel: expected a square n x n in "
                      "1..1024 (1, 4, 9, ...)", samples);
        return 0;
    }
    return grid;
}

rt_status rt__render_take(const rt_scene *scene,
                          const rt_render_options *options,
                          rt_render_plan *plan, rt_error *error)
{
    rt_status status = take_options(options, &plan->options, error);
    if (status != RT_OK)
        return status;
    /* The camera is copied: the caller's need only live through the
     * call's checks, and the frame reads the plan's. */
    plan->camera = plan->options.camera != NULL ? *plan->options.camera
                                                : scene->camera;
    plan->options.camera = &plan->camera;
    return image_size(scene, &plan->options, &plan->full_width,
                      &plan->full_height, &plan->width, &plan->height,
                      error);
}

/* A caller's camera: finite, with a screen (AB, AC non-zero) that the
 * observer is not on. */
static rt_status check_camera(const rt_camera *c, rt_error *error)
{
    rt_vec3 v[4] = {c->observer, c->screen_center, c->right, c->up};
    for (int i = 0; i < 4; i++)
        if (!isfinite(v[i].x) || !isfinite(v[i].y) || !isfinite(v[i].z))
            return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                                 "the render's camera has a coordinate that "
                                 "is not finite");
    if (v3_max_abs(c->right) == 0.0 || v3_max_abs(c->up) == 0.0 ||
        v3_max_abs(v3_sub(c->observer, c->screen_center)) == 0.0)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the render's camera is degenerate: expected "
                             "AB and AC non-zero and O off the screen "
                             "(see rt_scene_look)");
    if (!(c->aperture >= 0.0) || !isfinite(c->aperture) ||
        !(c->focal_distance > 0.0) || !isfinite(c->focal_distance))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the render's camera has a lens of aperture "
                             "%g and focus %g: expected a >= 0 and f > 0",
                             c->aperture, c->focal_distance);
    return RT_OK;
}

rt_status rt__render_check(rt_render_plan *plan, rt_error *error)
{
    rt_status status = check_camera(&plan->camera, error);
    if (status != RT_OK)
        return status;
    status = check_options(&plan->options, error);
    if (status != RT_OK)
        return status;
    plan->grid = sample_grid(plan->options.samples, error);
    return plan->grid == 0 ? RT_ERR_ARGUMENT : RT_OK;
}
