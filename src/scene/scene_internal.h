/*
 * scene_internal.h - what an rt_scene holds (internal).
 *
 * A scene keeps two views of its facets: the records as the file gave them
 * (for accessors and the course's API), and the double-precision kernel
 * (kernel.h), which holds only the facets that can be hit, with what the
 * renderer needs precomputed.  Zero-area facets and exact repeats of the
 * facet before them (rt_facet_info.degenerate) are absent from the kernel:
 * the renderer never spends a test on them.
 */
#ifndef RAYTRACE_SCENE_INTERNAL_H
#define RAYTRACE_SCENE_INTERNAL_H

#include <pthread.h>
#include <stdatomic.h>

#include "kernel/kernel.h"
#include "raytrace/scene.h"
#include "scene/scene_build.h"

struct rt_scene {
    char *name;
    rt_camera camera;
    rt_vec3 *vertices;
    int vertex_count;
    rt_facet_info *facets;
    int facet_count;
    rt_warning *warnings;
    int warning_count;
    rt_rgb8 background;
    rt_light *lights;       /* light_count >= 1; the first is the file's */
    int light_count;
    rt_kernel_d *kernel;    /* what the double-precision renderer reads */
    _Atomic(rt_kernel_f *) kernel_f;    /* the float renderer's, built by
                                           the first float render */
    pthread_mutex_t kernel_lock;        /* serialises that construction */
    int live_count;         /* facets that can be hit */
    int reflective_count;   /* live facets with k > 0 */
    int transparent_count;  /* live facets with t > 0 */
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

/* What a kernel of any precision is built from: the scene's own arrays. */
void rt__scene_kernel_source(const rt_scene *scene, rt_kernel_source *source);

/* The scene's float kernel, built on the first call (thread-safe) and kept
 * until the scene is freed; NULL when out of memory, or when `cancel` (may
 * be NULL) was raised during that first build (nothing is kept: the next
 * call builds again). */
const rt_kernel_f *rt__scene_kernel_f(const rt_scene *scene,
                                      const rt_cancel *cancel);

#endif /* RAYTRACE_SCENE_INTERNAL_H */
