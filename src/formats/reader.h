/*
 * reader.h - what every scene reader shares (internal): the poll of a
 * load's cancellation flag.  The bytes are read through the lexer
 * (lexer.h); the scene is reached through the builder's header
 * (scene/scene_build.h), with the warnings a reader collects.
 */
#ifndef RAYTRACE_READER_H
#define RAYTRACE_READER_H

#include <stddef.h>

#include "base/error.h"
#include "raytrace/scene.h"
#include "scene/scene_build.h"

/* Non-zero when `options` (may be NULL) carries a cancellation flag that
 * is raised.  Cheap (one atomic load), but readers poll it every
 * RT_LOAD_POLL items only. */
int rt__load_cancelled(const rt_load_options *options);

/* Fills *error for a cancelled load of `name` and returns
 * RT_ERR_CANCELLED. */
rt_status rt__load_cancel(rt_error *error, const char *name);

#endif /* RAYTRACE_READER_H */
