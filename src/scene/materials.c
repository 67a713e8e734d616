/*
 * materials.c - the scene's table of materials (scene_internal.h): facets
 * with the same k, t, n, d and colour share one entry, found by a hash of
 * their bits, so that a mesh of a million facets in one material stores
 * one material, not a million.  Entries are numbered in the order of
 * their first facet, so a table is the same for the same file.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene_internal.h"

/* The fullest a hash table runs (entries / slots), as a fraction: beyond
 * it the table doubles. */
#define FILL_NUMERATOR 1
#define FILL_DENOMINATOR 2

/* The bits of a material, as the table compares them (no padding read). */
typedef struct key {
    double values[6];
    unsigned char color[3];
} key;

static key key_of(const rt_material *m)
{
    key k;
    memset(&k, 0, sizeof k);
    k.values[0] = m->reflection;
    k.values[1] = m->transparency;
    k.values[2] = m->refractive_index;
    k.values[3] = m->diffuse;
    k.values[4] = m->highlight;
    k.values[5] = m->exponent;
    k.color[0] = m->color.r;
    k.color[1] = m->color.g;
    k.color[2] = m->color.b;
    return k;
}

/* FNV-1a over a key's bytes. */
static uint64_t hash_of(const key *k)
{
    const unsigned char *byte = (const unsigned char *)k;
    uint64_t hash = 0xcbf29ce484222325u;
    for (size_t j = 0; j < sizeof *k; j++)
        hash = (hash ^ byte[j]) * 0x100000001b3u;
    return hash;
}

static int same(const rt_material *a, const rt_material *b)
{
    key ka = key_of(a), kb = key_of(b);
    return memcmp(&ka, &kb, sizeof ka) == 0;
}

/* Puts entry `index` of t into its slot (the slots have room). */
static void place(rt_materials *t, int index)
{
    key k = key_of(&t->items[index]);
    size_t mask = t->slot_count - 1;
    size_t at = (size_t)hash_of(&k) & mask;
    while (t->slots[at] >= 0)
        at = (at + 1) & mask;
    t->slots[at] = index;
}

/* Doubles t's slots (or makes its first): 0 when out of memory. */
static int grow_slots(rt_materials *t)
{
    size_t count = t->slot_count ? 2 * t->slot_count : 16;
    int *slots = malloc(count * sizeof *slots);
    if (slots == NULL)
        return 0;
    for (size_t j = 0; j < count; j++)
        slots[j] = -1;
    free(t->slots);
    t->slots = slots;
    t->slot_count = count;
    for (int i = 0; i < t->count; i++)
        place(t, i);
    return 1;
}

int rt__materials_add(rt_materials *t, const rt_material *m)
{
    /* facets come in runs of one material: the last one first */
    if (t->count > 0 && same(&t->items[t->last], m))
        return t->last;
    if (t->slot_count > 0) {
        key k = key_of(m);
        size_t mask = t->slot_count - 1;
        for (size_t at = (size_t)hash_of(&k) & mask; t->slots[at] >= 0;
             at = (at + 1) & mask)
            if (same(&t->items[t->slots[at]], m))
                return t->last = t->slots[at];
    }
    if ((size_t)(t->count + 1) * FILL_DENOMINATOR >
            t->slot_count * FILL_NUMERATOR &&
        !grow_slots(t))
        return -1;
    if (t->count == t->capacity) {
        int capacity = t->capacity ? 2 * t->capacity : 4;
        rt_material *items = realloc(t->items, (size_t)capacity *
                                                   sizeof *items);
        if (items == NULL)
            return -1;
        t->items = items;
        t->capacity = capacity;
    }
    t->items[t->count] = *m;
    place(t, t->count);
    t->last = t->count;
    return t->count++;
}

void rt__materials_end(rt_materials *t)
{
    free(t->slots);
    t->slots = NULL;
    t->slot_count = 0;
    if (t->count > 0 && t->count < t->capacity) {
        rt_material *fitted = realloc(t->items, (size_t)t->count *
                                                    sizeof *fitted);
        if (fitted != NULL) {
            t->items = fitted;
            t->capacity = t->count;
        }
    }
}

void rt__materials_free(rt_materials *t)
{
    free(t->slots);
    free(t->items);
    memset(t, 0, sizeof *t);
}
