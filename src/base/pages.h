/*
 * pages.h - growable arrays in pages of their own (internal), for the
 * big temporary arrays of a build: mapped from the system rather than
 * taken from malloc's heap, so that a page costs memory only once it is
 * written, and an array given back returns its memory to the system at
 * once (the heap would keep it for later allocations).  A kd-tree build
 * holds its subtrees in them while it lays out the tree, and gives each
 * back as soon as it is copied: the copy then never holds the tree twice.
 */
#ifndef RAYTRACE_PAGES_H
#define RAYTRACE_PAGES_H

#include <stddef.h>

/*
 * Makes *array (NULL, or an array of *capacity elements of `size` bytes
 * from this module) hold at least `needed` elements, keeping its
 * contents: 1, with *array and *capacity updated (the capacity at least
 * doubles), or 0 when the system has no memory (*array unchanged).
 * Thread-safe (each array is its caller's).
 */
int rt__pages_grow(void **array, size_t *capacity, size_t needed,
                   size_t size);

/* Gives back an array of rt__pages_grow (NULL: nothing) of `capacity`
 * elements of `size` bytes. */
void rt__pages_free(void *array, size_t capacity, size_t size);

#endif /* RAYTRACE_PAGES_H */
