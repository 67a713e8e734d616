/*
 * view_camera.c - the arithmetic of rt-view's camera moves on rt_look
 * (see view_camera.h): orbit, pan, dolly, fly, field of view, aim, pick,
 * and the camera as text.
 */
#include "view_camera.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

static rt_vec3 add(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.x + b.x, a.y + b.y, a.z + b.z};
}

static rt_vec3 sub(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.x - b.x, a.y - b.y, a.z - b.z};
}

static rt_vec3 scale(rt_vec3 a, double s)
{
    return (rt_vec3){a.x * s, a.y * s, a.z * s};
}

static double dot(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static rt_vec3 cross(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                     a.x * b.y - a.y * b.x};
}

static double length(rt_vec3 a)
{
    return sqrt(dot(a, a));
}

/* a / |a|; the zero vector stays zero. */
static rt_vec3 unit(rt_vec3 a)
{
    double l = length(a);
    return l > 0 ? scale(a, 1 / l) : a;
}

static rt_vec3 axis_vector(rt_up_axis axis)
{
    switch (axis) {
    case RT_UP_X: return (rt_vec3){1, 0, 0};
    case RT_UP_Z: return (rt_vec3){0, 0, 1};
    case RT_UP_NEG_X: return (rt_vec3){-1, 0, 0};
    case RT_UP_NEG_Y: return (rt_vec3){0, -1, 0};
    case RT_UP_NEG_Z: return (rt_vec3){0, 0, -1};
    case RT_UP_Y:
    case RT_UP_AUTO:
    default: return (rt_vec3){0, 1, 0};
    }
}

rt_vec3 view_camera_world_up(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    if (info.up_axis != RT_UP_AUTO)
        return axis_vector(info.up_axis);
    /* The largest component of AC, with its sign (x before y before z on
     * a tie). */
    rt_vec3 up = info.camera.up;
    double ax = fabs(up.x), ay = fabs(up.y), az = fabs(up.z);
    if (ax >= ay && ax >= az)
        return (rt_vec3){up.x < 0 ? -1 : 1, 0, 0};
    if (ay >= az)
        return (rt_vec3){0, up.y < 0 ? -1 : 1, 0};
    return (rt_vec3){0, 0, up.z < 0 ? -1 : 1};
}

double view_camera_extent(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_vec3 low = {0, 0, 0}, high = {0, 0, 0};
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        if (i == 0) {
            low = high = v;
            continue;
        }
        low = (rt_vec3){fmin(low.x, v.x), fmin(low.y, v.y), fmin(low.z, v.z)};
        high = (rt_vec3){fmax(high.x, v.x), fmax(high.y, v.y),
                         fmax(high.z, v.z)};
    }
    double extent = length(sub(high, low));
    if (!(extent > 0) || !isfinite(extent))
        extent = length(sub(info.camera.screen_center, info.camera.observer));
    return extent;
}

rt_look view_camera_file_look(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_look look;
    rt_camera_get_look(&info.camera, &look);
    /* The screen centre A may be anywhere on the axis (a .scn file's
     * screen is often a unit away from the eye): the target an orbit turns
     * round is what the axis meets, else the point of the axis nearest the
     * middle of the vertices' box, in front of the eye. */
    rt_vec3 axis = sub(look.look_at, look.look_from);
    double along = length(axis);
    if (!(along > 0) || !isfinite(along))
        return look;
    rt_vec3 unit = {axis.x / along, axis.y / along, axis.z / along};
    rt_hit hit;
    double distance = 0;
    if (rt_scene_nearest_hit(scene, (rt_ray){look.look_from, unit}, INFINITY,
                             &hit))
        distance = hit.t;
    else if (info.vertex_count > 0) {
        rt_vec3 low = rt_scene_vertex(scene, 0), high = low;
        for (int i = 1; i < info.vertex_count; i++) {
            rt_vec3 v = rt_scene_vertex(scene, i);
            low = (rt_vec3){fmin(low.x, v.x), fmin(low.y, v.y),
                            fmin(low.z, v.z)};
            high = (rt_vec3){fmax(high.x, v.x), fmax(high.y, v.y),
                             fmax(high.z, v.z)};
        }
        rt_vec3 middle = {(low.x + high.x) / 2, (low.y + high.y) / 2,
                          (low.z + high.z) / 2};
        rt_vec3 to = sub(middle, look.look_from);
        distance = to.x * unit.x + to.y * unit.y + to.z * unit.z;
    }
    if (distance > 0 && isfinite(distance))
        look.look_at = (rt_vec3){look.look_from.x + distance * unit.x,
                                 look.look_from.y + distance * unit.y,
                                 look.look_from.z + distance * unit.z};
    return look;
}

/* The largest elevation an orbit gives, in radians. */
static double elevation_limit(void)
{
    return (90.0 - VIEW_CAMERA_POLE_DEGREES) * PI / 180.0;
}

/* Puts look_from at `distance` from look_at, in horizontal direction
 * `horizontal` (unit, perpendicular to world_up) at `elevation` radians
 * (clamped to the limit). */
static void place(rt_look *look, rt_vec3 world_up, rt_vec3 horizontal,
                  double elevation, double distance)
{
    double limit = elevation_limit();
    if (elevation > limit)
        elevation = limit;
    if (elevation < -limit)
        elevation = -limit;
    rt_vec3 offset = add(scale(horizontal, cos(elevation)),
                         scale(world_up, sin(elevation)));
    look->look_from = add(look->look_at, scale(offset, distance));
    look->up = world_up;
}

/* The observer's offset from the target split into a unit horizontal
 * direction and an elevation (radians); the distance returned. */
static double split(const rt_look *look, rt_vec3 world_up,
                    rt_vec3 *horizontal, double *elevation)
{
    rt_vec3 offset = sub(look->look_from, look->look_at);
    double distance = length(offset);
    double height = dot(offset, world_up);
    rt_vec3 flat = sub(offset, scale(world_up, height));
    double flat_length = length(flat);
    if (flat_length > distance * 1e-12) {
        *horizontal = scale(flat, 1 / flat_length);
    } else {
        /* Straight above (below) the target: the image's up points away
         * from (towards) the observer's side. */
        rt_vec3 up = sub(look->up, scale(world_up, dot(look->up, world_up)));
        if (length(up) == 0)
            up = fabs(world_up.x) < 0.5 ? (rt_vec3){1, 0, 0}
                                        : (rt_vec3){0, 1, 0};
        up = unit(sub(up, scale(world_up, dot(up, world_up))));
        *horizontal = height > 0 ? scale(up, -1) : up;
    }
    *elevation = atan2(height, flat_length);
    return distance;
}

void view_camera_orbit(rt_look *look, rt_vec3 world_up, double yaw,
                       double pitch)
{
    rt_vec3 horizontal;
    double elevation;
    double distance = split(look, world_up, &horizontal, &elevation);
    if (!(distance > 0))
        return;
    /* Rodrigues about world_up, horizontal being perpendicular to it;
     * world_up x horizontal is the view's right. */
    rt_vec3 side = cross(world_up, horizontal);
    horizontal = unit(add(scale(horizontal, cos(yaw)), scale(side, sin(yaw))));
    place(look, world_up, horizontal, elevation + pitch, distance);
}

void view_camera_pan(rt_look *look, const rt_camera *camera, int width,
                     double dx, double dy)
{
    /* A pixel of the screen plane (which holds the target) is 2|AB|/w
     * wide; the camera moves against the cursor. */
    double pixel = 2 * length(camera->right) / width;
    rt_vec3 shift = add(scale(unit(camera->right), -dx * pixel),
                        scale(unit(camera->up), dy * pixel));
    look->look_from = add(look->look_from, shift);
    look->look_at = add(look->look_at, shift);
}

void view_camera_dolly(rt_look *look, double factor, double min_distance,
                       double max_distance)
{
    rt_vec3 offset = sub(look->look_from, look->look_at);
    double distance = length(offset);
    if (!(distance > 0) || !(factor > 0))
        return;
    double wanted = distance * factor;
    if (wanted < min_distance)
        wanted = min_distance;
    if (wanted > max_distance)
        wanted = max_distance;
    look->look_from = add(look->look_at, scale(offset, wanted / distance));
}

void view_camera_fly(rt_look *look, const rt_camera *camera,
                     rt_vec3 world_up, double forward, double right,
                     double rise)
{
    rt_vec3 ahead = unit(sub(look->look_at, look->look_from));
    rt_vec3 shift = add(add(scale(ahead, forward),
                            scale(unit(camera->right), right)),
                        scale(world_up, rise));
    look->look_from = add(look->look_from, shift);
    look->look_at = add(look->look_at, shift);
}

double view_camera_clamp_fov(double fov)
{
    if (!(fov >= VIEW_CAMERA_MIN_FOV))
        return VIEW_CAMERA_MIN_FOV;
    return fov > VIEW_CAMERA_MAX_FOV ? VIEW_CAMERA_MAX_FOV : fov;
}

int view_camera_aim(rt_look *look, rt_vec3 world_up, rt_vec3 target)
{
    rt_vec3 offset = sub(look->look_from, target);
    if (!(length(offset) > 0))
        return 0;
    rt_look aimed = *look;
    aimed.look_at = target;
    rt_vec3 horizontal;
    double elevation;
    double distance = split(&aimed, world_up, &horizontal, &elevation);
    if (fabs(elevation) > elevation_limit())
        place(&aimed, world_up, horizontal, elevation, distance);
    aimed.up = world_up;
    *look = aimed;
    return 1;
}

int view_camera_pick(const rt_scene *scene, const rt_camera *camera,
                     int width, int height, int i, int j, rt_vec3 *point)
{
    rt_camera sized = *camera;
    sized.width = width;
    sized.height = height;
    rt_hit hit;
    if (!rt_scene_nearest_hit(scene, rt_camera_ray(&sized, i, j), INFINITY,
                              &hit))
        return 0;
    *point = hit.point;
    return 1;
}

/* Appends to a text of fixed capacity; false once it is full. */
typedef struct text {
    char *buffer;
    size_t size, used;
    int full;
} text;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void put(text *t, const char *format, ...)
{
    if (t->full)
        return;
    va_list args;
    va_start(args, format);
    int written = vsnprintf(t->buffer + t->used, t->size - t->used, format,
                            args);
    va_end(args);
    if (written < 0 || (size_t)written >= t->size - t->used)
        t->full = 1;
    else
        t->used += (size_t)written;
}

static void put_point(text *t, const char *separator, rt_vec3 p)
{
    put(t, "%.17g%s%.17g%s%.17g", p.x, separator, p.y, separator, p.z);
}

/* Whether the screen record needs the lens `a, f` to give `camera`: a
 * lens, or a focal distance other than the one a file without them gets
 * (|AO| as the library computes it: asked of a scene of no facets built
 * from the same three points). */
static int needs_lens(const rt_camera *camera, rt_vec3 b)
{
    if (camera->aperture != 0)
        return 1;
    rt_light light;
    memset(&light, 0, sizeof light);
    light.position = camera->observer;
    rt_scene_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.observer = camera->observer;
    desc.screen_center = camera->screen_center;
    desc.screen_right = b;
    desc.width = camera->width;
    desc.height = camera->height;
    desc.lights = &light;
    desc.light_count = 1;
    rt_scene *bare = NULL;
    if (rt_scene_create(&desc, &bare, NULL) != RT_OK)
        return 1;
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(bare, &info);
    rt_scene_destroy(bare);
    double plain = info.camera.focal_distance;
    return memcmp(&plain, &camera->focal_distance, sizeof plain) != 0;
}

rt_status view_camera_describe(const rt_scene *scene, const char *name,
                               const rt_look *look, char *buffer,
                               size_t size, rt_error *error)
{
    text t = {buffer, size, 0, size == 0};
    if (size > 0)
        buffer[0] = '\0';
    if (look == NULL) {
        put(&t, "# rt-view camera of %s: the file's own camera\n"
                "# rt-export needs no view options for it, and the "
                "scene file holds its records\n", name);
    } else {
        rt_camera camera;
        rt_vec3 b;
        rt_status status = rt_scene_look(scene, look, &camera, &b, error);
        if (status != RT_OK)
            return status;
        put(&t, "# rt-view camera of %s\n# rt-export options:\n", name);
        put(&t, "--look-from ");
        put_point(&t, ",", look->look_from);
        put(&t, " --look-at ");
        put_point(&t, ",", look->look_at);
        put(&t, " --up ");
        put_point(&t, ",", look->up);
        put(&t, " --fov %.17g\n", look->fov);
        put(&t, "# .scn camera records: the observer O, then the screen "
                "A, B, w, h[, a, f]\n");
        put_point(&t, ", ", camera.observer);
        put(&t, "\n");
        put_point(&t, ", ", camera.screen_center);
        put(&t, ", ");
        put_point(&t, ", ", b);
        put(&t, ", %d, %d", camera.width, camera.height);
        if (needs_lens(&camera, b))
            put(&t, ", %.17g, %.17g", camera.aperture, camera.focal_distance);
        put(&t, "\n");
    }
    if (t.full) {
        if (error) {
            memset(error, 0, sizeof *error);
            error->status = RT_ERR_LIMIT;
            snprintf(error->message, sizeof error->message,
                     "the camera's text does not fit in %zu bytes", size);
        }
        return RT_ERR_LIMIT;
    }
    return RT_OK;
}
