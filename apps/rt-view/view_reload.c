/*
 * view_reload.c - opening and reloading a scene (see view_app.h): the load
 * on its worker thread (view_load.h), the session that shows the scene
 * once it is read (the window fitted to it), R and --watch.  A load that
 * fails leaves the picture shown as it was.
 */
#include "view_app_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_text.h"

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "view_scene.h"
#include "view_window.h"

/* A copy of `text` (free() it), or NULL out of memory. */
static char *copy_text(const char *text)
{
    char *copy = malloc(strlen(text) + 1);
    if (copy)
        strcpy(copy, text);
    return copy;
}

/* The largest window that fits on the screen the window is on, placed so
 * that it is all visible. */
static void fit_window(view_app *app, int width, int height)
{
    SDL_Rect bounds = {0, 0, 1024, 768};
    int display = view_window_display(app->window);
    if (SDL_GetDisplayUsableBounds(display, &bounds) != 0)
        SDL_GetDisplayBounds(0, &bounds);
    /* Leave room for the window manager's border and title bar. */
    const int border = 8, title_bar = 32;
    int area[4] = {bounds.x + border, bounds.y + title_bar,
                   bounds.w - 2 * border, bounds.h - title_bar - border};
    int w, h;
    view_fit_size(width, height, area[2], area[3], &w, &h);
    view_window_place(app->window, w, h, area, !app->shown);
}

/* A session rendering `scene` (taken over), or NULL with the error shown. */
static view_session *new_session(view_app *app, rt_scene *scene,
                                 const char *path)
{
    view_session_options options;
    view_session_options_init(&options);
    options.render = view_app__render_options(app, scene);
    options.notify = view_app__wake;
    options.notify_user = app;
    options.stats = app->options.stats;
    view_session *session;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_session_create(scene, &options, &session, &error);
    if (status != RT_OK) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "%s: %s", path,
                 error.message[0] ? error.message
                                  : rt_status_string(status));
        view_app__show_message(app, message);
        return NULL;
    }
    return session;
}

/* Shows `session` (of the file `shown_path`, taken over) and renders. */
static void show_session(view_app *app, view_session *session,
                         char *shown_path)
{
    view_window_attach(app->window, NULL, NULL, 0);
    view_session_destroy(app->session);
    free(app->shown_path);
    app->session = session;
    app->shown_path = shown_path;
    app->scene_loaded = 1;

    const rt_image *image = view_session_image(session);
    fit_window(app, image->width, image->height);
    char message[256];
    if (!view_window_attach(app->window, session, message, sizeof message)) {
        view_app__show_message(app, message);
        return;
    }
    view_app__start_render(app);
    app->redraw = 1;
}

int view_app_open(view_app *app, const char *path)
{
    char *watched = copy_text(path);
    if (watched == NULL) {
        view_app__show_message(app, "out of memory");
        return 0;
    }
    free(app->path);
    app->path = watched;
    app->scene_asked = 1;
    /* Stamped before reading: an edit during the load is seen next time
     * (a stat: it does not block on a FIFO, unlike opening it). */
    view_file_stamp_read(path, &app->stamp);
    view_load_abandon(app->load);   /* a new load replaces it */
    app->load = NULL;
    view_load_func load = app->options.load_scene ? app->options.load_scene
                                                  : view_scene_load;
    if (view_load_start(path, app->options.load, load, view_app__wake, app,
                        &app->load) != RT_OK) {
        view_app__show_message(app, "cannot start loading the scene: out of "
                                    "memory");
        return 0;
    }
    view_app__update_title(app);
    return 1;
}

int view_app_loading(const view_app *app)
{
    return app->load != NULL;
}

/* The load under way has ended: shows its scene, or its error (the
 * current picture stays).  Returns 1 when it loaded. */
int view_app__finish_load(view_app *app)
{
    view_load *load = app->load;
    app->load = NULL;
    char *shown = copy_text(view_load_path(load));
    rt_scene *scene;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_load_finish(load, &scene, &error);
    if (status != RT_OK || shown == NULL) {
        view_app__show_message(app, shown == NULL       ? "out of memory"
                                    : error.message[0] ? error.message
                                                 : rt_status_string(status));
        rt_scene_destroy(scene);
        free(shown);
        return 0;
    }
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, VIEW_APP_PROGRAM ": %s\n",
                rt_scene_warning(scene, i)->message);
    cli_print_up_note(stderr, VIEW_APP_PROGRAM, shown, scene);
    view_session *session = new_session(app, scene, shown);
    if (session == NULL) {
        free(shown);
        return 0;
    }
    show_session(app, session, shown);
    return 1;
}

int view_app_wait_load(view_app *app)
{
    if (app->load == NULL)
        return 0;
    view_load_wait(app->load);
    return view_app__finish_load(app);
}

int view_app_reload(view_app *app)
{
    if (app->path == NULL)
        return 0;
    char *path = copy_text(app->path);
    if (path == NULL) {
        view_app__show_message(app, "out of memory");
        return 0;
    }
    int started = view_app_open(app, path);
    free(path);
    return started;
}

int view_app_check_watch(view_app *app)
{
    if (app->path == NULL)
        return 0;
    view_file_stamp now;
    view_file_stamp_read(app->path, &now);
    if (view_file_stamp_equal(&now, &app->stamp))
        return 0;
    if (!now.exists) {
        /* Gone for now (an editor between removing and renaming): wait
         * for it to come back rather than report it missing. */
        app->stamp = now;
        return 0;
    }
    return view_app_reload(app);
}
