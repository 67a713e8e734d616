/*
 * names.c - a set of numbered names in one buffer (names.h).
 */
#include "formats/names.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

void rt__names_free(rt_names *names)
{
    free(names->bytes);
    free(names->offsets);
    free(names->lengths);
    free(names->slots);
    memset(names, 0, sizeof *names);
}

static size_t hash(const char *name, size_t length)
{
    uint64_t h = 14695981039346656037u;     /* FNV-1a, 64 bits */
    for (size_t i = 0; i < length; i++)
        h = (h ^ (unsigned char)name[i]) * 1099511628211u;
    return (size_t)(h ^ (h >> 32));
}

static int same(const rt_names *names, int id, const char *name,
                size_t length)
{
    return names->lengths[id] == length &&
           memcmp(names->bytes + names->offsets[id], name, length) == 0;
}

/* The slot of `name`, or the empty one where it would go (slot_count >
 * 0). */
static size_t slot_of(const rt_names *names, const char *name, size_t length)
{
    size_t mask = names->slot_count - 1;
    for (size_t i = hash(name, length) & mask;; i = (i + 1) & mask) {
        int id = names->slots[i];
        if (id < 0 || same(names, id, name, length))
            return i;
    }
}

int rt__names_find(const rt_names *names, const char *name, size_t length)
{
    if (names->slot_count == 0)
        return -1;
    return names->slots[slot_of(names, name, length)];
}

/* Doubles the table (or makes the first one) and puts every id back. */
static int grow_slots(rt_names *names)
{
    size_t bigger = names->slot_count ? 2 * names->slot_count : 16;
    if (bigger > SIZE_MAX / 2 / sizeof *names->slots)
        return 0;
    int *slots = malloc(bigger * sizeof *slots);
    if (slots == NULL)
        return 0;
    memset(slots, 0xff, bigger * sizeof *slots);    /* every slot -1 */
    free(names->slots);
    names->slots = slots;
    names->slot_count = bigger;
    for (int id = 0; id < names->count; id++)
        slots[slot_of(names, names->bytes + names->offsets[id],
                      names->lengths[id])] = id;
    return 1;
}

/* Room for one more id and `length` + 1 more bytes. */
static int make_room(rt_names *names, size_t length)
{
    if (names->count == names->capacity) {
        if (names->capacity > INT_MAX / 2)
            return 0;
        int bigger = names->capacity ? 2 * names->capacity : 16;
        size_t *offsets = realloc(names->offsets,
                                  (size_t)bigger * sizeof *offsets);
        if (offsets == NULL)
            return 0;
        names->offsets = offsets;
        uint32_t *lengths = realloc(names->lengths,
                                    (size_t)bigger * sizeof *lengths);
        if (lengths == NULL)
            return 0;
        names->lengths = lengths;
        names->capacity = bigger;
    }
    size_t needed = names->bytes_used + length + 1;
    if (needed < length)
        return 0;
    if (needed > names->bytes_capacity) {
        size_t bigger = names->bytes_capacity ? names->bytes_capacity : 256;
        while (bigger < needed && bigger <= SIZE_MAX / 2)
            bigger *= 2;
        if (bigger < needed)
            return 0;
        char *bytes = realloc(names->bytes, bigger);
        if (bytes == NULL)
            return 0;
        names->bytes = bytes;
        names->bytes_capacity = bigger;
    }
    return 1;
}

int rt__names_put(rt_names *names, const char *name, size_t length,
                  int *added)
{
    if (added != NULL)
        *added = 0;
    int id = rt__names_find(names, name, length);
    if (id >= 0)
        return id;
    if (length >= UINT32_MAX || names->count == INT_MAX ||
        !make_room(names, length))
        return -1;
    if (2 * ((size_t)names->count + 1) > names->slot_count &&
        !grow_slots(names))
        return -1;
    id = names->count++;
    names->offsets[id] = names->bytes_used;
    names->lengths[id] = (uint32_t)length;
    if (length > 0)
        memcpy(names->bytes + names->bytes_used, name, length);
    names->bytes[names->bytes_used + length] = '\0';
    names->bytes_used += length + 1;
    names->slots[slot_of(names, name, length)] = id;
    if (added != NULL)
        *added = 1;
    return id;
}

const char *rt__names_text(const rt_names *names, int id)
{
    return names->bytes + names->offsets[id];
}

size_t rt__names_length(const rt_names *names, int id)
{
    return names->lengths[id];
}
