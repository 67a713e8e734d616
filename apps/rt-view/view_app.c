/*
 * view_app.c - rt-view's app (see view_app.h): creating and destroying it,
 * the title and the messages, starting a render, the termination signals
 * and the event loop; loads, saves and the keys are in view_reload.c,
 * view_save.c and view_navigation.c (view_app_internal.h).  The main
 * thread sleeps in SDL_WaitEventTimeout and is woken by a user event that
 * the session's notify hook pushes when rows are finished, and the load's
 * when a scene is read; frames are drawn at most every FRAME_MS, with
 * --watch the file is looked at every VIEW_WATCH_MS, and the loop never
 * sleeps longer than VIEW_SIGNAL_MS (termination signals cannot wake it).
 */
#include "view_app.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "view_app_internal.h"
#include "view_scene.h"
#include "view_window.h"

#define FRAME_MS 16        /* shortest time between two frames */
#define TITLE_MS 100       /* how often the elapsed time is refreshed */
#define EMPTY_SIZE 480     /* window side when no scene is loaded */

void view_app_options_init(view_app_options *options)
{
    memset(options, 0, sizeof *options);
    rt_render_options_init(&options->render);
    options->scale = 1.0;
    options->format = rt_image_format_supported(RT_IMAGE_PNG) ? RT_IMAGE_PNG
                                                              : RT_IMAGE_P6;
}

/* The session's notify hook: wakes the event loop (any thread). */
void view_app__wake(void *user)
{
    const view_app *app = user;
    SDL_Event event;
    SDL_zero(event);
    event.type = app->wake_event;
    SDL_PushEvent(&event);
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

void view_app__update_title(view_app *app)
{
    char title[sizeof app->title];
    char loading[160] = "";
    if (app->load != NULL)
        snprintf(loading, sizeof loading, "loading %.120s - ",
                 base_name(view_load_path(app->load)));
    if (app->message[0]) {
        snprintf(title, sizeof title, "%s - %s" VIEW_APP_PROGRAM, app->message,
                 loading);
    } else if (app->session == NULL) {
        if (loading[0])
            snprintf(title, sizeof title, "%s" VIEW_APP_PROGRAM, loading);
        else
            snprintf(title, sizeof title,
                     VIEW_APP_PROGRAM " - drop a .scn file here");
    } else {
        view_progress progress;
        view_session_get_progress(app->session, &progress);
        char state[96];
        view_progress_describe(&progress, state, sizeof state);
        const rt_image *image = view_session_image(app->session);
        char view[64] = "";
        if (app->view == RT_VIEW_SHADOW || app->view == RT_VIEW_NS)
            snprintf(view, sizeof view, " - %s of light %d",
                     view_app__view_name(app->view), app->view_light);
        else if (app->view)
            snprintf(view, sizeof view, " - %s",
                     view_app__view_name(app->view));
        snprintf(title, sizeof title,
                 "%s %dx%d depth %d - %s%s - %s" VIEW_APP_PROGRAM,
                 base_name(app->shown_path), image->width, image->height,
                 progress.max_depth, state, view, loading);
    }
    if (strcmp(title, app->title) != 0) {
        snprintf(app->title, sizeof app->title, "%s", title);
        view_window_set_title(app->window, app->title);
    }
}

void view_app__show_message(view_app *app, const char *message)
{
    fprintf(stderr, VIEW_APP_PROGRAM ": %s\n", message);
    snprintf(app->message, sizeof app->message, "%s", message);
    view_app__update_title(app);
}

void view_app__start_render(view_app *app)
{
    if (app->session == NULL)
        return;
    app->message[0] = '\0';
    /* The debug view shown (or the picture), rendered again. */
    view_app__show_view(app);
    /* The explanation was of the render before. */
    view_app__clear_explanation(app);
}

view_app *view_app_create(const view_app_options *options, char *error,
                          size_t error_size)
{
    view_app *app = calloc(1, sizeof *app);
    if (app == NULL) {
        snprintf(error, error_size, "out of memory");
        return NULL;
    }
    app->options = *options;
    app->view = options->view;
    app->view_light = options->view_light;
    app->wake_event = SDL_RegisterEvents(1);
    if (app->wake_event == (Uint32)-1) {
        snprintf(error, error_size, "cannot register an SDL event");
        free(app);
        return NULL;
    }
    /* Hidden until it has the scene's size and place. */
    app->window = view_window_create(VIEW_APP_PROGRAM, EMPTY_SIZE,
                                     EMPTY_SIZE * 3 / 4,
                                     options->window_flags |
                                         VIEW_WINDOW_HIDDEN,
                                     error, error_size);
    if (app->window == NULL) {
        free(app);
        return NULL;
    }
    view_app__update_title(app);
    return app;
}

void view_app_destroy(view_app *app)
{
    if (app == NULL)
        return;
    /* A load is let go, never waited for (it may be blocked for ever);
     * the window closes at once, then the render stops. */
    view_load_abandon(app->load);
    app->load = NULL;
    view_window_hide(app->window);
    view_window_attach(app->window, NULL, NULL, 0);
    view_session_destroy(app->session);
    view_window_destroy(app->window);
    view_explanation_release(&app->explanation);
    free(app->path);
    free(app->shown_path);
    free(app);
}

/* The render options for `scene`: --scale gives the size when --size did
 * not. */
rt_render_options view_app__render_options(const view_app *app,
                                           const rt_scene *scene)
{
    rt_render_options render = app->options.render;
    if (render.width == 0 && render.height == 0 &&
        app->options.scale != 1.0) {
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        render.width = view_scale_side(info.width, app->options.scale);
        render.height = view_scale_side(info.height, app->options.scale);
    }
    /* A moved camera is the picture's, its explanations' and overlays'. */
    if (app->move.moved && scene == app->move.scene)
        render.camera = &app->move.camera;
    return render;
}

/* SIGINT, SIGTERM and SIGHUP are blocked in every thread (rt-view's main
 * blocks them before any thread starts) and taken here, in the event loop,
 * so that a save under way first removes its temporary file
 * (rt_image_save). */
static void termination_signals(sigset_t *set)
{
    sigemptyset(set);
    sigaddset(set, SIGINT);
    sigaddset(set, SIGTERM);
    sigaddset(set, SIGHUP);
}

/* Takes a pending termination signal, if any, and asks the loop to quit. */
void view_app__take_signal(view_app *app)
{
    sigset_t set;
    termination_signals(&set);
    struct timespec now = {0, 0};
    int signal_number = sigtimedwait(&set, NULL, &now);
    if (signal_number > 0) {
        app->quit = 1;
        app->quit_signal = signal_number;
    }
}

static void handle_event(view_app *app, SDL_Event *event)
{
    switch (event->type) {
    case SDL_QUIT:
        app->quit = 1;
        break;
    case SDL_KEYDOWN:
        if (!view_app__move_event(app, event))
            view_app_key(app, event->key.keysym.sym, event->key.repeat);
        break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
    case SDL_MOUSEMOTION:
    case SDL_MOUSEWHEEL:
        /* drags move the camera; a click without motion explains the
         * pixel (left) or clears (right) on its release (view_move.c) */
        view_app__move_event(app, event);
        break;
    case SDL_DROPFILE:
        view_app_open(app, event->drop.file);
        SDL_free(event->drop.file);
        break;
    case SDL_WINDOWEVENT:
        if (event->window.event == SDL_WINDOWEVENT_CLOSE)
            app->quit = 1;
        else
            app->redraw = 1;
        break;
    default:
        break;
    }
}

static int rendering(view_app *app)
{
    if (app->session == NULL)
        return 0;
    view_progress progress;
    view_session_get_progress(app->session, &progress);
    return progress.state == VIEW_RENDERING;
}

/* How long the loop may sleep: until the next frame while rendering, never
 * past the next look at a watched file, and never more than VIEW_SIGNAL_MS
 * (a termination signal is taken at each turn). */
static int wait_ms(int busy, Uint64 now, Uint64 next_frame, Uint64 next_watch,
                   int watch)
{
    int timeout = VIEW_SIGNAL_MS;
    if (busy && next_frame > now && next_frame - now < (Uint64)timeout)
        timeout = (int)(next_frame - now);
    if (watch) {
        int until_watch = next_watch > now ? (int)(next_watch - now) : 0;
        if (until_watch < timeout)
            timeout = until_watch;
    }
    return timeout;
}

void view_app_run(view_app *app)
{
    view_window_show(app->window);
    app->shown = 1;
    Uint64 next_frame = 0, next_title = 0;
    Uint64 next_watch = SDL_GetTicks64() + VIEW_WATCH_MS;
    int was_rendering = 1;
    while (!app->quit) {
        Uint64 now = SDL_GetTicks64();
        int busy = rendering(app) || was_rendering;
        SDL_Event event;
        if (SDL_WaitEventTimeout(&event, wait_ms(busy, now, next_frame,
                                                 next_watch,
                                                 app->options.watch))) {
            handle_event(app, &event);
            while (!app->quit && SDL_PollEvent(&event))
                handle_event(app, &event);
        }
        view_app__apply_moves(app);  /* the turn's moves: one restart */
        view_app__take_signal(app);
        if (app->quit)
            break;
        if (app->load != NULL && view_load_done(app->load)) {
            view_app__finish_load(app);
            app->redraw = 1;
        }
        now = SDL_GetTicks64();
        if (app->options.watch && now >= next_watch) {
            view_app_check_watch(app);
            next_watch = now + VIEW_WATCH_MS;
        }
        if (now < next_frame)
            continue;
        was_rendering = rendering(app);
        if (view_window_sync(app->window) || app->redraw) {
            view_window_draw(app->window);
            app->redraw = 0;
            next_frame = now + FRAME_MS;
        }
        if (now >= next_title || !was_rendering) {
            view_app__update_title(app);
            next_title = now + TITLE_MS;
        }
    }
}

int view_app_exit_status(const view_app *app)
{
    if (app->quit_signal)
        return 128 + app->quit_signal;
    return app->scene_asked && !app->scene_loaded ? 1 : 0;
}

view_session *view_app_session(view_app *app)
{
    return app->session;
}

const char *view_app_title(const view_app *app)
{
    return app->title;
}

view_window *view_app_window(view_app *app)
{
    return app->window;
}

const char *view_app_message(const view_app *app)
{
    return app->message;
}
