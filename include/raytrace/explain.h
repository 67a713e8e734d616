/*
 * raytrace/explain.h - why a pixel has its colour: the ray tree of one
 * pixel, and debug views of a whole image.
 *
 * rt_explain_pixel re-renders one pixel with the render's own kernel and a
 * recorder attached, so the tree holds every ray the renderer cast for that
 * pixel (camera, shadow, reflected, refracted), what each hit, and what each
 * term of the rendering model's formula (docs/rendering-model.md) added:
 *
 *     C = sum over lights l of E_l (N.S_l) d C_S,l C_F / 255 + k C_R + t C_T
 *
 * The value of the tree (rt_ray_tree_value) is the pixel's value before
 * rounding, bit for bit what rt_render computes with the same options
 * (depth, samples, sampling, lens, precision, fast square root, kernel,
 * accel, size and region): rt_channel_to_byte of it is the rendered byte.
 *
 *     rt_ray_tree *tree;
 *     if (rt_explain_pixel(scene, &options, x, y, -1, &tree, &error) == RT_OK) {
 *         size_t count;
 *         const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
 *         for (size_t i = 0; i < count; i++) ... nodes[i] ...
 *         rt_ray_tree_destroy(tree);
 *     }
 *
 * rt_render_view writes, instead of the image, one of the debug views of
 * rt_debug_view (docs/teaching.md says how to read each).
 *
 * Both only read the scene: thread-safe with any other reads of it.
 */
#ifndef RAYTRACE_EXPLAIN_H
#define RAYTRACE_EXPLAIN_H

#include "raytrace/export.h"

#include <stddef.h>

#include "raytrace/image.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"
#include "raytrace/status.h"
#include "raytrace/vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a ray of the tree is. */
typedef enum rt_ray_kind {
    RT_RAY_CAMERA = 0,      /* a primary ray (one per sample) */
    RT_RAY_SHADOW = 1,      /* from a hit towards one light */
    RT_RAY_REFLECTED = 2,   /* the mirror ray of a facet with k > 0 (or of a
                               total internal reflection: weight k + t) */
    RT_RAY_REFRACTED = 3    /* through a facet with t > 0 */
} rt_ray_kind;

/* A tree records at most this many rays; a deeper or wider tree is cut
 * (rt_ray_tree_truncated), its value stays exact. */
#define RT_RAY_TREE_MAX_NODES 65536

/*
 * One ray of the tree, a plain value.  Nodes are in the order the renderer
 * cast them; a node's parent comes before it.  Numbers are in double
 * whatever the precision (a float render's values converted exactly).
 */
typedef struct rt_ray_node {
    rt_ray_kind kind;
    int parent;             /* index of the ray it comes from; -1 for a
                               camera ray.  A shadow ray's parent is the ray
                               whose hit it leaves */
    int depth;              /* bounces before it: 0 for a camera ray and the
                               shadow rays of its hit, 1 for a reflected or
                               refracted ray of that hit, ... */
    int sample;             /* the pixel's sample it belongs to, 0..n*n-1 */
    rt_vec3 origin;         /* where it starts (secondary rays: offset off
                               the surface, as the renderer does) */
    rt_vec3 direction;      /* unit, except a shadow ray's: light - origin */
    double weight;          /* the product of the k (and t) of the hits
                               before it: what its colour is multiplied by
                               in the pixel (1 for a camera ray) */

    /* Camera, reflected and refracted rays: what they hit. */
    int hit;                /* 1: a facet; 0: nothing, the background */
    int facet;              /* the facet's index in the file, -1 if none */
    int line;               /* the line of its record in the source, 0 if
                               the scene was not read from text */
    double t;               /* distance along `direction` to the hit */
    rt_vec3 point;          /* the hit point */
    rt_vec3 normal;         /* the facet's unit normal as used: turned
                               towards the ray's origin */
    double reflection;      /* the facet's k */
    double transparency;    /* its t (its refractive index n is
                               rt_scene_facet's) */
    double diffuse;         /* its diffuse weight d (1 - k - t in .scn) */
    rt_color own;           /* what this ray adds to the pixel by itself,
                               weighted: weight x background when it hits
                               nothing; zero for a hit (its direct light is
                               in its shadow rays) */
    rt_color subtotal;      /* the sum of `own` over this ray and all rays
                               that come from it, in double: the weighted
                               colour it carries (its terms k C_R, t C_T are
                               its reflected / refracted child's subtotal) */

    /* Shadow rays (one per light where the renderer considered one): */
    int light;              /* the light's index */
    double n_dot_s;         /* N.S: the used normal . the unit direction to
                               the light; <= 0: no ray was cast, E = 0 */
    int cast;               /* 1: the renderer cast the ray; 0: skipped
                               (N.S <= 0 or d = 0: the term is 0) */
    double e;               /* the visibility term E: 1 lit, 0 in shadow
                               (or not cast) */
    int blocker;            /* when cast and E = 0: the nearest facet on the
                               segment to the light; else -1 */
    int blocker_line;       /* its record's line (0: unknown) */
    /* (own: E (N.S) d C_S C_F / 255 x weight, plus the highlight below,
     * as the renderer added it) */

    /* Since 0.4 (docs/rendering-model.md, "Smooth shading and
     * highlights").  Hits: */
    int smooth;             /* 1: the facet has vertex normals */
    rt_vec3 shading_normal; /* N_s as used (unit, on the side of `normal`;
                               `normal` itself on a flat facet) */
    rt_vec3 shading_point;  /* P', where its shadow rays leave (`point` on
                               a flat facet) */
    double highlight;       /* the facet's highlight weight s */
    double highlight_exponent;  /* its exponent p */
    /* Shadow rays: */
    double r_dot_v;         /* R_l.V of the highlight (0 when not lit or
                               s = 0) */
    rt_color highlight_own; /* the highlight's term E s max(0, R.V)^p C_S
                               x weight, part of `own` */
} rt_ray_node;

/* The rays of one pixel (opaque: rt_ray_tree_nodes reads it). */
typedef struct rt_ray_tree rt_ray_tree;

/*
 * The ray tree of pixel (x, y) of the image a render with `options` (NULL:
 * the defaults) writes - x, y in that image's coordinates, so with a region
 * (0, 0) is the region's top-left pixel - and its samples: `sample` -1 for
 * all of them, else 0..samples-1 for one (its value is then that sample's
 * colour, not the pixel's).  On RT_OK *tree is the new tree, to free with
 * rt_ray_tree_destroy.  RT_ERR_ARGUMENT (a pixel outside the image, a bad
 * sample, any option rt_render refuses, a NULL scene or tree),
 * RT_ERR_RANGE (as rt_render in float), RT_ERR_NOMEM; then *tree is NULL,
 * *error (may be NULL) says why.
 * Thread-safe.
 */
RT_API rt_status rt_explain_pixel(const rt_scene *scene,
                                  const rt_render_options *options, int x,
                                  int y, int sample, rt_ray_tree **tree,
                                  rt_error *error);

/* Frees a tree; NULL: no-op.  Not on a tree another thread reads. */
RT_API void rt_ray_tree_destroy(rt_ray_tree *tree);

/* The rays, *count of them (count may be NULL).  The array lives as long
 * as the tree.  A NULL tree is asserted (NULL and a count of 0 where
 * NDEBUG is defined), as in the two functions below (a zero value).
 * Thread-safe (read only). */
RT_API const rt_ray_node *rt_ray_tree_nodes(const rt_ray_tree *tree,
                                            size_t *count);

/* The pixel's value before rounding (the mean of the explained samples),
 * exactly what the render computes.  Thread-safe. */
RT_API rt_color rt_ray_tree_value(const rt_ray_tree *tree);

/* The number of rays left out because the tree reached
 * RT_RAY_TREE_MAX_NODES (0 normally).  Thread-safe. */
RT_API size_t rt_ray_tree_truncated(const rt_ray_tree *tree);

/*
 * The debug views.  Each reads the first sample of each pixel (with one
 * sample: the ray through its centre) and its camera ray's hit; a pixel
 * whose camera ray hits nothing is black (0, 0, 0) in every view but
 * RT_VIEW_DEPTH's.  docs/teaching.md shows how to read them.
 */
typedef enum rt_debug_view {
    RT_VIEW_NORMAL = 1,     /* the geometric normal N_g as used, n, as (n + 1) / 2 x 255
                               per axis x, y, z -> red, green, blue */
    RT_VIEW_DEPTH = 2,      /* t of the camera ray: the nearest t of the
                               image's hits 255, the farthest 0, linear
                               between (all the same: 255); no hit: 0 */
    RT_VIEW_FACET = 3,      /* each facet index its own colour, from a fixed
                               hash (rt_debug_facet_color) */
    RT_VIEW_SHADOW = 4,     /* E of light `light` at the camera ray's hit:
                               white lit, dark red (128, 0, 0) shadowed, dark
                               blue (0, 0, 128) facing away (N.S <= 0 or
                               d = 0: no shadow ray) */
    RT_VIEW_BOUNCES = 5,    /* reflected and refracted rays of the tree at
                               the deepest: 0 black, the render's depth
                               white, grey levels 255 b / depth between */
    RT_VIEW_NS = 6,         /* N.S of light `light`: 255 N.S when positive
                               (grey), 0 when <= 0 */
    RT_VIEW_SHADING_NORMAL = 7  /* the shading normal N_s as RT_VIEW_NORMAL
                                   shows the geometric one (the same on a
                                   flat facet) */
} rt_debug_view;

/* The colour RT_VIEW_FACET gives facet `index`: a fixed hash of it, each
 * channel in 64..255.  Thread-safe. */
RT_API rt_rgb8 rt_debug_facet_color(int index);

/*
 * Writes view `view` of the render with `options` (NULL: defaults) into
 * `image`, of the size rt_render would write (regions apply); `light` is the
 * light of RT_VIEW_SHADOW and RT_VIEW_NS (ignored by the others).  Since
 * 0.5 a view is a render like rt_render's: on options->threads, rows taken
 * dynamically, on_row called for each finished row (for RT_VIEW_DEPTH,
 * whose greys depend on the whole image, once every row's t is known and
 * the rows are written), options->cancel polled before each pixel, and
 * options->stats filled with what the view traced (camera rays; the
 * shadow, reflection and refraction rays of each pixel's first sample's
 * tree).  Same statuses as rt_render (RT_ERR_CANCELLED included: the rows
 * not reported hold what they held), plus RT_ERR_ARGUMENT for an unknown
 * view, a light outside 0..light_count-1, or an image whose stride is
 * less than 3 x its width.  Thread-safe as rt_render.
 */
RT_API rt_status rt_render_view(const rt_scene *scene,
                                const rt_render_options *options,
                                rt_debug_view view, int light,
                                rt_image *image, rt_error *error);

#ifdef __cplusplus
}
#endif

#endif /* RAYTRACE_EXPLAIN_H */
