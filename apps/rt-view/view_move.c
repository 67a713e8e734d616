/*
 * view_move.c - moving rt-view's camera (see view_app_internal.h): the
 * mouse drags (orbit, pan), the wheel (dolly, field of view), the keys
 * (fly, field of view, Home) and a double-click (a new target), gathered
 * as the events come and applied once a turn of the event loop, so a fast
 * drag restarts the render once a turn, not once an event.  Each new view
 * is an rt_look (the arithmetic is view_camera.c's) made into a camera by
 * rt_scene_look at the render's size and handed to the session; the scene
 * is never reloaded for it.  Also C: the camera as text, printed and
 * written beside the scene.
 */
#include "view_app_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "view_camera.h"
#include "view_overlay.h"
#include "view_scene.h"
#include "view_window.h"

#define CLICK_SLOP 3            /* window points a click may move */
#define ORBIT_DEGREES 0.4       /* an orbit's turn per window point */
#define DOLLY_STEP 1.2          /* a wheel notch divides the distance */
#define FOV_STEP 1.1            /* ] multiplies the field of view, [ divides */
#define FLY_FRACTION 0.02       /* a fly step: this much of the extent */
#define FLY_FAST 5.0            /* steps a key press with Shift */

#define PI 3.14159265358979323846

static void clear_input(view_move *m)
{
    m->pending = 0;
    m->drag_x = m->drag_y = 0;
    m->wheel = m->fov_wheel = 0;
    m->fly_forward = m->fly_right = m->fly_rise = 0;
    m->fov_steps = 0;
    m->pick = 0;
}

/* Makes `camera` the session's and renders again (NULL: the file's). */
static void show_camera(view_app *app, const rt_camera *camera)
{
    if (view_session_set_camera(app->session, camera) != RT_OK) {
        view_app__show_message(app, "cannot move the camera");
        return;
    }
    view_app__start_render(app);
}

/* After a load the session is another, with the file's camera: a reload
 * of the same file keeps the view (the look applied to the new scene),
 * another file starts from its own.  A new scene is read while the old
 * one still exists, so the two are never at the same address. */
static void follow_scene(view_app *app)
{
    view_move *m = &app->move;
    const rt_scene *scene =
        app->session ? view_session_scene(app->session) : NULL;
    if (scene == m->scene)
        return;
    int same_file = m->moved && scene && app->shown_path &&
                    strcmp(app->shown_path, m->path) == 0;
    m->scene = scene;
    m->button = 0;
    clear_input(m);
    m->path[0] = '\0';
    if (scene == NULL) {
        m->moved = 0;
        return;
    }
    if (app->shown_path && strlen(app->shown_path) < sizeof m->path)
        snprintf(m->path, sizeof m->path, "%s", app->shown_path);
    m->world_up = view_camera_world_up(scene);
    m->extent = view_camera_extent(scene);
    if (same_file &&
        rt_scene_look(scene, &m->look, &m->camera, NULL, NULL) == RT_OK) {
        show_camera(app, &m->camera);
        return;
    }
    m->moved = 0;
}

/* Image pixels per window point, from the letterbox the window draws
 * (view_window.c): what a pan's motion is measured in. */
static void measure(view_app *app, Uint32 window_id)
{
    view_move *m = &app->move;
    m->pixels_per_point = 1;
    SDL_Window *window = SDL_GetWindowFromID(window_id);
    SDL_Renderer *renderer = window ? SDL_GetRenderer(window) : NULL;
    if (renderer == NULL || app->session == NULL)
        return;
    int width, height, out_width, out_height, rect[4];
    SDL_GetWindowSize(window, &width, &height);
    if (SDL_GetRendererOutputSize(renderer, &out_width, &out_height) != 0 ||
        width <= 0 || out_width <= 0 || out_height <= 0)
        return;
    const rt_image *image = view_session_image(app->session);
    view_letterbox(image->width, image->height, out_width, out_height, rect);
    if (rect[2] > 0)
        m->pixels_per_point = (double)out_width / width * image->width /
                              rect[2];
}

static void on_press(view_app *app, const SDL_MouseButtonEvent *button)
{
    view_move *m = &app->move;
    if (m->button)
        return;                 /* one drag at a time */
    int shift = (SDL_GetModState() & KMOD_SHIFT) != 0;
    m->button = button->button;
    m->pan = button->button == SDL_BUTTON_RIGHT ||
             button->button == SDL_BUTTON_MIDDLE ||
             (button->button == SDL_BUTTON_LEFT && shift);
    m->dragging = 0;
    m->picked = 0;
    m->press_x = m->last_x = button->x;
    m->press_y = m->last_y = button->y;
    measure(app, button->windowID);
    int i, j;
    if (button->button == SDL_BUTTON_LEFT && !shift && button->clicks >= 2 &&
        app->session &&
        view_window_pixel_at(app->window, button->x, button->y, &i, &j)) {
        m->picked = 1;
        m->pick = 1;
        m->pick_i = i;
        m->pick_j = j;
        m->pending = 1;
    }
}

static void on_motion(view_app *app, const SDL_MouseMotionEvent *motion)
{
    view_move *m = &app->move;
    if (!m->button || app->session == NULL)
        return;
    if (!m->dragging) {
        if (abs(motion->x - m->press_x) <= CLICK_SLOP &&
            abs(motion->y - m->press_y) <= CLICK_SLOP)
            return;
        m->dragging = 1;
        m->last_x = m->press_x;
        m->last_y = m->press_y;
    }
    m->drag_x += motion->x - m->last_x;
    m->drag_y += motion->y - m->last_y;
    m->last_x = motion->x;
    m->last_y = motion->y;
    m->pending = 1;
}

static void on_release(view_app *app, const SDL_MouseButtonEvent *button)
{
    view_move *m = &app->move;
    if (button->button != m->button)
        return;
    m->button = 0;
    if (m->dragging || m->picked)
        return;
    /* A click, as before the camera moved. */
    if (button->button == SDL_BUTTON_LEFT)
        view_app_click(app, button->x, button->y);
    else if (button->button == SDL_BUTTON_RIGHT)
        view_app__clear_explanation(app);
}

static void on_wheel(view_app *app, const SDL_MouseWheelEvent *wheel)
{
    view_move *m = &app->move;
    double notches = wheel->y;
    if (wheel->direction == SDL_MOUSEWHEEL_FLIPPED)
        notches = -notches;
    if (notches == 0 || app->session == NULL)
        return;
    if (SDL_GetModState() & KMOD_CTRL)
        m->fov_wheel += notches;
    else
        m->wheel += notches;
    m->pending = 1;
}

/* The keys of the camera: 1 when `key` is one. */
static int on_key(view_app *app, const SDL_KeyboardEvent *event)
{
    view_move *m = &app->move;
    double steps = (event->keysym.mod & KMOD_SHIFT) ? FLY_FAST : 1;
    switch (event->keysym.sym) {
    case SDLK_UP: m->fly_forward += steps; break;
    case SDLK_DOWN: m->fly_forward -= steps; break;
    case SDLK_RIGHT: m->fly_right += steps; break;
    case SDLK_LEFT: m->fly_right -= steps; break;
    case SDLK_PAGEUP: m->fly_rise += steps; break;
    case SDLK_PAGEDOWN: m->fly_rise -= steps; break;
    case SDLK_RIGHTBRACKET: m->fov_steps++; break;
    case SDLK_LEFTBRACKET: m->fov_steps--; break;
    case SDLK_HOME:
        if (!event->repeat)
            view_app__camera_home(app);
        return 1;
    case SDLK_c:
        if (!event->repeat)
            view_app__print_camera(app, NULL, 0);
        return 1;
    default:
        return 0;
    }
    if (app->session)
        m->pending = 1;
    return 1;
}

int view_app__move_event(view_app *app, const SDL_Event *event)
{
    follow_scene(app);
    switch (event->type) {
    case SDL_MOUSEBUTTONDOWN:
        on_press(app, &event->button);
        return 1;
    case SDL_MOUSEBUTTONUP:
        on_release(app, &event->button);
        return 1;
    case SDL_MOUSEMOTION:
        on_motion(app, &event->motion);
        return 1;
    case SDL_MOUSEWHEEL:
        on_wheel(app, &event->wheel);
        return 1;
    case SDL_KEYDOWN:
        return on_key(app, &event->key);
    default:
        return 0;
    }
}

void view_app__apply_moves(view_app *app)
{
    view_move *m = &app->move;
    follow_scene(app);
    if (!m->pending)
        return;
    view_move input = *m;
    clear_input(m);
    const rt_scene *scene = m->scene;
    if (scene == NULL)
        return;
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_render_options options = view_app__render_options(app, scene);
    int width = options.width > 0 ? options.width : info.width;
    int height = options.height > 0 ? options.height : info.height;

    rt_look look = m->moved ? m->look : view_camera_file_look(scene);
    rt_camera camera = m->moved ? m->camera : info.camera;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = RT_OK;
    /* Each step moves from where the one before left the camera. */
    if (input.pick) {
        rt_vec3 target;
        if (view_camera_pick(scene, &camera, width, height,
                             input.pick_i + options.region.x0,
                             input.pick_j + options.region.y0, &target) &&
            view_camera_aim(&look, m->world_up, target))
            status = rt_scene_look(scene, &look, &camera, NULL, &error);
    }
    if (status == RT_OK && (input.drag_x != 0 || input.drag_y != 0)) {
        if (input.pan) {
            view_camera_pan(&look, &camera, width,
                            input.drag_x * input.pixels_per_point,
                            input.drag_y * input.pixels_per_point);
        } else {
            double turn = ORBIT_DEGREES * PI / 180;
            view_camera_orbit(&look, m->world_up, -input.drag_x * turn,
                              input.drag_y * turn);
            status = rt_scene_look(scene, &look, &camera, NULL, &error);
        }
    }
    if (status == RT_OK && input.wheel != 0)
        view_camera_dolly(&look, pow(DOLLY_STEP, -input.wheel),
                          m->extent * VIEW_CAMERA_MIN_DISTANCE,
                          m->extent * VIEW_CAMERA_MAX_DISTANCE);
    if (status == RT_OK && (input.fov_steps != 0 || input.fov_wheel != 0))
        look.fov = view_camera_clamp_fov(
            look.fov * pow(FOV_STEP, input.fov_steps - input.fov_wheel));
    if (status == RT_OK && (input.fly_forward != 0 || input.fly_right != 0 ||
                            input.fly_rise != 0)) {
        double step = m->extent * FLY_FRACTION;
        view_camera_fly(&look, &camera, m->world_up,
                        input.fly_forward * step, input.fly_right * step,
                        input.fly_rise * step);
    }
    if (status == RT_OK)
        status = rt_scene_look(scene, &look, &camera, NULL, &error);
    if (status != RT_OK) {
        /* The view shown stays. */
        char message[sizeof app->message];
        snprintf(message, sizeof message, "cannot move the camera there: %s",
                 error.message[0] ? error.message : rt_status_string(status));
        view_app__show_message(app, message);
        return;
    }
    m->look = look;
    m->camera = camera;
    m->moved = 1;
    show_camera(app, &m->camera);
}

void view_app__camera_home(view_app *app)
{
    view_move *m = &app->move;
    follow_scene(app);
    clear_input(m);
    if (!m->moved || app->session == NULL)
        return;
    m->moved = 0;
    show_camera(app, NULL);
}

/* Creates the file the camera's text goes to, never over another:
 * STEM-camera.txt, else the first free STEM-camera-N.txt.  Returns the
 * open file with its name in `path`, or NULL with the reason shown. */
static FILE *claim_camera_file(view_app *app, char *path, size_t size)
{
    char stem[4096];
    char message[sizeof app->message];
    if (!view_scene_side_path(app->shown_path, "-camera.txt", stem,
                              sizeof stem) ||
        strlen(stem) >= size) {
        view_app__show_message(app, "cannot write the camera: its path is "
                                    "too long");
        return NULL;
    }
    int fd = open(stem, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
        snprintf(path, size, "%s", stem);
    } else {
        rt_error error;
        memset(&error, 0, sizeof error);
        if (errno != EEXIST) {
            snprintf(error.message, sizeof error.message, "%.400s: %s", stem,
                     strerror(errno));
        } else if (view_save_claim_numbered(stem, NULL, path, size, &error)) {
            fd = open(path, O_WRONLY | O_TRUNC | O_CLOEXEC);
            if (fd < 0)
                snprintf(error.message, sizeof error.message, "%.400s: %s",
                         path, strerror(errno));
        }
        if (fd < 0) {
            snprintf(message, sizeof message, "cannot write the camera: %s",
                     error.message);
            view_app__show_message(app, message);
            return NULL;
        }
    }
    FILE *file = fdopen(fd, "w");
    if (file == NULL) {
        close(fd);
        unlink(path);
        view_app__show_message(app, "cannot write the camera: out of memory");
    }
    return file;
}

int view_app__print_camera(view_app *app, char *path, size_t size)
{
    follow_scene(app);
    if (app->session == NULL) {
        view_app__show_message(app, "no camera: no scene is loaded");
        return 0;
    }
    view_move *m = &app->move;
    char text[4096];
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_camera_describe(m->scene, app->shown_path,
                                            m->moved ? &m->look : NULL, text,
                                            sizeof text, &error);
    if (status != RT_OK) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "cannot describe the camera: %s",
                 error.message);
        view_app__show_message(app, message);
        return 0;
    }
    fputs(text, stdout);
    char name[4096];
    FILE *file = claim_camera_file(app, name, sizeof name);
    int written = 0;
    if (file) {
        written = fputs(text, file) >= 0;
        written = (fclose(file) == 0) && written;
        if (written) {
            printf("# written to %s\n", name);
            if (path && size > 0)
                snprintf(path, size, "%s", name);
        } else {
            unlink(name);
            char message[sizeof app->message];
            snprintf(message, sizeof message, "cannot write the camera to "
                     "%.400s", name);
            view_app__show_message(app, message);
        }
    }
    fflush(stdout);
    return written;
}
