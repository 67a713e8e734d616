/*
 * pages.c - growable arrays in pages of their own (pages.h): anonymous
 * mappings, grown in place or moved by the system where it can (Linux's
 * mremap), copied otherwise.
 */
#define _GNU_SOURCE     /* mremap */
#include "base/pages.h"

#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

/* The bytes of the mapping of `capacity` elements of `size`: whole
 * pages. */
static size_t mapped_bytes(size_t capacity, size_t size)
{
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    size_t bytes = capacity * size;
    return (bytes + page - 1) / page * page;
}

int rt__pages_grow(void **array, size_t *capacity, size_t needed,
                   size_t size)
{
    if (needed <= *capacity)
        return 1;
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    size_t wanted = *capacity ? 2 * *capacity : page / size + 1;
    while (wanted < needed)
        wanted *= 2;
    if (wanted > (size_t)-1 / 2 / size)
        return 0;
    /* every page of the mapping holds elements */
    wanted = mapped_bytes(wanted, size) / size;
    size_t old_bytes = *array ? mapped_bytes(*capacity, size) : 0;
    size_t new_bytes = mapped_bytes(wanted, size);
    void *grown;
#ifdef MREMAP_MAYMOVE
    if (*array != NULL) {
        grown = mremap(*array, old_bytes, new_bytes, MREMAP_MAYMOVE);
        if (grown == MAP_FAILED)
            return 0;
        *array = grown;
        *capacity = wanted;
        return 1;
    }
#endif
    grown = mmap(NULL, new_bytes, PROT_READ | PROT_WRITE,
                 MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (grown == MAP_FAILED)
        return 0;
    if (*array != NULL) {
        memcpy(grown, *array, *capacity * size);
        munmap(*array, old_bytes);
    }
    *array = grown;
    *capacity = wanted;
    return 1;
}

void rt__pages_free(void *array, size_t capacity, size_t size)
{
    if (array != NULL)
        munmap(array, mapped_bytes(capacity, size));
}
