/* tests_imgsdl.c - the example of libimgsdl, in the course's style: parse
 * does not read the file, it only sets the window's size, and
 * traceSDLScene draws a gradient with putPixel. */
#include "imgsdl.h"
#include "raytracer.h"

int parse(char *fname, scene *s)
{
    (void)fname;
    s->width = 64;
    s->height = 48;
    return 0;
}

void traceSDLScene(SDL_Surface *display, scene *s)
{
    int w = s->width, h = s->height;
    for (int x = 0; x < w; ++x)
        for (int y = 0; y < h; ++y)
            putPixel(display, x, y, 255 * x / (w - 1), 255 * y / (h - 1),
                     255 * (x + y) / (w + h - 2));
}
