/*
 * view_app.c - rt-view's window, keys, reloads, saves and event loop (see
 * view_app.h).  The main thread sleeps in SDL_WaitEventTimeout and is woken
 * by a user event that the session's notify hook pushes when rows are
 * finished; frames are drawn at most every FRAME_MS, and with --watch the
 * file is looked at every VIEW_WATCH_MS.
 */
#include "view_app.h"

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "view_scene.h"
#include "view_window.h"

#define PROGRAM "rt-view"
#define FRAME_MS 16        /* shortest time between two frames */
#define TITLE_MS 100       /* how often the elapsed time is refreshed */
#define IDLE_MS 500        /* wait when nothing is rendering */
#define EMPTY_SIZE 480     /* window side when no scene is loaded */

struct view_app {
    view_app_options options;
    char *path;                 /* the file R and --watch reload; NULL */
    char *shown_path;           /* the file of the session's scene */
    view_file_stamp stamp;      /* of `path` when last read */
    int scene_asked;            /* a scene was asked for */
    int scene_loaded;           /* one loaded at least once */
    int output_written;         /* -o PATH has a complete image */
    view_session *session;
    view_window *window;
    Uint32 wake_event;
    char message[RT_ERROR_MESSAGE_SIZE + 64]; /* shown in the title */
    char title[RT_ERROR_MESSAGE_SIZE + 256];
    int shown;                  /* the window is on screen */
    int quit;
    int quit_signal;            /* the termination signal, or 0 */
    int redraw;
};

void view_app_options_init(view_app_options *options)
{
    memset(options, 0, sizeof *options);
    rt_render_options_init(&options->render);
    options->scale = 1.0;
    options->format = rt_image_format_supported(RT_IMAGE_PNG) ? RT_IMAGE_PNG
                                                              : RT_IMAGE_P6;
}

/* The session's notify hook: wakes the event loop (any thread). */
static void wake(void *user)
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

static void update_title(view_app *app)
{
    char title[sizeof app->title];
    if (app->message[0]) {
        snprintf(title, sizeof title, "%s - " PROGRAM, app->message);
    } else if (app->session == NULL) {
        snprintf(title, sizeof title, PROGRAM " - drop a .scn file here");
    } else {
        view_progress progress;
        view_session_get_progress(app->session, &progress);
        char state[96];
        view_progress_describe(&progress, state, sizeof state);
        const rt_image *image = view_session_image(app->session);
        snprintf(title, sizeof title, "%s %dx%d depth %d - %s - " PROGRAM,
                 base_name(app->shown_path), image->width, image->height,
                 progress.max_depth, state);
    }
    if (strcmp(title, app->title) != 0) {
        snprintf(app->title, sizeof app->title, "%s", title);
        view_window_set_title(app->window, app->title);
    }
}

static void show_message(view_app *app, const char *message)
{
    fprintf(stderr, PROGRAM ": %s\n", message);
    snprintf(app->message, sizeof app->message, "%s", message);
    update_title(app);
}

static void start_render(view_app *app)
{
    if (app->session == NULL)
        return;
    app->message[0] = '\0';
    if (view_session_start(app->session) != RT_OK)
        show_message(app, "cannot start the rendering thread");
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

view_app *view_app_create(const view_app_options *options, char *error,
                          size_t error_size)
{
    view_app *app = calloc(1, sizeof *app);
    if (app == NULL) {
        snprintf(error, error_size, "out of memory");
        return NULL;
    }
    app->options = *options;
    app->wake_event = SDL_RegisterEvents(1);
    if (app->wake_event == (Uint32)-1) {
        snprintf(error, error_size, "cannot register an SDL event");
        free(app);
        return NULL;
    }
    /* Hidden until it has the scene's size and place. */
    app->window = view_window_create(PROGRAM, EMPTY_SIZE, EMPTY_SIZE * 3 / 4,
                                     options->window_flags |
                                         VIEW_WINDOW_HIDDEN,
                                     error, error_size);
    if (app->window == NULL) {
        free(app);
        return NULL;
    }
    update_title(app);
    return app;
}

void view_app_destroy(view_app *app)
{
    if (app == NULL)
        return;
    /* Close the window at once, then wait for the render to stop. */
    view_window_hide(app->window);
    view_window_attach(app->window, NULL, NULL, 0);
    view_session_destroy(app->session);
    view_window_destroy(app->window);
    free(app->path);
    free(app->shown_path);
    free(app);
}

static char *copy_text(const char *text)
{
    char *copy = malloc(strlen(text) + 1);
    if (copy)
        strcpy(copy, text);
    return copy;
}

/* The render options for `scene`: --scale gives the size when --size did
 * not. */
static rt_render_options render_options(const view_app *app,
                                        const rt_scene *scene)
{
    rt_render_options render = app->options.render;
    if (render.width == 0 && render.height == 0 &&
        app->options.scale != 1.0) {
        rt_scene_info info;
        rt_scene_get_info(scene, &info);
        render.width = view_scale_side(info.width, app->options.scale);
        render.height = view_scale_side(info.height, app->options.scale);
    }
    return render;
}

/* A session rendering `scene` (taken over), or NULL with the error shown. */
static view_session *new_session(view_app *app, rt_scene *scene,
                                 const char *path)
{
    view_session_options options;
    view_session_options_init(&options);
    options.render = render_options(app, scene);
    options.notify = wake;
    options.notify_user = app;
    view_session *session;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_session_create(scene, &options, &session, &error);
    if (status != RT_OK) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "%s: %s", path,
                 error.message[0] ? error.message
                                  : rt_status_string(status));
        show_message(app, message);
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
        show_message(app, message);
        return;
    }
    start_render(app);
    app->redraw = 1;
}

int view_app_open(view_app *app, const char *path)
{
    char *watched = copy_text(path);
    char *shown = copy_text(path);
    if (watched == NULL || shown == NULL) {
        free(watched);
        free(shown);
        show_message(app, "out of memory");
        return 0;
    }
    free(app->path);
    app->path = watched;
    app->scene_asked = 1;
    /* Stamped before reading: an edit during the load is seen next time. */
    view_file_stamp_read(path, &app->stamp);

    rt_scene *scene;
    rt_error error;
    if (view_scene_load(path, app->options.load, &scene, &error) != RT_OK) {
        free(shown);
        show_message(app, error.message);
        return 0;
    }
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, PROGRAM ": %s\n", rt_scene_warning(scene, i)->message);
    view_session *session = new_session(app, scene, path);
    if (session == NULL) {
        free(shown);
        return 0;
    }
    show_session(app, session, shown);
    return 1;
}

int view_app_reload(view_app *app)
{
    if (app->path == NULL)
        return 0;
    char *path = copy_text(app->path);
    if (path == NULL) {
        show_message(app, "out of memory");
        return 0;
    }
    int loaded = view_app_open(app, path);
    free(path);
    return loaded;
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
    view_app_reload(app);
    return 1;
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
static void take_termination_signal(view_app *app)
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

/* The finished rows (the others black) in a new image; their count in
 * *rows. */
static rt_status copy_finished_rows(view_app *app, rt_image *copy, int *rows)
{
    const rt_image *image = view_session_image(app->session);
    rt_status status = rt_image_init(copy, image->width, image->height, NULL);
    *rows = 0;
    if (status != RT_OK)
        return status;
    for (int y = 0; y < image->height; y++) {
        if (view_session_row_done(app->session, y)) {
            memcpy(rt_image_pixel(copy, 0, y), rt_image_pixel(image, 0, y),
                   (size_t)image->width * 3);
            (*rows)++;
        }
    }
    return RT_OK;
}

/* Where this save goes (see view_app.h); *claimed is 1 when the name was
 * created empty for it (to remove if the save fails). */
static int choose_save_path(view_app *app, int partial, char *path,
                            size_t size, int *claimed)
{
    char stem[4096];
    rt_error error;
    *claimed = 0;
    if (app->options.output) {
        if (!partial && !app->output_written) {
            int written = snprintf(path, size, "%s", app->options.output);
            return written >= 0 && (size_t)written < size;
        }
        snprintf(stem, sizeof stem, "%s", app->options.output);
    } else if (!view_scene_image_path(
                   app->shown_path,
                   app->options.format == RT_IMAGE_PNG ? ".png" : ".ppm",
                   stem, sizeof stem)) {
        show_message(app, "cannot save: the image's path is too long");
        return 0;
    }
    if (!view_save_claim_numbered(stem, partial ? "partial" : NULL, path,
                                  size, &error)) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "cannot save: %s", error.message);
        show_message(app, message);
        return 0;
    }
    *claimed = 1;
    return 1;
}

int view_app_save(view_app *app, char *path, size_t size)
{
    if (app->session == NULL) {
        show_message(app, "nothing to save: no scene is loaded");
        return 0;
    }
    rt_image copy;
    int rows;
    if (copy_finished_rows(app, &copy, &rows) != RT_OK) {
        show_message(app, "cannot save: out of memory");
        return 0;
    }
    int partial = rows < copy.height;
    int claimed;
    int saved = 0;
    if (choose_save_path(app, partial, path, size, &claimed)) {
        rt_error error;
        rt_status status =
            rt_image_save(path, &copy, app->options.format, &error);
        if (status == RT_OK) {
            saved = 1;
            if (!claimed)
                app->output_written = 1;
            if (partial)
                printf("%s (partial: %d of %d rows)\n", path, rows,
                       copy.height);
            else
                printf("%s\n", path);
            fflush(stdout);
        } else {
            if (claimed)
                unlink(path);   /* the empty file claimed for it */
            if (status == RT_ERR_INTERRUPTED)
                take_termination_signal(app);  /* nothing else changed */
            else
                show_message(app, error.message);
        }
    }
    rt_image_release(&copy);
    return saved;
}

static void change_depth(view_app *app, int delta)
{
    int depth = app->options.render.max_depth + delta;
    if (depth < 0 || depth > VIEW_MAX_DEPTH)
        return;
    app->options.render.max_depth = depth;
    if (app->session) {
        view_session_set_depth(app->session, depth);
        start_render(app);
    }
}

static void handle_key(view_app *app, const SDL_KeyboardEvent *key)
{
    char path[4096];
    switch (key->keysym.sym) {
    case SDLK_q:
    case SDLK_ESCAPE:
        app->quit = 1;
        break;
    case SDLK_s:
        if (!key->repeat)
            view_app_save(app, path, sizeof path);
        break;
    case SDLK_r:
        if (!key->repeat)
            view_app_reload(app);
        break;
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS:
        change_depth(app, +1);
        break;
    case SDLK_MINUS:
    case SDLK_KP_MINUS:
        change_depth(app, -1);
        break;
    default:
        break;
    }
}

static void handle_event(view_app *app, SDL_Event *event)
{
    switch (event->type) {
    case SDL_QUIT:
        app->quit = 1;
        break;
    case SDL_KEYDOWN:
        handle_key(app, &event->key);
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

/* How long the loop may sleep: until the next frame while rendering, and
 * never past the next look at a watched file. */
static int wait_ms(int busy, Uint64 now, Uint64 next_frame, Uint64 next_watch,
                   int watch)
{
    int timeout = IDLE_MS;
    if (busy)
        timeout = next_frame > now ? (int)(next_frame - now) : TITLE_MS;
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
        take_termination_signal(app);
        if (app->quit)
            break;
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
            update_title(app);
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

const char *view_app_message(const view_app *app)
{
    return app->message;
}
