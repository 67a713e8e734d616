/*
 * raytrace/scene.h - loading a scene and asking it questions.
 *
 * An rt_scene is an immutable, opaque object built from a `.scn` description
 * (the format is in docs/scene-format.md).  Loading validates everything the
 * renderer relies on: a scene that loads can be rendered, and a scene that
 * cannot be rendered does not load.  Once loaded, a scene is never modified,
 * so every function below that takes a `const rt_scene *` may be called from
 * any number of threads at once.
 *
 * The loader reads from memory (rt_scene_parse); rt_scene_load reads a
 * file first.  Both take rt_load_options (NULL for the defaults).  On
 * failure the out-pointer is set to NULL, nothing is leaked, and the
 * rt_error (if given) says what and where; a NULL where an object or
 * out-pointer is expected is RT_ERR_ARGUMENT.
 *
 * The accessors (rt_scene_get_info, rt_scene_vertex, rt_scene_facet,
 * rt_scene_light, rt_scene_source_at, rt_scene_warning) and the queries
 * (rt_camera_ray, rt_scene_nearest_hit, rt_scene_occluded) return no
 * status: a NULL scene or out-pointer, or an index outside 0..count-1, is a
 * programmer's error that an assert stops in a debug build.  Where NDEBUG
 * compiles asserts out (a Release build) they read nothing out of bounds
 * and give a zero value instead: a zero vertex, a zeroed facet, light or
 * info, a NULL pointer, no hit, not occluded, a zero ray.
 */
#ifndef RAYTRACE_SCENE_H
#define RAYTRACE_SCENE_H

#include "raytrace/export.h"

#include <stddef.h>
#include <stdint.h>

#include "raytrace/image.h"
#include "raytrace/status.h"
#include "raytrace/vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The up axis of the automatic camera of the formats that hold no view
 * (OBJ, PLY; docs/formats.md, "The automatic camera"), and what decided it
 * (rt_scene_info.up_cue). */
typedef enum rt_up_axis {
    RT_UP_AUTO = 0,             /* the file's cue, else +y */
    RT_UP_X, RT_UP_Y, RT_UP_Z,
    RT_UP_NEG_X, RT_UP_NEG_Y, RT_UP_NEG_Z
} rt_up_axis;

typedef enum rt_up_cue {
    RT_UP_CUE_NONE = 0,         /* the file has its own camera */
    RT_UP_CUE_DEFAULT,          /* nothing said: +y, OBJ's usual up */
    RT_UP_CUE_COMMENT,          /* a comment names it (up_cue_line) */
    RT_UP_CUE_EXPORTER,         /* the exporter a comment names writes it
                                   by default (up_cue_line) */
    RT_UP_CUE_OPTION            /* rt_load_options.up_axis */
} rt_up_cue;

/* Limits the loader enforces (docs/scene-format.md). */
#define RT_MAX_IMAGE_SIDE 16384

/* The most lights a scene may have (docs/robustness-input.md): every hit
 * casts one shadow ray per light, so the time of a render grows linearly
 * with them (100 000 lights took 14 minutes at 400 x 400), and the kernel
 * keeps a diffuse term per facet and light.  64 covers the SPD scenes (at
 * most 7) and a grid of 8 x 8 point lights standing for an area light.
 * rt_scene_create and every reader refuse more (RT_ERR_LIMIT). */
#define RT_MAX_LIGHTS 64

typedef struct rt_scene rt_scene;

/* A point light: its position and its colour C_S. */
typedef struct rt_light {
    rt_vec3 position;
    rt_rgb8 color;
} rt_light;

/* A non-fatal remark about the scene, such as a zero-area facet. */
typedef struct rt_warning {
    int line;
    int column;
    char message[RT_ERROR_MESSAGE_SIZE]; /* "path:line:column: warning: ..." */
} rt_warning;

/*
 * The camera after validation (docs/rendering-model.md, "The camera"): the
 * observer, the screen
 * centre A, the right half-width AB (B projected onto the screen plane when
 * the file's B was not perpendicular) and the up half-height AC with
 * |AC| = |AB| and (AB, AC, AO) right-handed.
 */
typedef struct rt_camera {
    rt_vec3 observer;
    rt_vec3 screen_center;  /* A */
    rt_vec3 right;          /* AB, after projection */
    rt_vec3 up;             /* AC */
    int width, height;      /* image size in pixels */
    int b_was_projected;    /* non-zero when the file's B needed projection */
    double aperture;        /* thin-lens radius a >= 0, scene units; 0 for
                               the pinhole camera */
    double focal_distance;  /* f > 0, scene units, along AO from O: the
                               distance that stays sharp (default |AO|) */
} rt_camera;

/*
 * How the structs the library fills grow (rt_scene_info, rt_facet_info
 * here, rt_render_stats in raytrace/render.h), as the option structs do
 * (raytrace/render.h, above rt_render_options): the first field, `size`,
 * is set by the caller to sizeof the struct as it was compiled (`info.size
 * = sizeof info`, or `rt_scene_info info = {.size = sizeof info}`) before
 * each call, and the library keeps it.  New fields are only ever appended.
 * The library fills the fields that lie wholly within `size` and writes
 * nothing beyond it; bytes within `size` past the fields it knows (a
 * program built against a newer header) it sets to zero.  A size of 0 (a
 * struct never set) or one that does not reach the last field of the
 * layout of 0.3, the first with `size`, is a programmer's error: where the
 * function returns a status it is RT_ERR_ARGUMENT with a message giving
 * both sizes; the accessors below assert, and where NDEBUG compiles the
 * assert out they write nothing at all.
 */

/* What a facet record of the file says. */
typedef struct rt_facet_info {
    size_t size;            /* sizeof(rt_facet_info), set by the caller */
    int vertex[3];          /* 0-based indices into the vertex list */
    double reflection;      /* reflection coefficient k in [0, 1] */
    rt_rgb8 color;
    rt_vec3 normal;         /* unit (b-a)x(c-a); zero for a zero-area facet */
    int degenerate;         /* 0, or why no ray ever meets the facet:
                               RT_FACET_ZERO_AREA, RT_FACET_REPEATED */
    int line;               /* line of the record in the source */
    double transparency;    /* t in [0, 1], k + t <= 1 */
    double refractive_index; /* n > 0 (1 when not given) */
    double diffuse;         /* diffuse weight d >= 0 (1 - k - t in .scn) */
    /* Since 0.4 (docs/rendering-model.md, "Smooth shading and
     * highlights"): */
    double highlight;       /* Phong highlight weight s >= 0 (0: none) */
    double highlight_exponent; /* its exponent p >= 1 */
    int smooth;             /* 1: each corner has a vertex normal */
    rt_vec3 vertex_normal[3]; /* unit, per corner, when smooth; else zero */
} rt_facet_info;

/* Values of rt_facet_info.degenerate: facets the renderer leaves out, as
 * no ray can meet them (docs/robustness-input.md, "Facets no ray meets").
 * A repeated facet has the vertex positions of the facet before it that the
 * renderer keeps, in the same order: the tie rule of rt_scene_nearest_hit
 * keeps that earlier one wherever both are met, so the repeat changes no
 * pixel; it only cost every ray there a test. */
#define RT_FACET_ZERO_AREA 1    /* its vertices are collinear */
#define RT_FACET_REPEATED 2     /* an exact repeat of the facet before it */

/* Sizes and settings of a scene. */
typedef struct rt_scene_info {
    size_t size;            /* sizeof(rt_scene_info), set by the caller */
    int width, height;
    int vertex_count;
    int facet_count;        /* as in the file, degenerate ones included */
    int live_facet_count;   /* facets that can be hit: facet_count less the
                               zero-area and repeated ones */
    int reflective_facet_count; /* live facets with reflection k > 0 */
    int warning_count;      /* warnings stored (rt_scene_warning); a warning
                               may stand for many ("... and N more") */
    rt_rgb8 background;
    rt_camera camera;
    int light_count;        /* 1..RT_MAX_LIGHTS; each is rt_scene_light */
    int transparent_facet_count; /* live facets with transparency t > 0 */
    /* Since 0.4: */
    int smooth_facet_count; /* live facets with a normal at each corner */
    int highlight_facet_count;  /* live facets with a highlight s > 0 */
    rt_up_axis up_axis;     /* the automatic camera's up; RT_UP_AUTO when
                               the file has its own camera */
    rt_up_cue up_cue;       /* what chose it */
    int up_cue_line;        /* the comment's line, for a comment's cue */
} rt_scene_info;

/*
 * A facet to build a scene from, with the rendering model's symbols
 * (docs/rendering-model.md) in the comments.  A description zeroed beyond
 * `color` is a handout facet: opaque (t = 0), n = 1, d = 1 - k.
 */
typedef struct rt_facet_desc {
    int vertex[3];          /* 0-based indices into the vertex array */
    double reflection;      /* reflection coefficient k in [0, 1] */
    rt_rgb8 color;
    double transparency;    /* t >= 0, k + t <= 1 */
    double refractive_index; /* n > 0; 0 stands for 1 */
    double diffuse;         /* diffuse weight d >= 0, used when
                               diffuse_given */
    int diffuse_given;      /* 0: d = 1 - k - t (the .scn rule) */
    double highlight;       /* Phong highlight weight s >= 0 (0: none) */
    double highlight_exponent; /* its exponent p >= 1; 0 stands for 1 */
} rt_facet_desc;

/*
 * Everything a scene holds, for building one without a file (the `.scn`
 * loader is itself a client of rt_scene_create).  The arrays are copied.
 */
typedef struct rt_scene_desc {
    rt_vec3 observer;       /* O */
    rt_vec3 screen_center;  /* A */
    rt_vec3 screen_right;   /* B, projected when AB is not perpendicular to AO */
    int width, height;      /* 1..RT_MAX_IMAGE_SIDE */
    const rt_vec3 *vertices;
    int vertex_count;
    const rt_facet_desc *facets;
    int facet_count;
    rt_rgb8 background;
    const rt_light *lights; /* the point lights (copied) */
    int light_count;        /* 1..RT_MAX_LIGHTS */
    double aperture;        /* thin-lens radius a >= 0 (0: pinhole) */
    double focal_distance;  /* f > 0; 0 stands for |AO| */
    const rt_vec3 *normals; /* NULL, or vertex_count vertex normals (copied,
                               normalised): a facet whose three corners
                               have one is smooth; a zero vector stands
                               for none; others must be finite */
    rt_up_axis up_axis;     /* reported by rt_scene_info (a reader's
                               automatic camera); RT_UP_AUTO: none */
    rt_up_cue up_cue;
    int up_cue_line;
} rt_scene_desc;

/*
 * Builds a scene from `desc`, checking the rules of the rendering model
 * (docs/rendering-model.md): finite coordinates, k and t in [0, 1] with
 * k + t <= 1, n > 0, d >= 0, indices in range, sizes, a >= 0, f >= 0, a
 * camera that is not degenerate (RT_ERR_RANGE, RT_ERR_CAMERA), at least
 * one light (RT_ERR_RANGE) and at most RT_MAX_LIGHTS (RT_ERR_LIMIT).  A
 * NULL `desc` or `scene`, a negative count or a missing array is
 * RT_ERR_ARGUMENT.  Messages have no file position;
 * zero-area facets give warnings (the first 8 one by one, then one that
 * counts the others and lists their lines), and exact repeats of the facet
 * before them one warning.  Thread-safe.
 */
RT_API rt_status rt_scene_create(const rt_scene_desc *desc, rt_scene **scene,
                                 rt_error *error);

/* The scene file formats the loader reads. */
typedef enum rt_scene_format {
    RT_SCENE_FORMAT_AUTO = 0,   /* from the name's extension */
    RT_SCENE_FORMAT_SCN = 1,    /* the course's .scn (docs/scene-format.md) */
    RT_SCENE_FORMAT_NFF = 2,    /* Eric Haines' Neutral File Format (.nff) */
    RT_SCENE_FORMAT_OBJ = 3,    /* Wavefront OBJ (.obj) with its .mtl */
    RT_SCENE_FORMAT_PLY = 4     /* Stanford polygon files (.ply), ASCII or
                                   binary */
} rt_scene_format;

/* Largest input a loader reads, in bytes (1 GiB): line and column numbers
 * stay far from int's range, and a stream with no end (/dev/zero) is
 * refused instead of filling the memory. */
#define RT_MAX_SCENE_BYTES ((size_t)1 << 30)

/* Largest magnitude of a vertex, observer or screen coordinate: the
 * intersection test multiplies differences of coordinates, which overflow
 * from about 6.7e153 (the square root of DBL_MAX over 2); this leaves a
 * factor of 60 for its error bounds.  Lights may be farther: a light's
 * position only gives a direction and the end of a shadow ray. */
#define RT_MAX_COORDINATE 1e152

/* A cancellation flag (raytrace/render.h); loads poll it too. */
typedef struct rt_cancel rt_cancel;

/*
 * A file a scene refers to (an OBJ's material library), as a resolver hands
 * it to the loader.  The loader takes ownership of `data` and `name` (both
 * from malloc; it frees them with free).
 */
typedef struct rt_resolved_file {
    char *data;             /* the file's bytes (need not be NUL-terminated) */
    size_t length;
    char *name;             /* how messages name it (a path, usually),
                               as raw bytes: messages escape its control
                               bytes when they show it */
    uint64_t device;        /* the file's identity (st_dev, st_ino): one */
    uint64_t inode;         /* file is read once however it is spelt, and
                               programs refuse to write over it; 0 and 0
                               for bytes that are no file (memory) */
} rt_resolved_file;

/*
 * Opens the file `reference` (NUL-terminated, as the scene spells it, with
 * the format's escapes already removed) that the scene called `scene_name`
 * (the name given to the load; may be NULL) refers to, taking at most
 * `limit` bytes.  Returns RT_OK with *file filled, or a status with *error
 * filled and *file untouched; a refusal's message names `reference` and
 * never quotes any file's content.  Called on the loading thread.
 */
typedef rt_status (*rt_resolve_func)(void *user, const char *scene_name,
                                     const char *reference, size_t limit,
                                     rt_resolved_file *file, rt_error *error);

/*
 * The default resolver of rt_scene_load (docs/robustness-input.md,
 * "Files a scene names"): `reference` is taken relative to the folder of
 * `scene_name` (the current folder when it has no slash or is NULL) and
 * must stay inside it: no absolute path, no `..` component, no symbolic
 * link leading out (links that stay inside are followed); it is walked
 * one component at a time from the folder, so nothing outside is looked
 * up, and refusals there do not say whether the file exists.  The file
 * must be a regular one (checked before it is opened, and on the
 * descriptor after), opened without blocking and without becoming a
 * controlling terminal, of at most `limit` bytes.  On success *file holds
 * the bytes, the folder of `scene_name` joined with `reference` as its
 * name (control bytes written \xHH) and the file's device and inode.
 * `user` is unused (NULL).  Thread-safe.
 */
RT_API rt_status rt_resolve_in_folder(void *user, const char *scene_name,
                                      const char *reference, size_t limit,
                                      rt_resolved_file *file,
                                      rt_error *error);

/* How to read a scene, for the formats that leave room.  It grows by the
 * rule of raytrace/render.h: `size` first, set by rt_load_options_init;
 * fields beyond it keep their defaults; 0 or a size larger than the
 * library's is refused with RT_ERR_ARGUMENT. */
typedef struct rt_load_options {
    size_t size;                /* sizeof(rt_load_options); set by
                                   rt_load_options_init */
    rt_scene_format format;     /* default RT_SCENE_FORMAT_AUTO */
    double tessellation;        /* NFF spheres, cylinders and cones: the
                                   largest distance between the surface and
                                   its facets, relative to the radius, in
                                   (0, 1); 0: the default (docs/formats.md) */
    int width, height;          /* the image size for formats that give none
                                   (OBJ); 0: the default */
    /* A view that overrides or completes the file's camera, each part on
     * its own (the others keep the file's values): */
    int look_from_given, look_at_given, up_given, fov_given;
    rt_vec3 look_from;          /* the observer O */
    rt_vec3 look_at;            /* the screen centre A lies on O -> look_at,
                                   at its distance (the default focus) */
    rt_vec3 up;                 /* up in the image (need not be unit) */
    double fov;                 /* horizontal field of view in degrees,
                                   in (0, 180) */
    const rt_light *lights;     /* when light_count > 0: the lights, in place
                                   of the file's (copied) */
    int light_count;
    rt_cancel *cancel;          /* optional: the load polls it and returns
                                   RT_ERR_CANCELLED soon after it is raised */
    rt_resolve_func resolve;    /* opens the files the scene names; NULL:
                                   rt_resolve_in_folder for rt_scene_load,
                                   no file at all for a parse from memory */
    void *resolve_user;         /* passed to resolve */
    /* Since 0.4: */
    rt_up_axis up_axis;         /* the automatic camera's up (OBJ, PLY);
                                   RT_UP_AUTO: from the file's cue, else
                                   +y (docs/formats.md) */
} rt_load_options;

/* Sets size to sizeof(rt_load_options) and the defaults above.  NULL:
 * no-op.  Thread-safe. */
RT_API void rt_load_options_init(rt_load_options *options);

/* The format a path's extension names, case-insensitively (.scn, .nff,
 * .obj, .ply); RT_ERR_FORMAT for another or none (*format untouched), with
 * a message naming the path and listing the formats in *error (may be
 * NULL).  Thread-safe. */
RT_API rt_status rt_scene_format_from_path(const char *path,
                                           rt_scene_format *format,
                                           rt_error *error);

/* The lower-case name of a format ("scn", "nff", "obj", "ply"; "auto";
 * "unknown" for a value the enum does not name).  Thread-safe. */
RT_API const char *rt_scene_format_name(rt_scene_format format);

/*
 * Reads text[0..length) (no NUL needed) as a number of the scene format
 * (docs/scene-format.md, "Values"): an optional sign, digits with an
 * optional decimal point, an optional exponent (`-1.5`, `.5`, `2.`,
 * `1e-9`), at most 256 characters, in the C locale whatever the caller's.
 * A value below the smallest double rounds to the nearest one (a subnormal,
 * or zero), as the readers take it.  Returns RT_OK with *value set;
 * RT_ERR_SYNTAX for any other text (white space, hexadecimal `0x10`, `1e`,
 * an empty string); RT_ERR_RANGE for `nan`, `inf` and a value beyond a
 * double's range (`1e999`); RT_ERR_LIMIT for more than 256 characters;
 * RT_ERR_ARGUMENT for a NULL text or value; RT_ERR_NOMEM; each with the
 * reason in *error (may be NULL: "expected a number, found `0x10`").
 * *value is untouched on failure.  For the programs' command-line numbers,
 * so that they follow the scene files' rule; each call sets up a C locale
 * (not for bulk reading).  Thread-safe.
 */
RT_API rt_status rt_scene_read_number(const char *text, size_t length,
                                      double *value, rt_error *error);

/*
 * Parses a scene in any format from `length` bytes at `text` (no
 * terminating NUL needed).  `name` names the input in messages as the
 * file name ("<memory>" when NULL) and is what the options' resolver
 * locates the files the scene names from (an OBJ's material libraries);
 * without a resolver no file is read (a warning says so).  With
 * RT_SCENE_FORMAT_AUTO (the default) the format comes from `name`'s
 * extension (.scn when it has none or names no format: here the name is
 * a label; rt_scene_load refuses a file's unknown extension).  Numbers are read
 * in the C locale whatever the process's locale.  `options` may be NULL
 * (the defaults, as rt_load_options_init sets them).  Every field of the
 * options is checked whatever the format reads, and one outside its
 * domain is RT_ERR_ARGUMENT naming it: a size of 0 or beyond the
 * library's, a format the enum does not name, a tessellation outside
 * (0, 1) but 0, a side outside 1..RT_MAX_IMAGE_SIDE but 0, a given field
 * of view outside (0, 180), a given look-from, look-at or up that is not
 * finite, a negative light count or lights without an array.  NULL `text`
 * with a non-zero length, or a NULL `scene`, is RT_ERR_ARGUMENT too.  The
 * scene's sources (rt_scene_source_at) are the files the resolver gave.
 * Thread-safe.
 */
RT_API rt_status rt_scene_parse(const char *text, size_t length,
                                const char *name,
                                const rt_load_options *options,
                                rt_scene **scene, rt_error *error);

/* Reads the file at `path` (at most RT_MAX_SCENE_BYTES, and stopping at
 * the first NUL byte, which no text scene file holds, except for PLY,
 * whose body may be binary; FIFOs and terminals are read to their end) and
 * parses it as rt_scene_parse does, in the format its extension names by
 * default (see rt_scene_format_from_path; .scn when it has no extension;
 * RT_ERR_FORMAT, before anything is read, for one that names no format); messages name `path`.  The files it names are read
 * by the options' resolver, rt_resolve_in_folder when they give none (or
 * `options` is NULL).  The scene's first source is the file at `path`.
 * A NULL `path` or `scene` is RT_ERR_ARGUMENT.  Thread-safe. */
RT_API rt_status rt_scene_load(const char *path,
                               const rt_load_options *options,
                               rt_scene **scene, rt_error *error);

/* Frees a scene.  rt_scene_destroy(NULL) does nothing.  Not thread-safe on
 * the same scene (no other call may be using it). */
RT_API void rt_scene_destroy(rt_scene *scene);

/* Fills `info`, whose size the caller has set (the rule above rt_facet_info;
 * a zeroed info, size kept, for a NULL scene where asserts are compiled
 * out).  Thread-safe. */
RT_API void rt_scene_get_info(const rt_scene *scene, rt_scene_info *info);

/* The i-th vertex (0-based, i < vertex_count; else asserted, or the zero
 * vector where NDEBUG is defined).  Thread-safe. */
RT_API rt_vec3 rt_scene_vertex(const rt_scene *scene, int i);

/* The i-th vertex's unit normal, or the zero vector when it has none (and
 * for a bad index: asserted as rt_scene_vertex's).  Thread-safe. */
RT_API rt_vec3 rt_scene_vertex_normal(const rt_scene *scene, int i);

/* The i-th facet record (0-based, i < facet_count; else asserted, or a
 * zeroed *facet, size kept, where NDEBUG is defined) into `facet`, whose
 * size the caller has set (the rule above rt_facet_info).  Thread-safe. */
RT_API void rt_scene_facet(const rt_scene *scene, int i, rt_facet_info *facet);

/* The i-th light (0-based, i < light_count; 0 is the first; else asserted,
 * or a zeroed *light where NDEBUG is defined).  Thread-safe. */
RT_API void rt_scene_light(const rt_scene *scene, int i, rt_light *light);

/* A file a load read: the scene file itself (first, when the scene was
 * loaded from a path) and every file it names that was read, each once
 * however often and under whatever names the scene gave it. */
typedef struct rt_scene_source {
    const char *name;       /* its path as the load was given it (raw
                               bytes: escape control bytes before
                               printing); owned by the scene */
    uint64_t device;        /* identity (st_dev, st_ino); 0 and 0 when */
    uint64_t inode;         /* unknown (standard input, memory) */
    size_t bytes;           /* how many bytes were read */
} rt_scene_source;

/* How many files the load of `scene` read (0 for a scene built from
 * memory without a resolver, or by rt_scene_create).  Thread-safe. */
RT_API int rt_scene_source_count(const rt_scene *scene);

/* The i-th of them (0-based, i < rt_scene_source_count; else asserted, or
 * NULL where NDEBUG is defined), owned by the scene.  Thread-safe. */
RT_API const rt_scene_source *rt_scene_source_at(const rt_scene *scene,
                                                 int i);

/* The i-th warning (0-based, i < warning_count; else asserted, or NULL
 * where NDEBUG is defined).  Thread-safe. */
RT_API const rt_warning *rt_scene_warning(const rt_scene *scene, int i);

/* The primary ray of pixel (column i, row j from the top) of the camera's
 * width x height image, as docs/rendering-model.md ("The camera") defines
 * it: from the observer through the pixel's centre; direction not
 * normalised; i and j outside the image give rays beyond the screen.
 * Thread-safe. */
RT_API rt_ray rt_camera_ray(const rt_camera *camera, int i, int j);

/*
 * Since 0.5: a view of a scene, as rt-export's --look-from, --look-at, --up
 * and --fov give it when all four are given (docs/rendering-model.md, "The
 * camera"; docs/viewer.md, "Moving the camera").
 */
typedef struct rt_look {
    rt_vec3 look_from;      /* the observer O, scene units */
    rt_vec3 look_at;        /* the screen centre A */
    rt_vec3 up;             /* up in the image: any length, not along A - O */
    double fov;             /* horizontal field of view in degrees, in
                               (0, 180) */
} rt_look;

/*
 * The camera `scene` would have had, had it been loaded with the four view
 * options of `look` (rt_load_options' look_from, look_at, up and fov, all
 * given), bit for bit: observer O = look_from, screen centre A = look_at, B =
 * A + |AO| tan(fov / 2) unit((A - O) x up), then the camera of those three
 * points; the scene's image size, aperture and focal distance (|AO| of the
 * new camera unless the file set one).  *screen_point (may be NULL)
 * receives that B: the third point of a .scn file's first line that gives
 * this camera.  Returns RT_OK, or RT_ERR_ARGUMENT with the reason in
 * *error (may be NULL) for a NULL argument, a point that is not finite, a
 * fov outside (0, 180), look_at equal to look_from or up along the view;
 * *camera is then untouched.  Thread-safe.
 */
RT_API rt_status rt_scene_look(const rt_scene *scene, const rt_look *look,
                               rt_camera *camera, rt_vec3 *screen_point,
                               rt_error *error);

/* The look of `camera`: from its observer at its screen centre, up along
 * its up half-height AC, fov 2 atan(|AB| / |AO|) in degrees.  rt_scene_look
 * of it gives the same view (to rounding: not the same bits).  NULL
 * arguments: no-op.  Thread-safe. */
RT_API void rt_camera_get_look(const rt_camera *camera, rt_look *look);

/* A ray-facet intersection. */
typedef struct rt_hit {
    double t;               /* ray parameter: origin + t * direction */
    int facet;              /* 0-based index of the facet record */
    rt_vec3 point;          /* the hit point */
    rt_vec3 normal;         /* unit normal facing the ray's origin */
} rt_hit;

/*
 * Nearest hit of `ray` for t in (0, t_max) over every facet (brute force),
 * using the watertight test of docs/robustness.md.  Among hits at exactly
 * the same t the facet that comes first in the file wins.  Returns non-zero
 * and fills `hit` when there is one.  Thread-safe.
 */
RT_API int rt_scene_nearest_hit(const rt_scene *scene, rt_ray ray,
                                double t_max, rt_hit *hit);

/*
 * Non-zero when some facet lies strictly between `from` and `to` (an any-hit
 * query that stops at the first blocker).  `skip_facet` (or -1) is a facet to
 * ignore: the one `from` lies on.  Thread-safe.
 */
RT_API int rt_scene_occluded(const rt_scene *scene, rt_vec3 from, rt_vec3 to,
                             int skip_facet);

/* What a handout .scn file cannot hold (rt_scene_write_scn's *dropped,
 * bits): lights beyond the first, transparency and refractive indices, a
 * lens, diffuse weights other than 1 - k - t (as NFF's Kd), and since 0.4
 * vertex normals and highlights. */
#define RT_SCN_DROPPED_LIGHTS 1u
#define RT_SCN_DROPPED_TRANSPARENCY 2u
#define RT_SCN_DROPPED_LENS 4u
#define RT_SCN_DROPPED_DIFFUSE 8u
#define RT_SCN_DROPPED_NORMALS 16u
#define RT_SCN_DROPPED_HIGHLIGHTS 32u

/*
 * Writes `scene` as a .scn file to the sink: the handout's records only,
 * or with `extended` also the optional lens, transparency, diffuse weight,
 * highlight, vertex normal and further-light values (docs/scene-format.md),
 * each only where the scene needs it.  Numbers are written with 17 significant
 * digits, so reading the file back gives the same doubles and the same
 * picture.  *dropped (may be NULL) receives the RT_SCN_DROPPED_ bits of
 * what the file could not hold.  Returns RT_OK, RT_ERR_IO (the sink
 * refused) or RT_ERR_ARGUMENT.  Thread-safe.
 */
RT_API rt_status rt_scene_write_scn(const rt_scene *scene, int extended,
                                    rt_write_func write, void *user,
                                    unsigned *dropped, rt_error *error);

/* The same saved at `path` by the rule of raytrace/image.h (atomic
 * replacement, streams written directly), with `options` as rt_image_save
 * takes them (NULL: the defaults, which leave the signal mask alone).
 * Thread-safe on distinct paths. */
RT_API rt_status rt_scene_save_scn(const rt_scene *scene, const char *path,
                                   int extended, unsigned *dropped,
                                   const rt_save_options *options,
                                   rt_error *error);

#ifdef __cplusplus
}
#endif

#endif /* RAYTRACE_SCENE_H */
