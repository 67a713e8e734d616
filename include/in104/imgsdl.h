/*
 * imgsdl.h - the IN 104 course's libimgsdl, rebuilt over SDL2 (library
 * raytrace-imgsdl, companion of raytrace-in104): show a rendered scene in
 * a window without writing a PPM file.
 *
 * The student writes parse() (raytracer.h) and traceSDLScene() below, and
 * no main(): the library's main() does, in this order,
 *
 *   1. parse(argv[1], &s) on a zeroed scene (argv[1] missing: a usage line
 *      on stderr, exit status 2; parse() non-zero: "imgsdl: cannot read
 *      the scene FILE" on stderr, exit status 1);
 *   2. opens a window of s.width x s.height pixels titled with the scene's
 *      file name (SDL failures and sizes outside 1..16384: a message
 *      naming the cause, exit status 1);
 *   3. traceSDLScene(display, &s), display being the window's surface;
 *   4. shows the result until the window is closed or Esc is pressed,
 *      then exits with status 0.
 *
 * Headless runs and tests: when the environment variable IMGSDL_OUTPUT is
 * set and not empty, it names a file: step 4 writes the surface there as a
 * binary PPM (P6) instead and exits (0, or 1 with a message if the file cannot be
 * written).  With SDL_VIDEODRIVER=dummy no display is needed at all:
 *
 *     SDL_VIDEODRIVER=dummy IMGSDL_OUTPUT=out.ppm ./bin/tests_sdl scenes/cubes.scn
 *
 * main() reads only the width and height of the scene; it keeps the scene
 * in static storage of IMGSDL_SCENE_ROOM bytes (zeroed, never freed: what
 * parse allocated stays reachable until the process ends), so a student's
 * own scene struct may be larger than the handout's as long as it starts
 * with the handout's fields `color back; int width, height;`.
 *
 * The library is static (libraytrace-imgsdl.a) on purpose: the linker
 * takes its main() only when the program's own objects define none, so a
 * program with a main() of its own (a test, tests_notes.c) must not be
 * linked with it, exactly as with the course's library.
 *
 * Build (SDL2's include folder gives <SDL.h>; `geometry.h` is taken from
 * the include path, so a project's own include/geometry.h wins when its
 * -I comes first):
 *     cc -Iinclude -I<prefix>/include/in104 $(sdl2-config --cflags) \
 *        prog.c <prefix>/lib/libraytrace-imgsdl.a $(sdl2-config --libs)
 *     cc prog.c $(pkg-config --cflags --libs raytrace-imgsdl)
 *     find_package(raytrace COMPONENTS imgsdl) and raytrace::imgsdl
 *
 * Threads: everything runs on the main thread; traceSDLScene() may use
 * threads of its own but must return with every putPixel() finished.
 */
#ifndef IN104_IMGSDL_H
#define IN104_IMGSDL_H

#include <SDL.h>

#include <geometry.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bytes of the static storage main() passes to parse() (see above). */
#define IMGSDL_SCENE_ROOM 4096

/*
 * Written by the student: draws the scene *s on `display` (s->width x
 * s->height pixels, origin at the top left) with putPixel().  Called once,
 * after parse() succeeded.
 */
void traceSDLScene(SDL_Surface *display, scene *s);

/*
 * Sets the pixel in column x and row y (from the top left, from 0) of
 * `surface` to the colour (r, g, b), whatever the surface's pixel format
 * (8 to 32 bits a pixel, SDL_MapRGB's nearest colour).  A pixel outside the
 * surface, or a NULL surface, is ignored.  The caller locks the surface if
 * SDL_MUSTLOCK says so (main() does so around traceSDLScene()).
 * Thread-safe on distinct pixels.
 */
void putPixel(SDL_Surface *surface, int x, int y, Uint8 r, Uint8 g, Uint8 b);

#ifdef __cplusplus
}
#endif

#endif /* IN104_IMGSDL_H */
