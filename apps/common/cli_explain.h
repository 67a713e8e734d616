/*
 * cli_explain.h - reading a pixel's ray tree (raytrace/explain.h) as the
 * rendering model writes its formula, shared by rt-export's --explain and
 * rt-view's click so that both name a ray and split a hit's colour into
 * its terms the same way.
 *
 * The one case where a ray's kind is not its term: a total internal
 * reflection.  The model (docs/rendering-model.md) says that when the
 * refracted direction does not exist (q < 0) C_T is the colour of the
 * mirror ray R; the renderer then casts one mirror ray, of kind
 * RT_RAY_REFLECTED and weight k + t, for both k C_R and t C_T.  On a facet
 * with k = 0 that ray is all of the t C_T term, none of k C_R.
 */
#ifndef RAYTRACE_CLI_EXPLAIN_H
#define RAYTRACE_CLI_EXPLAIN_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* Whether node i of nodes[0..count) is the mirror ray of a total internal
 * reflection: a reflected ray whose parent hit a facet with t > 0 and cast
 * no refracted ray (a refracted ray is recorded before its mirror ray, so
 * a tree cut when full cannot hide one). */
int cli_explain_total_reflection(const rt_ray_node *nodes, size_t count,
                                 size_t i);

/* How node i is named in an explanation: "camera", "shadow", "reflected",
 * "refracted", or "totally reflected" (cli_explain_total_reflection). */
const char *cli_explain_ray_name(const rt_ray_node *nodes, size_t count,
                                 size_t i);

/* The terms of the colour node i (a ray that hit) brings back, each
 * weighted as in the pixel: its direct light (the sum of its shadow rays),
 * k C_R and t C_T.  Under a total internal reflection the mirror ray's
 * colour is split k : t between k C_R and t C_T (with k = 0, all of it is
 * t C_T).  Returns 1 in that case, else 0. */
int cli_explain_terms(const rt_ray_node *nodes, size_t count, size_t i,
                      rt_color *direct, rt_color *reflection,
                      rt_color *refraction);

#endif /* RAYTRACE_CLI_EXPLAIN_H */
