/*
 * cli_explain.h - a pixel's ray tree (raytrace/explain.h) read as the
 * rendering model writes its formula: the one formatter of rt-export's
 * --explain (text or JSON) and rt-view's click (the same text, on standard
 * output and in the window), so that both name a ray, split a hit's colour
 * into its terms and word every line the same way (docs/teaching.md reads
 * the text line by line; docs/command-line.md lists the JSON's fields).
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
#include <stdio.h>

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

/*
 * The explanation of `tree`, the tree of pixel (x, y) of the image a
 * render with `samples` rays a pixel writes (x, y in that image: a
 * region's own coordinates), as text on `out`: a first line with the
 * formula, each camera ray (under "sample N:" when samples > 1) and the
 * rays that come from it indented by generation, each hit's terms and
 * their sum, and the pixel's value with the bytes it rounds to.  `scene`
 * names the scene (its control bytes escaped).  Thread-safe on distinct
 * streams.
 */
void cli_explain_print_text(FILE *out, const rt_ray_tree *tree,
                            const char *scene, int x, int y, int samples);

/* The same tree as one JSON object on one line (its strings through
 * cli_json_string), on `out`. */
void cli_explain_print_json(FILE *out, const rt_ray_tree *tree,
                            const char *scene, int x, int y);

#endif /* RAYTRACE_CLI_EXPLAIN_H */
