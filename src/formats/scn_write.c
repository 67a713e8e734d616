/*
 * scn_write.c - writing a scene as a .scn file, whatever format it was read
 * from, so that tools that read only the course's format can take it.
 *
 * Every number is printed with 17 significant digits, which reads back as
 * the same double: a scene converted and read again renders the same bytes
 * as the scene itself.  The vertex normals written are the scene's unit
 * ones, which the builder keeps as they are when read again (it leaves a
 * vector of unit length to within rounding alone).  What the course's records cannot hold is reported
 * to the caller (RT_SCN_DROPPED_ bits) rather than approximated silently.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "formats/formats.h"
#include "raytrace/scene.h"
#include "raytrace/version.h"

typedef struct out {
    rt_write_func write;
    void *user;
    int failed;
} out;

static void put(out *o, const char *fmt, ...) RT_PRINTF_LIKE(2, 3);

static void put(out *o, const char *fmt, ...)
{
    if (o->failed)
        return;
    char line[256];
    va_list args;
    va_start(args, fmt);
    int n = vsnprintf(line, sizeof line, fmt, args);
    va_end(args);
    if (n < 0 || (size_t)n >= sizeof line || !o->write(o->user, line,
                                                      (size_t)n))
        o->failed = 1;
}

static void put_point(out *o, rt_vec3 p, const char *end)
{
    put(o, "%.17g, %.17g, %.17g%s", p.x, p.y, p.z, end);
}

/* Non-zero when the facet's diffuse weight is the .scn rule's. */
static int scn_diffuse(const rt_facet_info *f)
{
    return f->diffuse == 1.0 - f->reflection - f->transparency;
}

rt_status rt_scene_write_scn(const rt_scene *scene, int extended,
                             rt_write_func write, void *user,
                             unsigned *dropped, rt_error *error)
{
    if (scene == NULL || write == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a scene and a sink");
    unsigned lost = 0;
    out o = {write, user, 0};
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    const rt_camera *c = &info.camera;
    put(&o, "# written by libraytrace %s\n", rt_version_string());
    put_point(&o, c->observer, "\n");
    put_point(&o, c->screen_center, ", ");
    rt_vec3 b = {c->screen_center.x + c->right.x,
                 c->screen_center.y + c->right.y,
                 c->screen_center.z + c->right.z};
    put_point(&o, b, "");
    put(&o, ", %d, %d", info.width, info.height);
    if (c->aperture > 0 && extended)
        put(&o, ", %.17g, %.17g", c->aperture, c->focal_distance);
    else if (c->aperture > 0)
        lost |= RT_SCN_DROPPED_LENS;
    put(&o, "\n%d\n", info.vertex_count);
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 n = rt_scene_vertex_normal(scene, i);
        int normal = n.x != 0.0 || n.y != 0.0 || n.z != 0.0;
        put_point(&o, rt_scene_vertex(scene, i),
                  normal && extended ? ", " : "\n");
        if (normal && extended)
            put_point(&o, n, "\n");
        else if (normal)
            lost |= RT_SCN_DROPPED_NORMALS;
    }
    put(&o, "%d\n", info.facet_count);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        put(&o, "%d, %d, %d, %.17g, %d, %d, %d", f.vertex[0] + 1,
            f.vertex[1] + 1, f.vertex[2] + 1, f.reflection, f.color.r,
            f.color.g, f.color.b);
        /* The optional values go as far as the last one needed: t, n
         * for glass, then d when it is not 1 - k - t, then s, p. */
        int glass = f.transparency > 0 || f.refractive_index != 1.0;
        int diffuse = !scn_diffuse(&f);
        int highlight = f.highlight != 0.0 || f.highlight_exponent != 1.0;
        if (extended) {
            if (glass || diffuse || highlight)
                put(&o, ", %.17g, %.17g", f.transparency,
                    f.refractive_index);
            if (diffuse || highlight)
                put(&o, ", %.17g", f.diffuse);
            if (highlight)
                put(&o, ", %.17g, %.17g", f.highlight,
                    f.highlight_exponent);
        } else {
            lost |= (glass ? RT_SCN_DROPPED_TRANSPARENCY : 0u) |
                    (diffuse ? RT_SCN_DROPPED_DIFFUSE : 0u) |
                    (f.highlight != 0.0 ? RT_SCN_DROPPED_HIGHLIGHTS : 0u);
        }
        put(&o, "\n");
    }
    put(&o, "%d, %d, %d\n", info.background.r, info.background.g,
        info.background.b);
    for (int i = 0; i < info.light_count; i++) {
        if (i > 0 && !extended) {
            lost |= RT_SCN_DROPPED_LIGHTS;
            break;
        }
        rt_light light;
        rt_scene_light(scene, i, &light);
        put_point(&o, light.position, "");
        put(&o, ", %d, %d, %d\n", light.color.r, light.color.g,
            light.color.b);
    }
    if (dropped != NULL)
        *dropped = lost;
    if (o.failed)
        return rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                             "cannot write the scene");
    return RT_OK;
}

typedef struct scn_bytes {
    const rt_scene *scene;
    int extended;
    unsigned *dropped;
} scn_bytes;

static rt_status produce_scn(rt_write_func write, void *user,
                             const void *what, rt_error *error)
{
    const scn_bytes *b = what;
    return rt_scene_write_scn(b->scene, b->extended, write, user,
                              b->dropped, error);
}

rt_status rt_scene_save_scn(const rt_scene *scene, const char *path,
                            int extended, unsigned *dropped,
                            const rt_save_options *options, rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, path, 0, 0,
                             "expected a scene");
    scn_bytes bytes = {scene, extended, dropped};
    rt_producer producer = {produce_scn, &bytes, "scene"};
    return rt__save(path, &producer, options, error);
}
