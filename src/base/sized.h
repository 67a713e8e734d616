/*
 * sized.h - the rule of the structs the library fills for the caller
 * (rt_scene_info, rt_facet_info, rt_render_stats; raytrace/scene.h, above
 * rt_facet_info): the caller sets their first field, `size`, and the
 * library writes only within it.  Not public API.
 */
#ifndef RAYTRACE_SIZED_H
#define RAYTRACE_SIZED_H

#include <stddef.h>
#include <string.h>

/* The offset just past `field` of `type`: the least size that holds it.
 * Each filled struct's smallest accepted size is this for the last field
 * of its layout in 0.3, the first release with `size`. */
#define RT__FIELD_END(type, field)                                           \
    (offsetof(type, field) + sizeof(((type *)0)->field))

/* The size the caller set in the struct at `out` (its first field). */
static inline size_t rt__sized_size(const void *out)
{
    size_t size;
    memcpy(&size, out, sizeof size);
    return size;
}

/* Copies the library's filled struct `full`, of `full_size` bytes, into
 * the caller's `out`, whose size (at least sizeof(size_t), checked by the
 * caller) says how many bytes are its: the fields within it get their
 * values, bytes within it past `full_size` (fields of a newer header) are
 * zeroed, and its size is kept. */
static inline void rt__sized_fill(void *out, const void *full,
                                  size_t full_size)
{
    size_t size = rt__sized_size(out);
    size_t copied = size < full_size ? size : full_size;
    memcpy((char *)out + sizeof size, (const char *)full + sizeof size,
           copied - sizeof size);
    if (size > full_size)
        memset((char *)out + full_size, 0, size - full_size);
}

#endif /* RAYTRACE_SIZED_H */
