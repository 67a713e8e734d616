/*
 * cases_invariance.c - the robustness cases (docs/robustness.md) of the
 * same image whatever the scene's scale and place (T: invariance), whatever
 * the order of coincident facets (Q), whatever the threads and loops (X:
 * determinism).  Their table is in cases.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robust/cases.h"

/* ================================================================== */
/* Translation and scale invariance (images)                           */

/* Floor (reflective), a slab lifted by 1e-3 of the scene's size, a sphere,
 * a mirror wall; 64 x 64. */
void rb_invariance_scene(rb_mesh *m, rb_view *v)
{
    rb_mesh_grid(m, rb_v(-1, -1, 0), rb_v(0.25, 0, 0), rb_v(0, 0.25, 0), 8, 0,
                 0.3, GREY);
    rb_mesh_box(m, rb_v(-0.45, -0.3, 0.002), rb_v(0.15, 0.3, 0.152), 0, RED);
    rb_mesh_icosphere(m, rb_v(0.5, 0.45, 0.36), 0.35, 1, 0.2, GREEN);
    int w0 = rb_mesh_vertex(m, rb_v(-1, -1, 0)), w1 = rb_mesh_vertex(m, rb_v(-1, 1, 0)),
        w2 = rb_mesh_vertex(m, rb_v(-1, 1, 1.2)), w3 = rb_mesh_vertex(m, rb_v(-1, -1, 1.2));
    rb_mesh_facet(m, w0, w1, w2, 0.8, BLUE);
    rb_mesh_facet(m, w0, w2, w3, 0.8, BLUE);
    *v = (rb_view){rb_v(1.7, -2.3, 2.1), rb_v(1.19, -1.61, 1.53),
                   rb_v(1.19 + 0.55, -1.61 + 0.4, 1.53), 64, 64,
                   rb_v(1.3, 0.9, 3.1), WHITE, SKY};
}

/* The sequence of facets and shadow tests along a pixel's path (ours,
 * double, unit scale): pixels whose 8 neighbours all share it are not on a
 * crease, a silhouette or a shadow edge, even seen in a mirror. */
static uint64_t path_signature(const rt_scene *scene, rt_ray ray)
{
    uint64_t sig = 1469598103934665603u;
    rt_light light;
    rt_scene_light(scene, 0, &light);
    for (int bounce = 0; bounce < 6; bounce++) {
        rt_hit h;
        if (!rt_scene_nearest_hit(scene, ray, INFINITY, &h))
            return sig * 1099511628211u;
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, h.facet, &f);
        rt_vec3 off = rb_add(h.point, rb_scale(h.normal, 1e-9));
        int lit = rb_dot(h.normal, rb_sub(light.position, h.point)) > 0 &&
                  !rt_scene_occluded(scene, off, light.position, h.facet);
        sig = (sig ^ (uint64_t)(h.facet * 2 + lit + 7)) * 1099511628211u;
        if (f.reflection == 0)
            break;
        rt_vec3 d = rb_scale(ray.direction, 1 / rb_length(ray.direction));
        d = rb_sub(d, rb_scale(h.normal, 2 * rb_dot(d, h.normal)));
        ray = (rt_ray){off, d};
    }
    return sig;
}

static unsigned char *edge_mask(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    int w = info.width, hgt = info.height;
    uint64_t *sig = malloc(sizeof *sig * (size_t)(w * hgt));
    unsigned char *mask = calloc((size_t)(w * hgt), 1);
    for (int j = 0; j < hgt; j++)
        for (int i = 0; i < w; i++)
            sig[j * w + i] = path_signature(scene, rt_camera_ray(&info.camera, i, j));
    for (int j = 0; j < hgt; j++)
        for (int i = 0; i < w; i++)
            for (int dj = -1; dj <= 1; dj++)
                for (int di = -1; di <= 1; di++) {
                    int x = i + di, y = j + dj;
                    if (x >= 0 && y >= 0 && x < w && y < hgt &&
                        sig[y * w + x] != sig[j * w + i])
                        mask[j * w + i] = 1;
                }
    free(sig);
    return mask;
}

long rb_count_differing(const rt_image *a, const rt_image *b)
{
    if (a->pixels == NULL || b->pixels == NULL)
        return (long)a->width * a->height;
    long n = 0;
    for (int j = 0; j < a->height; j++)
        for (int i = 0; i < a->width; i++)
            n += memcmp(rt_image_pixel(a, i, j), rt_image_pixel(b, i, j), 3) != 0;
    return n;
}

rt_image rb_render_view(const rb_mesh *base, const rb_view *base_view,
                            double scale, rt_vec3 shift, rb_method method,
                            rt_precision precision, long *nans)
{
    rb_mesh m = {0};
    for (int i = 0; i < base->vertex_count; i++)
        rb_mesh_vertex(&m, rb_transform_point(base->vertices[i], scale, shift));
    for (int i = 0; i < base->facet_count; i++)
        rb_mesh_facet(&m, base->facets[i].vertex[0], base->facets[i].vertex[1],
                      base->facets[i].vertex[2], base->facets[i].reflection,
                      base->facets[i].color);
    rb_view view = *base_view;
    rb_view_transform(&view, scale, shift);
    rt_scene *scene = rb_scene(&m, &view);
    rt_image image = {0};
    if (scene == NULL) {
        *nans = -1;
        rb_mesh_free(&m);
        return image;
    }
    rt_image_init(&image, view.width, view.height, NULL);
    rb_engine *e = rb_engine_create(scene, method, precision);
    *nans = rb_engine_render(e, 5, 2, &image);
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
    return image;
}

/* The scene at unit scale against the same scene moved: differing pixels
 * at most 0.1 % of the image, each on an edge of the mask. */
static void invariance(rb_method method, rt_precision precision, rb_result *r,
                       double scale, rt_vec3 shift)
{
    rb_mesh m = {0};
    rb_view view;
    rb_invariance_scene(&m, &view);
    rt_scene *reference_scene = rb_scene(&m, &view);
    unsigned char *mask = edge_mask(reference_scene);
    long nans_a, nans_b;
    rt_image a = rb_render_view(&m, &view, 1, rb_v(0, 0, 0), method, precision,
                                &nans_a);
    rt_image b = rb_render_view(&m, &view, scale, shift, method, precision,
                                &nans_b);
    long differ = 0, off_edge = 0, edges = 0;
    r->total = (long)view.width * view.height;
    if (b.pixels == NULL || nans_b < 0) {
        r->failures = r->total;
        snprintf(r->note, sizeof r->note, "the moved scene was refused");
    } else {
        for (int j = 0; j < view.height; j++)
            for (int i = 0; i < view.width; i++) {
                edges += mask[j * view.width + i];
                if (memcmp(rt_image_pixel(&a, i, j), rt_image_pixel(&b, i, j), 3)) {
                    differ++;
                    off_edge += !mask[j * view.width + i];
                }
            }
        r->failures = differ * 1000 > r->total ? differ : off_edge;
        r->nans = nans_a + nans_b;
        snprintf(r->note, sizeof r->note,
                 "%ld pixels differ, %ld of them off the %ld edge pixels",
                 differ, off_edge, edges);
    }
    rt_image_release(&a);
    rt_image_release(&b);
    free(mask);
    rt_scene_destroy(reference_scene);
    rb_mesh_free(&m);
}

void rb_case_t1(rb_method m, rt_precision p, rb_result *r)
{
    if (!rb_is_double(p)) {
        rb_not_applicable(r, "float's step at 1e6 is 0.06: the scene loses its shape (V6)");
        return;
    }
    invariance(m, p, r, 1, rb_v(1e6, -1e6, 1e6));
}
void rb_case_t2(rb_method m, rt_precision p, rb_result *r) { invariance(m, p, r, 1e-6, rb_v(0, 0, 0)); }
void rb_case_t3(rb_method m, rt_precision p, rb_result *r) { invariance(m, p, r, 1e6, rb_v(0, 0, 0)); }
void rb_case_t4(rb_method m, rt_precision p, rb_result *r)
{
    invariance(m, p, r, rb_is_double(p) ? 1e-150 : 1e-15, rb_v(0, 0, 0));
}
void rb_case_t5(rb_method m, rt_precision p, rb_result *r)
{
    invariance(m, p, r, rb_is_double(p) ? 1e150 : 1e15, rb_v(0, 0, 0));
}

/* ================================================================== */
/* Coincident facets                                                   */

/* A floor whose every facet is listed twice (red, then blue), the second
 * copy's vertices `rotation` places on (or reversed with -1): the first
 * record wins every hit. */
static void duplicates(rb_method method, rt_precision precision, rb_result *r,
                       int rotation)
{
    rb_mesh m = {0};
    rb_mesh_grid(&m, rb_v(-1, -1, 0), rb_v(0.25, 0, 0), rb_v(0, 0.25, 0), 8, 1,
                 0, RED);
    int n = m.facet_count;
    for (int i = 0; i < n; i++) {
        const int *v = m.facets[i].vertex;
        if (rotation < 0)
            rb_mesh_facet(&m, v[2], v[1], v[0], 0, BLUE);
        else
            rb_mesh_facet(&m, v[rotation % 3], v[(rotation + 1) % 3],
                          v[(rotation + 2) % 3], 0, BLUE);
    }
    /* Tilted: a plane no axis is aligned with. */
    for (int i = 0; i < m.vertex_count; i++)
        m.vertices[i] = rb_rotate(m.vertices[i]);
    rb_view view = rb_ray_view(1, rb_v(0, 0, 3), SKY);
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    rt_test_rng rng = {66};
    for (int i = 0; i < rb_scaled(50000); i++) {
        rt_vec3 target = rb_v(rt_test_rng_range(&rng, -0.98, 0.98),
                              rt_test_rng_range(&rng, -0.98, 0.98), 0);
        rt_vec3 origin = rb_add(target,
                                rb_add(rb_random_in_ball(&rng, 0.8),
                                       rb_v(0, 0, 1)));
        target = rb_rotate(target), origin = rb_rotate(origin);
        rb_hit h;
        r->total++;
        if (!rb_engine_hit(e, (rt_ray){origin, rb_sub(target, origin)}, &h))
            r->failures++;
        else if (rb_hit_is_nan(&h))
            r->nans++;
        else if (h.facet >= n)
            r->failures++;
    }
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

void rb_case_q1(rb_method m, rt_precision p, rb_result *r) { duplicates(m, p, r, 0); }
void rb_case_q2(rb_method m, rt_precision p, rb_result *r)
{
    rb_result parts[3];
    static const int rotations[3] = {1, 2, -1};
    for (int k = 0; k < 3; k++) {
        memset(&parts[k], 0, sizeof parts[k]);
        duplicates(m, p, &parts[k], rotations[k]);
        r->total += parts[k].total;
        r->failures += parts[k].failures;
        r->nans += parts[k].nans;
    }
    snprintf(r->note, sizeof r->note, "rotated once %ld, twice %ld, reversed %ld",
             parts[0].failures, parts[1].failures, parts[2].failures);
}

/* ================================================================== */
/* Determinism                                                         */

static rt_scene *determinism_scene(int which)
{
    rb_mesh m = {0};
    rb_view view;
    rb_invariance_scene(&m, &view);
    double scales[3] = {1, 1e-6, 1};
    rt_vec3 shifts[3] = {rb_v(0, 0, 0), rb_v(0, 0, 0), rb_v(1e6, 1e6, -1e6)};
    rb_mesh_transform(&m, scales[which], shifts[which]);
    rb_view_transform(&view, scales[which], shifts[which]);
    rt_scene *scene = rb_scene(&m, &view);
    rb_mesh_free(&m);
    return scene;
}

static void render_with(const rt_scene *scene, rt_precision precision,
                        int threads, rt_kernel_choice kernel, rt_image *image)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.precision = precision;
    options.threads = threads;
    options.kernel = kernel;
    options.accel = rb_accel();
    rt_render(scene, &options, image, NULL);
}

/* Thread counts 1, 2, 3 and 8, and the scalar and AVX2 loops, give the
 * same image bit for bit. */
static void determinism(rb_method method, rt_precision precision, rb_result *r,
                        int vary_kernel)
{
    if (method != RB_OURS) {
        rb_not_applicable(r, "a single-threaded scalar loop");
        return;
    }
    for (int which = 0; which < 3; which++) {
        rt_scene *scene = determinism_scene(which);
        if (rt_scene_check_precision(scene, precision, NULL) != RT_OK) {
            /* float refuses the translated scene (RT_FLOAT_SPREAD_MAX):
             * every render of it is refused alike */
            snprintf(r->note, sizeof r->note, "float refuses the scene "
                                              "translated by 1e6");
            rt_scene_destroy(scene);
            continue;
        }
        rt_image reference, other;
        rt_image_init(&reference, 64, 64, NULL);
        rt_image_init(&other, 64, 64, NULL);
        render_with(scene, precision, 1, RT_KERNEL_SCALAR, &reference);
        static const int threads[4] = {1, 2, 3, 8};
        for (int k = 0; k < 4; k++) {
            memset(other.pixels, 0x55, 64 * 64 * 3);
            render_with(scene, precision, vary_kernel ? 2 : threads[k],
                        vary_kernel && k % 2 ? RT_KERNEL_SCALAR : RT_KERNEL_AUTO,
                        &other);
            r->total += 64 * 64;
            r->failures += rb_count_differing(&reference, &other);
        }
        rt_image_release(&reference);
        rt_image_release(&other);
        rt_scene_destroy(scene);
    }
}

void rb_case_x1(rb_method m, rt_precision p, rb_result *r) { determinism(m, p, r, 0); }
void rb_case_x2(rb_method m, rt_precision p, rb_result *r) { determinism(m, p, r, 1); }

