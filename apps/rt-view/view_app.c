/*
 * view_app.c - rt-view's window, keys, reloads, saves and event loop (see
 * view_app.h).  The main thread sleeps in SDL_WaitEventTimeout and is woken
 * by a user event that the session's notify hook pushes when rows are
 * finished, and the load's when a scene is read; frames are drawn at most
 * every FRAME_MS, with --watch the file is looked at every VIEW_WATCH_MS,
 * and the loop never sleeps longer than VIEW_SIGNAL_MS (termination
 * signals cannot wake it).
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

#include "cli_output.h"
#include "view_explain.h"
#include "view_scene.h"
#include "view_window.h"

#define PROGRAM "rt-view"
#define FRAME_MS 16        /* shortest time between two frames */
#define TITLE_MS 100       /* how often the elapsed time is refreshed */
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
    view_load *load;            /* the load under way, or NULL */
    view_window *window;
    Uint32 wake_event;
    char message[RT_ERROR_MESSAGE_SIZE + 64]; /* shown in the title */
    char title[RT_ERROR_MESSAGE_SIZE + 256];
    int shown;                  /* the window is on screen */
    int quit;
    int quit_signal;            /* the termination signal, or 0 */
    int redraw;
    int view;                   /* 0: the picture, else an rt_debug_view */
    int view_light;             /* the light of the shadow and N.S views */
    view_explanation explanation; /* of the clicked pixel; text NULL: none */
    int help;                   /* the help is shown in the window */
};

const char view_app_keys_help[] =
    "Keys (rt-view --help says more)\n"
    "click    explain that pixel: its rays over\n"
    "         the image (camera white, shadow\n"
    "         yellow, blocked red, reflected\n"
    "         cyan, refracted magenta) and text\n"
    "right click, Esc  clear (Esc: else quit)\n"
    "N normal   D depth   F facet index\n"
    "L shadow term E (again: next light)\n"
    "B bounces  I N.S (again: next light)\n"
    "V, 0     the picture\n"
    "S save   R reload   + - depth\n"
    "H, F1    this help  Q quit\n";

static const char *const view_names[] = {
    "", "normal view", "depth view", "facet view", "shadow view",
    "bounces view", "N.S view",
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
    char loading[160] = "";
    if (app->load != NULL)
        snprintf(loading, sizeof loading, "loading %.120s - ",
                 base_name(view_load_path(app->load)));
    if (app->message[0]) {
        snprintf(title, sizeof title, "%s - %s" PROGRAM, app->message,
                 loading);
    } else if (app->session == NULL) {
        if (loading[0])
            snprintf(title, sizeof title, "%s" PROGRAM, loading);
        else
            snprintf(title, sizeof title, PROGRAM " - drop a .scn file here");
    } else {
        view_progress progress;
        view_session_get_progress(app->session, &progress);
        char state[96];
        view_progress_describe(&progress, state, sizeof state);
        const rt_image *image = view_session_image(app->session);
        char view[64] = "";
        if (app->view == RT_VIEW_SHADOW || app->view == RT_VIEW_NS)
            snprintf(view, sizeof view, " - %s of light %d",
                     view_names[app->view], app->view_light);
        else if (app->view)
            snprintf(view, sizeof view, " - %s", view_names[app->view]);
        snprintf(title, sizeof title, "%s %dx%d depth %d - %s%s - %s" PROGRAM,
                 base_name(app->shown_path), image->width, image->height,
                 progress.max_depth, state, view, loading);
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

static int show_view(view_app *app);
static void clear_explanation(view_app *app);

static void start_render(view_app *app)
{
    if (app->session == NULL)
        return;
    app->message[0] = '\0';
    if (view_session_start(app->session) != RT_OK)
        show_message(app, "cannot start the rendering thread");
    /* The explanation and the debug view were of the render before. */
    clear_explanation(app);
    if (app->view)
        show_view(app);
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
    app->view = options->view;
    app->view_light = options->view_light;
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
    if (watched == NULL) {
        show_message(app, "out of memory");
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
    if (view_load_start(path, app->options.load, load, wake, app,
                        &app->load) != RT_OK) {
        show_message(app, "cannot start loading the scene: out of memory");
        return 0;
    }
    update_title(app);
    return 1;
}

int view_app_loading(const view_app *app)
{
    return app->load != NULL;
}

/* The load under way has ended: shows its scene, or its error (the
 * current picture stays).  Returns 1 when it loaded. */
static int finish_load(view_app *app)
{
    view_load *load = app->load;
    app->load = NULL;
    char *shown = copy_text(view_load_path(load));
    rt_scene *scene;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_load_finish(load, &scene, &error);
    if (status != RT_OK || shown == NULL) {
        show_message(app, shown == NULL ? "out of memory"
                          : error.message[0] ? error.message
                                             : rt_status_string(status));
        rt_scene_destroy(scene);
        free(shown);
        return 0;
    }
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, PROGRAM ": %s\n", rt_scene_warning(scene, i)->message);
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
    return finish_load(app);
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
    char clash[sizeof app->message];
    if (!choose_save_path(app, partial, path, size, &claimed)) {
        /* the reason is shown */
    } else if (cli_output_clash(path, view_session_scene(app->session),
                                app->shown_path, 0, "the image", clash,
                                sizeof clash)) {
        /* -o names the scene, or a file the scene read: never over it */
        if (claimed)
            unlink(path);
        show_message(app, clash);
    } else {
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

/* The overlay and text panel for what is shown now. */
static void update_overlay(view_app *app)
{
    const view_explanation *e = &app->explanation;
    view_projection projection;
    if (app->session && e->text) {
        rt_render_options options =
            render_options(app, view_session_scene(app->session));
        view_projection_init(&projection, view_session_scene(app->session),
                             &options);
        view_window_set_overlay(app->window, &projection, e->segments,
                                e->segment_count);
    } else {
        view_window_set_overlay(app->window, NULL, NULL, 0);
    }
    /* The text away from the clicked pixel. */
    int bottom = 0;
    if (app->session && e->text && !app->help)
        bottom = e->y < view_session_image(app->session)->height / 2;
    view_window_set_text_place(app->window, bottom);
    view_window_set_text(app->window, app->help ? view_app_keys_help
                                                : e->text);
    app->redraw = 1;
}

static void clear_explanation(view_app *app)
{
    if (app->explanation.text == NULL && !app->help)
        return;
    view_explanation_release(&app->explanation);
    app->help = 0;
    update_overlay(app);
}

int view_app_explain(view_app *app, int x, int y)
{
    if (app->session == NULL)
        return 0;
    const rt_scene *scene = view_session_scene(app->session);
    rt_render_options options = render_options(app, scene);
    view_explanation explanation;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_explain_pixel(scene, &options, app->shown_path,
                                          x, y, &explanation, &error);
    if (status != RT_OK) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "cannot explain pixel (%d, %d): %s",
                 x, y, error.message[0] ? error.message
                                        : rt_status_string(status));
        show_message(app, message);
        return 0;
    }
    view_explanation_release(&app->explanation);
    app->explanation = explanation;
    app->help = 0;
    fputs(explanation.text, stdout);
    fflush(stdout);
    update_overlay(app);
    return 1;
}

int view_app_click(view_app *app, int window_x, int window_y)
{
    int x, y;
    if (!view_window_pixel_at(app->window, window_x, window_y, &x, &y))
        return 0;
    return view_app_explain(app, x, y);
}

const view_explanation *view_app_explanation(const view_app *app)
{
    return app->explanation.text ? &app->explanation : NULL;
}

/* Renders debug view app->view into the window (or the picture again). */
static int show_view(view_app *app)
{
    if (app->session == NULL)
        return 0;
    app->redraw = 1;
    if (app->view == 0)
        return view_window_show_image(app->window, NULL);
    const rt_scene *scene = view_session_scene(app->session);
    rt_render_options options = render_options(app, scene);
    const rt_image *picture = view_session_image(app->session);
    rt_image image;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_image_init(&image, picture->width, picture->height,
                                     NULL);
    if (status == RT_OK) {
        status = rt_render_view(scene, &options, (rt_debug_view)app->view,
                                app->view_light, &image, &error);
        if (status == RT_OK)
            view_window_show_image(app->window, &image);
        rt_image_release(&image);
    }
    if (status != RT_OK) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "cannot show the %s: %s",
                 view_names[app->view],
                 error.message[0] ? error.message : rt_status_string(status));
        app->view = 0;
        view_window_show_image(app->window, NULL);
        show_message(app, message);
        return 0;
    }
    update_title(app);
    return 1;
}

int view_app_set_view(view_app *app, int view, int light)
{
    if (view < 0 || view > RT_VIEW_NS)
        return 0;
    app->view = view;
    app->view_light = light;
    int shown = show_view(app);
    update_title(app);
    return shown;
}

/* L and I: the view of the first light, then of the next one. */
static void cycle_light_view(view_app *app, int view)
{
    int light = 0;
    if (app->view == view && app->session) {
        rt_scene_info info;
        rt_scene_get_info(view_session_scene(app->session), &info);
        light = (app->view_light + 1) % info.light_count;
    }
    view_app_set_view(app, view, light);
}

static void toggle_help(view_app *app)
{
    app->help = !app->help;
    if (app->help && !view_window_has_text(app->window))
        fputs(view_app_keys_help, stdout);
    update_overlay(app);
}

void view_app_key(view_app *app, int key, int repeat)
{
    char path[4096];
    switch (key) {
    case SDLK_ESCAPE:
        if (app->explanation.text || app->help)
            clear_explanation(app);
        else
            app->quit = 1;
        break;
    case SDLK_q:
        app->quit = 1;
        break;
    case SDLK_n:
        view_app_set_view(app, RT_VIEW_NORMAL, 0);
        break;
    case SDLK_d:
        view_app_set_view(app, RT_VIEW_DEPTH, 0);
        break;
    case SDLK_f:
        view_app_set_view(app, RT_VIEW_FACET, 0);
        break;
    case SDLK_b:
        view_app_set_view(app, RT_VIEW_BOUNCES, 0);
        break;
    case SDLK_l:
        cycle_light_view(app, RT_VIEW_SHADOW);
        break;
    case SDLK_i:
        cycle_light_view(app, RT_VIEW_NS);
        break;
    case SDLK_v:
    case SDLK_0:
    case SDLK_KP_0:
        view_app_set_view(app, 0, 0);
        break;
    case SDLK_h:
    case SDLK_F1:
        if (!repeat)
            toggle_help(app);
        break;
    case SDLK_s:
        if (!repeat)
            view_app_save(app, path, sizeof path);
        break;
    case SDLK_r:
        if (!repeat)
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
        view_app_key(app, event->key.keysym.sym, event->key.repeat);
        break;
    case SDL_MOUSEBUTTONDOWN:
        if (event->button.button == SDL_BUTTON_LEFT)
            view_app_click(app, event->button.x, event->button.y);
        else if (event->button.button == SDL_BUTTON_RIGHT)
            clear_explanation(app);
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
        take_termination_signal(app);
        if (app->quit)
            break;
        if (app->load != NULL && view_load_done(app->load)) {
            finish_load(app);
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
