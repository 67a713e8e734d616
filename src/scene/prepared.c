/*
 * prepared.c - what a scene prepares once for all its renders, besides its
 * records: a kernel per precision (kernel.h; the double one built with the
 * scene, the float one by the first float render), per precision the eye
 * of its camera's observer (built by the first render that reads it), and
 * the team of render threads (base/workers.h, started by the first render
 * on several threads).  Each is made once, under the scene's lock,
 * published with a release store and only read afterwards, as the octree
 * is within a kernel: the bands of one render and every later render
 * reuse it.
 */
#include <stdatomic.h>
#include <pthread.h>

#include "base/workers.h"
#include "scene_internal.h"

void rt__scene_prepared_init(rt_scene *s)
{
    atomic_init(&s->kernel_f, NULL);
    atomic_init(&s->eyes[RT_PRECISION_DOUBLE], NULL);
    atomic_init(&s->eyes[RT_PRECISION_FLOAT], NULL);
    atomic_init(&s->workers, NULL);
    pthread_mutex_init(&s->kernel_lock, NULL);
}

void rt__scene_prepared_free(rt_scene *s)
{
    rt__workers_destroy(atomic_load(&s->workers));
    rt_kernel *kernel_f = atomic_load(&s->kernel_f);
    rt_kernel_eye *eye_d = atomic_load(&s->eyes[RT_PRECISION_DOUBLE]);
    rt_kernel_eye *eye_f = atomic_load(&s->eyes[RT_PRECISION_FLOAT]);
    if (eye_d != NULL)
        rt__kernel_eye_destroy(s->kernel, eye_d);
    if (eye_f != NULL)
        rt__kernel_eye_destroy(kernel_f, eye_f);
    rt__kernel_destroy(s->kernel);
    rt__kernel_destroy(kernel_f);
    pthread_mutex_destroy(&s->kernel_lock);
}

void rt__scene_kernel_source(const rt_scene *s, rt_kernel_source *source)
{
    source->cancel = NULL;
    source->vertices = s->vertices;
    source->facets = s->facets;
    source->facet_count = s->facet_count;
    source->materials = s->materials.items;
    source->material_count = s->materials.count;
    source->normals = NULL;
    source->vertex_normals = s->vertex_normals;
    source->lights = s->lights;
    source->light_count = s->light_count;
    source->background = s->background;
}

const rt_kernel *rt__scene_kernel(const rt_scene *scene,
                                  rt_precision precision,
                                  const rt_cancel *cancel)
{
    if (precision == RT_PRECISION_DOUBLE)
        return scene->kernel;
    rt_scene *s = (rt_scene *)scene;   /* only the lazy kernel changes */
    rt_kernel *k = atomic_load_explicit(&s->kernel_f, memory_order_acquire);
    if (k != NULL)
        return k;
    pthread_mutex_lock(&s->kernel_lock);
    k = atomic_load_explicit(&s->kernel_f, memory_order_relaxed);
    if (k == NULL) {
        rt_kernel_source source;
        rt__scene_kernel_source(scene, &source);
        source.cancel = cancel;
        k = rt__kernel_float_ops.create(&source);   /* NULL: not stored */
        atomic_store_explicit(&s->kernel_f, k, memory_order_release);
    }
    pthread_mutex_unlock(&s->kernel_lock);
    return k;
}

const rt_kernel_eye *rt__scene_eye(const rt_scene *scene,
                                   rt_precision precision)
{
    rt_scene *s = (rt_scene *)scene;   /* only the lazy eye changes */
    _Atomic(rt_kernel_eye *) *slot = &s->eyes[precision];
    rt_kernel_eye *eye = atomic_load_explicit(slot, memory_order_acquire);
    if (eye != NULL)
        return eye;
    const rt_kernel *kernel = rt__scene_kernel(scene, precision, NULL);
    if (kernel == NULL)
        return NULL;
    pthread_mutex_lock(&s->kernel_lock);
    eye = atomic_load_explicit(slot, memory_order_relaxed);
    if (eye == NULL) {
        eye = rt__kernel_eye_create(kernel, scene->camera.observer);
        atomic_store_explicit(slot, eye, memory_order_release);
    }
    pthread_mutex_unlock(&s->kernel_lock);
    return eye;
}

rt_workers *rt__scene_workers(const rt_scene *scene)
{
    rt_scene *s = (rt_scene *)scene;   /* only the lazy team changes */
    rt_workers *w = atomic_load_explicit(&s->workers, memory_order_acquire);
    if (w != NULL)
        return w;
    pthread_mutex_lock(&s->kernel_lock);
    w = atomic_load_explicit(&s->workers, memory_order_relaxed);
    if (w == NULL) {
        w = rt__workers_create();      /* NULL: each render starts its own */
        atomic_store_explicit(&s->workers, w, memory_order_release);
    }
    pthread_mutex_unlock(&s->kernel_lock);
    return w;
}
