/*
 * camera.c - the camera frame of docs/rendering-model.md and primary rays.
 *
 * The screen's right half-width AB is made perpendicular to the viewing axis
 * AO by projection when the scene file's B is not; the up half-height AC
 * completes the right-handed frame (AB, AC, AO) with |AC| = |AB|.  Pixels are
 * square: the screen is 2|AB| wide and 2|AB| h / w tall.
 */
#include <float.h>

#include "base/error.h"
#include "scene_internal.h"
#include "base/vecmath.h"

const char *rt__camera_make(rt_vec3 observer, rt_vec3 a, rt_vec3 b,
                            int width, int height, rt_camera *camera,
                            rt_field *field)
{
    rt_vec3 ao = v3_sub(observer, a);
    rt_vec3 ab = v3_sub(b, a);
    rt_field ignored;
    if (field == NULL)
        field = &ignored;
    *field = RT_FIELD_SCREEN_CENTER;
    if (v3_max_abs(ao) == 0.0)
        return "the observer O is the screen centre A";
    *field = RT_FIELD_SCREEN_RIGHT;
    if (v3_max_abs(ab) == 0.0)
        return "the screen point B is the screen centre A";
    if (!v3_is_finite(ao) || !v3_is_finite(ab))
        return "the camera's points are too far apart to be represented";

    /* Project B onto the plane through A perpendicular to AO.  Scaling AO
     * to unit length first keeps the products in range at any scale. */
    rt_vec3 axis = v3_normalize(ao);
    double along = v3_dot(ab, axis);
    rt_vec3 right = ab;
    int projected = along != 0.0;
    if (projected)
        right = v3_sub(ab, v3_scale(axis, along));
    /* What is left must stand clear of the rounding noise of the
     * subtraction, or B was (numerically) on the line OA. */
    if (v3_length(right) <= 64.0 * DBL_EPSILON * v3_length(ab))
        return "the screen point B lies on the line through O and A";

    rt_vec3 up = v3_scale(v3_normalize(v3_cross(axis, right)),
                          v3_length(right));
    camera->observer = observer;
    camera->screen_center = a;
    camera->right = right;
    camera->up = up;
    camera->width = width;
    camera->height = height;
    camera->b_was_projected = projected;
    camera->aperture = 0.0;
    camera->focal_distance = v3_length(ao);
    return NULL;
}

rt_ray rt_camera_ray(const rt_camera *camera, int i, int j)
{
    if (!RT__EXPECT(camera != NULL))
        return (rt_ray){{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    /* P = A + (2(i+1/2)/w - 1) AB + (1 - 2(j+1/2)/h)(h/w) AC, with each
     * coefficient's numerator an exact integer: one rounding each. */
    double w = camera->width, h = camera->height;
    double s = (2.0 * i + 1.0 - w) / w;
    double t = (h - 2.0 * j - 1.0) / w;
    rt_vec3 p = v3_add(camera->screen_center,
                       v3_add(v3_scale(camera->right, s),
                              v3_scale(camera->up, t)));
    return (rt_ray){camera->observer, v3_sub(p, camera->observer)};
}
