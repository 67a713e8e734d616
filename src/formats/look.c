/*
 * look.c - another view of a loaded scene (rt_scene_look, raytrace/scene.h):
 * the camera the loader would have built with the four view options, by
 * the same framing (framing.h) and the same camera builder, so that a
 * viewer's camera and rt-export's --look-from, --look-at, --up and --fov
 * give the same rays bit for bit.
 */
#include <math.h>

#include "base/error.h"
#include "base/vecmath.h"
#include "formats/framing.h"
#include "scene/scene_internal.h"

#define PI 3.14159265358979323846

static int finite_point(rt_vec3 p)
{
    return isfinite(p.x) && isfinite(p.y) && isfinite(p.z);
}

static int within_range(rt_vec3 p)
{
    return fabs(p.x) <= RT_MAX_COORDINATE && fabs(p.y) <= RT_MAX_COORDINATE &&
           fabs(p.z) <= RT_MAX_COORDINATE;
}

rt_status rt_scene_look(const rt_scene *scene, const rt_look *look,
                        rt_camera *camera, rt_vec3 *screen_point,
                        rt_error *error)
{
    if (scene == NULL || look == NULL || camera == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a scene, a look and a camera to fill");
    if (!finite_point(look->look_from) || !finite_point(look->look_at) ||
        !finite_point(look->up) || !isfinite(look->fov))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a look with a coordinate that is not finite");
    /* As the loader's view options: rt_load_options' look_* with all four
     * given (formats/reader.c, apply_view). */
    rt_view view = {look->look_from, look->look_at, look->up, look->fov,
                    scene->camera.width, 0};
    rt_vec3 o, a, b;
    switch (rt__frame_view(&view, &o, &a, &b)) {
    case RT_FRAME_OK:
        break;
    case RT_FRAME_FOV:
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a field of view of %g degrees: expected "
                             "(0, 180)", look->fov);
    case RT_FRAME_SAME_POINT:
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the look-from point is the look-at point");
    case RT_FRAME_UP_ALONG_VIEW:
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the up direction is along the view");
    }
    if (!within_range(o) || !within_range(a) || !within_range(b))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a camera point beyond %g, the loader's limit",
                             RT_MAX_COORDINATE);
    rt_camera made;
    const char *reason =
        rt__camera_make(o, a, b, scene->camera.width, scene->camera.height,
                        &made, NULL);
    if (reason != NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0, "%s",
                             reason);
    /* The lens as the scene builder sets it: the file's aperture, and its
     * focal distance when it gave one (else |AO| of this camera). */
    made.aperture = scene->camera.aperture;
    if (scene->focus_given)
        made.focal_distance = scene->camera.focal_distance;
    *camera = made;
    if (screen_point != NULL)
        *screen_point = b;
    return RT_OK;
}

void rt_camera_get_look(const rt_camera *camera, rt_look *look)
{
    if (camera == NULL || look == NULL)
        return;
    rt_vec3 ao = v3_sub(camera->observer, camera->screen_center);
    look->look_from = camera->observer;
    look->look_at = camera->screen_center;
    look->up = camera->up;
    look->fov = 2 * atan(v3_length(camera->right) / v3_length(ao)) * 180 / PI;
}
