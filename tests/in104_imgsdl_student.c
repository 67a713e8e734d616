/*
 * in104_imgsdl_student.c - a program in the style of the course's
 * tests_imgsdl.c, linked with raytrace-imgsdl (whose main() runs it): its
 * parse() only checks that the file opens and sets a 40x30 picture, its
 * traceSDLScene() draws the gradient that `kit_ppm gradient` expects.
 * tests/in104.cmake runs it on SDL's dummy video driver with
 * IMGSDL_OUTPUT, and without a scene, and on a missing one.
 */
#include <stdio.h>

#include "imgsdl.h"
#include "raytracer.h"

int parse(char *fname, scene *s)
{
    FILE *file = fopen(fname, "r");
    if (NULL == file)
        return 1;
    fclose(file);
    s->width = 40;
    s->height = 30;
    return 0;
}

void traceSDLScene(SDL_Surface *display, scene *s)
{
    int w = s->width, h = s->height;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            putPixel(display, x, y, (Uint8)(255 * x / (w - 1)),
                     (Uint8)(255 * y / (h - 1)),
                     (Uint8)(255 * (x + y) / (w + h - 2)));
}
