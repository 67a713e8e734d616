/*
 * raytrace/render.h - turning a scene into pixels.
 *
 * Whitted ray tracing as docs/rendering-model.md defines it: one primary ray
 * through
 * each pixel centre, the nearest facet (by brute force or through an octree,
 * with the same result), a shadow ray to the point light, mirror reflections
 * up to a depth, real-valued colours rounded once per pixel.  Rendering only
 * reads the scene, so several renders of one scene may run at once; each
 * render writes only the rows it was asked for.
 *
 * A render can report progress and be cancelled: `on_rows` is called each
 * time a row is finished, and returning 0 from it stops the render as soon as
 * every thread notices (within one pixel's work), with RT_ERR_CANCELLED.
 */
#ifndef RAYTRACE_RENDER_H
#define RAYTRACE_RENDER_H

#include "raytrace/export.h"

#include <stddef.h>
#include <stdint.h>

#include "raytrace/image.h"
#include "raytrace/scene.h"
#include "raytrace/status.h"
#include "raytrace/vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RT_DEFAULT_DEPTH 5

/*
 * Counters of the work a render did; filled when options.stats is set,
 * by the rule of the structs the library fills (raytrace/scene.h, above
 * rt_facet_info): the caller sets stats->size to sizeof(rt_render_stats)
 * before the render, a smaller size or 0 is refused with RT_ERR_ARGUMENT
 * before any work.  `size` is no counter: RT_STATS_MAP leaves it out.
 * The "skipped" counts compare with a renderer that skips nothing: one that
 * casts a shadow ray at every hit, a reflected ray at every hit before the
 * depth limit, tests every facet of the file (zero-area ones too) and lets
 * shadow rays test every facet even after a hit.
 *
 * RT_STATS_MAP(X) declares them once, in the order of rt_render_stats's
 * fields: X(type, name, origin, merge, group, key, title), where
 *   origin  THREAD: counted by each rendering thread and summed at the end;
 *           RENDER: filled once at the end of the render;
 *           OCTREE: a property of the octree the render used;
 *   merge   how the stats of parts of one image (bands rendered apart)
 *           combine: SUM, MAX, or SAME (the octree's, the same in every
 *           part that used it: kept from any of them);
 *   group, key   where the JSON of --stats=json lists it (an object of
 *           docs/command-line.md, or `image`, `tests`: the top level;
 *           `flag`: not listed, it says whether `octree` is);
 *   title   what the text of --stats calls it (rays and rays skipped),
 *           or says what it is.
 * The library, the programs' reports and the MPI farm's sum are generated
 * from it, so a counter is added in one place.
 */
#define RT_STATS_MAP(X)                                                      \
    X(uint64_t, camera_rays, THREAD, SUM, rays, camera, "camera")            \
    X(uint64_t, shadow_rays, THREAD, SUM, rays, shadow, "shadow")            \
    X(uint64_t, reflection_rays, THREAD, SUM, rays, reflection,              \
      "reflection")                                                          \
    X(uint64_t, ray_facet_tests, THREAD, SUM, tests, ray_facet_tests,        \
      "ray-facet tests")                                                     \
    X(uint64_t, shadow_rays_skipped, THREAD, SUM, rays_skipped, shadow,      \
      "shadow rays (N.S <= 0 or d = 0)")                                     \
    X(uint64_t, reflection_rays_skipped, THREAD, SUM, rays_skipped,          \
      reflection, "reflection rays (k = 0)")                                 \
    X(uint64_t, pixels, THREAD, SUM, image, pixels, "pixels")                \
    /* the wall-clock time of the render */                                  \
    X(double, seconds, RENDER, SUM, seconds, render, "render")               \
    /* tests the renderer that skips nothing would make on top: the skipped  \
       rays (one pass each; their own reflections not counted), the          \
       zero-area facets, the shadow rays' tests after their first hit */     \
    X(uint64_t, ray_facet_tests_skipped, RENDER, SUM, tests,                 \
      ray_facet_tests_skipped, "more without the analysis and early exits")  \
    /* 1: the render used the octree, whose figures follow; 0: brute force   \
       (and they are 0) */                                                   \
    X(int, accel_used, OCTREE, MAX, flag, used, "octree")                    \
    /* the time its construction took (once per scene and precision, by the  \
       first render that used it) */                                         \
    X(double, accel_build_seconds, OCTREE, MAX, octree, build_seconds,       \
      "built in")                                                            \
    X(uint64_t, accel_nodes, OCTREE, SAME, octree, nodes, "nodes")           \
    X(uint64_t, accel_leaves, OCTREE, SAME, octree, leaves, "leaves")        \
    X(int, accel_depth, OCTREE, SAME, octree, depth, "depth")                \
    X(uint64_t, accel_references, OCTREE, SAME, octree, references,          \
      "facet entries in all leaves")                                         \
    /* 0 but for scenes whose coordinates leave no room for cells (slivers   \
       are in leaves) */                                                     \
    X(uint64_t, accel_always, OCTREE, SAME, octree, always_tested,           \
      "facets every ray tests, in no leaf")                                  \
    X(uint64_t, accel_bytes, OCTREE, SAME, octree, bytes, "its memory")      \
    X(uint64_t, accel_queries, THREAD, SUM, octree, queries,                 \
      "ray queries through it")                                              \
    X(uint64_t, accel_leaves_visited, THREAD, SUM, octree, leaves_visited,   \
      "leaves visited")                                                      \
    /* brute force tests every live facet per query */                       \
    X(uint64_t, accel_facet_tests, THREAD, SUM, octree, facet_tests,         \
      "facets tested")                                                       \
    X(uint64_t, accel_fallbacks, THREAD, SUM, octree, fallbacks,             \
      "queries left to brute force")                                         \
    X(uint64_t, accel_facets, OCTREE, SAME, octree, facets,                  \
      "live facets: what brute force tests per query")                       \
    X(uint64_t, refraction_rays, THREAD, SUM, rays, refraction,              \
      "refraction")                                                          \
    /* the mirror ray of a total internal reflection carries t */            \
    X(uint64_t, refraction_rays_skipped, THREAD, SUM, rays_skipped,          \
      refraction, "refraction rays (depth limit or total internal "          \
                  "reflection; none where t = 0)")                           \
    /* 1: the structure the render used (accel_used) was the kd-tree, whose  \
       figures the accel_ fields are; 0: the octree */                       \
    X(int, accel_kdtree, OCTREE, MAX, flag, kdtree, "kd-tree")           \
    /* the nodes the walks took up, leaves and inner nodes: each node       \
       popped from the walk's stack or descended into, whether entered or   \
       passed over beyond the stopping point (0 for queries left to brute   \
       force before any walk) */                                            \
    X(uint64_t, accel_steps, THREAD, SUM, octree, steps, "traversal steps")

typedef struct rt_render_stats {
    size_t size;            /* sizeof(rt_render_stats), set by the caller */
#define RT_STATS_FIELD_(type, name, origin, merge, group, key, title)      \
    type name;
    RT_STATS_MAP(RT_STATS_FIELD_)
#undef RT_STATS_FIELD_
} rt_render_stats;

/*
 * The rays a render cast: the sum of the counters of RT_STATS_MAP's group
 * `rays` (camera, shadow, reflection and refraction rays; `total` in
 * --stats=json), as many as lie wholly within stats->size.  A count of
 * rays, never a wrap in practice (64 bits).  `stats`, the caller's, is
 * only read.  A NULL `stats`, or a size short of the layout of 0.3 (the
 * rule above), is a programmer's error: an assert stops a debug build; with
 * NDEBUG the result is 0.  Thread-safe.
 */
RT_API uint64_t rt_render_stats_rays(const rt_render_stats *stats);

/*
 * Called from a rendering thread each time row `row` is complete in the
 * image; calls are serialised (never two at once) but may come from any
 * thread and in any row order.  Return non-zero to go on, 0 to cancel.
 */
typedef int (*rt_row_callback)(void *user, int row);

/* The arithmetic of intersection and shading.  Double is the reference;
 * float is faster and less accurate (docs/accuracy.md). */
typedef enum rt_precision {
    RT_PRECISION_DOUBLE = 0,
    RT_PRECISION_FLOAT = 1
} rt_precision;

/* Where the samples of a pixel go when there are several. */
typedef enum rt_sampling {
    RT_SAMPLING_REGULAR = 0,    /* the centres of an n x n grid */
    RT_SAMPLING_STRATIFIED = 1  /* one point per cell of the grid, placed by
                                   a hash of the pixel and the sample, so the
                                   image is the same on every run */
} rt_sampling;

/*
 * The loops that test a ray against the facets.  Both give the same image,
 * bit for bit; the choice exists to measure and to test the fast one.
 */
typedef enum rt_kernel_choice {
    RT_KERNEL_AUTO = 0,     /* the fastest this processor runs: facets in
                               blocks of eight tested with AVX2 on x86-64,
                               else the scalar loops */
    RT_KERNEL_SCALAR = 1    /* one facet at a time, plain C */
} rt_kernel_choice;

/*
 * How a ray finds the facets it may hit.  Every choice gives the same
 * image, bit for bit; the octree is built once per scene and precision, by
 * the first render that needs it, and kept with the scene; so is the
 * kd-tree.
 */
typedef enum rt_accel {
    RT_ACCEL_AUTO = 0,      /* the kd-tree from RT_ACCEL_AUTO_FACETS live
                               facets on, else brute force */
    RT_ACCEL_NONE = 1,      /* brute force: every ray tests every facet */
    RT_ACCEL_OCTREE = 2,    /* an octree of the facets, whatever their
                               number */
    RT_ACCEL_KDTREE = 3     /* a kd-tree of the facets built by the surface
                               area heuristic, whatever their number
                               (docs/kdtree.md) */
} rt_accel;

/* Below this many live facets brute force is as fast as the kd-tree (and
 * faster than the octree) on the machine of docs/kdtree.md (measured
 * there, "What auto chooses"). */
#define RT_ACCEL_AUTO_FACETS 240

/*
 * A cancellation flag that renders poll before every pixel, and while they
 * build an octree (about every millisecond).  Any thread may raise it while
 * renders that were given it run; each then stops within one pixel's work
 * on every thread and returns RT_ERR_CANCELLED.  It stays raised
 * until reset.  All functions are thread-safe on the same flag, except
 * rt_cancel_destroy, which must wait until no render uses it.
 */
typedef struct rt_cancel rt_cancel;

/* A new flag, not raised, in *cancel; RT_ERR_NOMEM (and *cancel NULL)
 * when out of memory, RT_ERR_ARGUMENT when `cancel` is NULL. */
RT_API rt_status rt_cancel_create(rt_cancel **cancel, rt_error *error);
/* Frees the flag; NULL: no-op. */
RT_API void rt_cancel_destroy(rt_cancel *cancel);
/* Raises the flag; NULL: no-op. */
RT_API void rt_cancel_request(rt_cancel *cancel);
/* Lowers the flag; NULL: no-op. */
RT_API void rt_cancel_reset(rt_cancel *cancel);
/* Non-zero while the flag is raised; 0 for NULL. */
RT_API int rt_cancel_requested(const rt_cancel *cancel);

/*
 * A rectangle of pixels of the image: columns x0 <= x < x1, rows
 * y0 <= y < y1, with (0, 0) the top-left pixel.  All four zero: the whole
 * image.
 */
typedef struct rt_region {
    int x0, y0, x1, y1;
} rt_region;

/*
 * What a render does (rt_render_options_init sets every default).
 *
 * How the option structs grow (rt_render_options here, rt_load_options in
 * raytrace/scene.h, rt_save_options in raytrace/image.h): the first field, `size`, is sizeof the struct as the
 * caller was compiled, set by the _init function.  New fields are only ever
 * appended.  The library reads the fields that lie wholly within `size`;
 * every later field keeps its default, so a program built against an older
 * header keeps working with a newer library.  A size of 0 (a struct that was
 * never initialised) or larger than the library knows (a program built
 * against a newer header than the library it runs with) is refused with
 * RT_ERR_ARGUMENT and a message giving both sizes.  Always call the _init
 * function, then set fields by name.
 */
typedef struct rt_render_options {
    size_t size;                /* sizeof(rt_render_options); set by
                                   rt_render_options_init */
    int max_depth;              /* reflections after a primary ray, >= 0;
                                   default 5 */
    int threads;                /* 0: one per online core (default); 1: the
                                   calling thread only; n > 1: n threads
                                   (at most one per row); negative: refused */
    rt_precision precision;     /* default RT_PRECISION_DOUBLE */
    int fast_inv_sqrt;          /* non-zero: normalise vectors with the
                                   handout's fastInvSqrt (one Newton step)
                                   instead of 1/sqrt; default 0 */
    int samples;                /* rays per pixel, a square n*n; default 1:
                                   one ray through the pixel's centre, as
                                   the model says; the pixel is their mean */
    rt_sampling sampling;       /* default RT_SAMPLING_REGULAR */
    rt_row_callback on_row;     /* optional progress / cancellation */
    rt_cancel *cancel;          /* optional: cancels within one pixel */
    void *user;                 /* passed to on_row */
    rt_render_stats *stats;     /* optional; its size set by the caller
                                   (see rt_render_stats), then every
                                   counter is zeroed and filled */
    rt_kernel_choice kernel;    /* default RT_KERNEL_AUTO */
    rt_accel accel;             /* default RT_ACCEL_AUTO */
    double aperture;        /* thin-lens radius a in scene units; negative
                               (the default): the scene's; 0: the pinhole
                               camera, today's rays exactly; NaN or
                               infinite: refused */
    double focal_distance;  /* f > 0 in scene units; 0 (the default): the
                               scene's (|AO| unless the file sets it);
                               negative, NaN or infinite: refused */
    int width;              /* the image's size in pixels, each in
                               1..RT_MAX_IMAGE_SIDE; 0 (the default): the */
    int height;             /* scene's.  The screen keeps its width 2|AB|
                               and the pixels stay square, so another ratio
                               of width to height shows more or less of the
                               scene above and below (docs/rendering-model.md,
                               "Image size and regions") */
    rt_region region;       /* the part of that image to render; the output
                               image holds just it, and its pixels are those
                               the whole image has there, byte for byte.
                               Zero (the default): the whole image */
    /* Since 0.5: */
    const rt_camera *camera;    /* NULL (the default): the scene's camera;
                                   else this one (rt_scene_look makes one),
                                   its width and height the image's default
                                   size, its aperture and focal distance the
                                   lens's; read during the call only.  Its
                                   vectors must be finite, AB and AC
                                   non-zero, O off the screen (else
                                   RT_ERR_ARGUMENT).  Renders, views and
                                   explanations with other cameras reuse
                                   the scene's kernel and accelerator */
    rt_image_float *linear;     /* NULL (the default): bytes only; else a
                                   float image of the output image's size
                                   that the render also fills with each
                                   pixel's linear colour (the mean of its
                                   samples before rounding, / 255,
                                   unclamped), exactly as the bytes are
                                   rounded from it: rt_channel_to_byte(255.0
                                   * (double)value) is the byte.  Rows the
                                   render writes only.  Refused by the debug
                                   views */
} rt_render_options;

/* Sets size to sizeof(rt_render_options) and the defaults: max_depth 5,
 * all cores, double precision, exact square root, one sample per pixel, no
 * callback, no stats, the fastest kernel, the octree chosen by facet count,
 * the scene's image size, the whole image.  NULL: no-op.  Thread-safe. */
RT_API void rt_render_options_init(rt_render_options *options);

/*
 * The size of the image a render of `scene` with `options` (NULL: the
 * defaults) writes: the region's when one is set, else options->width x
 * options->height (each 0 meaning the scene's).  RT_OK, or RT_ERR_ARGUMENT
 * with the reason in *error (may be NULL) when `scene`, `width` or `height`
 * is NULL, the options' size is wrong, a side is outside
 * 1..RT_MAX_IMAGE_SIDE or the region is empty or reaches outside the
 * image; *width and *height (those given) are then 0.  It reads only the
 * size, width, height and region of the options.  Thread-safe.
 */
RT_API rt_status rt_render_image_size(const rt_scene *scene,
                                      const rt_render_options *options,
                                      int *width, int *height,
                                      rt_error *error);

/*
 * Renders the image (or its region) into `image`, which must have the size
 * rt_render_image_size gives: the scene's width x height by default (see
 * rt_image_init).  Returns RT_OK, RT_ERR_ARGUMENT (no scene or image, the
 * image's size is not the render's, a bad size or region, a negative
 * depth or thread count, samples not a square in 1..1024, an enum value
 * the header does not name - precision, sampling, kernel, accel -, a lens
 * value the fields above refuse, or a bad size of the options; the message
 * names the field and its value), RT_ERR_RANGE (a float render of a
 * scene float cannot hold or resolve: see rt_scene_check_precision),
 * RT_ERR_NOMEM (nothing is rendered) or RT_ERR_CANCELLED (some rows are
 * finished, the others hold whatever they held before); *error (may be
 * NULL) then says what was wrong ("the image is 400 x 300 but the render
 * writes 200 x 100").  Thread-safe as long as no two calls write the same
 * rows of the same image.
 */
RT_API rt_status rt_render(const rt_scene *scene,
                           const rt_render_options *options, rt_image *image,
                           rt_error *error);

/* A float render refuses a scene whose vertices and camera points reach
 * more than this many times the extent of its vertices (the largest side
 * of their bounding box): float's 24 bits then leave steps coarser than
 * 1/2^12 of the scene - a tenth of a pixel in a 400-pixel image of it
 * (docs/accuracy.md, "Float's rule"). */
#define RT_FLOAT_SPREAD_MAX 4096.0

/* A float render refuses a vertex, observer or screen coordinate of
 * magnitude beyond this: the intersection test multiplies differences of
 * coordinates, which overflow float from about 1.3e19 (the square root of
 * FLT_MAX over 2); this leaves a factor of 100 for its error bounds, as
 * RT_MAX_COORDINATE does in double (measured: a ground of half-size 5e18
 * renders exactly in float, one of 1e20 not at all; docs/accuracy.md).
 * Lights may be farther, up to FLT_MAX. */
#define RT_FLOAT_MAX_COORDINATE 1e17

/*
 * RT_OK when a render in `precision` can hold and resolve `scene`;
 * RT_ERR_ARGUMENT for a NULL scene or a precision rt_precision does not
 * name; else RT_ERR_RANGE with the reason in *error (may be NULL): in float, a
 * coordinate beyond FLT_MAX (lights included), a vertex or camera
 * coordinate beyond RT_FLOAT_MAX_COORDINATE, or vertices and camera
 * points reaching beyond RT_FLOAT_SPREAD_MAX times the vertices' extent.
 * Double holds every scene the loader accepts.  Thread-safe.
 */
RT_API rt_status rt_scene_check_precision(const rt_scene *scene,
                                          rt_precision precision,
                                          rt_error *error);

/*
 * Renders rows [row_begin, row_end) of `image` (of the size rt_render
 * takes; with a region, row 0 is the region's top row); other rows are not
 * touched, and on_row reports rows of `image`.  Same results, status and
 * messages as rt_render.  Thread-safe on disjoint bands.
 */
RT_API rt_status rt_render_rows(const rt_scene *scene,
                                const rt_render_options *options,
                                int row_begin, int row_end, rt_image *image,
                                rt_error *error);

/*
 * The real-valued colour carried by `ray` (docs/rendering-model.md, "What a
 * ray sees"), following at
 * most `max_depth` reflections; the direction need not be unit length.
 * The value is not clamped.  A direction that is zero or not finite, or a
 * negative depth, gives black.  `scene` must not be NULL (asserted; black
 * where NDEBUG compiles asserts out).  Thread-safe.
 */
RT_API rt_color rt_trace(const rt_scene *scene, rt_ray ray, int max_depth);

/* The 8-bit value a real channel is written as: clamped to [0, 255] and
 * rounded to nearest, halves away from zero; NaN gives 0.  Thread-safe. */
RT_API unsigned char rt_channel_to_byte(double value);

#ifdef __cplusplus
}
#endif

#endif /* RAYTRACE_RENDER_H */
