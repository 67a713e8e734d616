/*
 * scene_internal.h - what an rt_scene holds (internal).
 *
 * A scene keeps two views of its facets: the records as the file gave them
 * (for accessors and the course's API: corners, line, and an index into
 * a table of the materials they share), and its kernels (kernel.h), one
 * per precision, which hold only the facets that can be hit, with what the
 * renderer needs precomputed.  Zero-area facets and exact repeats of the
 * facet before them (rt_facet_record.degenerate) are absent from the kernel:
 * the renderer never spends a test on them.
 */
#ifndef RAYTRACE_SCENE_INTERNAL_H
#define RAYTRACE_SCENE_INTERNAL_H

#include <pthread.h>
#include <stdatomic.h>

#include "kernel/kernel.h"
#include "raytrace/scene.h"
#include "scene/scene_build.h"

/* A scene's materials (materials.c): an array, and while the scene is
 * built, the hash table that finds an entry alike. */
typedef struct rt_materials {
    rt_material *items;
    int count, capacity;
    int last;               /* the entry found or added last */
    int *slots;             /* the build's: entry indices, -1 empty */
    size_t slot_count;      /* a power of two, or 0 */
} rt_materials;

/* The index of the entry of `t` equal to *m (every field, bit for bit),
 * added when there is none; -1 when out of memory. */
int rt__materials_add(rt_materials *t, const rt_material *m);
/* Ends a build: frees the hash table and fits the array. */
void rt__materials_end(rt_materials *t);
void rt__materials_free(rt_materials *t);

/* Copies d's vertex normals (normals.c), normalised, into s; 0 when out
 * of memory.  None but zero ones: s->vertex_normals stays NULL. */
int rt__scene_copy_normals(struct rt_scene *s, const rt_scene_desc *d);
/* Whether facet record r of s has a vertex normal at each corner. */
int rt__scene_facet_smooth(const struct rt_scene *s,
                           const rt_facet_record *r);

struct rt_scene {
    char *name;
    rt_camera camera;
    int focus_given;            /* the file set the focal distance (else
                                   |AO|, which rt_scene_look recomputes) */
    rt_vec3 *vertices;
    rt_vec3 *vertex_normals;    /* NULL when no vertex has a normal; else
                                   per vertex, unit or zero (none) */
    int vertex_count;
    rt_facet_record *facets;    /* as the file gave them (kernel.h) */
    int facet_count;
    rt_materials materials;     /* what the facets' records index */
    rt_warning *warnings;
    int warning_count;
    rt_rgb8 background;
    rt_light *lights;       /* light_count >= 1; the first is the file's */
    int light_count;
    rt_kernel *kernel;      /* the double-precision kernel, built with the
                               scene: what rt_trace and the queries read */
    _Atomic(rt_kernel *) kernel_f;      /* the float kernel, built by the
                                           first float render */
    _Atomic(rt_kernel_eye *) eyes[2];   /* per rt_precision, the eye of the
                                           camera's observer, built by the
                                           first render that reads it */
    _Atomic(struct rt_workers *) workers;  /* the render threads, started
                                              by the first render on
                                              several */
    pthread_mutex_t kernel_lock;        /* serialises those constructions */
    int live_count;         /* facets that can be hit */
    int reflective_count;   /* live facets with k > 0 */
    int transparent_count;  /* live facets with t > 0 */
    int smooth_count;       /* live facets with three vertex normals */
    struct {                /* the reader's automatic camera (info) */
        rt_up_axis axis;
        rt_up_cue cue;
        int line;
    } up;
    int highlight_count;    /* live facets with s > 0 */
    rt_scene_source *sources;   /* the files the load read (names owned) */
    int source_count;
};

/*
 * Computes the camera of docs/rendering-model.md (aperture 0, focal distance
 * |AO|: the pinhole camera).  Returns NULL on success, or a phrase saying
 * what is degenerate ("the observer O is the screen centre A"), with
 * *field (may be NULL) the point to blame: the screen centre A when O is
 * A, else the screen point B.
 */
const char *rt__camera_make(rt_vec3 observer, rt_vec3 a, rt_vec3 b,
                            int width, int height, rt_camera *camera,
                            rt_field *field);

/* The bytes of a scene's own records (itself, its name, vertices, facet
 * records, warnings and lights; not its kernels): what a load leaves in
 * memory besides the renderer's data.  For tests of the budgets. */
size_t rt__scene_bytes(const rt_scene *scene);

/*
 * What the scene prepares once for its renders (prepared.c): its kernels,
 * their eyes and its render threads.  Each is made on first use, under
 * the scene's lock, and only read afterwards: any number of renders share
 * them.
 */

/* Sets up the fields of a new scene that hold them (none made yet). */
void rt__scene_prepared_init(rt_scene *scene);
/* Ends the render threads and frees the kernels and eyes. */
void rt__scene_prepared_free(rt_scene *scene);

/* Fills *info with what facet record i says (its normal computed). */
void rt__scene_facet_info(const rt_scene *scene, int i, rt_facet_info *info);

/* What a kernel of any precision is built from: the scene's own arrays. */
void rt__scene_kernel_source(const rt_scene *scene, rt_kernel_source *source);

/* The scene's kernel in `precision` (double: the one built with the
 * scene; float: built on the first call, thread-safe, and kept until the
 * scene is freed); NULL when out of memory, or when `cancel` (may be NULL)
 * was raised during that first build (nothing is kept: the next call
 * builds again). */
const rt_kernel *rt__scene_kernel(const rt_scene *scene,
                                  rt_precision precision,
                                  const rt_cancel *cancel);

/* The eye of the camera's observer for the scene's kernel in `precision`
 * (which rt__scene_kernel must have returned), built on the first call
 * (thread-safe) and kept with the scene; NULL when out of memory. */
const rt_kernel_eye *rt__scene_eye(const rt_scene *scene,
                                   rt_precision precision);

/* The scene's team of render threads (base/workers.h), made on the first
 * call (thread-safe); NULL when out of memory (renders then start threads
 * of their own). */
struct rt_workers *rt__scene_workers(const rt_scene *scene);

/* RT_OK for a precision rt_precision names, else RT_ERR_ARGUMENT with the
 * reason in *error (may be NULL). */
rt_status rt__precision_check(rt_precision precision, rt_error *error);

/* rt_scene_check_precision of `scene` seen through `camera` (the scene's,
 * or a render's own: rt_render_options.camera). */
rt_status rt__scene_check_precision_with(const rt_scene *scene,
                                         const rt_camera *camera,
                                         rt_precision precision,
                                         rt_error *error);

#endif /* RAYTRACE_SCENE_INTERNAL_H */
