#ifndef RAYTRACER_H
#define RAYTRACER_H

#include "geometry.h"

/* Reads a .scn file into *s; 0 on success, else a message on stderr. */
int parse(char *fname, scene *s);

/* Frees what parse allocated. */
void freeScene(scene *s);

#endif
