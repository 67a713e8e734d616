/*
 * engine.c - one interface over the methods the robustness cases compare:
 * our renderer (the library's kernels, in double or float) and the naive
 * reference renderer of naive_impl.h (in double or float).
 */
#include <stdlib.h>
#include <string.h>
#include <tgmath.h>

#include "kernel/kernel.h"
#include "robust/robust.h"

#define R double
#define N(x) naive_d_##x
#include "robust/naive_impl.h"
#undef R
#undef N
#define R float
#define N(x) naive_f_##x
#include "robust/naive_impl.h"
#undef R
#undef N

struct rb_engine {
    const rt_scene *scene;
    rb_method method;
    rt_precision precision;
    rt_vec3 *vertices;          /* ours: what the kernel was built from */
    rt_facet_record *facets;
    rt_material *materials;     /* one per facet */
    rt_kernel *kernel;
    naive_d_scene *nd;
    naive_f_scene *nf;
};

const char *rb_method_name(rb_method method)
{
    switch (method) {
    case RB_OURS: return "ours";
    case RB_NAIVE_MT: return "naive MT";
    case RB_NAIVE_MT_FMA: return "naive MT+FMA";
    case RB_NAIVE_PLANE: return "naive plane";
    default: return "?";
    }
}

int rb_color_has_nan(rt_color c)
{
    return isnan(c.r) || isnan(c.g) || isnan(c.b);
}

rb_engine *rb_engine_create(const rt_scene *scene, rb_method method,
                            rt_precision precision)
{
    rb_engine *e = calloc(1, sizeof *e);
    e->scene = scene;
    e->method = method;
    e->precision = precision;
    if (method != RB_OURS) {
        if (precision == RT_PRECISION_FLOAT)
            e->nf = naive_f_create(scene, (int)method);
        else
            e->nd = naive_d_create(scene, (int)method);
        return e;
    }
    /* The kernel is built from what the public accessors give. */
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    e->vertices = calloc((size_t)info.vertex_count + 1, sizeof *e->vertices);
    e->facets = calloc((size_t)info.facet_count + 1, sizeof *e->facets);
    e->materials = calloc((size_t)info.facet_count + 1,
                          sizeof *e->materials);
    for (int i = 0; i < info.vertex_count; i++)
        e->vertices[i] = rt_scene_vertex(scene, i);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        memcpy(e->facets[i].vertex, f.vertex, sizeof f.vertex);
        e->facets[i].material = i;
        e->facets[i].line = f.line;
        e->facets[i].degenerate = (unsigned char)f.degenerate;
        e->materials[i] = (rt_material){f.reflection, f.transparency,
                                        f.refractive_index, f.diffuse,
                                        f.color};
    }
    rt_kernel_source source;
    memset(&source, 0, sizeof source);
    source.vertices = e->vertices;
    source.facets = e->facets;
    source.facet_count = info.facet_count;
    source.materials = e->materials;
    source.material_count = info.facet_count;
    rt_light *lights = calloc((size_t)info.light_count, sizeof *lights);
    for (int i = 0; lights != NULL && i < info.light_count; i++)
        rt_scene_light(scene, i, &lights[i]);
    source.lights = lights;
    source.light_count = lights != NULL ? info.light_count : 0;
    source.background = info.background;
    if (lights != NULL)
        e->kernel = (precision == RT_PRECISION_FLOAT ? &rt__kernel_float_ops
                                                     : &rt__kernel_double_ops)
                        ->create(&source);
    free(lights);       /* the kernel keeps its own copy */
    /* With the octree or the kd-tree forced on, every query of the kernel
     * goes through it (a kernel that has one uses it for nearest_hit and
     * occluded too). */
    /* Brute force runs the AVX2 loops once the kernel's blocks exist
     * (made with the kernel only below RT_ACCEL_AUTO_FACETS facets). */
    if (e->kernel != NULL)
        rt__kernel_prepare_blocks(e->kernel);
    if (rb_accel() == RT_ACCEL_OCTREE && e->kernel != NULL)
        rt__kernel_prepare_octree(e->kernel, NULL, NULL);
    if (rb_accel() == RT_ACCEL_KDTREE && e->kernel != NULL)
        rt__kernel_prepare_kdtree(e->kernel, NULL, NULL, 1, NULL);
    return e;
}

rt_accel rb_accel(void)
{
    const char *accel = getenv("RT_TEST_ACCEL");
    if (accel != NULL && strcmp(accel, "octree") == 0)
        return RT_ACCEL_OCTREE;
    if (accel != NULL && strcmp(accel, "kdtree") == 0)
        return RT_ACCEL_KDTREE;
    if (accel != NULL && strcmp(accel, "none") == 0)
        return RT_ACCEL_NONE;
    return RT_ACCEL_AUTO;
}

void rb_engine_free(rb_engine *e)
{
    if (e == NULL)
        return;
    rt__kernel_destroy(e->kernel);
    naive_d_free_scene(e->nd);
    naive_f_free_scene(e->nf);
    free(e->vertices);
    free(e->facets);
    free(e->materials);
    free(e);
}

int rb_engine_hit(const rb_engine *e, rt_ray ray, rb_hit *hit)
{
    if (e->nd != NULL)
        return naive_d_hit(e->nd, ray, hit);
    if (e->nf != NULL)
        return naive_f_hit(e->nf, ray, hit);
    rt_kernel_hit h;
    int found = rt__kernel_nearest_hit(e->kernel, ray, INFINITY, &h);
    if (found) {
        hit->t = h.t;
        hit->facet = h.facet;
        hit->point = h.point;
    }
    return found;
}

rt_color rb_engine_trace(const rb_engine *e, rt_ray ray, int depth)
{
    if (e->nd != NULL)
        return naive_d_color(e->nd, ray, depth);
    if (e->nf != NULL)
        return naive_f_color(e->nf, ray, depth);
    rt_trace_settings settings;
    memset(&settings, 0, sizeof settings);
    settings.max_depth = depth;
    settings.kernel = RT_KERNEL_AUTO;
    settings.octree = rb_accel() == RT_ACCEL_OCTREE;
    settings.kdtree = rb_accel() == RT_ACCEL_KDTREE;
    rt_counters counters;
    memset(&counters, 0, sizeof counters);
    return rt__kernel_trace(e->kernel, ray.origin, ray.direction, &settings,
                            &counters);
}

long rb_engine_render(const rb_engine *e, int depth, int threads,
                      rt_image *image)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(e->scene, &info);
    long nans = 0;
    if (e->method == RB_OURS) {
        rt_render_options options;
        rt_render_options_init(&options);
        options.max_depth = depth;
        options.threads = threads;
        options.precision = e->precision;
        options.accel = rb_accel();
        if (rt_render(e->scene, &options, image, NULL) != RT_OK)
            return -1;
    }
    for (int j = 0; j < info.height; j++) {
        for (int i = 0; i < info.width; i++) {
            rt_color c = rb_engine_trace(e, rt_camera_ray(&info.camera, i, j),
                                         depth);
            nans += rb_color_has_nan(c);
            if (e->method != RB_OURS) {
                unsigned char *p = rt_image_pixel(image, i, j);
                p[0] = rt_channel_to_byte(c.r);
                p[1] = rt_channel_to_byte(c.g);
                p[2] = rt_channel_to_byte(c.b);
            }
        }
    }
    return nans;
}
