/*
 * rt-view - shows a scene in an SDL window while it renders.
 *
 * This file is the command line and the event loop; the work is elsewhere:
 * view_session renders on its own thread and reports finished rows,
 * view_window uploads those rows and draws, view_scene loads and names
 * files.  The main thread sleeps in SDL_WaitEventTimeout and is woken by a
 * user event that the session's notify hook pushes when rows are finished;
 * frames are drawn at most every FRAME_MS.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <time.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "cli_values.h"
#include "raytrace/raytrace.h"
#include "view_scene.h"
#include "view_session.h"
#include "view_window.h"

#define PROGRAM "rt-view"
#define FRAME_MS 16        /* shortest time between two frames */
#define TITLE_MS 100       /* how often the elapsed time is refreshed */
#define IDLE_MS 500        /* wait when nothing is rendering */
#define EMPTY_SIZE 480     /* window side when no scene is loaded */

static const char usage_text[] =
    "Usage: " PROGRAM " [OPTION]... [SCENE.scn]\n"
    "Show SCENE.scn in a window while it renders; each finished row appears\n"
    "at once.  The title shows the scene, the progress and the elapsed time,\n"
    "then the total time.\n"
    "\n"
    "Options:\n"
    "  --depth N     reflections followed after a primary ray, 0.."
    "100 (default 5)\n"
    "  --scale F     render at F times the scene's size in pixels, e.g. 0.5\n"
    "                for a quick preview or 2 for detail (default 1; the\n"
    "                window is scaled down to fit the screen either way)\n"
    "  --threads N   rendering threads, 0 for one per core (default 0)\n"
    "  --samples N   rays per pixel, a square (1, 4, 9, ...; default 1)\n"
    "  --aperture A  lens radius in scene units (default: the scene's; 0 for\n"
    "                a pinhole); depth of field needs several samples\n"
    "  --focus F     distance in focus, in scene units along the view axis\n"
    "                (default: the scene's, else the screen's distance)\n"
    "  --input-format F, --tessellate T, --look-from X,Y,Z, --look-at X,Y,Z,\n"
    "  --up X,Y,Z, --fov DEGREES, --light X,Y,Z[,R,G,B] (repeatable)\n"
    "                as in rt-export: the scene's format, the tolerance of\n"
    "                NFF's curved shapes, a view and lights that replace the\n"
    "                scene's\n"
    "  --help        show this help and exit\n"
    "  --version     show the version and exit\n"
    "\n"
    "Keys:\n"
    "  S             save the image next to the scene, as SCENE.png (or\n"
    "                SCENE.ppm in a build without PNG support); rows not\n"
    "                rendered yet are black; prints the path\n"
    "  R             render again\n"
    "  + / -         one more / one less reflection, and render again\n"
    "  Q, Esc        quit (a render in progress is cancelled)\n"
    "\n"
    "Drop a .scn file on the window to load and render it.  A scene with\n"
    "errors is reported as FILE:LINE:COLUMN: MESSAGE on stderr and in the\n"
    "title; the picture shown before stays.  The window can be moved,\n"
    "resized or closed at any time.  SIGINT, SIGTERM or SIGHUP cancel the\n"
    "render (and a save under way, leaving the file as it was) and end\n"
    "rt-view with 128 + the signal's number.\n";

typedef struct viewer {
    double scale;
    int max_depth;
    int threads;
    int samples;
    double aperture;            /* negative: the scene's */
    double focal_distance;      /* 0: the scene's */
    rt_load_options load;       /* format, tessellation, view, lights */
    rt_light lights[16];        /* --light, in order */
    char *scene_path;           /* of the session; NULL when none */
    view_session *session;
    view_window *window;
    Uint32 wake_event;
    char message[RT_ERROR_MESSAGE_SIZE + 64]; /* shown in the title */
    char title[RT_ERROR_MESSAGE_SIZE + 256];
    int shown;                  /* the window is on screen */
    int quit;
    int quit_signal;        /* the termination signal that ended it, or 0 */
    int redraw;
} viewer;

/* The session's notify hook: wakes the event loop (any thread). */
static void wake(void *context)
{
    const viewer *v = context;
    SDL_Event event;
    SDL_zero(event);
    event.type = v->wake_event;
    SDL_PushEvent(&event);
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static void update_title(viewer *v)
{
    char title[sizeof v->title];
    if (v->message[0]) {
        snprintf(title, sizeof title, "%s - " PROGRAM, v->message);
    } else if (v->session == NULL) {
        snprintf(title, sizeof title, PROGRAM " - drop a .scn file here");
    } else {
        view_progress progress;
        view_session_get_progress(v->session, &progress);
        char state[96];
        view_progress_describe(&progress, state, sizeof state);
        const rt_image *image = view_session_image(v->session);
        snprintf(title, sizeof title, "%s %dx%d depth %d - %s - " PROGRAM,
                 base_name(v->scene_path), image->width, image->height,
                 progress.max_depth, state);
    }
    if (strcmp(title, v->title) != 0) {
        snprintf(v->title, sizeof v->title, "%s", title);
        view_window_set_title(v->window, v->title);
    }
}

static void show_message(viewer *v, const char *message)
{
    fprintf(stderr, PROGRAM ": %s\n", message);
    snprintf(v->message, sizeof v->message, "%s", message);
    update_title(v);
}

static void start_render(viewer *v)
{
    if (v->session == NULL)
        return;
    v->message[0] = '\0';
    if (view_session_start(v->session) != RT_OK)
        show_message(v, "cannot start the rendering thread");
}

/* The largest window that fits on the screen the window is on, placed so
 * that it is all visible. */
static void fit_window(viewer *v, int width, int height)
{
    SDL_Rect bounds = {0, 0, 1024, 768};
    int display = view_window_display(v->window);
    if (SDL_GetDisplayUsableBounds(display, &bounds) != 0)
        SDL_GetDisplayBounds(0, &bounds);
    /* Leave room for the window manager's border and title bar. */
    const int border = 8, title_bar = 32;
    int area[4] = {bounds.x + border, bounds.y + title_bar,
                   bounds.w - 2 * border, bounds.h - title_bar - border};
    int w, h;
    view_fit_size(width, height, area[2], area[3], &w, &h);
    view_window_place(v->window, w, h, area, !v->shown);
}

/* Loads `path` and shows it instead of the current scene.  On error the
 * current scene stays and the error is printed and put in the title. */
static void open_scene(viewer *v, const char *path)
{
    rt_scene *scene;
    rt_error error;
    if (view_scene_load_with(path, v->scale, &v->load, &scene, &error) !=
        RT_OK) {
        show_message(v, error.message);
        return;
    }
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, PROGRAM ": %s\n", rt_scene_warning(scene, i)->message);

    char *copy = malloc(strlen(path) + 1);
    if (copy == NULL) {
        rt_scene_free(scene);
        show_message(v, "out of memory");
        return;
    }
    strcpy(copy, path);
    view_session_options options;
    view_session_options_init(&options);
    options.max_depth = v->max_depth;
    options.threads = v->threads;
    options.samples = v->samples;
    options.aperture = v->aperture;
    options.focal_distance = v->focal_distance;
    options.notify = wake;
    options.notify_context = v;
    view_session *session;
    if (view_session_create(scene, &options, &session) != RT_OK) {
        free(copy); /* the scene was freed by view_session_create */
        show_message(v, "out of memory");
        return;
    }

    view_window_attach(v->window, NULL, NULL, 0);
    view_session_destroy(v->session);
    free(v->scene_path);
    v->session = session;
    v->scene_path = copy;

    const rt_image *image = view_session_image(session);
    fit_window(v, image->width, image->height);
    char message[256];
    if (!view_window_attach(v->window, session, message, sizeof message)) {
        show_message(v, message);
        return;
    }
    start_render(v);
    v->redraw = 1;
}

/* SIGINT, SIGTERM and SIGHUP are blocked in every thread (main() blocks
 * them before any thread starts) and taken here, in the event loop, so that
 * a save under way first removes its temporary file (rt_image_save). */
static void termination_signals(sigset_t *set)
{
    sigemptyset(set);
    sigaddset(set, SIGINT);
    sigaddset(set, SIGTERM);
    sigaddset(set, SIGHUP);
}

/* Takes a pending termination signal, if any, and asks the loop to quit. */
static void take_termination_signal(viewer *v)
{
    sigset_t set;
    termination_signals(&set);
    struct timespec now = {0, 0};
    int signal_number = sigtimedwait(&set, NULL, &now);
    if (signal_number > 0) {
        v->quit = 1;
        v->quit_signal = signal_number;
    }
}

/* Saves the finished rows (the others black) next to the scene. */
static void save_image(viewer *v)
{
    if (v->session == NULL)
        return;
    char path[4096];
    rt_image_format format =
        rt_image_format_supported(RT_IMAGE_PNG) ? RT_IMAGE_PNG : RT_IMAGE_P6;
    if (!view_scene_image_path(v->scene_path,
                               format == RT_IMAGE_PNG ? ".png" : ".ppm", path,
                               sizeof path)) {
        show_message(v, "the image's path is too long");
        return;
    }
    const rt_image *image = view_session_image(v->session);
    rt_image copy;
    if (rt_image_create(&copy, image->width, image->height) != RT_OK) {
        show_message(v, "cannot save: out of memory");
        return;
    }
    int rows = 0;
    for (int y = 0; y < image->height; y++) {
        if (view_session_row_done(v->session, y)) {
            memcpy(rt_image_pixel(&copy, 0, y), rt_image_pixel(image, 0, y),
                   (size_t)image->width * 3);
            rows++;
        }
    }
    rt_error error;
    rt_status status = rt_image_save(path, &copy, format, &error);
    if (status == RT_ERR_INTERRUPTED) {
        take_termination_signal(v);     /* the file is as it was */
    } else if (status != RT_OK) {
        show_message(v, error.message);
    } else if (rows < image->height) {
        printf("%s (partial: %d of %d rows)\n", path, rows, image->height);
    } else {
        printf("%s\n", path);
    }
    fflush(stdout);
    rt_image_destroy(&copy);
}

static void change_depth(viewer *v, int delta)
{
    int depth = v->max_depth + delta;
    if (depth < 0 || depth > VIEW_MAX_DEPTH)
        return;
    v->max_depth = depth;
    if (v->session) {
        view_session_set_depth(v->session, depth);
        start_render(v);
    }
}

static void handle_key(viewer *v, const SDL_KeyboardEvent *key)
{
    switch (key->keysym.sym) {
    case SDLK_q:
    case SDLK_ESCAPE:
        v->quit = 1;
        break;
    case SDLK_s:
        if (!key->repeat)
            save_image(v);
        break;
    case SDLK_r:
        if (!key->repeat)
            start_render(v);
        break;
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS:
        change_depth(v, +1);
        break;
    case SDLK_MINUS:
    case SDLK_KP_MINUS:
        change_depth(v, -1);
        break;
    default:
        break;
    }
}

static void handle_event(viewer *v, SDL_Event *event)
{
    switch (event->type) {
    case SDL_QUIT:
        v->quit = 1;
        break;
    case SDL_KEYDOWN:
        handle_key(v, &event->key);
        break;
    case SDL_DROPFILE:
        open_scene(v, event->drop.file);
        SDL_free(event->drop.file);
        break;
    case SDL_WINDOWEVENT:
        if (event->window.event == SDL_WINDOWEVENT_CLOSE)
            v->quit = 1;
        else
            v->redraw = 1;
        break;
    default:
        break;
    }
}

static int rendering(viewer *v)
{
    if (v->session == NULL)
        return 0;
    view_progress progress;
    view_session_get_progress(v->session, &progress);
    return progress.state == VIEW_RENDERING;
}

static void run(viewer *v)
{
    Uint64 next_frame = 0, next_title = 0;
    int was_rendering = 1;
    while (!v->quit) {
        Uint64 now = SDL_GetTicks64();
        int busy = rendering(v) || was_rendering;
        int timeout = IDLE_MS;
        if (busy)
            timeout = next_frame > now ? (int)(next_frame - now) : TITLE_MS;
        SDL_Event event;
        if (SDL_WaitEventTimeout(&event, timeout)) {
            handle_event(v, &event);
            while (!v->quit && SDL_PollEvent(&event))
                handle_event(v, &event);
        }
        take_termination_signal(v);
        if (v->quit)
            break;
        now = SDL_GetTicks64();
        if (now < next_frame)
            continue;
        was_rendering = rendering(v);
        if (view_window_sync(v->window) || v->redraw) {
            view_window_draw(v->window);
            v->redraw = 0;
            next_frame = now + FRAME_MS;
        }
        if (now >= next_title || !was_rendering) {
            update_title(v);
            next_title = now + TITLE_MS;
        }
    }
}

static int parse_int(const char *text, int low, int high, int *value)
{
    char *end;
    errno = 0;
    long number = strtol(text, &end, 10);
    if (errno || end == text || *end || number < low || number > high)
        return 0;
    *value = (int)number;
    return 1;
}

static int parse_scale(const char *text, double *value)
{
    char *end;
    errno = 0;
    double number = strtod(text, &end);
    if (errno || end == text || *end || !(number >= VIEW_MIN_SCALE) ||
        !(number <= VIEW_MAX_SCALE))
        return 0;
    *value = number;
    return 1;
}

/* One of the loader's options (shared with rt-export); returns NULL, or
 * what was expected. */
static const char *load_option(viewer *v, const char *arg, const char *text)
{
    rt_load_options *o = &v->load;
    if (strcmp(arg, "--input-format") == 0)
        return cli_parse_scene_format(text, &o->format)
                   ? NULL
                   : "--input-format expects scn, nff or obj, not";
    if (strcmp(arg, "--tessellate") == 0)
        return cli_parse_length(text, 1, &o->tessellation) &&
                       o->tessellation < 1
                   ? NULL
                   : "--tessellate expects a tolerance in (0, 1), not";
    if (strcmp(arg, "--fov") == 0) {
        if (!cli_parse_length(text, 1, &o->fov) || !(o->fov < 180))
            return "--fov expects degrees in (0, 180), not";
        o->fov_given = 1;
        return NULL;
    }
    if (strcmp(arg, "--light") == 0) {
        if (o->light_count == 16)
            return "at most 16 --light options; one more:";
        if (!cli_parse_light(text, &v->lights[o->light_count]))
            return "--light expects x,y,z or x,y,z,r,g,b (0..255), not";
        o->lights = v->lights;
        o->light_count++;
        return NULL;
    }
    int *given = strcmp(arg, "--look-from") == 0 ? &o->look_from_given
                 : strcmp(arg, "--look-at") == 0 ? &o->look_at_given
                                                  : &o->up_given;
    rt_vec3 *point = strcmp(arg, "--look-from") == 0 ? &o->look_from
                     : strcmp(arg, "--look-at") == 0 ? &o->look_at
                                                      : &o->up;
    if (!cli_parse_point(text, point))
        return "expected x,y,z after the option, not";
    *given = 1;
    return NULL;
}

static int usage_error(const char *message, const char *argument)
{
    fprintf(stderr, PROGRAM ": %s '%s'\nTry '" PROGRAM " --help'.\n",
            message, argument);
    return 2;
}

/* Fills v from the command line; returns -1 to go on, else an exit code. */
static int parse_arguments(int argc, char **argv, viewer *v,
                           const char **scene)
{
    *scene = NULL;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            fputs(usage_text, stdout);
            return 0;
        } else if (strcmp(arg, "--version") == 0) {
            printf(PROGRAM " (libraytrace) %s\n", rt_version_string());
            return 0;
        } else if (strcmp(arg, "--input-format") == 0 ||
                   strcmp(arg, "--tessellate") == 0 ||
                   strcmp(arg, "--look-from") == 0 ||
                   strcmp(arg, "--look-at") == 0 ||
                   strcmp(arg, "--up") == 0 || strcmp(arg, "--fov") == 0 ||
                   strcmp(arg, "--light") == 0) {
            if (next == NULL)
                return usage_error("missing value after", arg);
            i++;
            const char *wrong = load_option(v, arg, next);
            if (wrong != NULL)
                return usage_error(wrong, next);
        } else if (strcmp(arg, "--samples") == 0 ||
                   strcmp(arg, "--aperture") == 0 ||
                   strcmp(arg, "--focus") == 0) {
            if (next == NULL)
                return usage_error("missing value after", arg);
            i++;
            if (strcmp(arg, "--samples") == 0) {
                int root = 1;
                if (!parse_int(next, 1, 1024, &v->samples))
                    return usage_error("--samples expects a square in "
                                       "1..1024, not", next);
                while (root * root < v->samples)
                    root++;
                if (root * root != v->samples)
                    return usage_error("--samples expects a square (1, 4, "
                                       "9, 16, ...), not", next);
            } else if (!cli_parse_length(next, strcmp(arg, "--focus") == 0,
                                     strcmp(arg, "--focus") == 0
                                         ? &v->focal_distance
                                         : &v->aperture)) {
                return usage_error(strcmp(arg, "--focus") == 0
                                       ? "--focus expects a distance > 0, not"
                                       : "--aperture expects a radius >= 0, "
                                         "not",
                                   next);
            }
        } else if (strcmp(arg, "--depth") == 0 ||
                   strcmp(arg, "--threads") == 0 ||
                   strcmp(arg, "--scale") == 0) {
            if (next == NULL)
                return usage_error("missing value after", arg);
            i++;
            int ok = strcmp(arg, "--scale") == 0
                         ? parse_scale(next, &v->scale)
                     : strcmp(arg, "--depth") == 0
                         ? parse_int(next, 0, VIEW_MAX_DEPTH, &v->max_depth)
                         : parse_int(next, 0, 1024, &v->threads);
            if (!ok)
                return usage_error(
                    strcmp(arg, "--scale") == 0
                        ? "--scale expects a number in 0.01..64, not"
                    : strcmp(arg, "--depth") == 0
                        ? "--depth expects an integer in 0..100, not"
                        : "--threads expects an integer in 0..1024, not",
                    next);
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return usage_error("unknown option", arg);
        } else if (*scene != NULL) {
            return usage_error("only one scene, extra argument", arg);
        } else {
            *scene = arg;
        }
    }
    return -1;
}

int main(int argc, char **argv)
{
    viewer v;
    memset(&v, 0, sizeof v);
    v.scale = 1.0;
    v.max_depth = RT_DEFAULT_DEPTH;
    v.samples = 1;
    v.aperture = -1.0;
    rt_load_options_init(&v.load);
    const char *scene;
    int code = parse_arguments(argc, argv, &v, &scene);
    if (code >= 0)
        return code;

    /* Before any thread exists, so that every thread inherits the mask. */
    sigset_t signals;
    termination_signals(&signals);
    pthread_sigmask(SIG_BLOCK, &signals, NULL);
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");

    SDL_SetMainReady();
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, PROGRAM ": cannot start SDL: %s\n", SDL_GetError());
        return 1;
    }
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");
    v.wake_event = SDL_RegisterEvents(1);
    char error[256];
    /* Hidden until it has the scene's size and place. */
    v.window = view_window_create(PROGRAM, EMPTY_SIZE, EMPTY_SIZE * 3 / 4,
                                  VIEW_WINDOW_HIDDEN, error, sizeof error);
    if (v.window == NULL || v.wake_event == (Uint32)-1) {
        fprintf(stderr, PROGRAM ": %s\n",
                v.window ? "cannot register an SDL event" : error);
        view_window_destroy(v.window);
        SDL_Quit();
        return 1;
    }
    if (scene)
        open_scene(&v, scene);
    update_title(&v);
    view_window_show(v.window);
    v.shown = 1;
    run(&v);

    /* Close the window at once, then wait for the render to stop. */
    view_window_hide(v.window);
    view_window_attach(v.window, NULL, NULL, 0);
    view_session_destroy(v.session);
    view_window_destroy(v.window);
    free(v.scene_path);
    SDL_Quit();
    return v.quit_signal ? 128 + v.quit_signal : 0;
}
