/*
 * precision.c - whether a scene can be rendered in a precision
 * (rt_scene_check_precision, raytrace/render.h): double holds every scene
 * the loader accepts; float refuses coordinates it cannot hold or resolve
 * (docs/accuracy.md, "Float's rule").  A question about the scene's
 * numbers, answered before any float kernel is built.
 */
#include <float.h>
#include <math.h>

#include "base/error.h"
#include "base/vecmath.h"
#include "scene_internal.h"

rt_status rt__precision_check(rt_precision precision, rt_error *error)
{
    if (precision != RT_PRECISION_DOUBLE && precision != RT_PRECISION_FLOAT)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a precision of %d: expected RT_PRECISION_DOUBLE "
                             "or RT_PRECISION_FLOAT", (int)precision);
    return RT_OK;
}

rt_status rt_scene_check_precision(const rt_scene *scene,
                                   rt_precision precision, rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a scene");
    return rt__scene_check_precision_with(scene, &scene->camera, precision,
                                          error);
}

rt_status rt__scene_check_precision_with(const rt_scene *scene,
                                         const rt_camera *c,
                                         rt_precision precision,
                                         rt_error *error)
{
    rt_status status = rt__precision_check(precision, error);
    if (status != RT_OK || precision == RT_PRECISION_DOUBLE)
        return status;
    double largest = fmax(v3_max_abs(c->observer),
                          v3_max_abs(v3_add(c->screen_center,
                                            v3_add(v3_abs(c->right),
                                                   v3_abs(c->up)))));
    double lights = 0;
    for (int i = 0; i < scene->light_count; i++)
        lights = fmax(lights, v3_max_abs(scene->lights[i].position));
    rt_vec3 low = {INFINITY, INFINITY, INFINITY}, high = v3_scale(low, -1);
    for (int i = 0; i < scene->vertex_count; i++) {
        rt_vec3 v = scene->vertices[i];
        largest = fmax(largest, v3_max_abs(v));
        low = v3(fmin(low.x, v.x), fmin(low.y, v.y), fmin(low.z, v.z));
        high = v3(fmax(high.x, v.x), fmax(high.y, v.y), fmax(high.z, v.z));
    }
    if (!(fmax(largest, lights) < FLT_MAX))
        return rt__error_set(error, RT_ERR_RANGE, scene->name, 0, 0,
                             "a float render cannot hold coordinates of "
                             "%g (float ends at %g): render in double",
                             fmax(largest, lights), (double)FLT_MAX);
    if (largest > RT_FLOAT_MAX_COORDINATE)
        return rt__error_set(error, RT_ERR_RANGE, scene->name, 0, 0,
                             "a float render cannot hold vertex or camera "
                             "coordinates of %g: its intersection test "
                             "overflows beyond %g: render in double",
                             largest, RT_FLOAT_MAX_COORDINATE);
    double extent = scene->vertex_count > 1 ? v3_max_abs(v3_sub(high, low))
                                            : 0;
    if (extent > 0 && largest > RT_FLOAT_SPREAD_MAX * extent)
        return rt__error_set(error, RT_ERR_RANGE, scene->name, 0, 0,
                             "a float render cannot resolve this scene: its "
                             "coordinates reach %g while its vertices span "
                             "%g, more than %d times less (float keeps 24 "
                             "bits: its steps at %g are %g, too coarse for "
                             "the scene): render in double",
                             largest, extent, (int)RT_FLOAT_SPREAD_MAX,
                             largest, largest * FLT_EPSILON);
    return RT_OK;
}
