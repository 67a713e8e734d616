/*
 * normals.c - the vertex normals of a scene (docs/rendering-model.md,
 * "Smooth shading and highlights"): copied from a description and
 * normalised, which facets they make smooth, and their accessor.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "base/sized.h"
#include "base/vecmath.h"
#include "scene/scene_internal.h"

/* v / |v| for a finite non-zero v, scaled first by its largest
 * component so that neither tiny nor huge vectors lose their length;
 * the zero vector stays zero.  A v already of unit length to within
 * rounding (|v.v - 1| <= 8 DBL_EPSILON; what this function returns is
 * within 4) is kept as given, so that normalising is idempotent: a
 * scene written with its unit normals (rt_scene_write_scn) reads back
 * with the same bits. */
static rt_vec3 unit_normal(rt_vec3 v)
{
    double m = v3_max_abs(v);
    if (m == 0.0)
        return v;
    if (m <= 1.0 &&
        fabs(v.x * v.x + v.y * v.y + v.z * v.z - 1.0) <= 8 * DBL_EPSILON)
        return v;
    rt_vec3 w = {v.x / m, v.y / m, v.z / m};
    double length = sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
    return (rt_vec3){w.x / length, w.y / length, w.z / length};
}

/* The description's vertex normals, normalised, into s; none at all
 * (every one zero) keeps s->vertex_normals NULL.  0: out of memory. */
int rt__scene_copy_normals(rt_scene *s, const rt_scene_desc *d)
{
    int any = 0;
    for (int i = 0; i < d->vertex_count && !any; i++)
        any = v3_max_abs(d->normals[i]) != 0.0;
    if (!any)
        return 1;
    s->vertex_normals =
        malloc((size_t)d->vertex_count * sizeof *s->vertex_normals);
    if (s->vertex_normals == NULL)
        return 0;
    for (int i = 0; i < d->vertex_count; i++)
        s->vertex_normals[i] = unit_normal(d->normals[i]);
    return 1;
}

int rt__scene_facet_smooth(const rt_scene *s, const rt_facet_record *r)
{
    if (s->vertex_normals == NULL)
        return 0;
    for (int j = 0; j < 3; j++)
        if (v3_max_abs(s->vertex_normals[r->vertex[j]]) == 0.0)
            return 0;
    return 1;
}

rt_vec3 rt_scene_vertex_normal(const rt_scene *scene, int i)
{
    if (!RT__EXPECT(scene != NULL && i >= 0 && i < scene->vertex_count) || scene->vertex_normals == NULL)
        return (rt_vec3){0.0, 0.0, 0.0};
    return scene->vertex_normals[i];
}

