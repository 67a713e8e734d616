/*
 * view_load.h - a scene read on a worker thread for the viewer, so that its
 * window stays live whatever the file does: a file replaced by a FIFO that
 * no one writes, a slow disk, a huge scene.  The event loop only asks
 * whether the load is done, and quitting never waits for it.
 *
 * view_load_start copies what the load needs (the path, the load options
 * and their lights), creates a cancellation flag that it passes to the
 * loader in rt_load_options.cancel, and starts the worker.  When the loader
 * returns, the worker keeps its result and calls `notify` from its own
 * thread.  The controlling thread then takes the scene (view_load_finish),
 * or lets the load go (view_load_abandon): that raises the flag and returns
 * at once, never waiting for a worker that may be blocked in read() for
 * ever; the worker frees everything when, if ever, its loader returns, and
 * calls nobody back.  The process may exit with such a worker still
 * blocked.
 *
 * Threading: every function is for one controlling thread, except that
 * `notify` runs on the worker (it must not call back into the load).
 */
#ifndef VIEW_LOAD_H
#define VIEW_LOAD_H

#include "raytrace/raytrace.h"
#include "view_session.h"

/*
 * How a scene is read, on the worker thread: view_scene_load
 * (rt_scene_load) in rt-view, another function in the tests.  It is
 * given the path, the load options with `cancel` set to the load's flag,
 * and fills *scene (NULL on failure) and *error like rt_scene_load.
 */
typedef rt_status (*view_load_func)(const char *path,
                                    const rt_load_options *options,
                                    rt_scene **scene, rt_error *error);

typedef struct view_load view_load;

/*
 * Starts reading `path` with `options` (NULL: the defaults; copied, with
 * their lights, so they need not outlive the call; resolve_user is passed
 * as is and must stay valid while the process runs) through `load` on a new
 * thread.  `notify` (may be NULL) is called from that thread once the
 * loader returned, unless the load was abandoned first.  Returns RT_OK with
 * *load set, or RT_ERR_NOMEM (out of memory, or no thread) with *load
 * NULL.
 */
rt_status view_load_start(const char *path, const rt_load_options *options,
                          view_load_func load, view_notify_func notify,
                          void *notify_user, view_load **out);

/* The path being read. */
const char *view_load_path(const view_load *load);

/* Non-zero once the loader has returned. */
int view_load_done(view_load *load);

/* Waits until the loader returns (which may be never, for a loader
 * blocked on a FIFO: the event loop polls view_load_done instead). */
void view_load_wait(view_load *load);

/*
 * Waits for the loader (see view_load_wait), then hands over its result
 * and frees the load: the scene in *scene (the caller's from now on; NULL
 * on failure) and the status, with the loader's error in *error (may be
 * NULL).  When this returns, the worker thread has ended.
 */
rt_status view_load_finish(view_load *load, rt_scene **scene,
                           rt_error *error);

/* Raises the load's cancellation flag and lets the load go, without
 * waiting: the worker frees it when its loader returns.  NULL: no-op. */
void view_load_abandon(view_load *load);

#endif /* VIEW_LOAD_H */
