/*
 * mesh.h - what the mesh readers share (internal): OBJ (obj.c) and PLY
 * (ply.c) files hold vertices and faces and nothing of a view, so both
 * get the same default material, the same cut of a face into facets
 * (repeated corners dropped, the triangulator for more than three) and
 * the same automatic camera and light (docs/formats.md, "The automatic
 * camera").
 */
#ifndef RAYTRACE_MESH_H
#define RAYTRACE_MESH_H

#include "base/error.h"
#include "formats/triangulate.h"
#include "raytrace/scene.h"

/* 0.8 * 255: the grey of a facet no material colours (OBJ's default Kd). */
#define RT_MESH_GREY 204

/* Sets *facet to the default material: grey RT_MESH_GREY, k = t = 0, no
 * vertices (all zero). */
void rt__mesh_default_look(rt_facet_desc *facet);

/* What rt__mesh_face did with a face. */
typedef enum rt_face_outcome {
    RT_FACE_DRAWN,          /* its facets emitted, nothing to say */
    RT_FACE_FEW_CORNERS,    /* fewer than 3 distinct corners: left out */
    RT_FACE_FLAT_TRIANGLE,  /* 3 corners on a line: left out */
    RT_FACE_FLAT_POLYGON,   /* a polygon without area: left out */
    RT_FACE_OVER_BUDGET,    /* cut balanced: the ear budget was spent */
    RT_FACE_CROSSING        /* cut as a fan: it crosses itself */
} rt_face_outcome;

/*
 * Cuts the face whose i-th corner is vertices[corners[i]] (n >= 3 corners,
 * each index valid) into facets through `emit`: a corner that repeats the
 * one before it (cyclically) is dropped first (corners[] is rewritten),
 * a triangle is emitted when it has an area, a polygon goes to the
 * triangulator `t`.  *outcome says what a reader should warn about.
 * Returns RT_OK, or emit's or the triangulator's failure (RT_ERR_NOMEM,
 * RT_ERR_CANCELLED).
 */
rt_status rt__mesh_face(rt_triangulator *t, const rt_vec3 *vertices,
                        int *corners, int n, rt_tri_emit emit, void *user,
                        rt_face_outcome *outcome);

/* The words of a warning about an outcome other than RT_FACE_DRAWN
 * ("this face has no area ... and is left out"), as OBJ always said
 * them. */
const char *rt__mesh_face_remark(rt_face_outcome outcome, char *buffer,
                                 size_t size);

/* The lines of a file looked at for a comment naming the up axis. */
#define RT_MESH_CUE_LINES 64

/*
 * The up axis of the automatic camera into d->up_axis, d->up_cue and
 * d->up_cue_line (docs/formats.md, "The automatic camera"): the options'
 * up_axis when given; else one named by a comment among the first
 * RT_MESH_CUE_LINES lines of text (`#` lines for OBJ, `comment` lines of a
 * PLY header: "Z-up", "up axis: z", ...); else the default of an exporter
 * a comment names (Blender: +y for OBJ, +z for PLY); else +y.  O(lines).
 */
void rt__mesh_up(const char *text, size_t length, int ply,
                 const rt_load_options *options, rt_scene_desc *d);

/* "+x", "+y", "+z", "-x", "-y" or "-z" ("+y" for RT_UP_AUTO). */
const char *rt__mesh_up_name(rt_up_axis axis);

/*
 * The automatic camera and light of a mesh (docs/formats.md): the image
 * options->width x options->height (a missing side from the other, 512
 * without either), seen from the direction (0.5, 0.5, 1) in the frame of
 * d->up_axis (set by rt__mesh_up first: right, up, front) at the nearest
 * distance where every vertex of the facets (every vertex when there is no
 * facet) is inside the image with a 5% margin, the picture centred; one
 * white light above and to the left of the camera, stored in *light and
 * pointed at by desc->lights; background (32, 32, 32).  RT_ERR_RANGE,
 * naming `name`, when the camera would stand beyond RT_MAX_COORDINATE.
 */
rt_status rt__mesh_auto_view(const char *name, const rt_vec3 *vertices,
                             int vertex_count, const rt_facet_desc *facets,
                             int facet_count, const rt_load_options *options,
                             rt_scene_desc *desc, rt_light *light,
                             rt_error *error);

#endif /* RAYTRACE_MESH_H */
