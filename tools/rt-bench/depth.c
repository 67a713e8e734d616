/*
 * depth.c - the truncation bound of a scene and the depth analysis of
 * rt-bench (see depth.h).
 */
#include "depth.h"

#include <math.h>

static double distance_to_plane(rt_vec3 p, rt_vec3 a, rt_vec3 normal)
{
    return fabs((p.x - a.x) * normal.x + (p.y - a.y) * normal.y +
                (p.z - a.z) * normal.z);
}

static double max3(double a, double b, double c)
{
    return fmax(a, fmax(b, c));
}

/*
 * The constants of the truncation bound of the scene's facets.  A hit's
 * colour is (k + t) times what its two rays carry (at most peak) plus
 * d times its local term (at most the sum over the lights of C_S C_F / 255
 * per channel), so peak >= local d / (1 - k - t) keeps every colour within
 * peak; a facet with k + t = 1 and d > 0 bounds nothing (peak infinite, so
 * the bound is the 255 levels of the format).
 */
bench_depth_bound bench_find_depth_bound(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    bench_depth_bound b = {max3(info.background.r, info.background.g,
                                info.background.b), 0.0, 0.0};
    double light[3] = {0.0, 0.0, 0.0};
    for (int l = 0; l < info.light_count; l++) {
        rt_light s;
        rt_scene_light(scene, l, &s);
        light[0] += s.color.r, light[1] += s.color.g, light[2] += s.color.b;
    }
    double extent = 0.0;
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        extent = fmax(extent, max3(fabs(v.x), fabs(v.y), fabs(v.z)));
    }
    int top = -1;
    rt_facet_info f = {.size = sizeof f}, g = {.size = sizeof g};
    for (int i = 0; i < info.facet_count; i++) {
        rt_scene_facet(scene, i, &f);
        if (f.degenerate)
            continue;
        double carried = f.reflection + f.transparency;
        double local = f.diffuse *
                       max3(light[0] * f.color.r, light[1] * f.color.g,
                            light[2] * f.color.b) /
                       255.0;
        b.peak = fmax(b.peak, bench_peak_needed(local, carried));
        if (top < 0 || carried > b.k_max) {
            top = i;
            b.k_max = carried;
        }
    }
    if (top < 0)
        return b;
    /* The best pair holds a facet of largest k + t: any facet coplanar
     * with the other member of a better pair would be coplanar with it
     * too. */
    rt_scene_facet(scene, top, &f);
    rt_vec3 a = rt_scene_vertex(scene, f.vertex[0]);
    double tolerance = 1e-9 * fmax(extent, 1e-300);
    for (int i = 0; i < info.facet_count; i++) {
        rt_scene_facet(scene, i, &g);
        if (g.degenerate)
            continue;
        int coplanar = 1;
        for (int v = 0; v < 3; v++)
            coplanar &= distance_to_plane(rt_scene_vertex(scene, g.vertex[v]),
                                          a, f.normal) <= tolerance;
        if (!coplanar)
            b.pair = fmax(b.pair, (f.reflection + f.transparency) *
                                      (g.reflection + g.transparency));
    }
    return b;
}

int bench_analyse_depth(const rt_scene *scene, const rt_render_options *base,
                        const bench_depth_bound *b, int ref_depth,
                        bench_images *im, FILE *csv, int *converged_at,
                        int *reference_stable)
{
    bench_settings s = {RT_PRECISION_DOUBLE, 0, 1, RT_SAMPLING_REGULAR,
                        ref_depth};
    double seconds;
    if (!bench_render(scene, &s, base, &im->depth_reference, &seconds))
        return 0;
    s.depth = ref_depth + 1;
    if (!bench_render(scene, &s, base, &im->scratch, &seconds))
        return 0;
    bench_error e;
    bench_compare(&im->scratch, &im->depth_reference, &e);
    *reference_stable = e.differing == 0;
    unsigned long long reference_hash = bench_image_hash(&im->depth_reference);
    unsigned long long previous_hash = 0;
    *converged_at = -1;
    printf("\ndepth truncation, 1 ray per pixel in double, against depth %d "
           "(bound: docs/accuracy.md)\n"
           "%5s %14s %11s | %12s %8s %8s\n",
           ref_depth, "depth", "bound levels", "allowed max", "measured max",
           "RMSE", "%diff");
    fprintf(csv, "depth,bound_levels,allowed_max,measured_max,rmse,"
                 "differing,differing_pct,within_bound\n");
    int all_within = 1;
    for (int d = 0; d <= ref_depth; d++) {
        s.depth = d;
        if (d < ref_depth &&
            !bench_render(scene, &s, base, &im->scratch, &seconds))
            return 0;
        const rt_image *image = d < ref_depth ? &im->scratch
                                              : &im->depth_reference;
        unsigned long long hash = d < ref_depth ? bench_image_hash(image)
                                                : reference_hash;
        if (d > 0 && *converged_at < 0 && hash == previous_hash)
            *converged_at = d - 1;
        previous_hash = hash;
        bench_compare(image, &im->depth_reference, &e);
        double bound = bench_truncation_bound(b, d);
        int allowed = (int)ceil(bound);
        int within = e.max_error <= allowed;
        all_within &= within;
        printf("%5d %14.6g %11d | %12d %8.4f %8.4f%s\n", d, bound, allowed,
               e.max_error, e.rmse, bench_percent(e.differing, e.pixels),
               within ? "" : "  EXCEEDS THE BOUND");
        fprintf(csv, "%d,%.6g,%d,%d,%.6g,%ld,%.6g,%d\n", d, bound, allowed,
                e.max_error, e.rmse, e.differing,
                bench_percent(e.differing, e.pixels), within);
    }
    if (*converged_at < 0 && *reference_stable)
        *converged_at = ref_depth;
    printf("measured within the bound at every depth: %s; first depth that "
           "one more bounce leaves byte-identical: %d; depth %d vs %d: %s\n",
           all_within ? "yes" : "NO", *converged_at, ref_depth + 1,
           ref_depth, *reference_stable ? "byte-identical" : "DIFFERENT");
    return 1;
}
