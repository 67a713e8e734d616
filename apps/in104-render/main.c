/*
 * in104-render.c - a course-style program over the IN 104 handout's API:
 * reads a scene with parse(), renders it with renderToPPM() and writes a
 * P3 image, as the handout's `make run` asks.  It uses nothing but the
 * headers of the in104 layer, so it is also an example of how a course
 * program builds against libraytrace (docs/in104.md).
 *
 * Usage: in104-render scene.scn [image.ppm]   (default: scene name + .ppm)
 *        in104-render --help | --version
 * IN104_RENDER_VERSION, the project's version, comes from CMake.
 */
#include "geometry.h"
#include "raytracer.h"

#include <stdio.h>
#include <string.h>

/* "dir/cubes.scn" -> "cubes.ppm" in the current directory. */
static void defaultOutput(const char *sceneFile, char *out, size_t size)
{
    const char *base = strrchr(sceneFile, '/');
    base = (NULL == base) ? sceneFile : base + 1;
    size_t length = strlen(base);
    const char *dot = strrchr(base, '.');
    if (NULL != dot && dot != base)
        length = (size_t)(dot - base);
    snprintf(out, size, "%.*s.ppm", (int)length, base);
}

static void usage(FILE *out)
{
    fprintf(out,
            "Usage: in104-render SCENE [IMAGE.ppm]\n"
            "Reads the course scene SCENE with the IN 104 handout's parse(),\n"
            "renders it with renderToPPM() and writes a P3 image at IMAGE.ppm\n"
            "(default: SCENE's name with .ppm, in the current folder).\n"
            "\n"
            "  -h, --help      this help\n"
            "      --version   the version\n"
            "\n"
            "Exit status: 0 success, 1 bad scene or failed write, 2 bad "
            "usage.\n");
}

int main(int argc, char **argv)
{
    if (2 == argc && (0 == strcmp(argv[1], "--help") ||
                      0 == strcmp(argv[1], "-h"))) {
        usage(stdout);
        return 0;
    }
    if (2 == argc && 0 == strcmp(argv[1], "--version")) {
        printf("in104-render (libraytrace) %s\n", IN104_RENDER_VERSION);
        return 0;
    }
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: %s scene.scn [image.ppm]\n", argv[0]);
        return 2;
    }

    char output[4096];
    if (3 == argc)
        snprintf(output, sizeof output, "%s", argv[2]);
    else
        defaultOutput(argv[1], output, sizeof output);

    scene s;
    if (0 != parse(argv[1], &s))
        return 1;                       /* parse printed why */
    printf("%s: %d x %d pixels, %d points, %d facets\n", argv[1], s.width,
           s.height, s.nbPoints, s.nbFacets);

    int status = renderToPPM(&s, output);
    freeScene(&s);
    if (0 != status)
        return 1;                       /* renderToPPM printed why */
    printf("%s\n", output);
    return 0;
}
