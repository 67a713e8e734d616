#ifndef RENDER_H
#define RENDER_H

#include "geometry.h"

/* Reflections followed after a primary ray. */
#define MAX_DEPTH 5

/* The colour of the pixel in column i and row j (from the top left). */
color pixelColor(const scene *s, int i, int j);

/* Renders *s into the ASCII PPM (P3) file ppmFile; 0 on success. */
int writeP3(const scene *s, const char *ppmFile);

#endif
