/*
 * framing.c - the one framing of a view (framing.h).  Pixels are square
 * and the field of view is horizontal, so the screen's half width is all a
 * frame needs: the camera builder (scene/camera.c) completes the up half
 * height from B, the width and the height.
 */
#include "formats/framing.h"

#include <math.h>

#include "base/vecmath.h"

#define PI 3.14159265358979323846

double rt__frame_tan_half(double fov)
{
    return tan(fov * PI / 360);
}

rt_vec3 rt__frame_right(rt_vec3 at, rt_vec3 look, rt_vec3 up,
                        double half_width)
{
    return v3_add(at, v3_scale(v3_normalize(v3_cross(look, up)),
                               half_width));
}

rt_frame_problem rt__frame_view(const rt_view *view, rt_vec3 *observer,
                                rt_vec3 *screen_center,
                                rt_vec3 *screen_right)
{
    if (!(view->fov > 0 && view->fov < 180))
        return RT_FRAME_FOV;
    rt_vec3 look = v3_sub(view->at, view->from);
    double distance = v3_length(look);
    if (!(distance > 0) || !isfinite(distance))
        return RT_FRAME_SAME_POINT;
    if (!(v3_length(v3_cross(look, view->up)) > 0))
        return RT_FRAME_UP_ALONG_VIEW;
    double half = distance * rt__frame_tan_half(view->fov);
    if (view->centres && view->width > 1)
        half /= 1.0 - 1.0 / view->width;
    *observer = view->from;
    *screen_center = view->at;
    *screen_right = rt__frame_right(view->at, look, view->up, half);
    return RT_FRAME_OK;
}
