/*
 * view_window.c - the SDL window, renderer and texture that show a
 * view_session (see view_window.h).  Only the rows a pass changed are
 * uploaded, copied out of the session under its lock a band at a time;
 * until the first pass reaches a row the texture holds the placeholder
 * checker there.
 */
#include "view_window.h"

#define SDL_MAIN_HANDLED
#include <SDL.h>

#ifdef RAYTRACE_VIEWER_TTF
#include <SDL_ttf.h>
#endif

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef RAYTRACE_VIEWER_TTF
/* The monospaced font of the text panel, first found (Debian's
 * fonts-dejavu-core, then Fedora's and Arch's places for it). */
static const char *const font_paths[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf",
    "/usr/share/fonts/dejavu-sans-mono-fonts/DejaVuSansMono.ttf",
    "/usr/share/fonts/TTF/DejaVuSansMono.ttf",
};
#define FONT_POINTS 13
#endif
#define MARK_SIZE 7         /* side of the square marking a hit, in pixels */
#define STAGING_ROWS 64     /* rows copied out of the session at a time */

struct view_window {
    SDL_Window *window;
    SDL_Renderer *renderer;
    SDL_Texture *texture;       /* image-sized, RGB24; NULL when detached */
    int width, height;          /* of the texture */
    view_session *session;
    unsigned generation;        /* of the rows last uploaded */
    int *rows;                  /* scratch for take_finished_rows */
    unsigned char *staging;     /* STAGING_ROWS rows copied for upload */
    int unshown;                /* rows of `generation` uploaded, no frame
                                   presented with them yet */
    unsigned shown_generation;  /* the last render a frame was shown of */
    view_projection projection; /* of the overlay's rays */
    view_segment *segments;     /* the overlay's rays; NULL: none */
    int segment_count;
    SDL_Texture *text;          /* the text panel, NULL: none */
    int text_width, text_height;
    int text_bottom;            /* the panel at the bottom, not the top */
#ifdef RAYTRACE_VIEWER_TTF
    TTF_Font *font;             /* NULL when no font was found */
#endif
};

/* Background around the letterboxed picture. */
static const SDL_Color background = {18, 18, 18, 255};

void view_placeholder_color(int x, int y, unsigned char rgb[3])
{
    int dark = ((x / VIEW_CHECKER_SIZE) + (y / VIEW_CHECKER_SIZE)) % 2;
    unsigned char value = dark ? 40 : 56;
    rgb[0] = rgb[1] = rgb[2] = value;
}

void view_fit_size(int width, int height, int max_width, int max_height,
                   int *out_width, int *out_height)
{
    if (max_width < 1)
        max_width = 1;
    if (max_height < 1)
        max_height = 1;
    if (width <= max_width && height <= max_height) {
        *out_width = width;
        *out_height = height;
        return;
    }
    double sx = (double)max_width / width;
    double sy = (double)max_height / height;
    double scale = sx < sy ? sx : sy;
    int w = (int)(width * scale);
    int h = (int)(height * scale);
    *out_width = w < 1 ? 1 : w > max_width ? max_width : w;
    *out_height = h < 1 ? 1 : h > max_height ? max_height : h;
}

/* Drivers that show nothing to anyone. */
static int headless_driver(const char *name)
{
    return strcmp(name, "offscreen") == 0 || strcmp(name, "dummy") == 0 ||
           strcmp(name, "evdev") == 0;
}

/* Through the environment rather than SDL_HINT_VIDEODRIVER, which SDL
 * before 2.0.22 does not read. */
static int try_driver(const char *name)
{
    setenv("SDL_VIDEODRIVER", name, 1);
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) == 0)
        return 1;
    unsetenv("SDL_VIDEODRIVER");
    return 0;
}

int view_video_init(char *error, size_t error_size)
{
    const char *asked = SDL_getenv("SDL_VIDEODRIVER");
    if (asked != NULL && asked[0] != '\0') {
        if (SDL_InitSubSystem(SDL_INIT_VIDEO) == 0)
            return 1;
        snprintf(error, error_size, "%s", SDL_GetError());
        return 0;
    }
    const char *runtime_dir = SDL_getenv("XDG_RUNTIME_DIR");
    const char *display = SDL_getenv("DISPLAY");
    const char *wayland = SDL_getenv("WAYLAND_DISPLAY");
    int tried = 0;
    for (int i = 0; i < SDL_GetNumVideoDrivers(); i++) {
        const char *name = SDL_GetVideoDriver(i);
        if (headless_driver(name) ||
            (strcmp(name, "wayland") == 0 && runtime_dir == NULL))
            continue;
        if (try_driver(name))
            return 1;
        /* The first failure says most (x11's, with DISPLAY set). */
        if (tried++ == 0)
            snprintf(error, error_size, "%s%s%s", SDL_GetError(),
                     display ? " with DISPLAY=" : "", display ? display : "");
    }
    if ((display == NULL || display[0] == '\0') &&
        (wayland == NULL || wayland[0] == '\0'))
        snprintf(error, error_size,
                 "no display (DISPLAY and WAYLAND_DISPLAY are not set)");
    else if (tried == 0)
        snprintf(error, error_size, "this SDL has no display driver");
    return 0;
}

view_window *view_window_create(const char *title, int width, int height,
                                unsigned flags, char *error,
                                size_t error_size)
{
    view_window *window = calloc(1, sizeof *window);
    if (window == NULL) {
        snprintf(error, error_size, "cannot create window: out of memory");
        return NULL;
    }
    Uint32 window_flags = SDL_WINDOW_RESIZABLE |
                          ((flags & VIEW_WINDOW_HIDDEN) ? SDL_WINDOW_HIDDEN
                                                        : SDL_WINDOW_SHOWN);
    window->window = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED,
                                      SDL_WINDOWPOS_CENTERED, width, height,
                                      window_flags);
    if (window->window == NULL) {
        snprintf(error, error_size, "cannot create window: %s",
                 SDL_GetError());
        free(window);
        return NULL;
    }
    Uint32 renderer_flags = (flags & VIEW_WINDOW_SOFTWARE)
                                ? SDL_RENDERER_SOFTWARE : 0;
    window->renderer = SDL_CreateRenderer(window->window, -1,
                                          renderer_flags);
    if (window->renderer == NULL && !(flags & VIEW_WINDOW_SOFTWARE))
        window->renderer = SDL_CreateRenderer(window->window, -1,
                                              SDL_RENDERER_SOFTWARE);
    if (window->renderer == NULL) {
        snprintf(error, error_size, "cannot create renderer: %s",
                 SDL_GetError());
        SDL_DestroyWindow(window->window);
        free(window);
        return NULL;
    }
    SDL_SetRenderDrawBlendMode(window->renderer, SDL_BLENDMODE_BLEND);
#ifdef RAYTRACE_VIEWER_TTF
    if (TTF_Init() == 0) {
        for (size_t i = 0; i < sizeof font_paths / sizeof *font_paths &&
                           window->font == NULL; i++)
            window->font = TTF_OpenFont(font_paths[i], FONT_POINTS);
        if (window->font == NULL)
            TTF_Quit();
    }
#endif
    return window;
}

static void detach(view_window *window)
{
    if (window->texture)
        SDL_DestroyTexture(window->texture);
    free(window->rows);
    free(window->staging);
    window->texture = NULL;
    window->rows = NULL;
    window->staging = NULL;
    window->session = NULL;
    window->width = window->height = 0;
    window->unshown = 0;
}

void view_window_destroy(view_window *window)
{
    if (window == NULL)
        return;
    detach(window);
    view_window_set_overlay(window, NULL, NULL, 0);
    view_window_set_text(window, NULL);
#ifdef RAYTRACE_VIEWER_TTF
    if (window->font) {
        TTF_CloseFont(window->font);
        TTF_Quit();
    }
#endif
    SDL_DestroyRenderer(window->renderer);
    SDL_DestroyWindow(window->window);
    free(window);
}

/* Fills the whole texture with the checker, a band of two squares' height
 * at a time (the pattern repeats every band). */
static void fill_placeholder(view_window *window)
{
    int band = 2 * VIEW_CHECKER_SIZE;
    size_t pitch = (size_t)window->width * 3;
    unsigned char *pixels = malloc(pitch * (size_t)band);
    if (pixels == NULL)
        return;
    for (int y = 0; y < band; y++)
        for (int x = 0; x < window->width; x++)
            view_placeholder_color(x, y, pixels + (size_t)y * pitch +
                                             (size_t)x * 3);
    for (int y = 0; y < window->height; y += band) {
        int rows = window->height - y < band ? window->height - y : band;
        SDL_Rect rect = {0, y, window->width, rows};
        SDL_UpdateTexture(window->texture, &rect, pixels, (int)pitch);
    }
    free(pixels);
}

int view_window_attach(view_window *window, view_session *session,
                       char *error, size_t error_size)
{
    detach(window);
    if (session == NULL)
        return 1;
    const rt_image *image = view_session_image(session);
    window->rows = malloc(sizeof *window->rows * (size_t)image->height);
    window->staging = malloc((size_t)image->width * 3 * STAGING_ROWS);
    window->texture = SDL_CreateTexture(window->renderer,
                                        SDL_PIXELFORMAT_RGB24,
                                        SDL_TEXTUREACCESS_STATIC,
                                        image->width, image->height);
    if (window->rows == NULL || window->staging == NULL ||
        window->texture == NULL) {
        snprintf(error, error_size, "cannot show a %dx%d image: %s",
                 image->width, image->height,
                 window->texture ? "out of memory" : SDL_GetError());
        detach(window);
        return 0;
    }
    window->session = session;
    window->width = image->width;
    window->height = image->height;
    view_progress progress;
    view_session_get_progress(session, &progress);
    window->generation = progress.generation;
    window->shown_generation = progress.generation;
    fill_placeholder(window);
    return 1;
}

int view_window_sync(view_window *window)
{
    if (window->session == NULL)
        return 0;
    unsigned generation;
    int count = view_session_take_finished_rows(
        window->session, window->rows, window->height, &generation);
    /* A new render keeps the old pixels until its passes replace them. */
    window->generation = generation;
    size_t pitch = (size_t)window->width * 3;
    for (int i = 0; i < count;) {
        int first = window->rows[i];
        int run = 1;
        while (i + run < count && run < STAGING_ROWS &&
               window->rows[i + run] == first + run)
            run++;
        if (view_session_copy_rows(window->session, first, run,
                                   window->staging, pitch)) {
            SDL_Rect rect = {0, first, window->width, run};
            SDL_UpdateTexture(window->texture, &rect, window->staging,
                              (int)pitch);
        }
        i += run;
    }
    if (count > 0)
        window->unshown = 1;
    return count > 0;
}

/* After a frame is presented: tells the session when the first frame of
 * its render was shown (--stats). */
static void note_shown(view_window *window)
{
    if (window->session == NULL || !window->unshown)
        return;
    window->unshown = 0;
    if (window->shown_generation == window->generation)
        return;
    window->shown_generation = window->generation;
    view_session_note_shown(window->session, window->generation);
}

/* Clips the segment (x0, y0)-(x1, y1) to `box` (Liang-Barsky), so that
 * far projections stay within int; 0 when nothing is left. */
static int clip_to_box(double line[4], const double box[4])
{
    double dx = line[2] - line[0], dy = line[3] - line[1];
    double p[4] = {-dx, dx, -dy, dy};
    double q[4] = {line[0] - box[0], box[2] - line[0], line[1] - box[1],
                   box[3] - line[1]};
    double enter = 0, leave = 1;
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return 0;
            continue;
        }
        double r = q[k] / p[k];
        if (p[k] < 0 && r > enter)
            enter = r;
        else if (p[k] > 0 && r < leave)
            leave = r;
    }
    if (enter > leave)
        return 0;
    double x0 = line[0], y0 = line[1];
    line[0] = x0 + enter * dx;
    line[1] = y0 + enter * dy;
    line[2] = x0 + leave * dx;
    line[3] = y0 + leave * dy;
    return 1;
}

/* Draws the overlay's rays over the picture placed at `target`: each a
 * one-pixel line of its kind's colour, its hit marked by a square. */
static void draw_overlay(view_window *window, const SDL_Rect *target)
{
    double sx = (double)target->w / window->width;
    double sy = (double)target->h / window->height;
    double box[4] = {target->x, target->y, target->x + target->w - 1,
                     target->y + target->h - 1};
    for (int pass = 0; pass < 2; pass++) {
        /* The lines first, then the marks over them. */
        for (int k = 0; k < window->segment_count; k++) {
            const view_segment *segment = &window->segments[k];
            double line[4];
            if (!view_project_segment(&window->projection, segment->from,
                                      segment->to, line))
                continue;
            for (int c = 0; c < 4; c += 2) {
                line[c] = target->x + line[c] * sx;
                line[c + 1] = target->y + line[c + 1] * sy;
            }
            double end_x = line[2], end_y = line[3];
            unsigned char rgb[3];
            view_ray_color(segment->kind, rgb);
            SDL_SetRenderDrawColor(window->renderer, rgb[0], rgb[1], rgb[2],
                                   255);
            if (pass == 0 && clip_to_box(line, box)) {
                SDL_RenderDrawLine(window->renderer, (int)floor(line[0]),
                                   (int)floor(line[1]), (int)floor(line[2]),
                                   (int)floor(line[3]));
            } else if (pass == 1 && segment->mark && end_x >= box[0] &&
                       end_x <= box[2] && end_y >= box[1] &&
                       end_y <= box[3]) {
                SDL_Rect mark = {(int)floor(end_x) - MARK_SIZE / 2,
                                 (int)floor(end_y) - MARK_SIZE / 2,
                                 MARK_SIZE, MARK_SIZE};
                SDL_RenderDrawRect(window->renderer, &mark);
            }
        }
    }
}

/* Clears the window and copies the picture, scaled to fit and centred,
 * then the text panel and the overlay's rays over it. */
static void render(view_window *window)
{
    SDL_SetRenderDrawColor(window->renderer, background.r, background.g,
                           background.b, background.a);
    SDL_RenderClear(window->renderer);
    if (window->texture == NULL)
        return;
    int out_width, out_height;
    if (SDL_GetRendererOutputSize(window->renderer, &out_width,
                                  &out_height) != 0)
        return;
    int rect[4];
    view_letterbox(window->width, window->height, out_width, out_height,
                   rect);
    SDL_Rect target = {rect[0], rect[1], rect[2], rect[3]};
    SDL_RenderCopy(window->renderer, window->texture, NULL, &target);
    if (window->text) {
        int top = window->text_bottom
                      ? out_height - window->text_height - 12 : 4;
        SDL_Rect panel = {4, top, window->text_width + 8,
                          window->text_height + 8};
        SDL_SetRenderDrawColor(window->renderer, 0, 0, 0, 192);
        SDL_RenderFillRect(window->renderer, &panel);
        SDL_Rect place = {8, top + 4, window->text_width,
                          window->text_height};
        SDL_RenderCopy(window->renderer, window->text, NULL, &place);
    }
    /* The rays over the text: one-pixel lines hide little of it, and a ray
     * under the panel would be lost. */
    draw_overlay(window, &target);
}

void view_window_draw(view_window *window)
{
    render(window);
    SDL_RenderPresent(window->renderer);
    note_shown(window);
}

int view_window_read(view_window *window, rt_image *out)
{
    memset(out, 0, sizeof *out);
    int width, height;
    if (SDL_GetRendererOutputSize(window->renderer, &width, &height) != 0)
        return 0;
    if (rt_image_init(out, width, height, NULL) != RT_OK)
        return 0;
    render(window);
    int ok = SDL_RenderReadPixels(window->renderer, NULL,
                                  SDL_PIXELFORMAT_RGB24, out->pixels,
                                  (int)out->stride) == 0;
    SDL_RenderPresent(window->renderer);
    note_shown(window);
    if (!ok)
        rt_image_release(out);
    return ok;
}

void view_window_set_title(view_window *window, const char *title)
{
    SDL_SetWindowTitle(window->window, title);
}

void view_window_place(view_window *window, int width, int height,
                       const int bounds[4], int center)
{
    SDL_SetWindowSize(window->window, width, height);
    int x, y;
    SDL_GetWindowPosition(window->window, &x, &y);
    if (center || x < bounds[0] || y < bounds[1] || x + width > bounds[0] + bounds[2] ||
        y + height > bounds[1] + bounds[3])
        SDL_SetWindowPosition(window->window,
                              bounds[0] + (bounds[2] - width) / 2,
                              bounds[1] + (bounds[3] - height) / 2);
}

void view_window_show(view_window *window)
{
    SDL_ShowWindow(window->window);
}

void view_window_hide(view_window *window)
{
    SDL_HideWindow(window->window);
}

int view_window_display(const view_window *window)
{
    int display = SDL_GetWindowDisplayIndex(window->window);
    return display < 0 ? 0 : display;
}

int view_window_set_overlay(view_window *window,
                            const view_projection *projection,
                            const view_segment *segments, int count)
{
    free(window->segments);
    window->segments = NULL;
    window->segment_count = 0;
    if (count <= 0)
        return 1;
    window->segments = malloc(sizeof *segments * (size_t)count);
    if (window->segments == NULL)
        return 0;
    memcpy(window->segments, segments, sizeof *segments * (size_t)count);
    window->segment_count = count;
    window->projection = *projection;
    return 1;
}

void view_window_set_text_place(view_window *window, int bottom)
{
    window->text_bottom = bottom;
}

int view_window_set_text(view_window *window, const char *text)
{
    if (window->text)
        SDL_DestroyTexture(window->text);
    window->text = NULL;
    if (text == NULL || text[0] == '\0')
        return 1;
#ifdef RAYTRACE_VIEWER_TTF
    if (window->font == NULL)
        return 0;
    SDL_Color white = {235, 235, 235, 255};
    int out_width = 640, out_height;
    SDL_GetRendererOutputSize(window->renderer, &out_width, &out_height);
    SDL_Surface *surface = TTF_RenderUTF8_Blended_Wrapped(
        window->font, text, white, (Uint32)(out_width > 32 ? out_width - 16
                                                             : 16));
    if (surface == NULL)
        return 0;
    window->text = SDL_CreateTextureFromSurface(window->renderer, surface);
    window->text_width = surface->w;
    window->text_height = surface->h;
    SDL_FreeSurface(surface);
    return window->text != NULL;
#else
    return 0;
#endif
}

int view_window_pixel_at(view_window *window, int x, int y, int *i, int *j)
{
    if (window->texture == NULL)
        return 0;
    int width, height, out_width, out_height;
    SDL_GetWindowSize(window->window, &width, &height);
    if (SDL_GetRendererOutputSize(window->renderer, &out_width,
                                  &out_height) != 0 || width <= 0 ||
        height <= 0)
        return 0;
    /* Window points to drawable pixels (they differ on high-DPI). */
    double ox = (x + 0.5) * out_width / width;
    double oy = (y + 0.5) * out_height / height;
    return view_output_to_pixel(window->width, window->height, out_width,
                                out_height, ox, oy, i, j);
}

int view_window_has_text(const view_window *window)
{
#ifdef RAYTRACE_VIEWER_TTF
    return window->font != NULL;
#else
    (void)window;
    return 0;
#endif
}
