/*
 * bench_scenes.c - generated benchmark scenes (a tessellated sphere, a
 * random soup of triangles), through the public scene builder
 * (rt_scene_create).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "bench_scenes.h"

/* A camera at `observer` looking at the origin, z up, a screen of half
 * width `half_width` at distance 1. */
static void look_at_origin(rt_scene_desc *d, rt_vec3 observer,
                           double half_width)
{
    double n = sqrt(observer.x * observer.x + observer.y * observer.y +
                    observer.z * observer.z);
    rt_vec3 dir = {-observer.x / n, -observer.y / n, -observer.z / n};
    /* right = dir x (0, 0, 1), normalised */
    rt_vec3 right = {dir.y, -dir.x, 0.0};
    double r = sqrt(right.x * right.x + right.y * right.y);
    d->observer = observer;
    d->screen_center = (rt_vec3){observer.x + dir.x, observer.y + dir.y,
                                 observer.z + dir.z};
    d->screen_right = (rt_vec3){d->screen_center.x + right.x / r * half_width,
                                d->screen_center.y + right.y / r * half_width,
                                d->screen_center.z};
}

static rt_status build(rt_scene_desc *d, rt_vec3 *vertices,
                       rt_facet_desc *facets, rt_scene **scene,
                       rt_error *error)
{
    rt_status status = RT_ERR_NOMEM;
    if (vertices != NULL && facets != NULL) {
        d->vertices = vertices;
        d->facets = facets;
        status = rt_scene_create(d, scene, error);
    }
    free(vertices);
    free(facets);
    return status;
}

rt_status bench_sphere(int facets, int width, int height, rt_scene **scene,
                       rt_error *error)
{
    /* r rings of s = 2 r segments: 2 s (r - 1) facets (quads split in two,
     * the caps as fans). */
    int rings = 2;
    while (4 * rings * (rings - 1) < facets)
        rings++;
    int segments = 2 * rings;
    rt_scene_desc d = {.width = width, .height = height,
                       .background = {20, 30, 60},
                       .lights = &(rt_light){{-3.0, -4.0, 5.0},
                                             {255, 255, 255}},
                       .light_count = 1};
    look_at_origin(&d, (rt_vec3){0.5, -3.5, 1.0}, 0.4);
    int vertex_count = 2 + (rings - 1) * segments;
    int facet_count = 2 * segments * (rings - 1);
    rt_vec3 *v = malloc((size_t)vertex_count * sizeof *v);
    rt_facet_desc *f = malloc((size_t)facet_count * sizeof *f);
    if (v == NULL || f == NULL)
        return build(&d, v, f, scene, error);
    const double pi = 3.14159265358979323846;
    v[0] = (rt_vec3){0.0, 0.0, 1.0};
    v[1] = (rt_vec3){0.0, 0.0, -1.0};
    for (int i = 1; i < rings; i++) {
        double theta = pi * i / rings;
        for (int j = 0; j < segments; j++) {
            double phi = 2.0 * pi * j / segments;
            v[2 + (i - 1) * segments + j] =
                (rt_vec3){sin(theta) * cos(phi), sin(theta) * sin(phi),
                          cos(theta)};
        }
    }
    int n = 0;
    rt_rgb8 grey = {200, 200, 200};
    for (int j = 0; j < segments; j++) {
        int j1 = (j + 1) % segments;
        f[n++] = (rt_facet_desc){{0, 2 + j, 2 + j1}, 0.0, grey};
        int last = 2 + (rings - 2) * segments;
        f[n++] = (rt_facet_desc){{1, last + j1, last + j}, 0.0, grey};
        for (int i = 1; i < rings - 1; i++) {
            int a = 2 + (i - 1) * segments + j, b = 2 + (i - 1) * segments + j1;
            int c = a + segments, e = b + segments;
            f[n++] = (rt_facet_desc){{a, c, e}, 0.0, grey};
            f[n++] = (rt_facet_desc){{a, e, b}, 0.0, grey};
        }
    }
    d.vertex_count = vertex_count;
    d.facet_count = n;
    return build(&d, v, f, scene, error);
}

static uint32_t next(uint64_t *state)
{
    *state = *state * 6364136223846793005u + 1442695040888963407u;
    return (uint32_t)(*state >> 33);
}

static double uniform(uint64_t *state, double lo, double hi)
{
    return lo + (hi - lo) * (next(state) / 2147483648.0);
}

rt_status bench_soup(int facets, int width, int height, rt_scene **scene,
                     rt_error *error)
{
    rt_scene_desc d = {.width = width, .height = height,
                       .background = {40, 40, 40},
                       .lights = &(rt_light){{-2.5, -3.0, 4.0},
                                             {255, 255, 255}},
                       .light_count = 1};
    look_at_origin(&d, (rt_vec3){1.0, -4.0, 1.5}, 0.45);
    rt_vec3 *v = malloc((size_t)facets * 3 * sizeof *v);
    rt_facet_desc *f = calloc((size_t)facets, sizeof *f);
    if (v == NULL || f == NULL)
        return build(&d, v, f, scene, error);
    uint64_t state = 12345;
    /* triangles about as wide as the spacing of their centres */
    double size = 1.2 / cbrt((double)facets);
    for (int i = 0; i < facets; i++) {
        rt_vec3 c = {uniform(&state, -1, 1), uniform(&state, -1, 1),
                     uniform(&state, -1, 1)};
        for (int j = 0; j < 3; j++)
            v[3 * i + j] = (rt_vec3){c.x + uniform(&state, -size, size),
                                     c.y + uniform(&state, -size, size),
                                     c.z + uniform(&state, -size, size)};
        f[i].vertex[0] = 3 * i;
        f[i].vertex[1] = 3 * i + 1;
        f[i].vertex[2] = 3 * i + 2;
        f[i].reflection = i % 3 == 0 ? 0.3 : 0.0;
        f[i].color = (rt_rgb8){(unsigned char)(64 + next(&state) % 192),
                               (unsigned char)(64 + next(&state) % 192),
                               (unsigned char)(64 + next(&state) % 192)};
    }
    d.vertex_count = 3 * facets;
    d.facet_count = facets;
    return build(&d, v, f, scene, error);
}
