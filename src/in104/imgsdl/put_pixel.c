/*
 * put_pixel.c - putPixel() of the course's libimgsdl (imgsdl.h): one pixel
 * of an SDL2 surface, in any of SDL's packed pixel formats.
 */
#include "imgsdl.h"

#include <string.h>

void putPixel(SDL_Surface *surface, int x, int y, Uint8 r, Uint8 g, Uint8 b)
{
    if (NULL == surface || x < 0 || y < 0 || x >= surface->w ||
        y >= surface->h)
        return;
    Uint32 value = SDL_MapRGB(surface->format, r, g, b);
    int bytes = surface->format->BytesPerPixel;
    Uint8 *at = (Uint8 *)surface->pixels + (size_t)y * (size_t)surface->pitch +
                (size_t)x * (size_t)bytes;

    switch (bytes) {
    case 1:
        *at = (Uint8)value;
        break;
    case 2: {
        Uint16 v16 = (Uint16)value;
        memcpy(at, &v16, sizeof v16);
        break;
    }
    case 3:
        /* Byte order of a 24-bit pixel follows the machine's. */
        if (SDL_BYTEORDER == SDL_BIG_ENDIAN) {
            at[0] = (Uint8)(value >> 16);
            at[1] = (Uint8)(value >> 8);
            at[2] = (Uint8)value;
        } else {
            at[0] = (Uint8)value;
            at[1] = (Uint8)(value >> 8);
            at[2] = (Uint8)(value >> 16);
        }
        break;
    default:
        memcpy(at, &value, sizeof value);
        break;
    }
}
