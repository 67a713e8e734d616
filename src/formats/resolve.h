/*
 * resolve.h - the files one load reads (internal): the scene file itself,
 * then every file it names (an OBJ's material libraries), opened through
 * the load options' resolver (rt_resolve_in_folder by default for a load
 * from a path; none for a parse from memory), each read once however it
 * is spelt, within a budget of bytes for the whole scene
 * (docs/robustness-input.md, "Files a scene names").  What was read
 * becomes the scene's rt_scene_source list.
 */
#ifndef RAYTRACE_RESOLVE_H
#define RAYTRACE_RESOLVE_H

#include <stddef.h>

#include "formats/names.h"
#include "raytrace/scene.h"

/* The bytes the files a scene names may hold in all: a floor for small
 * scenes with large libraries, and in proportion to the scene beyond it
 * (a library larger than the scene many times over is no library of
 * it).  The same MTL read under a thousand spellings costs its size
 * once; a hostile scene cannot make a load read more than this. */
#define RT_RESOLVE_BUDGET_FLOOR ((size_t)64 << 20)     /* 64 MiB */
#define RT_RESOLVE_BUDGET_PER_BYTE 16

/* The most distinct names a scene may ask for (each costs a walk of its
 * path through the file system): far more than any exporter writes. */
#define RT_RESOLVE_MAX_NAMES 1024

/* What rt__files_open found. */
typedef enum rt_found {
    RT_FOUND_NEW,       /* a file not read before: its bytes */
    RT_FOUND_AGAIN,     /* named (or read) before, under this spelling or
                           another: nothing more to do */
    RT_FOUND_SCENE,     /* the scene file itself: not to be read again */
    RT_FOUND_REFUSED    /* named before under this spelling and refused
                           then (with a message then) */
} rt_found;

typedef struct rt_files {
    rt_resolve_func resolve;    /* NULL: no file may be read */
    void *user;
    const char *scene_name;     /* as given to the load (may be NULL) */
    const char *scene_text;
    size_t scene_length;
    size_t budget, spent;       /* bytes */
    rt_names asked;             /* references, spelt canonically */
    int *outcome;               /* per asked name: a source index, -1
                                   (refused) or -2 (the scene itself) */
    int outcome_capacity;
    rt_scene_source *sources;   /* [0]: the scene file when from a path */
    int count, capacity;
    int scene_is_source;        /* sources[0] is the scene file */
} rt_files;

/*
 * Starts the list of a load of `text` (`length` bytes) called
 * `scene_name`, with the resolver of `options` (NULL: none).
 * `scene_file`, when the scene was read from a path, becomes the first
 * source (its name copied).  Returns RT_OK or RT_ERR_NOMEM.
 */
rt_status rt__files_init(rt_files *files, rt_resolve_func resolve,
                         void *user, const char *scene_name,
                         const char *text, size_t length,
                         const rt_scene_source *scene_file);

/* Non-zero when files named by the scene can be read at all. */
int rt__files_can_open(const rt_files *files);

/*
 * The file `reference` (as the scene spells it, its escapes removed).
 * RT_OK with *found: for RT_FOUND_NEW, *data (malloc'd, NUL-terminated,
 * the caller frees it), *length and *name (the file's name for messages,
 * owned by `files`).  Otherwise a refusal whose *why says what and names
 * the reference, quoting no file's content; RT_ERR_NOMEM is a failure
 * of the load, any other status only means that file is not read.
 */
rt_status rt__files_open(rt_files *files, const char *reference,
                         rt_found *found, char **data, size_t *length,
                         const char **name, rt_error *why);

/* Hands the sources to `scene` (rt__scene_take_sources); `files` keeps
 * none. */
void rt__files_attach(rt_files *files, rt_scene *scene);

void rt__files_free(rt_files *files);

/* A copy of `name` for the body of a message (malloc'd; NULL out of
 * memory), escaped by rt__escape_name's rule (error.h) so that no name a
 * file gives can reach a terminal as an escape sequence.  Names given as
 * the `name` of rt__error_set or rt__notes_add are escaped there: pass
 * them raw. */
char *rt__shown_name(const char *name);

#endif /* RAYTRACE_RESOLVE_H */
