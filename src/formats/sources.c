/*
 * sources.c - the files one load reads (resolve.h, rt_files): the scene
 * file first, then each file it names, asked of the load's resolver once
 * however the scene spells it (a canonical spelling first, then the
 * device and inode of what was read, then the scene's own bytes), within
 * the load's budget of bytes and names; the list becomes the scene's
 * rt_scene_source list.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/resolve.h"
#include "scene/scene_build.h"

rt_status rt__files_init(rt_files *files, rt_resolve_func resolve,
                         void *user, const char *scene_name,
                         const char *text, size_t length,
                         const rt_scene_source *scene_file)
{
    memset(files, 0, sizeof *files);
    files->resolve = resolve;
    files->user = user;
    files->scene_name = scene_name;
    files->scene_text = text;
    files->scene_length = length;
    size_t most = SIZE_MAX - RT_RESOLVE_BUDGET_FLOOR;
    files->budget = RT_RESOLVE_BUDGET_FLOOR +
                    (length < most / RT_RESOLVE_BUDGET_PER_BYTE
                         ? length * RT_RESOLVE_BUDGET_PER_BYTE
                         : most);
    if (scene_file == NULL)
        return RT_OK;
    files->sources = malloc(4 * sizeof *files->sources);
    const char *raw = scene_file->name ? scene_file->name : "<memory>";
    char *name = malloc(strlen(raw) + 1);
    if (name != NULL)
        memcpy(name, raw, strlen(raw) + 1);
    if (files->sources == NULL || name == NULL) {
        free(files->sources);
        free(name);
        files->sources = NULL;
        return RT_ERR_NOMEM;
    }
    files->capacity = 4;
    files->sources[0] = *scene_file;
    files->sources[0].name = name;
    files->count = 1;
    files->scene_is_source = 1;
    return RT_OK;
}

int rt__files_can_open(const rt_files *files)
{
    return files->resolve != NULL;
}

/* `reference` spelt canonically: without empty and `.` components (a
 * leading and a trailing slash kept), so that `./m.mtl` and `.//m.mtl`
 * are `m.mtl`.  Malloc'd; *length its length. */
static char *canonical(const char *reference, size_t *length)
{
    size_t n = strlen(reference), used = 0;
    char *out = malloc(n + 1);
    if (out == NULL)
        return NULL;
    if (reference[0] == '/')
        out[used++] = '/';
    for (const char *c = reference; *c != '\0';) {
        while (*c == '/')
            c++;
        const char *end = strchr(c, '/');
        size_t part = end ? (size_t)(end - c) : strlen(c);
        if (part > 0 && !(part == 1 && c[0] == '.')) {
            if (used > 0 && out[used - 1] != '/')
                out[used++] = '/';
            memcpy(out + used, c, part);
            used += part;
        }
        c += part;
    }
    if (n > 0 && reference[n - 1] == '/' && (used == 0 || out[used - 1] != '/'))
        out[used++] = '/';
    out[used] = '\0';
    *length = used;
    return out;
}

static rt_status nomem(rt_error *why)
{
    return rt__error_set(why, RT_ERR_NOMEM, NULL, 0, 0, "out of memory");
}

/* The source index of the file read before with this identity, or -1. */
static int same_file(const rt_files *files, const rt_resolved_file *file)
{
    if (file->device == 0 && file->inode == 0)
        return -1;
    for (int i = 0; i < files->count; i++)
        if (files->sources[i].device == file->device &&
            files->sources[i].inode == file->inode)
            return i;
    return -1;
}

static rt_status add_source(rt_files *files, rt_resolved_file *file)
{
    if (files->count == files->capacity) {
        int bigger = files->capacity ? 2 * files->capacity : 4;
        rt_scene_source *grown = realloc(files->sources,
                                         (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return RT_ERR_NOMEM;
        files->sources = grown;
        files->capacity = bigger;
    }
    files->sources[files->count++] =
        (rt_scene_source){file->name, file->device, file->inode,
                          file->length};
    file->name = NULL;
    return RT_OK;
}

/* Asks the resolver, within what is left of the budget. */
static rt_status ask(rt_files *files, const char *reference, const char *shown,
                     rt_resolved_file *file, rt_error *why)
{
    size_t left = files->budget - files->spent;
    if (left == 0)
        return rt__error_set(why, RT_ERR_LIMIT, NULL, 0, 0,
                             "`%s` is not read: the files this scene names "
                             "have taken the %zu bytes they may hold in all "
                             "(%d per byte of the scene, plus %zu)", shown,
                             files->budget, RT_RESOLVE_BUDGET_PER_BYTE,
                             RT_RESOLVE_BUDGET_FLOOR);
    size_t limit = left < RT_MAX_SCENE_BYTES ? left : RT_MAX_SCENE_BYTES;
    rt_error answer;
    memset(&answer, 0, sizeof answer);
    memset(file, 0, sizeof *file);
    rt_status status = files->resolve(files->user, files->scene_name,
                                      reference, limit, file, &answer);
    if (status != RT_OK) {
        if (answer.message[0] == '\0')
            snprintf(answer.message, sizeof answer.message,
                     "`%s` is not read: %s", shown, rt_status_string(status));
        *why = answer;
        why->status = status;
        return status;
    }
    if (file->length > limit) {
        free(file->data);
        free(file->name);
        return rt__error_set(why, RT_ERR_LIMIT, NULL, 0, 0,
                             "`%s` is not read: the resolver gave %zu bytes, "
                             "more than the %zu asked", shown, file->length,
                             limit);
    }
    if (file->data == NULL && (file->data = malloc(1)) == NULL) {
        free(file->name);
        return nomem(why);
    }
    if (file->name == NULL && (file->name = strdup(shown)) == NULL) {
        free(file->data);
        return nomem(why);
    }
    files->spent += file->length;
    return RT_OK;
}

rt_status rt__files_open(rt_files *files, const char *reference,
                         rt_found *found, char **data, size_t *length,
                         const char **name, rt_error *why)
{
    *found = RT_FOUND_AGAIN;
    *data = NULL;
    *length = 0;
    *name = NULL;
    size_t key_length;
    char *key = canonical(reference, &key_length);
    char *shown = rt__shown_name(reference);
    int added = 0;
    int id = key && shown ? rt__names_put(&files->asked, key, key_length,
                                          &added)
                          : -1;
    free(key);
    if (id >= 0 && added && id >= files->outcome_capacity) {
        int bigger = files->outcome_capacity ? 2 * files->outcome_capacity
                                             : 16;
        int *grown = realloc(files->outcome, (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            id = -1;
        else
            files->outcome = grown, files->outcome_capacity = bigger;
    }
    if (id < 0) {
        free(shown);
        return nomem(why);
    }
    if (!added) {
        /* Asked before under this spelling: read then, or refused with a
         * message then. */
        *found = files->outcome[id] == -1 ? RT_FOUND_REFUSED : RT_FOUND_AGAIN;
        free(shown);
        return RT_OK;
    }
    files->outcome[id] = -1;
    rt_status status = RT_OK;
    if (!files->resolve) {
        status = rt__error_set(why, RT_ERR_ARGUMENT, NULL, 0, 0,
                               "`%s` is not read: the scene was given from "
                               "memory, without a resolver", shown);
    } else if (files->asked.count > RT_RESOLVE_MAX_NAMES) {
        status = rt__error_set(why, RT_ERR_LIMIT, NULL, 0, 0,
                               "`%s` is not read: the scene names more than "
                               "%d files", shown, RT_RESOLVE_MAX_NAMES);
    } else {
        rt_resolved_file file;
        status = ask(files, reference, shown, &file, why);
        int before = status == RT_OK ? same_file(files, &file) : -1;
        if (status == RT_OK &&
            (before >= 0 || (file.length == files->scene_length &&
                             (file.length == 0 ||
                              memcmp(file.data, files->scene_text,
                                     file.length) == 0)))) {
            *found = (before == 0 && files->scene_is_source) || before < 0
                         ? RT_FOUND_SCENE
                         : RT_FOUND_AGAIN;
            files->outcome[id] = before >= 0 ? before : -2;
            free(file.data);
            free(file.name);
        } else if (status == RT_OK) {
            *name = file.name;
            if ((status = add_source(files, &file)) != RT_OK) {
                free(file.data);
                free(file.name);
                *name = NULL;
                status = nomem(why);
            } else {
                files->outcome[id] = files->count - 1;
                *found = RT_FOUND_NEW;
                *data = file.data;
                *length = file.length;
            }
        }
    }
    free(shown);
    return status;
}

void rt__files_attach(rt_files *files, rt_scene *scene)
{
    rt__scene_take_sources(scene, files->sources, files->count);
    files->sources = NULL;
    files->count = files->capacity = 0;
}

void rt__files_free(rt_files *files)
{
    for (int i = 0; i < files->count; i++)
        free((char *)files->sources[i].name);
    free(files->sources);
    free(files->outcome);
    rt__names_free(&files->asked);
    memset(files, 0, sizeof *files);
}
