/*
 * imgsdl_main.c - main() of the course's libimgsdl (imgsdl.h): parse the
 * scene named on the command line with the student's parse(), open a
 * window of its size, let the student's traceSDLScene() draw it, then show
 * it until the window is closed or Esc is pressed, or, when IMGSDL_OUTPUT
 * is set, write it to that PPM file and exit.  In a file of its own so
 * that the linker takes it from the static library only when the
 * program's objects define no main().
 */
#define SDL_MAIN_HANDLED 1 /* our main() is the program's, not SDL_main */
#include "imgsdl.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The student's (raytracer.h of the handout). */
int parse(char *fname, scene *s);

/* The limit on each side of the window, libraytrace's image limit. */
enum { MAX_SIDE = 16384 };

/* Zeroed, large enough for a student's scene struct that grew beyond the
 * handout's, and static so that what parse() allocated stays reachable
 * until exit (the student may have no freeScene()): see imgsdl.h. */
static union {
    scene s;
    max_align_t align;
    unsigned char room[IMGSDL_SCENE_ROOM];
} storage;

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static Uint32 get_pixel(const SDL_Surface *surface, int x, int y)
{
    int bytes = surface->format->BytesPerPixel;
    const Uint8 *at = (const Uint8 *)surface->pixels +
                      (size_t)y * (size_t)surface->pitch +
                      (size_t)x * (size_t)bytes;
    Uint16 v16;
    Uint32 v32;

    switch (bytes) {
    case 1:
        return *at;
    case 2:
        memcpy(&v16, at, sizeof v16);
        return v16;
    case 3:
        if (SDL_BYTEORDER == SDL_BIG_ENDIAN)
            return (Uint32)at[0] << 16 | (Uint32)at[1] << 8 | at[2];
        return (Uint32)at[2] << 16 | (Uint32)at[1] << 8 | at[0];
    default:
        memcpy(&v32, at, sizeof v32);
        return v32;
    }
}

/* Writes the surface as a binary PPM; 0 on success, else a message. */
static int save_ppm(SDL_Surface *surface, const char *path)
{
    FILE *file = fopen(path, "wb");
    int failed;

    if (NULL == file) {
        perror(path);
        return 1;
    }
    if (SDL_MUSTLOCK(surface))
        SDL_LockSurface(surface);
    fprintf(file, "P6\n%d %d\n255\n", surface->w, surface->h);
    for (int y = 0; y < surface->h; y++)
        for (int x = 0; x < surface->w; x++) {
            Uint8 rgb[3];
            SDL_GetRGB(get_pixel(surface, x, y), surface->format, &rgb[0],
                       &rgb[1], &rgb[2]);
            fwrite(rgb, 1, sizeof rgb, file);
        }
    if (SDL_MUSTLOCK(surface))
        SDL_UnlockSurface(surface);
    failed = ferror(file);
    if (0 != fclose(file) || failed) {
        perror(path);
        return 1;
    }
    return 0;
}

/* Shows the window until it is closed or Esc is pressed. */
static void wait_for_close(SDL_Window *window)
{
    SDL_Event event;

    while (SDL_WaitEvent(&event)) {
        if (SDL_QUIT == event.type)
            return;
        if (SDL_KEYDOWN == event.type &&
            SDLK_ESCAPE == event.key.keysym.sym)
            return;
        if (SDL_WINDOWEVENT == event.type &&
            SDL_WINDOWEVENT_CLOSE == event.window.event)
            return;
        if (SDL_WINDOWEVENT == event.type &&
            SDL_WINDOWEVENT_EXPOSED == event.window.event)
            SDL_UpdateWindowSurface(window);
    }
}

/* Opens the window, draws, shows or saves; the exit status. */
static int show(scene *s, const char *title, const char *output)
{
    SDL_Window *window;
    SDL_Surface *display;
    int status = 0;

    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, "imgsdl: cannot start SDL's video: %s\n",
                SDL_GetError());
        return 1;
    }
    window = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED,
                              SDL_WINDOWPOS_CENTERED, s->width, s->height, 0);
    display = window ? SDL_GetWindowSurface(window) : NULL;
    if (NULL == display) {
        fprintf(stderr, "imgsdl: cannot open a %dx%d window: %s\n", s->width,
                s->height, SDL_GetError());
        status = 1;
    } else {
        if (SDL_MUSTLOCK(display))
            SDL_LockSurface(display);
        traceSDLScene(display, s);
        if (SDL_MUSTLOCK(display))
            SDL_UnlockSurface(display);
        SDL_UpdateWindowSurface(window);
        if (output)
            status = save_ppm(display, output);
        else
            wait_for_close(window);
    }
    if (window)
        SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}

int main(int argc, char **argv)
{
    const char *output = getenv("IMGSDL_OUTPUT");
    scene *s = &storage.s;

    if (argc < 2 || NULL == argv[1]) {
        fprintf(stderr,
                "usage: %s SCENE.scn\n"
                "  shows the scene in a window (Esc or closing it quits);\n"
                "  with IMGSDL_OUTPUT=FILE.ppm, writes the picture there "
                "instead\n",
                argc > 0 && argv[0] ? argv[0] : "imgsdl");
        return 2;
    }
    if (0 != parse(argv[1], s)) {
        fprintf(stderr, "imgsdl: cannot read the scene %s\n", argv[1]);
        return 1;
    }
    if (s->width < 1 || s->height < 1 || s->width > MAX_SIDE ||
        s->height > MAX_SIDE) {
        fprintf(stderr,
                "imgsdl: %s: the picture is %dx%d pixels, expected 1 to %d "
                "on each side\n",
                argv[1], s->width, s->height, (int)MAX_SIDE);
        return 1;
    }
    return show(s, base_name(argv[1]), output && *output ? output : NULL);
}
