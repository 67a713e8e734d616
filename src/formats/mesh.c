/*
 * mesh.c - what the mesh readers share (mesh.h): the default material,
 * a face cut into facets, and the automatic camera and light that OBJ and
 * PLY files, which hold no view, are seen through.
 */
#include "formats/mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/exact.h"
#include "base/vecmath.h"
#include "formats/framing.h"

/* The automatic view (docs/formats.md): from the front (+z), to the right
 * (+x) and above (+y, OBJ's usual up), the horizontal field of view. */
#define VIEW_X 0.5
#define VIEW_Y 0.5
#define VIEW_Z 1.0
#define VIEW_FOV_DEGREES 40.0
#define VIEW_MARGIN 1.05
#define DEFAULT_SIDE 512

void rt__mesh_default_look(rt_facet_desc *facet)
{
    memset(facet, 0, sizeof *facet);
    facet->color = (rt_rgb8){RT_MESH_GREY, RT_MESH_GREY, RT_MESH_GREY};
}

/* ------------------------------------------------------------------ faces */

rt_status rt__mesh_face(rt_triangulator *t, const rt_vec3 *vertices,
                        int *corners, int n, rt_tri_emit emit, void *user,
                        rt_face_outcome *outcome)
{
    *outcome = RT_FACE_DRAWN;
    /* A corner repeated next to itself bounds nothing. */
    int *p = corners, m = 0;
    for (int i = 0; i < n; i++)
        if (m == 0 || p[i] != p[m - 1])
            p[m++] = p[i];
    while (m > 1 && p[m - 1] == p[0])
        m--;
    if (m < 3) {
        *outcome = RT_FACE_FEW_CORNERS;
        return RT_OK;
    }
    if (m == 3) {
        if (!rt__triangle_has_area(vertices[p[0]], vertices[p[1]],
                                   vertices[p[2]])) {
            *outcome = RT_FACE_FLAT_TRIANGLE;
            return RT_OK;
        }
        return emit(user, p[0], p[1], p[2]);
    }
    rt_tri_result result;
    rt_status status = rt__triangulate(t, vertices, p, m, emit, user,
                                       &result);
    if (status != RT_OK)
        return status;
    if (result.facets == 0)
        *outcome = RT_FACE_FLAT_POLYGON;
    else if (result.over_budget)
        *outcome = RT_FACE_OVER_BUDGET;
    else if (result.crossing)
        *outcome = RT_FACE_CROSSING;
    return RT_OK;
}

const char *rt__mesh_face_remark(rt_face_outcome outcome, char *buffer,
                                 size_t size)
{
    switch (outcome) {
    case RT_FACE_DRAWN:
        break;
    case RT_FACE_FEW_CORNERS:
        return "this face has fewer than 3 distinct corners and is left out";
    case RT_FACE_FLAT_TRIANGLE:
        return "this face has no area (its corners are on a line) and is "
               "left out";
    case RT_FACE_FLAT_POLYGON:
        return "this face has no area (its corners are on a line, or "
               "coincide) and is left out";
    case RT_FACE_OVER_BUDGET:
        snprintf(buffer, size,
                 "the load's budget for cutting non-convex polygons (%d "
                 "corner tests per byte of the file, plus %d) is spent: this "
                 "polygon is cut without looking for ears (each chain of "
                 "corners split at its middle), which may cover what it does "
                 "not",
                 RT_TRI_WORK_PER_BYTE, RT_TRI_WORK_FLOOR);
        return buffer;
    case RT_FACE_CROSSING:
        return "this polygon crosses itself or has no area: it is "
               "triangulated as a fan from its first corner, which may cover "
               "what it does not";
    }
    return "";
}

/* ---------------------------------------------------------------- the view */

/* fmax and fmin for finite values, as glibc gives them (the first argument
 * on a tie, so that the sign of a zero is the same), without the call:
 * the framing visits every corner of every facet four times. */
static double keep_max(double kept, double v)
{
    return kept >= v ? kept : v;
}

static double keep_min(double kept, double v)
{
    return kept <= v ? kept : v;
}

/*
 * The points the camera frames: the corners of the facets, or all vertices
 * when there is no facet.  The framing takes maxima and minima that keep
 * the first of equal values (keep_max, keep_min), so a corner seen again
 * changes nothing: each vertex is visited once, in the order of its first
 * corner (`order`), which gives the same camera as every corner in turn at
 * a sixth of the cost on a mesh; without the memory for the order, every
 * corner in turn.
 */
typedef struct framed_points {
    const rt_vec3 *vertices;
    const rt_facet_desc *facets;
    int facet_count;
    const int *order;       /* the vertices framed, or NULL */
} framed_points;

static rt_vec3 framed(const framed_points *f, long i)
{
    if (f->order != NULL)
        return f->vertices[f->order[i]];
    return f->vertices[f->facet_count > 0
                           ? f->facets[i / 3].vertex[i % 3]
                           : i];
}

/* The vertices of the facets in the order of their first corners, into a
 * new array (*order, freed by the caller; NULL when out of memory or
 * without facets); their count, or the points framed without it. */
static long first_corners(const framed_points *f, int vertex_count,
                          int **order)
{
    *order = NULL;
    if (f->facet_count == 0)
        return vertex_count;
    unsigned char *seen = calloc((size_t)vertex_count, 1);
    int *list = malloc((size_t)vertex_count * sizeof *list);
    if (seen == NULL || list == NULL) {
        free(seen);
        free(list);
        return 3L * f->facet_count;
    }
    long n = 0;
    for (int i = 0; i < f->facet_count; i++)
        for (int j = 0; j < 3; j++) {
            int v = f->facets[i].vertex[j];
            if (!seen[v]) {
                seen[v] = 1;
                list[n++] = v;
            }
        }
    free(seen);
    *order = list;
    return n;
}

rt_status rt__mesh_auto_view(const char *name, const rt_vec3 *vertices,
                             int vertex_count, const rt_facet_desc *facets,
                             int facet_count, const rt_load_options *o,
                             rt_scene_desc *d, rt_light *light,
                             rt_error *error)
{
    framed_points points = {vertices, facets, facet_count, NULL};
    int *order;
    long n = first_corners(&points, vertex_count, &order);
    points.order = order;
    const framed_points *r = &points;
    d->width = o->width > 0 ? o->width : o->height > 0 ? o->height
                                                       : DEFAULT_SIDE;
    d->height = o->height > 0 ? o->height : d->width;
    rt_vec3 lo = n > 0 ? framed(r, 0) : v3(0, 0, 0), hi = lo;
    for (long i = 1; i < n; i++) {
        rt_vec3 p = framed(r, i);
        lo = v3(keep_min(lo.x, p.x), keep_min(lo.y, p.y),
                keep_min(lo.z, p.z));
        hi = v3(keep_max(hi.x, p.x), keep_max(hi.y, p.y),
                keep_max(hi.z, p.z));
    }
    rt_vec3 center = v3_add(v3_scale(lo, 0.5), v3_scale(hi, 0.5));
    double radius = v3_length(v3_sub(v3_scale(hi, 0.5), v3_scale(lo, 0.5)));
    if (!(radius > 0.0))
        radius = fmax(1.0, v3_max_abs(center) * 1e-3);
    rt_vec3 view = v3_normalize(v3(VIEW_X, VIEW_Y, VIEW_Z));
    rt_vec3 right = v3_normalize(v3_cross(v3(0, 1, 0), view));
    rt_vec3 image_up = v3_cross(view, right);
    /* A vertex at (x, y) across the view and z towards the camera is
     * inside the image when |x| <= (D - z) tan_x and |y| <= (D - z) tan_y,
     * D the camera's distance from the point it looks at.  The first fit
     * looks at the box's centre; the second at the point that centres the
     * first picture, and its fit is again exact. */
    double tan_x = rt__frame_tan_half(VIEW_FOV_DEGREES);
    double tan_y = tan_x * d->height / d->width;
    double distance = 0.0;
    for (int pass = 0; pass < 2; pass++) {
        double low_x = 0, high_x = 0, low_y = 0, high_y = 0;
        distance = 0.05 * radius;
        for (long i = 0; i < n; i++) {
            rt_vec3 q = v3_sub(framed(r, i), center);
            double x = v3_dot(q, right), y = v3_dot(q, image_up);
            double z = v3_dot(q, view);
            distance = keep_max(distance, z + 0.05 * radius);
            distance = keep_max(distance, z + VIEW_MARGIN *
                                                  keep_max(fabs(x) / tan_x,
                                                           fabs(y) / tan_y));
        }
        for (long i = 0; i < n && pass == 0; i++) {
            rt_vec3 q = v3_sub(framed(r, i), center);
            double depth = distance - v3_dot(q, view);
            double x = v3_dot(q, right) / depth, y = v3_dot(q, image_up) / depth;
            low_x = keep_min(low_x, x), high_x = keep_max(high_x, x);
            low_y = keep_min(low_y, y), high_y = keep_max(high_y, y);
        }
        center = v3_add(center, v3_add(
            v3_scale(right, distance * (low_x + high_x) / 2),
            v3_scale(image_up, distance * (low_y + high_y) / 2)));
    }
    free(order);
    d->observer = v3_add(center, v3_scale(view, distance));
    d->screen_center = center;
    d->screen_right = rt__frame_right(center, v3_neg(view), v3(0, 1, 0),
                                      distance * tan_x);
    if (!(v3_max_abs(d->observer) <= RT_MAX_COORDINATE) ||
        !(v3_max_abs(d->screen_right) <= RT_MAX_COORDINATE))
        return rt__error_set(error, RT_ERR_RANGE, name, 0, 0,
                             "expected a model the automatic camera can "
                             "frame, found one of radius %g centred at "
                             "(%g, %g, %g): the camera would stand beyond "
                             "coordinates of 1e152 (give --look-from)",
                             radius, center.x, center.y, center.z);
    rt_vec3 toward_light = v3_normalize(v3_add(
        view, v3_add(v3_scale(right, -0.5), v3_scale(image_up, 1.0))));
    light->position = v3_add(center, v3_scale(toward_light, 2.0 * distance));
    light->color = (rt_rgb8){255, 255, 255};
    d->lights = light;
    d->light_count = 1;
    d->background = (rt_rgb8){32, 32, 32};
    return RT_OK;
}
