/*
 * load_util.c - the helpers of load_util.h.
 */
#include "load_util.h"

#include <check.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void load_text_add(load_text *t, const char *fmt, ...)
{
    char piece[256];
    va_list args;
    va_start(args, fmt);
    int n = vsnprintf(piece, sizeof piece, fmt, args);
    va_end(args);
    ck_assert(n >= 0 && (size_t)n < sizeof piece);
    if (t->length + (size_t)n + 1 > t->capacity) {
        t->capacity = 2 * (t->length + (size_t)n + 1);
        t->data = realloc(t->data, t->capacity);
        ck_assert_ptr_nonnull(t->data);
    }
    memcpy(t->data + t->length, piece, (size_t)n + 1);
    t->length += (size_t)n;
}

rt_scene_info load_info(const rt_scene *scene)
{
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    return info;
}

int load_count_warnings(const rt_scene *scene, const char *words)
{
    int n = 0, count = load_info(scene).warning_count;
    for (int i = 0; i < count; i++)
        n += strstr(rt_scene_warning(scene, i)->message, words) != NULL;
    return n;
}
