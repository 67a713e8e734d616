/*
 * reader.h - what every scene reader shares (internal): the readers' entry
 * points (scn.c, nff.c, obj.c, ply.c), the end of every read (rt__reader_finish:
 * the options' view and lights, the build, a refusal mapped to the token
 * the reader kept), and the poll of a load's cancellation flag.  The bytes
 * are read through the lexer (lexer.h); the scene is reached through the
 * builder's header (scene/scene_build.h), with the warnings a reader
 * collects.
 */
#ifndef RAYTRACE_READER_H
#define RAYTRACE_READER_H

#include <stddef.h>

#include "base/error.h"
#include "formats/lexer.h"
#include "raytrace/scene.h"
#include "scene/scene_build.h"

/*
 * Finds the token a reader kept for what `refusal` names (its item, index,
 * field and part): 1 with *token set, or 0 when the reader kept none (the
 * builder's words then stand without a position).
 */
typedef int (*rt_locate_func)(void *user, const rt_refusal *refusal,
                              rt_token *token);

/* What a reader hands over at its end (rt__reader_finish). */
typedef struct rt_reading {
    const char *name;               /* the file, for messages */
    const int *facet_lines;         /* each facet's line; may be NULL */
    const rt_notes *notes;          /* the reader's warnings; may be NULL */
    const rt_load_options *options; /* may be NULL */
    rt_locate_func locate;          /* may be NULL */
    void *user;                     /* for locate */
    /* May be NULL: frees the description's arrays (and sets the reader's
     * pointers to them to NULL), called with release_user once the
     * scene's records are made and before its kernel is built, so that
     * a big load never holds the description and the kernel at once. */
    void (*release)(void *release_user);
    void *release_user;
} rt_reading;

/*
 * What every reader ends with: applies the view and the lights of
 * reading->options to `desc`, then builds the scene (scene_build.h).  A
 * refusal of the builder that names an item of the file (not one the
 * options replaced) is reported at the token reading->locate finds for
 * it, "name:line:column: expected RULE, found `TOKEN`"; other failures
 * keep the builder's words.
 */
rt_status rt__reader_finish(rt_scene_desc *desc, const rt_reading *reading,
                            rt_scene **scene, rt_error *error);

/* The readers: the contract of rt_scene_parse for one format, with the
 * arguments and `options` as the loader took and checked them (loader.c;
 * `options` never NULL, but .scn also takes NULL as the defaults); each ends
 * with rt__reader_finish. */
rt_status rt__scn_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error);
rt_status rt__nff_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error);
/* PLY's text may hold binary data (its body): no NUL check applies past
 * the header. */
rt_status rt__ply_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error);
struct rt_files;
/* OBJ also reads the files it names through `files` (resolve.h). */
rt_status rt__obj_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options,
                        struct rt_files *files, rt_scene **scene,
                        rt_error *error);

/* The arguments every entry point that parses from memory takes
 * (rt_scene_parse): RT_OK with *scene NULL, or RT_ERR_ARGUMENT with
 * *error filled. */
rt_status rt__parse_arguments(const char *text, size_t length,
                              const char *name, rt_scene **scene,
                              rt_error *error);

/* Non-zero when `options` (may be NULL) carries a cancellation flag that
 * is raised.  Cheap (one atomic load), but readers poll it every
 * RT_LOAD_POLL items only. */
int rt__load_cancelled(const rt_load_options *options);

/* Fills *error for a cancelled load of `name` and returns
 * RT_ERR_CANCELLED. */
rt_status rt__load_cancel(rt_error *error, const char *name);

#endif /* RAYTRACE_READER_H */
