/*
 * view_load.c - a scene read by a worker thread for the viewer (see
 * view_load.h).  The load is shared by the controlling thread and the
 * worker, counted: whichever lets go of it last frees it, so a worker
 * abandoned while blocked in the loader frees it when (if ever) the loader
 * returns.  The notify hook is called under the load's mutex, so once
 * view_load_abandon has taken the mutex and cleared it, no call is under
 * way or to come.
 */
#include "view_load.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

struct view_load {
    char *path;
    rt_load_options options;    /* lights point at `lights`, cancel at
                                   `cancel` */
    rt_light *lights;
    rt_cancel *cancel;
    view_load_func load;
    pthread_t worker;

    pthread_mutex_t lock;       /* guards everything below */
    pthread_cond_t finished;    /* signalled once `done` is set */
    view_notify_func notify;    /* NULL once abandoned */
    void *notify_user;
    int owners;                 /* the controlling thread and the worker */
    int done;
    rt_status status;
    rt_scene *scene;            /* the loader's, until taken */
    rt_error error;
};

static void release(view_load *load)
{
    rt_scene_destroy(load->scene);
    rt_cancel_destroy(load->cancel);
    pthread_cond_destroy(&load->finished);
    pthread_mutex_destroy(&load->lock);
    free(load->lights);
    free(load->path);
    free(load);
}

/* Drops one owner's hold; the last one frees the load. */
static void let_go(view_load *load)
{
    pthread_mutex_lock(&load->lock);
    int last = --load->owners == 0;
    pthread_mutex_unlock(&load->lock);
    if (last)
        release(load);
}

static void *worker_main(void *arg)
{
    view_load *load = arg;
    rt_scene *scene = NULL;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = load->load(load->path, &load->options, &scene, &error);

    pthread_mutex_lock(&load->lock);
    load->status = status;
    load->scene = scene;
    load->error = error;
    load->done = 1;
    pthread_cond_broadcast(&load->finished);
    if (load->notify != NULL)
        load->notify(load->notify_user);
    pthread_mutex_unlock(&load->lock);
    let_go(load);
    return NULL;
}

rt_status view_load_start(const char *path, const rt_load_options *options,
                          view_load_func load, view_notify_func notify,
                          void *notify_user, view_load **out)
{
    *out = NULL;
    view_load *l = calloc(1, sizeof *l);
    if (l == NULL)
        return RT_ERR_NOMEM;
    if (options != NULL)
        l->options = *options;
    else
        rt_load_options_init(&l->options);
    size_t length = strlen(path) + 1;
    l->path = malloc(length);
    int lights = l->options.light_count > 0 && l->options.lights != NULL
                     ? l->options.light_count
                     : 0;
    if (lights > 0)
        l->lights = malloc((size_t)lights * sizeof *l->lights);
    int ready = l->path != NULL && (lights == 0 || l->lights != NULL) &&
                rt_cancel_create(&l->cancel, NULL) == RT_OK;
    if (ready && pthread_mutex_init(&l->lock, NULL) != 0) {
        ready = 0;
    } else if (ready && pthread_cond_init(&l->finished, NULL) != 0) {
        pthread_mutex_destroy(&l->lock);
        ready = 0;
    }
    if (!ready) {
        rt_cancel_destroy(l->cancel);
        free(l->lights);
        free(l->path);
        free(l);
        return RT_ERR_NOMEM;
    }
    memcpy(l->path, path, length);
    if (lights > 0) {
        memcpy(l->lights, l->options.lights,
               (size_t)lights * sizeof *l->lights);
        l->options.lights = l->lights;
    }
    l->options.cancel = l->cancel;
    l->load = load;
    l->notify = notify;
    l->notify_user = notify_user;
    l->owners = 2;
    l->status = RT_OK;
    if (pthread_create(&l->worker, NULL, worker_main, l) != 0) {
        l->owners = 1;
        release(l);
        return RT_ERR_NOMEM;
    }
    *out = l;
    return RT_OK;
}

const char *view_load_path(const view_load *load)
{
    return load->path;
}

int view_load_done(view_load *load)
{
    pthread_mutex_lock(&load->lock);
    int done = load->done;
    pthread_mutex_unlock(&load->lock);
    return done;
}

void view_load_wait(view_load *load)
{
    pthread_mutex_lock(&load->lock);
    while (!load->done)
        pthread_cond_wait(&load->finished, &load->lock);
    pthread_mutex_unlock(&load->lock);
}

rt_status view_load_finish(view_load *load, rt_scene **scene,
                           rt_error *error)
{
    view_load_wait(load);
    pthread_join(load->worker, NULL);  /* it has let go: only us now */
    *scene = load->scene;
    load->scene = NULL;
    if (error != NULL)
        *error = load->error;
    rt_status status = load->status;
    let_go(load);
    return status;
}

void view_load_abandon(view_load *load)
{
    if (load == NULL)
        return;
    rt_cancel_request(load->cancel);
    pthread_detach(load->worker);
    pthread_mutex_lock(&load->lock);
    load->notify = NULL;
    pthread_mutex_unlock(&load->lock);
    let_go(load);
}
