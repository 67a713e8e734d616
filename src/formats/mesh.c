/*
 * mesh.c - what the mesh readers share (mesh.h): the default material,
 * a face cut into facets, and the automatic camera and light that OBJ and
 * PLY files, which hold no view, are seen through.
 */
#include "formats/mesh.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/exact.h"
#include "base/vecmath.h"
#include "formats/framing.h"

/* The automatic view (docs/formats.md): from the front (+z), to the right
 * (+x) and above (+y, OBJ's usual up), the horizontal field of view; for
 * another up axis the same view turned (mesh_frame). */
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

/* The model's right, up and front (towards the camera) for an up axis:
 * +y gives x, y, z (the view of every earlier release, bit for bit);
 * +z the usual z-up frame, seen from -y; the others alike, each frame
 * right-handed (right = up x front). */
static void mesh_frame(rt_up_axis axis, rt_vec3 *right, rt_vec3 *up,
                       rt_vec3 *front)
{
    switch (axis) {
    case RT_UP_X:     *up = v3(1, 0, 0);  *front = v3(0, 0, 1);  break;
    case RT_UP_NEG_X: *up = v3(-1, 0, 0); *front = v3(0, 0, 1);  break;
    case RT_UP_NEG_Y: *up = v3(0, -1, 0); *front = v3(0, 0, 1);  break;
    case RT_UP_Z:     *up = v3(0, 0, 1);  *front = v3(0, -1, 0); break;
    case RT_UP_NEG_Z: *up = v3(0, 0, -1); *front = v3(0, 1, 0);  break;
    default:          *up = v3(0, 1, 0);  *front = v3(0, 0, 1);  break;
    }
    *right = v3_cross(*up, *front);
}

const char *rt__mesh_up_name(rt_up_axis axis)
{
    static const char *const names[] = {"+y", "+x", "+y", "+z",
                                        "-x", "-y", "-z"};
    return axis >= RT_UP_AUTO && axis <= RT_UP_NEG_Z ? names[axis] : "+y";
}

static int word_char(int c)
{
    return isalnum(c) || c == '_';
}

/* An axis named at text[at] ("z", "+z", "-Y"), followed by no letter or
 * digit: its value, its length in *length; RT_UP_AUTO for none. */
static rt_up_axis axis_at(const char *text, size_t n, size_t at,
                          size_t *length)
{
    int negative = 0;
    size_t i = at;
    if (i < n && (text[i] == '+' || text[i] == '-'))
        negative = text[i++] == '-';
    if (i >= n)
        return RT_UP_AUTO;
    int c = tolower((unsigned char)text[i]);
    if ((c != 'x' && c != 'y' && c != 'z') ||
        (i + 1 < n && isalnum((unsigned char)text[i + 1])))
        return RT_UP_AUTO;
    *length = i + 1 - at;
    rt_up_axis axis = c == 'x' ? RT_UP_X : c == 'y' ? RT_UP_Y : RT_UP_Z;
    return negative ? (rt_up_axis)(axis + 3) : axis;
}

/* The up axis a comment names: "Z-up", "+z up", "up axis: Y", "up=-z",
 * "up_axis Z" (any case); RT_UP_AUTO for none. */
static rt_up_axis comment_axis(const char *text, size_t n)
{
    for (size_t i = 0; i + 1 < n; i++) {
        if (tolower((unsigned char)text[i]) != 'u' ||
            tolower((unsigned char)text[i + 1]) != 'p' ||
            (i > 0 && isalnum((unsigned char)text[i - 1])) ||
            (i + 2 < n && isalpha((unsigned char)text[i + 2]) &&
             tolower((unsigned char)text[i + 2]) != 'a'))
            continue;
        /* before: "z-up", "+Z up", "Y_up" */
        size_t j = i;
        while (j > 0 && (text[j - 1] == ' ' || text[j - 1] == '-' ||
                         text[j - 1] == '_') && i - j < 2)
            j--;
        if (j < i && j > 0) {
            size_t start = j - 1, length;
            if (start > 0 && (text[start - 1] == '+' || text[start - 1] == '-'))
                start--;
            if ((start == 0 || !word_char((unsigned char)text[start - 1])) &&
                axis_at(text, n, start, &length) != RT_UP_AUTO &&
                start + length == j)
                return axis_at(text, n, start, &length);
        }
        /* after: "up z", "up: +z", "up axis = Y", "up_axis Z" */
        size_t k = i + 2;
        if (k + 4 <= n && (text[k] == '_' || text[k] == '-' ||
                           text[k] == ' ') &&
            strncasecmp(text + k + 1, "axis", 4) == 0)
            k += 5;
        else if (k + 4 <= n && strncasecmp(text + k, "axis", 4) == 0)
            k += 4;
        else if (k < n && isalpha((unsigned char)text[k]))
            continue;
        while (k < n && (text[k] == ' ' || text[k] == '\t' || text[k] == ':' ||
                         text[k] == '=' || text[k] == '_'))
            k++;
        size_t length;
        rt_up_axis axis = axis_at(text, n, k, &length);
        if (axis != RT_UP_AUTO)
            return axis;
    }
    return RT_UP_AUTO;
}

static int contains(const char *text, size_t n, const char *word)
{
    size_t w = strlen(word);
    for (size_t i = 0; i + w <= n; i++)
        if (strncasecmp(text + i, word, w) == 0)
            return 1;
    return 0;
}

void rt__mesh_up(const char *text, size_t length, int ply,
                 const rt_load_options *options, rt_scene_desc *d)
{
    d->up_axis = RT_UP_Y;
    d->up_cue = RT_UP_CUE_DEFAULT;
    d->up_cue_line = 0;
    if (options->up_axis != RT_UP_AUTO) {
        d->up_axis = options->up_axis;
        d->up_cue = RT_UP_CUE_OPTION;
        return;
    }
    int exporter_line = 0;
    size_t at = 0;
    for (int line = 1; line <= RT_MESH_CUE_LINES && at < length; line++) {
        const char *start = text + at;
        const char *end = memchr(start, '\n', length - at);
        size_t n = end ? (size_t)(end - start) : length - at;
        at += n + 1;
        size_t skip = 0;
        while (skip < n && (start[skip] == ' ' || start[skip] == '\t'))
            skip++;
        if (ply) {
            if (n - skip >= 10 && memcmp(start + skip, "end_header", 10) == 0)
                break;
            if (n - skip < 8 || memcmp(start + skip, "comment ", 8) != 0)
                continue;
            skip += 8;
        } else if (skip == n || start[skip] != '#') {
            continue;
        }
        rt_up_axis axis = comment_axis(start + skip, n - skip);
        if (axis != RT_UP_AUTO) {
            d->up_axis = axis;
            d->up_cue = RT_UP_CUE_COMMENT;
            d->up_cue_line = line;
            return;
        }
        if (exporter_line == 0 && contains(start + skip, n - skip, "blender"))
            exporter_line = line;
    }
    if (exporter_line > 0) {
        /* Blender writes OBJ with +y up and PLY with +z up unless told
         * otherwise (its exporters' default axes). */
        d->up_axis = ply ? RT_UP_Z : RT_UP_Y;
        d->up_cue = RT_UP_CUE_EXPORTER;
        d->up_cue_line = exporter_line;
    }
}

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
    rt_vec3 axis_right, axis_up, axis_front;
    mesh_frame(d->up_axis, &axis_right, &axis_up, &axis_front);
    rt_vec3 view = v3_normalize(v3_add(
        v3_add(v3_scale(axis_right, VIEW_X), v3_scale(axis_up, VIEW_Y)),
        v3_scale(axis_front, VIEW_Z)));
    rt_vec3 right = v3_normalize(v3_cross(axis_up, view));
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
    d->screen_right = rt__frame_right(center, v3_neg(view), axis_up,
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
