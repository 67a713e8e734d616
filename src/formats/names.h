/*
 * names.h - a set of names, each given a number in the order it was first
 * seen (internal): material names of an OBJ, the files a scene names.
 * The names live in one growing buffer and the table holds numbers only,
 * so a name costs its bytes plus about 20: a file of a million distinct
 * names costs what it weighs, not a million small allocations.  Lookups
 * and insertions take constant time on average (open addressing over a
 * power-of-two table kept at most half full).
 */
#ifndef RAYTRACE_NAMES_H
#define RAYTRACE_NAMES_H

#include <stddef.h>
#include <stdint.h>

typedef struct rt_names {
    char *bytes;            /* the names, each followed by a NUL */
    size_t bytes_used, bytes_capacity;
    size_t *offsets;        /* offsets[id]: where name `id` starts */
    uint32_t *lengths;      /* lengths[id]: its length */
    int count, capacity;    /* names; room in offsets and lengths */
    int *slots;             /* -1: empty; else an id */
    size_t slot_count;      /* 0 or a power of two */
} rt_names;

/* A zeroed rt_names is an empty set; rt__names_free empties it. */
void rt__names_free(rt_names *names);

/* The number of `name` (its `length` bytes, which may hold anything but
 * need no NUL), or -1 when it is not in the set. */
int rt__names_find(const rt_names *names, const char *name, size_t length);

/* The number of `name`, added when new (*added then non-zero; may be
 * NULL); -1 when out of memory or past INT_MAX names, or a name of
 * UINT32_MAX bytes or more. */
int rt__names_put(rt_names *names, const char *name, size_t length,
                  int *added);

/* Name `id` (0 <= id < count), NUL-terminated; valid until the next
 * rt__names_put. */
const char *rt__names_text(const rt_names *names, int id);
size_t rt__names_length(const rt_names *names, int id);

#endif /* RAYTRACE_NAMES_H */
