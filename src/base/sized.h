/*
 * sized.h - the rules of the structs that carry their size (not public
 * API).  Option structs (rt_load_options, rt_render_options,
 * rt_save_options; raytrace/render.h, above rt_render_options): the
 * library reads the fields that lie wholly within the caller's `size`, the
 * others keep their defaults.  Structs the library fills for the caller
 * (rt_scene_info, rt_facet_info, rt_render_stats; raytrace/scene.h, above
 * rt_facet_info): the caller sets their first field, `size`, and the
 * library writes only within it.
 */
#ifndef RAYTRACE_SIZED_H
#define RAYTRACE_SIZED_H

#include <stddef.h>
#include <string.h>

#include "base/error.h"

/* The offset just past `field` of `type`: the least size that holds it.
 * Each filled struct's smallest accepted size is this for the last field
 * of its layout in 0.3, the first release with `size`. */
#define RT__FIELD_END(type, field)                                           \
    (offsetof(type, field) + sizeof(((type *)0)->field))

/* The check of an option struct's size: RT_OK for 1..`full` bytes; else
 * RT_ERR_ARGUMENT, *error naming `name` (may be NULL) and the struct as
 * "<kind> options" set by rt_<kind>_options_init. */
static inline rt_status rt__options_size_check(size_t size, size_t full,
                                               const char *kind,
                                               const char *name,
                                               rt_error *error)
{
    if (size != 0 && size <= full)
        return RT_OK;
    return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                         "%s options of %zu bytes: expected 1..%zu (set by "
                         "rt_%s_options_init)",
                         kind, size, full, kind);
}

/* Copies `field` of the caller's option struct *in (of `type`) into *out
 * when the caller's size holds it whole. */
#define RT__TAKE_FIELD(type, in, out, field)                                     if (RT__FIELD_END(type, field) <= (in)->size)                                     (out)->field = (in)->field;

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
