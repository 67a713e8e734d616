/*
 * free_scene.c - freeScene(), the extension of raytracer.h that releases
 * what parse() allocated.
 */
#include "raytracer.h"

#include <stdlib.h>

void freeScene(scene *s)
{
    if (s == NULL)
        return;
    free(s->points);
    free(s->facets);
    s->points = NULL;
    s->facets = NULL;
    s->nbPoints = 0;
    s->nbFacets = 0;
}
