/* main.c - renders the scene named on the command line to NAME.p3 (the
 * scene's file name, its extension replaced) and prints that path. */
#include <stdio.h>
#include <string.h>

#include "raytracer.h"
#include "render.h"

int main(int argc, char **argv)
{
    char out[1024];
    const char *base, *dot;
    scene s;
    int failed;

    if (argc != 2) {
        fprintf(stderr, "usage: %s SCENE.scn\n", argv[0]);
        return 2;
    }
    base = strrchr(argv[1], '/');
    base = base ? base + 1 : argv[1];
    dot = strrchr(base, '.');
    if (snprintf(out, sizeof out, "%.*s.p3",
                 (int)(dot ? (size_t)(dot - base) : strlen(base)), base) >=
        (int)sizeof out) {
        fprintf(stderr, "%s: name too long\n", argv[1]);
        return 2;
    }
    if (0 != parse(argv[1], &s))
        return 1;
    printf("rendering %s (%dx%d, %d facets) to %s\n", argv[1], s.width,
           s.height, s.nbFacets, out);
    failed = writeP3(&s, out);
    freeScene(&s);
    if (failed)
        return 1;
    printf("%s\n", out);
    return 0;
}
