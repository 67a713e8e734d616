/*
 * notes.c - the warnings of a load (scene_build.h): those a reader finds
 * and those the builder adds, in the order found, as the scene's
 * rt_warning records will hold them.  Warnings of a kind that can repeat on
 * every line are summarised past the first few, so that their memory and
 * what a terminal shows stay small whatever the file.
 */
#include "scene/scene_build.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The array `items` of `count` elements of `size` bytes with room for one
 * more: itself, or moved to twice *capacity (`first` when empty), or NULL
 * (out of memory: the notes have failed, `items` is unchanged). */
static void *room_for_one(rt_notes *notes, void *items, int *capacity,
                          int count, size_t size, int first)
{
    if (count < *capacity)
        return items;
    int bigger = *capacity ? 2 * *capacity : first;
    void *grown = realloc(items, (size_t)bigger * size);
    if (grown == NULL) {
        notes->failed = 1;
        return NULL;
    }
    *capacity = bigger;
    return grown;
}

/* A new item at the end of the list, or NULL (out of memory: failed). */
static rt_warning *new_item(rt_notes *notes)
{
    rt_warning *items = room_for_one(notes, notes->items, &notes->capacity,
                                     notes->count, sizeof *items, 8);
    if (items == NULL)
        return NULL;
    notes->items = items;
    return &notes->items[notes->count++];
}

/* Fills w's position and its "name:line:column: warning: " prefix;
 * returns the prefix's length. */
static size_t start_item(rt_warning *w, const char *name, int line,
                         int column)
{
    w->line = line;
    w->column = line > 0 ? column : 0;
    size_t size = sizeof w->message;
    size_t used = rt__escape_name(name ? name : "<memory>", w->message, size);
    int more = line > 0 ? snprintf(w->message + used, size - used,
                                   ":%d:%d: warning: ", line, column)
                        : snprintf(w->message + used, size - used,
                                   ": warning: ");
    if (more < 0 || (size_t)more >= size - used)
        return 0;
    return used + (size_t)more;
}

static void add_item(rt_notes *notes, const char *name, int line, int column,
                     const char *fmt, va_list args)
{
    rt_warning *w = new_item(notes);
    if (w == NULL)
        return;
    size_t used = start_item(w, name, line, column);
    vsnprintf(w->message + used, sizeof w->message - used, fmt, args);
}

void rt__notes_add(rt_notes *notes, const char *name, int line, int column,
                   const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    add_item(notes, name, line, column, fmt, args);
    va_end(args);
}

/* Appends "a" or "a-b" (with ", " before when not first) if it fits. */
static void close_range(rt_note_lines *l)
{
    if (l->start == 0 || l->full)
        return;
    char range[32];
    int n = l->start == l->end
                ? snprintf(range, sizeof range, "%s%d",
                           l->length ? ", " : "", l->start)
                : snprintf(range, sizeof range, "%s%d-%d",
                           l->length ? ", " : "", l->start, l->end);
    if (n < 0 || l->length + (size_t)n > RT_NOTES_LINES_TEXT - 5) {
        l->full = 1;    /* room kept for ", ..." */
        return;
    }
    memcpy(l->text + l->length, range, (size_t)n + 1);
    l->length += (size_t)n;
}

static void add_line(rt_note_lines *l, int line)
{
    if (line <= 0)
        return;
    if (l->start != 0 && (line == l->end || line == l->end + 1)) {
        l->end = line;
        return;
    }
    close_range(l);
    l->start = l->end = line;
}

/* Writes the text of kind k's summary into w, after its prefix. */
static void write_summary(rt_warning *w, const rt_note_kind *k)
{
    rt_note_lines shown = k->lines;     /* the open range closed */
    close_range(&shown);
    char *at = w->message + k->prefix;
    size_t room = sizeof w->message - k->prefix;
    if (shown.length == 0 && !shown.full)
        snprintf(at, room, "... and %d more %s", k->more, k->kind);
    else
        snprintf(at, room, "... and %d more %s (line%s %s%s)", k->more,
                 k->kind, k->more > 1 ? "s" : "", shown.text,
                 shown.full ? ", ..." : "");
}

static rt_note_kind *find_kind(rt_notes *notes, const char *kind)
{
    for (int i = 0; i < notes->kind_count; i++)
        if (notes->kinds[i].kind == kind ||
            strcmp(notes->kinds[i].kind, kind) == 0)
            return &notes->kinds[i];
    rt_note_kind *kinds = room_for_one(notes, notes->kinds,
                                       &notes->kind_capacity,
                                       notes->kind_count, sizeof *kinds, 4);
    if (kinds == NULL)
        return NULL;
    notes->kinds = kinds;
    rt_note_kind *k = &notes->kinds[notes->kind_count++];
    memset(k, 0, sizeof *k);
    k->kind = kind;
    return k;
}

void rt__notes_add_kind(rt_notes *notes, const char *kind, const char *name,
                        int line, int column, const char *fmt, ...)
{
    rt_note_kind *k = find_kind(notes, kind);
    if (k == NULL)
        return;
    if (k->kept < RT_NOTES_SHOWN_PER_KIND) {
        k->kept++;
        va_list args;
        va_start(args, fmt);
        add_item(notes, name, line, column, fmt, args);
        va_end(args);
        return;
    }
    if (k->more == 0) {
        rt_warning *w = new_item(notes);
        if (w == NULL)
            return;
        k->summary = notes->count - 1;
        k->prefix = start_item(w, name, line, column);
    }
    k->more++;
    add_line(&k->lines, line);
}

void rt__notes_settle(rt_notes *notes)
{
    for (int i = 0; i < notes->kind_count; i++)
        if (notes->kinds[i].more > 0)
            write_summary(&notes->items[notes->kinds[i].summary],
                          &notes->kinds[i]);
}

void rt__notes_append(rt_notes *notes, const rt_notes *from)
{
    if (from == NULL)
        return;
    int first = notes->count;
    for (int i = 0; i < from->count; i++) {
        rt_warning *w = new_item(notes);
        if (w == NULL)
            return;
        *w = from->items[i];
    }
    for (int i = 0; i < from->kind_count; i++)
        if (from->kinds[i].more > 0)
            write_summary(&notes->items[first + from->kinds[i].summary],
                          &from->kinds[i]);
}

void rt__notes_free(rt_notes *notes)
{
    free(notes->items);
    free(notes->kinds);
    memset(notes, 0, sizeof *notes);
}
