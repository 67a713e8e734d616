/*
 * view_overlay.c - the camera projection and the letterbox mapping the
 * click overlay uses (see view_overlay.h).
 */
#include "view_overlay.h"

#include <math.h>

/* Points nearer the observer than this fraction of |AO| (along AO) are
 * behind it as far as drawing goes: their projection would be unbounded. */
#define NEAR_FRACTION 1e-3

static rt_vec3 sub(rt_vec3 a, rt_vec3 b)
{
    rt_vec3 r = {a.x - b.x, a.y - b.y, a.z - b.z};
    return r;
}

static double dot(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

void view_projection_init(view_projection *projection, const rt_scene *scene,
                          const rt_render_options *options)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    const rt_camera *camera =
        options->camera ? options->camera : &info.camera;
    projection->camera = *camera;
    projection->width = options->width > 0 ? options->width : camera->width;
    projection->height =
        options->height > 0 ? options->height : camera->height;
    projection->x0 = options->region.x0;
    projection->y0 = options->region.y0;
    projection->focal_distance = options->focal_distance > 0
                                     ? options->focal_distance
                                     : camera->focal_distance;
}

/* Depth of `point` along AO, in units of |AO| (the screen is at 1). */
static double depth(const view_projection *projection, rt_vec3 point)
{
    const rt_camera *camera = &projection->camera;
    rt_vec3 forward = sub(camera->screen_center, camera->observer);
    return dot(sub(point, camera->observer), forward) /
           dot(forward, forward);
}

int view_project_point(const view_projection *projection, rt_vec3 point,
                       double *x, double *y)
{
    const rt_camera *camera = &projection->camera;
    double s = depth(projection, point);
    if (!(s >= NEAR_FRACTION))
        return 0;
    /* P = O + (X - O)/s lies on the screen plane; P - A in AB, AC units. */
    rt_vec3 to_point = sub(point, camera->observer);
    rt_vec3 on_screen = {camera->observer.x + to_point.x / s,
                         camera->observer.y + to_point.y / s,
                         camera->observer.z + to_point.z / s};
    rt_vec3 d = sub(on_screen, camera->screen_center);
    double u = dot(d, camera->right) / dot(camera->right, camera->right);
    double v = dot(d, camera->up) / dot(camera->up, camera->up);
    double w = projection->width, h = projection->height;
    *x = w * (u + 1) / 2 - projection->x0;
    *y = (h - v * w) / 2 - projection->y0;
    return 1;
}

int view_project_segment(const view_projection *projection, rt_vec3 a,
                         rt_vec3 b, double out[4])
{
    double da = depth(projection, a), db = depth(projection, b);
    if (da < NEAR_FRACTION && db < NEAR_FRACTION)
        return 0;
    if (da < NEAR_FRACTION || db < NEAR_FRACTION) {
        /* Move the end behind to where the segment crosses the near
         * plane. */
        double f = (NEAR_FRACTION - da) / (db - da);
        rt_vec3 cut = {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y),
                       a.z + f * (b.z - a.z)};
        if (da < NEAR_FRACTION)
            a = cut;
        else
            b = cut;
    }
    return view_project_point(projection, a, &out[0], &out[1]) &&
           view_project_point(projection, b, &out[2], &out[3]);
}

int view_project_camera_ray(const view_projection *projection,
                            rt_vec3 origin, rt_vec3 direction, double *x,
                            double *y)
{
    const rt_camera *camera = &projection->camera;
    rt_vec3 forward = sub(camera->screen_center, camera->observer);
    double length = sqrt(dot(forward, forward));
    double f = projection->focal_distance > 0 ? projection->focal_distance
                                              : length;
    /* Along the unit axis w = AO/|AO|: the origin's depth, the ray's
     * speed; the point at depth f. */
    double start = dot(sub(origin, camera->observer), forward) / length;
    double speed = dot(direction, forward) / length;
    if (!(speed > 0) || !(length > 0))
        return 0;
    double s = (f - start) / speed;
    rt_vec3 focus = {origin.x + s * direction.x, origin.y + s * direction.y,
                     origin.z + s * direction.z};
    return view_project_point(projection, focus, x, y);
}

void view_ray_color(view_ray_kind kind, unsigned char rgb[3])
{
    static const unsigned char colors[][3] = {
        [VIEW_RAY_CAMERA] = {255, 255, 255},
        [VIEW_RAY_SHADOW] = {255, 255, 0},
        [VIEW_RAY_REFLECTED] = {0, 255, 255},
        [VIEW_RAY_REFRACTED] = {255, 0, 255},
        [VIEW_RAY_BLOCKED] = {255, 0, 0},
    };
    for (int c = 0; c < 3; c++)
        rgb[c] = colors[kind][c];
}

void view_letterbox(int image_width, int image_height, int out_width,
                    int out_height, int rect[4])
{
    double sx = (double)out_width / image_width;
    double sy = (double)out_height / image_height;
    double scale = sx < sy ? sx : sy;
    rect[2] = (int)(image_width * scale + 0.5);
    rect[3] = (int)(image_height * scale + 0.5);
    rect[0] = (out_width - rect[2]) / 2;
    rect[1] = (out_height - rect[3]) / 2;
}

int view_output_to_pixel(int image_width, int image_height, int out_width,
                         int out_height, double x, double y, int *i, int *j)
{
    int rect[4];
    view_letterbox(image_width, image_height, out_width, out_height, rect);
    if (rect[2] <= 0 || rect[3] <= 0)
        return 0;
    double u = (x - rect[0]) * image_width / rect[2];
    double v = (y - rect[1]) * image_height / rect[3];
    if (!(u >= 0 && v >= 0 && u < image_width && v < image_height))
        return 0;
    *i = (int)floor(u);
    *j = (int)floor(v);
    return 1;
}
