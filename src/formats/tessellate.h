/*
 * tessellate.h - spheres, cones and polygons turned into triangles
 * (internal), for the readers of formats that describe curved surfaces or
 * polygons (NFF).  Every curved surface is cut so that no point of its
 * facets is farther from the true surface than `tolerance` times its radius
 * (measured along the radius), and every facet is wound counter-clockwise
 * seen from outside (outward normal (b - a) x (c - a)) unless asked to face
 * inward.  Every vertex of a curved surface carries the surface's exact unit
 * normal there, facing as the facets are wound (a cone's point end is one
 * vertex per segment, each with the normal of its segment's middle); a
 * patch's vertices carry the normals given.  A curved surface emits no
 * zero-area facet (it counts them in
 * the mesh instead), and polls the mesh's cancellation flag as it goes.
 */
#ifndef RAYTRACE_TESSELLATE_H
#define RAYTRACE_TESSELLATE_H

#include "raytrace/scene.h"

/* The most facets a mesh may hold (16 Mi): about 1 GiB of descriptions. */
#define RT_TESS_MAX_FACETS (1 << 24)

/*
 * The facets a file of `bytes` bytes may make in all (rt__tess_budget):
 * RT_TESS_BUDGET_BASE + RT_TESS_BUDGET_PER_BYTE * bytes, at most
 * RT_TESS_MAX_FACETS.  A facet costs about 300 bytes at the peak of a load
 * (docs/robustness-input.md), and one line of 10 bytes (`s 0 0 0 1`) can
 * ask for the finest sphere (198 024 facets), so without a budget a few
 * hundred bytes took gigabytes.  The base holds five of the finest spheres
 * in any file (about 300 MB at the peak), every SPD scene at its own
 * resolution (at most 54 400 facets), and the per-byte term lets a large
 * file of small spheres keep the tessellation the view asks for (the SPD's
 * balls at size 4: 4 facets a byte).  --tessellate (a larger tolerance)
 * is the way to fewer facets.
 */
#define RT_TESS_BUDGET_BASE (1 << 20)
#define RT_TESS_BUDGET_PER_BYTE 32

/* The budget above for a file of `bytes` bytes. */
double rt__tess_budget(size_t bytes);

/* A growing list of vertices and facets, with each facet's source line. */
typedef struct rt_tess_mesh {
    rt_vec3 *vertices;
    int vertex_count, vertex_capacity;
    rt_vec3 *normals;       /* NULL until a vertex has a normal; then one a
                               vertex (zero: none), as rt_scene_desc's */
    int normal_capacity;
    rt_facet_desc *facets;
    int *facet_lines;
    int facet_count, facet_capacity;
    int dropped;            /* zero-area facets of curved surfaces, left out */
    const rt_cancel *cancel; /* polled while a surface is cut; may be NULL */
} rt_tess_mesh;

/* What rt__tess_sphere and rt__tess_cone return when the mesh's flag was
 * raised (0: done; -1: out of memory). */
#define RT_TESS_CANCELLED 1

void rt__tess_mesh_free(rt_tess_mesh *mesh);

/* Room for `vertices` more vertices and `facets` more facets: 0, or -1
 * when out of memory or past RT_TESS_MAX_FACETS / INT_MAX vertices. */
int rt__tess_reserve(rt_tess_mesh *mesh, double vertices, double facets);

/* The segments of a circle with r (1 - cos(pi / n)) <= tolerance r, the
 * fewest (at least 3); 0 when tolerance is not in (0, 1) or more than
 * 2^24 would be needed. */
int rt__tess_circle_segments(double tolerance);

/* The largest distance between the unit sphere and the facets of
 * rt__tess_sphere with `bands` bands (computed exactly, facet by
 * facet shape). */
double rt__tess_sphere_deviation(int bands);

/* The fewest bands (2 * bands meridians) whose deviation is at most
 * `tolerance`; 0 when tolerance is not in (0, 1) or the sphere would need
 * more than RT_TESS_MAX_FACETS facets. */
int rt__tess_sphere_bands(double tolerance);

/* Facets and vertices of a sphere of `bands` bands: 4 bands (bands - 1)
 * and 2 bands (bands - 1) + 2. */
double rt__tess_sphere_facet_count(int bands);
double rt__tess_sphere_vertex_count(int bands);

/* Facets of an open cone of `segments` segments (one radius 0: segments
 * triangles; otherwise 2 segments). */
double rt__tess_cone_facet_count(int segments, double r0, double r1);

/* Appends a sphere (poles along z) with every facet a copy of `facet`
 * (its vertex indices replaced) on `line`; bands >= 2 (2: an octahedron,
 * the coarsest).  0, -1 out of memory, or RT_TESS_CANCELLED. */
int rt__tess_sphere(rt_tess_mesh *mesh, rt_vec3 center, double radius,
                    int inward, int bands, const rt_facet_desc *facet,
                    int line);

/* Appends the open surface between the circle of radius r0 around `base`
 * and that of radius r1 around `apex`, perpendicular to the axis (no
 * caps); r0, r1 >= 0, not both 0, base != apex, segments >= 3.  Returns as
 * rt__tess_sphere. */
int rt__tess_cone(rt_tess_mesh *mesh, rt_vec3 base, double r0, rt_vec3 apex,
                  double r1, int inward, int segments,
                  const rt_facet_desc *facet, int line);

/* The ear-clipping budget of one NFF polygon, in corner tests
 * (triangulate.h): enough to clip any polygon of up to 2048 corners whole
 * (nff.c refuses non-convex ones beyond 1024), and in proportion to the
 * corners, each of which costs the file a line. */
#define RT_TESS_POLYGON_WORK_PER_CORNER 4096

/* Appends a polygon of n >= 3 vertices (all of them, in order) and its
 * triangles, cut by the readers' triangulator (triangulate.h) with the
 * polygon's winding: convex ones of up to RT_TRI_FAN_MAX_CORNERS corners
 * as a fan from the first vertex, larger ones balanced, others by ear
 * clipping.  No triangle without area is appended.  *irregular is set
 * non-zero when the polygon has no area, or no ear was left at some step
 * (it crosses itself) or the budget was spent (then the rest is a fan).
 * 0, or -1 out of memory. */
int rt__tess_polygon(rt_tess_mesh *mesh, const rt_vec3 *points, int n,
                     const rt_facet_desc *facet, int line, int *irregular);

/* The same with a normal at each vertex (as given; NULL: none), which the
 * triangles keep at their corners (NFF's `pp`). */
int rt__tess_patch(rt_tess_mesh *mesh, const rt_vec3 *points,
                   const rt_vec3 *normals, int n, const rt_facet_desc *facet,
                   int line, int *irregular);

/* Whether the polygon is convex in the plane of its normal (collinear
 * vertices allowed). */
int rt__tess_polygon_convex(const rt_vec3 *points, int n);

#endif /* RAYTRACE_TESSELLATE_H */
