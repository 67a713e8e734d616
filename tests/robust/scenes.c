/*
 * scenes.c - scene generators for the robustness cases: meshes whose facets
 * share vertices exactly (spheres, grids, boxes), transforms that move a
 * whole scene to another scale or place, and the small vector and random
 * helpers the cases use.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "probe.h"
#include "robust/robust.h"

rt_vec3 rb_add(rt_vec3 a, rt_vec3 b) { return rb_v(a.x + b.x, a.y + b.y, a.z + b.z); }
rt_vec3 rb_sub(rt_vec3 a, rt_vec3 b) { return rb_v(a.x - b.x, a.y - b.y, a.z - b.z); }
rt_vec3 rb_scale(rt_vec3 a, double s) { return rb_v(a.x * s, a.y * s, a.z * s); }
double rb_dot(rt_vec3 a, rt_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double rb_length(rt_vec3 a) { return sqrt(rb_dot(a, a)); }

rt_vec3 rb_cross(rt_vec3 a, rt_vec3 b)
{
    return rb_v(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                a.x * b.y - a.y * b.x);
}

rt_vec3 rb_lerp(rt_vec3 a, rt_vec3 b, double s)
{
    return rb_add(a, rb_scale(rb_sub(b, a), s));
}

rt_vec3 rb_rotate(rt_vec3 p)
{
    /* Rotations by 0.7 about z then 0.4 about x: no axis stays aligned. */
    double c1 = cos(0.7), s1 = sin(0.7), c2 = cos(0.4), s2 = sin(0.4);
    rt_vec3 q = rb_v(c1 * p.x - s1 * p.y, s1 * p.x + c1 * p.y, p.z);
    return rb_v(q.x, c2 * q.y - s2 * q.z, s2 * q.y + c2 * q.z);
}

int rb_scaled(int n)
{
    static int memcheck = -1;
    if (memcheck < 0)
        memcheck = rt_test_memcheck();
    if (!memcheck)
        return n;
    return n / 100 > 20 ? n / 100 : (n < 20 ? n : 20);
}

void rb_mesh_free(rb_mesh *mesh)
{
    free(mesh->vertices);
    free(mesh->facets);
    *mesh = (rb_mesh){0};
}

static void *grow(void *array, int *capacity, int needed, size_t size)
{
    if (needed <= *capacity)
        return array;
    int c = *capacity ? *capacity : 16;
    while (c < needed)
        c *= 2;
    void *p = realloc(array, (size_t)c * size);
    if (p == NULL) {
        fprintf(stderr, "robust: out of memory\n");
        abort();
    }
    *capacity = c;
    return p;
}

int rb_mesh_vertex(rb_mesh *m, rt_vec3 p)
{
    m->vertices = grow(m->vertices, &m->vertex_capacity, m->vertex_count + 1,
                       sizeof *m->vertices);
    m->vertices[m->vertex_count] = p;
    return m->vertex_count++;
}

int rb_mesh_facet(rb_mesh *m, int a, int b, int c, double k, rt_rgb8 color)
{
    m->facets = grow(m->facets, &m->facet_capacity, m->facet_count + 1,
                     sizeof *m->facets);
    m->facets[m->facet_count] = (rt_facet_desc){{a, b, c}, k, color};
    return m->facet_count++;
}

int rb_mesh_triangle(rb_mesh *m, rt_vec3 a, rt_vec3 b, rt_vec3 c, double k,
                     rt_rgb8 color)
{
    int ia = rb_mesh_vertex(m, a), ib = rb_mesh_vertex(m, b),
        ic = rb_mesh_vertex(m, c);
    return rb_mesh_facet(m, ia, ib, ic, k, color);
}

/* The midpoint vertex of edge (a, b), shared by both facets of the edge. */
static int midpoint(rb_mesh *m, int *cache, int cache_side, int a, int b,
                    rt_vec3 centre, double r)
{
    int lo = a < b ? a : b, hi = a < b ? b : a;
    int *slot = &cache[(size_t)lo * (size_t)cache_side + (size_t)hi];
    if (*slot >= 0)
        return *slot;
    rt_vec3 p = rb_scale(rb_add(rb_sub(m->vertices[a], centre),
                                rb_sub(m->vertices[b], centre)), 0.5);
    *slot = rb_mesh_vertex(m, rb_add(centre, rb_scale(p, r / rb_length(p))));
    return *slot;
}

void rb_mesh_icosphere(rb_mesh *m, rt_vec3 centre, double r, int levels,
                       double k, rt_rgb8 color)
{
    static const int faces[20][3] = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
        {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
        {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    double t = (1.0 + sqrt(5.0)) / 2.0;
    double corners[12][3] = {
        {-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
        {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
        {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    int base = m->vertex_count;
    for (int i = 0; i < 12; i++) {
        rt_vec3 p = rb_v(corners[i][0], corners[i][1], corners[i][2]);
        rb_mesh_vertex(m, rb_add(centre, rb_scale(p, r / rb_length(p))));
    }
    int count = 20;
    int *tris = malloc(sizeof(int) * 3 * 20);
    for (int i = 0; i < 20; i++)
        for (int j = 0; j < 3; j++)
            tris[3 * i + j] = base + faces[i][j];
    for (int level = 0; level < levels; level++) {
        int side = m->vertex_count + 3 * count;
        int *cache = malloc(sizeof(int) * (size_t)side * (size_t)side);
        for (size_t i = 0; i < (size_t)side * (size_t)side; i++)
            cache[i] = -1;
        int *next = malloc(sizeof(int) * 3 * 4 * (size_t)count);
        for (int i = 0; i < count; i++) {
            int a = tris[3 * i], b = tris[3 * i + 1], c = tris[3 * i + 2];
            int ab = midpoint(m, cache, side, a, b, centre, r);
            int bc = midpoint(m, cache, side, b, c, centre, r);
            int ca = midpoint(m, cache, side, c, a, centre, r);
            int out[4][3] = {{a, ab, ca}, {b, bc, ab}, {c, ca, bc},
                             {ab, bc, ca}};
            for (int j = 0; j < 4; j++)
                for (int l = 0; l < 3; l++)
                    next[12 * i + 3 * j + l] = out[j][l];
        }
        free(cache);
        free(tris);
        tris = next;
        count *= 4;
    }
    for (int i = 0; i < count; i++)
        rb_mesh_facet(m, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], k,
                      color);
    free(tris);
}

void rb_mesh_grid(rb_mesh *m, rt_vec3 corner, rt_vec3 u, rt_vec3 v, int n,
                  int alternate, double k, rt_rgb8 color)
{
    int base = m->vertex_count;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++)
            rb_mesh_vertex(m, rb_add(corner, rb_add(rb_scale(u, i),
                                                    rb_scale(v, j))));
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++) {
            int p00 = base + j * (n + 1) + i, p10 = p00 + 1;
            int p01 = p00 + n + 1, p11 = p01 + 1;
            if (alternate && (i + j) % 2) {
                rb_mesh_facet(m, p00, p11, p10, k, color);
                rb_mesh_facet(m, p00, p01, p11, k, color);
            } else if (alternate) {
                rb_mesh_facet(m, p10, p01, p00, k, color);
                rb_mesh_facet(m, p10, p11, p01, k, color);
            } else {
                rb_mesh_facet(m, p00, p10, p11, k, color);
                rb_mesh_facet(m, p00, p11, p01, k, color);
            }
        }
    }
}

void rb_mesh_box(rb_mesh *m, rt_vec3 lo, rt_vec3 hi, double k, rt_rgb8 color)
{
    int base = m->vertex_count;
    for (int i = 0; i < 8; i++)
        rb_mesh_vertex(m, rb_v(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y,
                               i & 4 ? hi.z : lo.z));
    static const int quads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                    {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (int q = 0; q < 6; q++) {
        rb_mesh_facet(m, base + quads[q][0], base + quads[q][1],
                      base + quads[q][2], k, color);
        rb_mesh_facet(m, base + quads[q][0], base + quads[q][2],
                      base + quads[q][3], k, color);
    }
}

rt_vec3 rb_transform_point(rt_vec3 p, double scale, rt_vec3 shift)
{
    return rb_add(rb_scale(p, scale), shift);
}

void rb_mesh_transform(rb_mesh *m, double scale, rt_vec3 shift)
{
    for (int i = 0; i < m->vertex_count; i++)
        m->vertices[i] = rb_transform_point(m->vertices[i], scale, shift);
}

void rb_view_transform(rb_view *view, double scale, rt_vec3 shift)
{
    view->observer = rb_transform_point(view->observer, scale, shift);
    view->screen_center = rb_transform_point(view->screen_center, scale, shift);
    view->screen_right = rb_transform_point(view->screen_right, scale, shift);
    view->light = rb_transform_point(view->light, scale, shift);
}

int rb_mesh_vertex_shared(rb_mesh *m, rt_vec3 p)
{
    for (int i = 0; i < m->vertex_count; i++)
        if (m->vertices[i].x == p.x && m->vertices[i].y == p.y &&
            m->vertices[i].z == p.z)
            return i;
    return rb_mesh_vertex(m, p);
}

int rb_mesh_quad(rb_mesh *m, rt_vec3 p0, rt_vec3 p1, rt_vec3 p2, rt_vec3 p3,
                 double k, rt_rgb8 color)
{
    int a = rb_mesh_vertex_shared(m, p0), b = rb_mesh_vertex_shared(m, p1),
        c = rb_mesh_vertex_shared(m, p2), d = rb_mesh_vertex_shared(m, p3);
    int first = rb_mesh_facet(m, a, b, c, k, color);
    rb_mesh_facet(m, a, c, d, k, color);
    return first;
}

void rb_mesh_orient_outward(rb_mesh *m, int first, rt_vec3 inside)
{
    for (int i = first; i < m->facet_count; i++) {
        int *v = m->facets[i].vertex;
        rt_vec3 a = m->vertices[v[0]], b = m->vertices[v[1]],
                c = m->vertices[v[2]];
        rt_vec3 n = rb_cross(rb_sub(b, a), rb_sub(c, a));
        if (rb_dot(n, rb_sub(a, inside)) < 0) {
            int swap = v[1];
            v[1] = v[2];
            v[2] = swap;
        }
    }
}

void rb_mesh_glass(rb_mesh *m, int first, double t, double n)
{
    for (int i = first; i < m->facet_count; i++) {
        m->facets[i].reflection = 0;
        m->facets[i].transparency = t;
        m->facets[i].refractive_index = n;
        m->facets[i].diffuse = 0;
        m->facets[i].diffuse_given = 1;
    }
}

rt_scene *rb_scene(const rb_mesh *mesh, const rb_view *view)
{
    return rb_scene_lights(mesh, view, NULL, 0);
}

rt_scene *rb_scene_lights(const rb_mesh *mesh, const rb_view *view,
                          const rt_light *further, int further_count)
{
    rt_light lights[RT_MAX_LIGHTS];
    if (further_count < 0 || further_count > RT_MAX_LIGHTS - 1) {
        fprintf(stderr, "robust: %d further lights\n", further_count);
        return NULL;
    }
    lights[0] = (rt_light){view->light, view->light_color};
    for (int i = 0; i < further_count; i++)
        lights[1 + i] = further[i];
    rt_scene_desc desc = {
        .observer = view->observer,
        .screen_center = view->screen_center,
        .screen_right = view->screen_right,
        .width = view->width > 0 ? view->width : 1,
        .height = view->height > 0 ? view->height : 1,
        .vertices = mesh->vertices,
        .vertex_count = mesh->vertex_count,
        .facets = mesh->facets,
        .facet_count = mesh->facet_count,
        .background = view->background,
        .lights = lights,
        .light_count = 1 + further_count};
    rt_scene *scene = NULL;
    rt_error error;
    if (rt_scene_create(&desc, &scene, &error) != RT_OK) {
        fprintf(stderr, "robust: scene refused: %s\n", error.message);
        return NULL;
    }
    return scene;
}
