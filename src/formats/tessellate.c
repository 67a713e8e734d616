/*
 * tessellate.c - spheres, open cones and planar polygons cut into facets
 * (see tessellate.h and docs/formats.md).
 *
 * A sphere is a latitude-longitude mesh: `bands` bands between the poles
 * and 2 * bands meridians, quads split along a diagonal, one triangle per
 * meridian at each pole.  Its deviation (the largest distance between a
 * facet and the sphere, along the radius) is that of its worst facet: all
 * vertices lie on the sphere, so a facet's farthest point from the sphere is
 * its point nearest the centre, which rt__tess_sphere_deviation finds
 * exactly for one facet of each shape (the bands are symmetric).  The band
 * count for a tolerance is the fewest whose deviation is within it.
 *
 * A cone or cylinder is two circles of `segments` points joined by
 * planar trapezoids: its deviation is r (1 - cos(pi / segments)) at the wider
 * end, so the segment count comes straight from the tolerance.
 *
 * A curved surface whose vertices round together (a radius of a few ulps of
 * its centre's coordinates) would give facets of zero area, which no ray
 * meets: they are left out and counted in the mesh, for the reader's one
 * warning.
 *
 * Polygons go to the readers' one triangulator (triangulate.h).
 *
 * Every vertex of a curved surface carries the exact normal of the surface
 * there (tessellate.h): a sphere's is the unit point it was scaled from; a
 * cone's, at azimuth phi, is normalise(h rho + (r0 - r1) w), rho = u cos phi
 * + v sin phi the radial direction, w the unit axis and h the height (the
 * side's generator is h w + (r1 - r0) rho, and this is perpendicular to it
 * and to the circle's tangent).  A cone's point end (radius 0) has no one
 * normal: it is one vertex per segment, at the same point, with the normal
 * of the segment's middle generator.  The positions are those the surface
 * had before it had normals, computed the same way.
 */
#include "formats/tessellate.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/exact.h"
#include "formats/triangulate.h"
#include "raytrace/render.h"
#include "scene/scene_build.h"
#include "base/vecmath.h"

/* Facets cut between two polls of the cancellation flag. */
#define POLL_FACETS 4096

#define PI 3.14159265358979323846

void rt__tess_mesh_free(rt_tess_mesh *mesh)
{
    free(mesh->vertices);
    free(mesh->normals);
    free(mesh->facets);
    free(mesh->facet_lines);
    memset(mesh, 0, sizeof *mesh);
}

static int grow(void **array, int *capacity, double needed, size_t size,
                double most)
{
    if (needed <= *capacity)
        return 0;
    if (needed > most)
        return -1;
    double bigger = *capacity > 0 ? 2.0 * *capacity : 64.0;
    if (bigger < needed)
        bigger = needed;
    if (bigger > most)
        bigger = most;
    void *grown = realloc(*array, (size_t)bigger * size);
    if (grown == NULL)
        return -1;
    *array = grown;
    *capacity = (int)bigger;
    return 0;
}

double rt__tess_budget(size_t bytes)
{
    double budget = RT_TESS_BUDGET_BASE + RT_TESS_BUDGET_PER_BYTE *
                                              (double)bytes;
    return budget < RT_TESS_MAX_FACETS ? budget : RT_TESS_MAX_FACETS;
}

int rt__tess_reserve(rt_tess_mesh *mesh, double vertices, double facets)
{
    double nv = mesh->vertex_count + vertices;
    double nf = mesh->facet_count + facets;
    if (grow((void **)&mesh->vertices, &mesh->vertex_capacity, nv,
             sizeof *mesh->vertices, (double)INT_MAX) != 0)
        return -1;
    if (mesh->normals != NULL && mesh->normal_capacity < mesh->vertex_capacity) {
        rt_vec3 *normals = realloc(mesh->normals,
                                   (size_t)mesh->vertex_capacity *
                                       sizeof *mesh->normals);
        if (normals == NULL)
            return -1;
        mesh->normals = normals;
        mesh->normal_capacity = mesh->vertex_capacity;
    }
    int lines_capacity = mesh->facet_capacity;
    if (grow((void **)&mesh->facets, &mesh->facet_capacity, nf,
             sizeof *mesh->facets, (double)RT_TESS_MAX_FACETS) != 0)
        return -1;
    if (grow((void **)&mesh->facet_lines, &lines_capacity, nf,
             sizeof *mesh->facet_lines, (double)RT_TESS_MAX_FACETS) != 0 ||
        lines_capacity != mesh->facet_capacity) {
        /* keep both arrays the same size */
        int *lines = realloc(mesh->facet_lines,
                             (size_t)mesh->facet_capacity *
                                 sizeof *mesh->facet_lines);
        if (lines == NULL)
            return -1;
        mesh->facet_lines = lines;
    }
    return 0;
}

/* The mesh's normals, made (zero for the vertices it has) for every
 * vertex it has room for: 0, or -1 when out of memory.  Called after
 * rt__tess_reserve, which keeps them as large as the vertices. */
static int keep_normals(rt_tess_mesh *mesh)
{
    if (mesh->normals != NULL)
        return 0;
    size_t room = mesh->vertex_capacity > 0 ? (size_t)mesh->vertex_capacity : 1;
    mesh->normals = calloc(room, sizeof *mesh->normals);
    if (mesh->normals == NULL)
        return -1;
    mesh->normal_capacity = (int)room;
    return 0;
}

static int add_vertex(rt_tess_mesh *mesh, rt_vec3 p)
{
    if (mesh->normals != NULL)
        mesh->normals[mesh->vertex_count] = (rt_vec3){0.0, 0.0, 0.0};
    mesh->vertices[mesh->vertex_count] = p;
    return mesh->vertex_count++;
}

/* A vertex with its normal (keep_normals called). */
static int add_normal_vertex(rt_tess_mesh *mesh, rt_vec3 p, rt_vec3 n)
{
    mesh->normals[mesh->vertex_count] = n;
    mesh->vertices[mesh->vertex_count] = p;
    return mesh->vertex_count++;
}

static void add_facet(rt_tess_mesh *mesh, const rt_facet_desc *facet,
                      int line, int a, int b, int c, int inward)
{
    rt_facet_desc *f = &mesh->facets[mesh->facet_count];
    *f = *facet;
    f->vertex[0] = a;
    f->vertex[1] = inward ? c : b;
    f->vertex[2] = inward ? b : c;
    mesh->facet_lines[mesh->facet_count++] = line;
}

/* A facet of a curved surface: as add_facet, unless its corners are
 * collinear (counted instead). */
static void add_surface_facet(rt_tess_mesh *mesh, const rt_facet_desc *facet,
                              int line, int a, int b, int c, int inward)
{
    const rt_vec3 *v = mesh->vertices;
    rt_vec3 n = rt__exact_cross(v[a], v[b], v[c]);
    if (n.x == 0 && n.y == 0 && n.z == 0) {
        mesh->dropped++;
        return;
    }
    add_facet(mesh, facet, line, a, b, c, inward);
}

/* Non-zero when the mesh's flag is raised; looked at when `done` (facets
 * cut so far) crosses a multiple of POLL_FACETS. */
static int cancelled(const rt_tess_mesh *mesh, long before, long done)
{
    return mesh->cancel != NULL && before / POLL_FACETS != done / POLL_FACETS &&
           rt_cancel_requested(mesh->cancel);
}

int rt__tess_circle_segments(double tolerance)
{
    if (!(tolerance > 0.0 && tolerance < 1.0))
        return 0;
    /* the fewest n with cos(pi / n) >= 1 - tolerance */
    double half = acos(1.0 - tolerance);
    double n = ceil(PI / half);
    if (!(n <= (double)(1 << 24)))
        return 0;
    int segments = n < 3 ? 3 : (int)n;
    while (segments > 3 && 1.0 - cos(PI / (segments - 1)) <= tolerance)
        segments--;
    while (1.0 - cos(PI / segments) > tolerance)
        segments++;
    return segments;
}

/* The point of triangle abc nearest the origin (Ericson, Real-Time
 * Collision Detection, 5.1.5). */
static rt_vec3 nearest_to_origin(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    rt_vec3 ab = v3_sub(b, a), ac = v3_sub(c, a);
    rt_vec3 ap = v3_neg(a);
    double d1 = v3_dot(ab, ap), d2 = v3_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    rt_vec3 bp = v3_neg(b);
    double d3 = v3_dot(ab, bp), d4 = v3_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return v3_add(a, v3_scale(ab, d1 / (d1 - d3)));
    rt_vec3 cp = v3_neg(c);
    double d5 = v3_dot(ab, cp), d6 = v3_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return v3_add(a, v3_scale(ac, d2 / (d2 - d6)));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return v3_add(b, v3_scale(v3_sub(c, b),
                                  (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    double denom = 1.0 / (va + vb + vc);
    return v3_add(a, v3_add(v3_scale(ab, vb * denom),
                            v3_scale(ac, vc * denom)));
}

/* A point of the unit sphere: polar angle theta from +z, azimuth phi. */
static rt_vec3 unit_point(int bands, int i, int j)
{
    if (i == 0)
        return v3(0, 0, 1);
    if (i == bands)
        return v3(0, 0, -1);
    double theta = PI * i / bands, phi = PI * j / bands;
    return v3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

static double triangle_deviation(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    return 1.0 - v3_length(nearest_to_origin(a, b, c));
}

double rt__tess_sphere_deviation(int bands)
{
    double worst = 0.0;
    for (int i = 0; i < bands; i++) {
        if (i > bands - 1 - i)
            break;          /* the southern half mirrors the northern */
        rt_vec3 a = unit_point(bands, i, 0), b = unit_point(bands, i + 1, 0);
        rt_vec3 c = unit_point(bands, i + 1, 1), d = unit_point(bands, i, 1);
        double e = triangle_deviation(a, b, c);
        if (i > 0 && i < bands - 1) {
            double f = triangle_deviation(a, c, d);
            if (f > e)
                e = f;
        } else if (i == bands - 1) {
            e = triangle_deviation(a, b, d);
        }
        if (e > worst)
            worst = e;
    }
    return worst;
}

double rt__tess_sphere_facet_count(int bands)
{
    return 4.0 * bands * (bands - 1.0);
}

double rt__tess_sphere_vertex_count(int bands)
{
    return 2.0 * bands * (bands - 1.0) + 2.0;
}

int rt__tess_sphere_bands(double tolerance)
{
    if (!(tolerance > 0.0 && tolerance < 1.0))
        return 0;
    /* A meridian's chords alone need pi / bands <= 2 acos(1 - tol). */
    double low = ceil(PI / (2.0 * acos(1.0 - tolerance)));
    if (low < 2)
        low = 2;
    if (rt__tess_sphere_facet_count((int)fmin(low, 1e6)) > RT_TESS_MAX_FACETS)
        return 0;
    int lo = (int)low - 1, hi = (int)low;
    while (rt__tess_sphere_deviation(hi) > tolerance) {
        lo = hi;
        hi *= 2;
        if (rt__tess_sphere_facet_count(hi) > 4.0 * RT_TESS_MAX_FACETS)
            return 0;
    }
    /* deviation(lo) > tol or lo below 2; deviation(hi) <= tol */
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (mid >= 2 && rt__tess_sphere_deviation(mid) <= tolerance)
            hi = mid;
        else
            lo = mid;
    }
    if (rt__tess_sphere_facet_count(hi) > RT_TESS_MAX_FACETS)
        return 0;
    return hi;
}

int rt__tess_sphere(rt_tess_mesh *mesh, rt_vec3 center, double radius,
                    int inward, int bands, const rt_facet_desc *facet,
                    int line)
{
    if (rt__tess_reserve(mesh, rt__tess_sphere_vertex_count(bands),
                         rt__tess_sphere_facet_count(bands)) != 0 ||
        keep_normals(mesh) != 0)
        return -1;
    int m = 2 * bands;
    /* the normals face as the facets are wound */
    double side = inward ? -1.0 : 1.0;
    int north = add_normal_vertex(mesh, v3_add(center, v3(0, 0, radius)),
                                  v3(0, 0, side));
    int first = mesh->vertex_count;     /* ring i (1..bands-1), point j */
    for (int i = 1; i < bands; i++)
        for (int j = 0; j < m; j++) {
            rt_vec3 unit = unit_point(bands, i, j);
            add_normal_vertex(mesh, v3_add(center, v3_scale(unit, radius)),
                              v3_scale(unit, side));
        }
    int south = add_normal_vertex(mesh, v3_add(center, v3(0, 0, -radius)),
                                  v3(0, 0, -side));
#define RING(i, j) (first + ((i) - 1) * m + ((j) % m))
    for (int j = 0; j < m; j++)
        add_surface_facet(mesh, facet, line, north, RING(1, j),
                          RING(1, j + 1), inward);
    for (int i = 1; i < bands - 1; i++) {
        /* a band of 2m facets (at most 2^13 below RT_TESS_MAX_FACETS) */
        if (cancelled(mesh, 2L * m * (i - 1), 2L * m * i))
            return RT_TESS_CANCELLED;
        for (int j = 0; j < m; j++) {
            add_surface_facet(mesh, facet, line, RING(i, j), RING(i + 1, j),
                              RING(i + 1, j + 1), inward);
            add_surface_facet(mesh, facet, line, RING(i, j),
                              RING(i + 1, j + 1), RING(i, j + 1), inward);
        }
    }
    for (int j = 0; j < m; j++)
        add_surface_facet(mesh, facet, line, RING(bands - 1, j), south,
                          RING(bands - 1, j + 1), inward);
#undef RING
    return 0;
}

/* The unit normal of a cone's side at azimuth phi (the comment at the top),
 * times `side` (-1: facing inward). */
static rt_vec3 cone_normal(rt_vec3 u, rt_vec3 v, rt_vec3 w, double height,
                           double narrowing, double phi, double side)
{
    rt_vec3 rho = v3_add(v3_scale(u, cos(phi)), v3_scale(v, sin(phi)));
    rt_vec3 n = v3_add(v3_scale(rho, height), v3_scale(w, narrowing));
    return v3_scale(v3_normalize(n), side);
}

double rt__tess_cone_facet_count(int segments, double r0, double r1)
{
    return r0 > 0 && r1 > 0 ? 2.0 * segments : (double)segments;
}

int rt__tess_cone(rt_tess_mesh *mesh, rt_vec3 base, double r0, rt_vec3 apex,
                  double r1, int inward, int segments,
                  const rt_facet_desc *facet, int line)
{
    int n = segments;
    if (rt__tess_reserve(mesh, 2.0 * n,
                         rt__tess_cone_facet_count(n, r0, r1)) != 0 ||
        keep_normals(mesh) != 0)
        return -1;
    rt_vec3 w = v3_normalize(v3_sub(apex, base));
    /* u perpendicular to w, from the axis least aligned with it */
    rt_vec3 e = fabs(w.x) <= fabs(w.y) && fabs(w.x) <= fabs(w.z) ? v3(1, 0, 0)
                : fabs(w.y) <= fabs(w.z)                           ? v3(0, 1, 0)
                                                                   : v3(0, 0, 1);
    rt_vec3 u = v3_normalize(v3_cross(w, e));
    rt_vec3 v = v3_cross(w, u);         /* (u, v, w) right-handed */
    double height = v3_length(v3_sub(apex, base));
    double side = inward ? -1.0 : 1.0;
    /* A circle's points, or at a point end (radius 0) one copy of the
     * point per segment, its normal at the segment's middle. */
    int b0 = mesh->vertex_count;
    for (int j = 0; j < n; j++) {
        double phi = 2.0 * PI * j / n;
        double mid = 2.0 * PI * (j + 0.5) / n;
        rt_vec3 at = r0 > 0 ? v3_add(base, v3_add(v3_scale(u, r0 * cos(phi)),
                                                  v3_scale(v, r0 * sin(phi))))
                            : base;
        add_normal_vertex(mesh, at,
                          cone_normal(u, v, w, height, r0 - r1,
                                      r0 > 0 ? phi : mid, side));
    }
    int a0 = mesh->vertex_count;
    for (int j = 0; j < n; j++) {
        double phi = 2.0 * PI * j / n;
        double mid = 2.0 * PI * (j + 0.5) / n;
        rt_vec3 at = r1 > 0 ? v3_add(apex, v3_add(v3_scale(u, r1 * cos(phi)),
                                                  v3_scale(v, r1 * sin(phi))))
                            : apex;
        add_normal_vertex(mesh, at,
                          cone_normal(u, v, w, height, r0 - r1,
                                      r1 > 0 ? phi : mid, side));
    }
    for (int j = 0; j < n; j++) {
        int k = (j + 1) % n;
        if (cancelled(mesh, 2L * j - 2, 2L * j))
            return RT_TESS_CANCELLED;
        if (r0 > 0 && r1 > 0) {
            add_surface_facet(mesh, facet, line, b0 + j, b0 + k, a0 + k,
                              inward);
            add_surface_facet(mesh, facet, line, b0 + j, a0 + k, a0 + j,
                              inward);
        } else if (r0 > 0) {
            add_surface_facet(mesh, facet, line, b0 + j, b0 + k, a0 + j,
                              inward);
        } else {
            add_surface_facet(mesh, facet, line, b0 + j, a0 + k, a0 + j,
                              inward);
        }
    }
    return 0;
}

/* Where the triangles of one NFF polygon go. */
typedef struct polygon_sink {
    rt_tess_mesh *mesh;
    const rt_facet_desc *facet;
    int line, first;
} polygon_sink;

/* Adds a triangle of the polygon, started at its lowest corner (the
 * rotation keeps its winding): with the corners handed over from the
 * second on, a convex polygon's triangles are then NFF's fan from the
 * first corner, (0, i, i+1), as this reader always made them. */
static rt_status polygon_facet(void *user, int a, int b, int c)
{
    polygon_sink *sink = user;
    int lowest = a < b ? (a < c ? 0 : 2) : (b < c ? 1 : 2);
    int v[3] = {a, b, c};
    add_facet(sink->mesh, sink->facet, sink->line,
              sink->first + v[lowest], sink->first + v[(lowest + 1) % 3],
              sink->first + v[(lowest + 2) % 3], 0);
    return RT_OK;
}

int rt__tess_polygon_convex(const rt_vec3 *points, int n)
{
    rt_triangulator t;
    rt__tri_init(&t, 0, NULL);
    int convex = rt__tri_is_convex(&t, points, NULL, n);
    rt__tri_free(&t);
    return convex;
}

int rt__tess_polygon(rt_tess_mesh *mesh, const rt_vec3 *points, int n,
                     const rt_facet_desc *facet, int line, int *irregular)
{
    return rt__tess_patch(mesh, points, NULL, n, facet, line, irregular);
}

int rt__tess_patch(rt_tess_mesh *mesh, const rt_vec3 *points,
                   const rt_vec3 *normals, int n, const rt_facet_desc *facet,
                   int line, int *irregular)
{
    if (rt__tess_reserve(mesh, n, n - 2) != 0 ||
        (normals != NULL && keep_normals(mesh) != 0))
        return -1;
    int first = mesh->vertex_count;
    for (int i = 0; i < n; i++) {
        if (normals != NULL)
            add_normal_vertex(mesh, points[i], normals[i]);
        else
            add_vertex(mesh, points[i]);
    }
    if (n == 3) {
        if (rt__triangle_has_area(points[0], points[1], points[2]))
            add_facet(mesh, facet, line, first, first + 1, first + 2, 0);
        else
            *irregular = 1;
        return 0;
    }
    /* The corners from the second on and the first last: the
     * triangulator's fans start at the last corner, NFF's at the first
     * (polygon_facet). */
    int *order = malloc((size_t)n * sizeof *order);
    if (order == NULL)
        return -1;
    for (int i = 0; i < n; i++)
        order[i] = (i + 1) % n;
    rt_triangulator t;
    rt__tri_init(&t, (double)RT_TESS_POLYGON_WORK_PER_CORNER * n, NULL);
    polygon_sink sink = {mesh, facet, line, first};
    rt_tri_result result;
    rt_status status = rt__triangulate(&t, points, order, n, polygon_facet,
                                       &sink, &result);
    rt__tri_free(&t);
    free(order);
    if (status != RT_OK)
        return -1;
    if (result.crossing || result.over_budget || result.facets == 0)
        *irregular = 1;
    return 0;
}
