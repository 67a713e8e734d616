/* sdl.c - traceSDLScene for libimgsdl's window: the same pixels as
 * writeP3's. */
#include "imgsdl.h"
#include "render.h"

void traceSDLScene(SDL_Surface *display, scene *s)
{
    for (int j = 0; j < s->height; j++)
        for (int i = 0; i < s->width; i++) {
            color c = pixelColor(s, i, j);
            putPixel(display, i, j, c.r, c.g, c.b);
        }
}
