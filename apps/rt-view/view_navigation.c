/*
 * view_navigation.c - what the user does in rt-view's window besides
 * loading and saving (see view_app.h): the keys, a click's explanation
 * drawn over the image with its text (one sample at a time, Tab for the
 * next), the debug views, the depth and the help.
 */
#include "view_app_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "view_explain.h"
#include "view_overlay.h"
#include "view_window.h"

const char view_app_keys_help[] =
    "Keys (rt-view --help says more)\n"
    "click    explain that pixel: its rays over\n"
    "         the image (camera white, shadow\n"
    "         yellow, blocked red, reflected\n"
    "         cyan, refracted magenta) and text\n"
    "Tab      next sample (Shift: previous)\n"
    "right click, Esc  clear (Esc: else quit)\n"
    "N normal   D depth   F facet index\n"
    "L shadow term E (again: next light)\n"
    "B bounces  I N.S (again: next light)\n"
    "M shading normal (smooth facets)\n"
    "V, 0     the picture\n"
    "S save   R reload   + - depth\n"
    "H, F1    this help  Q quit\n"
    "Camera\n"
    "left drag    orbit round the target\n"
    "right, middle or Shift+left drag  pan\n"
    "wheel        closer / farther\n"
    "[ ], Ctrl+wheel  field of view\n"
    "arrows       fly (Shift: faster)\n"
    "PgUp PgDn    fly up / down\n"
    "double-click the target there\n"
    "Home         the file's camera\n"
    "C            print the camera\n";

/* How the title and the messages name each view (the session's names;
 * the picture has none in the title). */
const char *view_app__view_name(int view)
{
    return view == 0 ? "" : view_session_view_name(view);
}

static void change_depth(view_app *app, int delta)
{
    int depth = app->options.render.max_depth + delta;
    if (depth < 0 || depth > VIEW_MAX_DEPTH)
        return;
    app->options.render.max_depth = depth;
    if (app->session) {
        view_session_set_depth(app->session, depth);
        view_app__start_render(app);
    }
}

/* The text panel's size (view_explain.h's view_explanation_panel) is
 * chosen here, from the picture's size in window points, as
 * view_window.c draws it: DejaVu Sans Mono at 13 points, 8 pixels a
 * character and 16 a line, wrapped at the window's width less 16 pixels,
 * 8 pixels of padding.  The panel takes at most two fifths of the
 * picture's height, on the side away from the clicked pixel (the rest of
 * the text is on standard output). */
#define PANEL_CHAR_PIXELS 8
#define PANEL_LINE_PIXELS 16
#define PANEL_MARGIN_PIXELS 16
#define PANEL_SHARE 0.4

/* How far the window points are looked along for the edges of a pixel or
 * of the picture: wider than any window. */
#define PROBE_RANGE (1 << 16)

/* The overlay and text panel for what is shown now. */
static void update_overlay(view_app *app)
{
    const view_explanation *e = &app->explanation;
    view_projection projection;
    if (app->session && e->text) {
        rt_render_options options =
            view_app__render_options(app, view_session_scene(app->session));
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
                                                : e->panel);
    app->redraw = 1;
}

void view_app__clear_explanation(view_app *app)
{
    if (app->explanation.text == NULL && !app->help)
        return;
    view_explanation_release(&app->explanation);
    app->help = 0;
    update_overlay(app);
}

/* The panel's columns and rows for a picture of width x height points. */
static void panel_size(int width, int height, int *columns, int *rows)
{
    *columns = (width - PANEL_MARGIN_PIXELS) / PANEL_CHAR_PIXELS;
    *rows = (int)(height * PANEL_SHARE - 8) / PANEL_LINE_PIXELS;
    if (*columns < 16)
        *columns = 16;
    if (*rows < 1)
        *rows = 1;
}

/* The panel for a picture of the size the window opens at: the image's,
 * fitted to the screen (view_reload.c), when no click says more. */
static void default_panel_size(view_app *app, int *columns, int *rows)
{
    const rt_image *image = view_session_image(app->session);
    int width = image->width, height = image->height;
    SDL_Rect bounds;
    if (SDL_GetDisplayUsableBounds(view_window_display(app->window),
                                   &bounds) == 0)
        view_fit_size(image->width, image->height, bounds.w, bounds.h,
                      &width, &height);
    panel_size(width, height, columns, rows);
}

/* The explanation's panel text, for its size (NULL when out of memory:
 * the window then shows no panel; the text is on standard output). */
static void make_panel(view_explanation *e)
{
    free(e->panel);
    e->panel = view_explanation_panel(e, e->panel_columns, e->panel_rows);
}

/* With several samples, which one is drawn, on standard output (the text
 * printed on the click holds them all, under "sample K:"). */
static void print_sample_line(const view_explanation *e)
{
    if (e->samples > 1)
        printf("pixel %d,%d: sample %d of %d drawn (Tab: next, Shift+Tab: "
               "previous)\n", e->x, e->y, e->sample, e->samples);
}

/* Explains image point (px, py) with a panel of columns x rows (0: the
 * default size). */
static int explain_point(view_app *app, double px, double py, int columns,
                         int rows)
{
    if (app->session == NULL)
        return 0;
    const rt_scene *scene = view_session_scene(app->session);
    rt_render_options options = view_app__render_options(app, scene);
    view_explanation explanation;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_explain_point(scene, &options, app->shown_path,
                                          px, py, &explanation, &error);
    if (status != RT_OK) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "cannot explain pixel (%d, %d): %s",
                 (int)floor(px), (int)floor(py),
                 error.message[0] ? error.message
                                  : rt_status_string(status));
        view_app__show_message(app, message);
        return 0;
    }
    if (columns <= 0 || rows <= 0)
        default_panel_size(app, &columns, &rows);
    explanation.panel_columns = columns;
    explanation.panel_rows = rows;
    make_panel(&explanation);
    view_explanation_release(&app->explanation);
    app->explanation = explanation;
    app->help = 0;
    fputs(explanation.text, stdout);
    print_sample_line(&explanation);
    fflush(stdout);
    update_overlay(app);
    return 1;
}

int view_app_explain_at(view_app *app, double x, double y)
{
    return explain_point(app, x, y, 0, 0);
}

int view_app_explain(view_app *app, int x, int y)
{
    return view_app_explain_at(app, x + 0.5, y + 0.5);
}

int view_app_step_sample(view_app *app, int delta)
{
    view_explanation *e = &app->explanation;
    if (app->session == NULL || e->text == NULL || e->samples <= 1)
        return 0;
    int sample = ((e->sample + delta) % e->samples + e->samples) % e->samples;
    const rt_scene *scene = view_session_scene(app->session);
    rt_render_options options = view_app__render_options(app, scene);
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = view_explanation_show_sample(
        scene, &options, app->shown_path, e, sample, &error);
    if (status != RT_OK) {
        char message[sizeof app->message];
        snprintf(message, sizeof message,
                 "cannot explain sample %d of pixel (%d, %d): %s", sample,
                 e->x, e->y,
                 error.message[0] ? error.message
                                  : rt_status_string(status));
        view_app__show_message(app, message);
        return 0;
    }
    make_panel(e);
    print_sample_line(e);
    fflush(stdout);
    update_overlay(app);
    return 1;
}

/* Whether window point (x, y) shows image pixel (i, j); with i < 0, any
 * pixel. */
static int shows(view_window *window, int x, int y, int i, int j)
{
    int pi, pj;
    return view_window_pixel_at(window, x, y, &pi, &pj) &&
           (i < 0 || (pi == i && pj == j));
}

/* How many window points beyond (x, y), stepping by (dx, dy), still show
 * what (x, y) shows (pixel (i, j), or with i < 0 the picture).  Those
 * points are a run (the letterbox mapping is monotonic), found by
 * bisection. */
static int run_beyond(view_window *window, int x, int y, int dx, int dy,
                      int i, int j)
{
    int inside = 0, outside = PROBE_RANGE;
    while (outside - inside > 1) {
        int middle = inside + (outside - inside) / 2;
        if (shows(window, x + middle * dx, y + middle * dy, i, j))
            inside = middle;
        else
            outside = middle;
    }
    return inside;
}

/*
 * The window tells only the pixel under a point (view_window_pixel_at);
 * the point's place in that pixel is read from the run of window points
 * showing the same pixel along each axis: the k-th of n points is at
 * (k + 1/2) / n of it, as the mapping samples each point at its centre.
 * With the picture at its own size (one point a pixel) that is the
 * pixel's centre.
 */
int view_app_click(view_app *app, int window_x, int window_y)
{
    int x, y;
    view_window *window = app->window;
    if (!view_window_pixel_at(window, window_x, window_y, &x, &y))
        return 0;
    int left = run_beyond(window, window_x, window_y, -1, 0, x, y);
    int right = run_beyond(window, window_x, window_y, 1, 0, x, y);
    int up = run_beyond(window, window_x, window_y, 0, -1, x, y);
    int down = run_beyond(window, window_x, window_y, 0, 1, x, y);
    double px = x + (left + 0.5) / (left + right + 1);
    double py = y + (up + 0.5) / (up + down + 1);
    /* The picture's size on screen, for the panel. */
    int width = 1 + run_beyond(window, window_x, window_y, -1, 0, -1, 0) +
                run_beyond(window, window_x, window_y, 1, 0, -1, 0);
    int height = 1 + run_beyond(window, window_x, window_y, 0, -1, -1, 0) +
                 run_beyond(window, window_x, window_y, 0, 1, -1, 0);
    int columns, rows;
    panel_size(width, height, &columns, &rows);
    return explain_point(app, px, py, columns, rows);
}

const view_explanation *view_app_explanation(const view_app *app)
{
    return app->explanation.text ? &app->explanation : NULL;
}

/* Renders debug view app->view (or the picture) in the session, on its
 * worker: the same passes, progress and cancellation as the picture. */
int view_app__show_view(view_app *app)
{
    if (app->session == NULL)
        return 0;
    app->redraw = 1;
    char message[sizeof app->message] = "";
    if (view_session_set_view(app->session, app->view, app->view_light) !=
        RT_OK) {
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(view_session_scene(app->session), &info);
        snprintf(message, sizeof message,
                 "cannot show the %s: the scene has no light %d (its "
                 "lights are 0..%d)",
                 view_app__view_name(app->view), app->view_light,
                 info.light_count - 1);
        app->view = 0;
        view_session_set_view(app->session, 0, 0);
    }
    if (view_session_start(app->session) != RT_OK)
        view_app__show_message(app, "cannot start the rendering thread");
    else if (message[0])
        view_app__show_message(app, message);
    view_app__update_title(app);
    return message[0] == '\0';
}

int view_app_set_view(view_app *app, int view, int light)
{
    if (view < 0 || view > RT_VIEW_SHADING_NORMAL)
        return 0;
    if (app->session) {
        /* The same view again goes on (or stays) as it is. */
        view_progress progress;
        view_session_get_progress(app->session, &progress);
        int per_light = view == RT_VIEW_SHADOW || view == RT_VIEW_NS;
        if (progress.view == view && app->view == view &&
            (!per_light || progress.light == light) &&
            (progress.state == VIEW_RENDERING ||
             progress.state == VIEW_DONE))
            return 1;
    }
    app->view = view;
    app->view_light = light;
    int shown = view_app__show_view(app);
    view_app__update_title(app);
    return shown;
}

/* L and I: the view of the first light, then of the next one. */
static void cycle_light_view(view_app *app, int view)
{
    int light = 0;
    if (app->view == view && app->session) {
        rt_scene_info info = {.size = sizeof info};
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

/* The keys that show a debug view (0: the picture); the light views
 * (L, I) step through the lights when pressed again. */
static const struct {
    int key;
    int view;
    int per_light;
} view_keys[] = {
    {SDLK_n, RT_VIEW_NORMAL, 0}, {SDLK_d, RT_VIEW_DEPTH, 0},
    {SDLK_f, RT_VIEW_FACET, 0},  {SDLK_b, RT_VIEW_BOUNCES, 0},
    {SDLK_l, RT_VIEW_SHADOW, 1}, {SDLK_i, RT_VIEW_NS, 1},
    {SDLK_m, RT_VIEW_SHADING_NORMAL, 0},
    {SDLK_v, 0, 0},              {SDLK_0, 0, 0},
    {SDLK_KP_0, 0, 0},
};

void view_app_key(view_app *app, int key, int repeat)
{
    for (size_t i = 0; i < sizeof view_keys / sizeof *view_keys; i++)
        if (view_keys[i].key == key) {
            if (view_keys[i].per_light)
                cycle_light_view(app, view_keys[i].view);
            else
                view_app_set_view(app, view_keys[i].view, 0);
            return;
        }
    char path[4096];
    switch (key) {
    case SDLK_ESCAPE:
        if (app->explanation.text || app->help)
            view_app__clear_explanation(app);
        else
            app->quit = 1;
        break;
    case SDLK_q:
        app->quit = 1;
        break;
    case SDLK_TAB:
        view_app_step_sample(app, SDL_GetModState() & KMOD_SHIFT ? -1 : 1);
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
