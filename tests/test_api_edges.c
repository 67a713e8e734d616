/*
 * test_api_edges.c - every public function that returns a status, at the
 * edges of its domain: NULL where an object is expected, and values
 * outside what its header allows.
 *
 * The rule (docs/api.md, "Arguments at the edges"): such a call answers
 * RT_ERR_ARGUMENT (RT_ERR_FORMAT for an image format that names none, as
 * its header says), fills the rt_error with a non-empty message that names
 * the field, and accepts a NULL rt_error too.  The tables below list every
 * RT_API function of include/raytrace/ that returns a status
 * (rt_resolve_in_folder is declared there but not yet defined, so it
 * cannot be called), and the NULL no-ops of those that return none; the
 * accessors' asserts are test_api_accessors.c's.  It runs in the sanitizer
 * pass like every suite.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static const char ppm_text[] = "P3\n1 1\n255\n1 2 3\n";

/* What the calls of the tables use: a scene, an image of its size, a
 * stream, a cancellation flag's place, outputs to fill. */
static rt_scene *scene;
static rt_image image;
static FILE *sink_file;

static void setup(void)
{
    ck_assert_int_eq(rt_scene_parse(rt_test_centred_facet_scene,
                                    strlen(rt_test_centred_facet_scene), NULL,
                                    NULL, &scene, NULL), RT_OK);
    ck_assert_int_eq(rt_image_init(&image, 40, 30, NULL), RT_OK);
    sink_file = fopen("/dev/null", "wb");
    ck_assert_ptr_nonnull(sink_file);
}

static void teardown(void)
{
    rt_scene_destroy(scene);
    rt_image_release(&image);
    fclose(sink_file);
}

static int sink(void *user, const void *data, size_t size)
{
    (void)user, (void)data, (void)size;
    return 1;
}

/* ------------------------------------------------------------------ */
/* Statuses                                                             */

/* One call at an edge: `call` makes it with the given error (which may
 * be NULL) and returns its status. */
typedef struct status_case {
    const char *what;
    rt_status expected;
    rt_status (*call)(rt_error *error);
} status_case;

#define CASE(name, expected, expression)                                     \
    static rt_status name(rt_error *error)                                   \
    {                                                                        \
        return (expression);                                                 \
    }
#define ROW(name, expected, expression) {#expression, expected, name},

/* Outputs the calls fill (they must not be written on failure beyond
 * what the header says; only the status is checked here). */
static rt_image out_image;
static rt_scene *out_scene;
static rt_ray_tree *out_tree;
static rt_image_format out_image_format;
static rt_scene_format out_scene_format;
static int out_width, out_height;
/* Load options as rt_load_options_init sets them (size, then zeros). */
static const rt_load_options defaults = {sizeof(rt_load_options)};

static rt_image no_pixels(void)
{
    return (rt_image){40, 30, 120, NULL};
}

static rt_image narrow_stride(void)
{
    rt_image view = image;
    view.stride = 3 * 40 - 1;
    return view;
}

static rt_image wrong_size(void)
{
    rt_image view = image;
    view.width = 39;
    return view;
}

static rt_status render_into(rt_image view, rt_error *error)
{
    return rt_render(scene, NULL, &view, error);
}

static rt_status view_into(rt_image view, rt_error *error)
{
    return rt_render_view(scene, NULL, RT_VIEW_NORMAL, 0, &view, error);
}

static rt_status save_view(rt_image view, rt_error *error)
{
    return rt_image_save("/dev/null", &view, RT_IMAGE_P6, NULL, error);
}

/* Save options of `size` bytes, the rest their defaults. */
static rt_save_options save_options_of(size_t size)
{
    rt_save_options options;
    rt_save_options_init(&options);
    options.size = size;
    return options;
}

static rt_status save_sized(size_t size, rt_error *error)
{
    rt_save_options options = save_options_of(size);
    return rt_image_save("/dev/null", &image, RT_IMAGE_P6, &options, error);
}

static rt_status check_sized(size_t size, rt_error *error)
{
    rt_save_options options = save_options_of(size);
    return rt_image_save_check("/dev/null", &options, error);
}

static rt_status save_scene_sized(size_t size, rt_error *error)
{
    rt_save_options options = save_options_of(size);
    return rt_scene_save_scn(scene, "/dev/null", 0, NULL, &options, error);
}

#define NULL_CASES(X)                                                        \
    /* raytrace/image.h */                                                   \
    X(n1, RT_ERR_ARGUMENT, rt_image_init(NULL, 4, 4, error))                 \
    X(n2, RT_ERR_ARGUMENT,                                                   \
      rt_image_format_from_path(NULL, &out_image_format, error))             \
    X(n3, RT_ERR_ARGUMENT, rt_image_format_from_path("x.png", NULL, error))  \
    X(n4, RT_ERR_ARGUMENT,                                                   \
      rt_image_write_to(NULL, NULL, &image, RT_IMAGE_P6, error))             \
    X(n5, RT_ERR_ARGUMENT,                                                   \
      rt_image_write_to(sink, NULL, NULL, RT_IMAGE_P6, error))               \
    X(n6, RT_ERR_ARGUMENT,                                                   \
      rt_image_write_file(NULL, &image, RT_IMAGE_P6, error))                 \
    X(n7, RT_ERR_ARGUMENT,                                                   \
      rt_image_write_file(sink_file, NULL, RT_IMAGE_P6, error))              \
    X(n8, RT_ERR_ARGUMENT,                                                   \
      rt_image_save(NULL, &image, RT_IMAGE_P6, NULL, error))                 \
    X(n9, RT_ERR_ARGUMENT,                                                   \
      rt_image_save("", &image, RT_IMAGE_P6, NULL, error))                   \
    X(n10, RT_ERR_ARGUMENT,                                                  \
      rt_image_save("/dev/null", NULL, RT_IMAGE_P6, NULL, error))            \
    X(n11, RT_ERR_ARGUMENT, save_view(no_pixels(), error))                   \
    X(n12, RT_ERR_ARGUMENT,                                                  \
      rt_image_save_check(NULL, NULL, error))                                \
    X(n13, RT_ERR_ARGUMENT,                                                  \
      rt_image_save_check("", NULL, error))                                  \
    X(n14, RT_ERR_ARGUMENT,                                                  \
      rt_image_write_to(NULL, NULL, &image, RT_IMAGE_P3, error))             \
    X(n15, RT_ERR_ARGUMENT,                                                  \
      rt_image_write_to(sink, NULL, NULL, RT_IMAGE_P3, error))               \
    X(n16, RT_ERR_ARGUMENT,                                                  \
      rt_image_write_file(NULL, &image, RT_IMAGE_P3, error))                 \
    X(n17, RT_ERR_ARGUMENT,                                                  \
      rt_image_write_file(sink_file, NULL, RT_IMAGE_P3, error))              \
    X(n18, RT_ERR_ARGUMENT,                                                  \
      rt_image_save(NULL, &image, RT_IMAGE_P3, NULL, error))                 \
    X(n19, RT_ERR_ARGUMENT,                                                  \
      rt_image_save("/dev/null", NULL, RT_IMAGE_P3, NULL, error))            \
    X(n20, RT_ERR_ARGUMENT, rt_ppm_parse(NULL, 10, NULL, &out_image, error)) \
    X(n21, RT_ERR_ARGUMENT,                                                  \
      rt_ppm_parse(ppm_text, sizeof ppm_text - 1, NULL, NULL, error))        \
    X(n22, RT_ERR_ARGUMENT, rt_ppm_load(NULL, &out_image, error))            \
    X(n23, RT_ERR_ARGUMENT, rt_ppm_load("/dev/null", NULL, error))           \
    /* raytrace/render.h */                                                  \
    X(n24, RT_ERR_ARGUMENT, rt_cancel_create(NULL, error))                   \
    X(n25, RT_ERR_ARGUMENT,                                                  \
      rt_render_image_size(NULL, NULL, &out_width, &out_height, error))      \
    X(n26, RT_ERR_ARGUMENT,                                                  \
      rt_render_image_size(scene, NULL, NULL, &out_height, error))           \
    X(n27, RT_ERR_ARGUMENT,                                                  \
      rt_render_image_size(scene, NULL, &out_width, NULL, error))            \
    X(n28, RT_ERR_ARGUMENT, rt_render(NULL, NULL, &image, error))            \
    X(n29, RT_ERR_ARGUMENT, rt_render(scene, NULL, NULL, error))             \
    X(n30, RT_ERR_ARGUMENT, render_into(no_pixels(), error))                 \
    X(n31, RT_ERR_ARGUMENT,                                                  \
      rt_scene_check_precision(NULL, RT_PRECISION_FLOAT, error))             \
    X(n32, RT_ERR_ARGUMENT,                                                  \
      rt_scene_check_precision(NULL, RT_PRECISION_DOUBLE, error))            \
    X(n33, RT_ERR_ARGUMENT, rt_render_rows(NULL, NULL, 0, 1, &image, error)) \
    X(n34, RT_ERR_ARGUMENT, rt_render_rows(scene, NULL, 0, 1, NULL, error))  \
    /* raytrace/scene.h */                                                   \
    X(n35, RT_ERR_ARGUMENT, rt_scene_create(NULL, &out_scene, error))        \
    X(n36, RT_ERR_ARGUMENT,                                                  \
      rt_scene_create(&(rt_scene_desc){0}, NULL, error))                     \
    X(n37, RT_ERR_ARGUMENT,                                                  \
      rt_scene_parse(NULL, 5, NULL, NULL, &out_scene, error))                \
    X(n38, RT_ERR_ARGUMENT,                                                  \
      rt_scene_parse(rt_test_centred_facet_scene,                            \
                     strlen(rt_test_centred_facet_scene), NULL, &defaults,   \
                     NULL, error))                                           \
    X(n39, RT_ERR_ARGUMENT,                                                  \
      rt_scene_load(NULL, &defaults, &out_scene, error))                     \
    X(n40, RT_ERR_ARGUMENT, rt_scene_load("x.scn", &defaults, NULL, error))  \
    X(n41, RT_ERR_ARGUMENT,                                                  \
      rt_scene_format_from_path(NULL, &out_scene_format, error))             \
    X(n42, RT_ERR_ARGUMENT, rt_scene_format_from_path("a.scn", NULL, error)) \
    X(n43, RT_ERR_ARGUMENT,                                                  \
      rt_scene_parse(NULL, 5, "a.nff", NULL, &out_scene, error))             \
    X(n44, RT_ERR_ARGUMENT,                                                  \
      rt_scene_parse(NULL, 5, "a.obj", NULL, &out_scene, error))             \
    X(n45, RT_ERR_ARGUMENT,                                                  \
      rt_scene_parse(rt_test_centred_facet_scene, 5, NULL, NULL, NULL,       \
                     error))                                                 \
    X(n46, RT_ERR_ARGUMENT, rt_scene_load(NULL, NULL, &out_scene, error))    \
    X(n47, RT_ERR_ARGUMENT, rt_scene_load("x.scn", NULL, NULL, error))       \
    X(n48, RT_ERR_ARGUMENT,                                                  \
      rt_scene_write_scn(NULL, 0, sink, NULL, NULL, error))                  \
    X(n49, RT_ERR_ARGUMENT,                                                  \
      rt_scene_write_scn(scene, 0, NULL, NULL, NULL, error))                 \
    X(n50, RT_ERR_ARGUMENT,                                                  \
      rt_scene_save_scn(NULL, "/dev/null", 0, NULL, NULL, error))            \
    X(n51, RT_ERR_ARGUMENT,                                                  \
      rt_scene_save_scn(scene, NULL, 0, NULL, NULL, error))                  \
    /* raytrace/explain.h */                                                 \
    X(n52, RT_ERR_ARGUMENT,                                                  \
      rt_explain_pixel(NULL, NULL, 0, 0, -1, &out_tree, error))              \
    X(n53, RT_ERR_ARGUMENT,                                                  \
      rt_explain_pixel(scene, NULL, 0, 0, -1, NULL, error))                  \
    X(n54, RT_ERR_ARGUMENT,                                                  \
      rt_render_view(NULL, NULL, RT_VIEW_NORMAL, 0, &image, error))          \
    X(n55, RT_ERR_ARGUMENT,                                                  \
      rt_render_view(scene, NULL, RT_VIEW_NORMAL, 0, NULL, error))           \
    X(n56, RT_ERR_ARGUMENT, view_into(no_pixels(), error))

#define RANGE_CASES(X)                                                       \
    X(r1, RT_ERR_ARGUMENT, rt_image_init(&out_image, 0, 4, error))           \
    X(r2, RT_ERR_ARGUMENT,                                                   \
      rt_image_init(&out_image, 4, RT_MAX_IMAGE_SIDE + 1, error))            \
    X(r3, RT_ERR_FORMAT,                                                     \
      rt_image_write_to(sink, NULL, &image, (rt_image_format)99, error))     \
    X(r4, RT_ERR_FORMAT,                                                     \
      rt_image_write_file(sink_file, &image, (rt_image_format)-1, error))    \
    X(r5, RT_ERR_FORMAT,                                                     \
      rt_image_save("/dev/null", &image, (rt_image_format)99, NULL, error))  \
    X(r6, RT_ERR_ARGUMENT, save_view(narrow_stride(), error))                \
    X(r7, RT_ERR_FORMAT,                                                     \
      rt_image_write_to(sink, NULL, &image, (rt_image_format)5, error))      \
    X(r8, RT_ERR_FORMAT,                                                     \
      rt_image_write_file(sink_file, &image, (rt_image_format)4, error))     \
    X(r9, RT_ERR_FORMAT,                                                     \
      rt_image_save("/dev/null", &image, (rt_image_format)0, NULL, error))   \
    X(sv1, RT_ERR_ARGUMENT, save_sized(0, error))                            \
    X(sv2, RT_ERR_ARGUMENT, save_sized(sizeof(rt_save_options) + 8, error))  \
    X(sv3, RT_ERR_ARGUMENT, check_sized(0, error))                           \
    X(sv4, RT_ERR_ARGUMENT,                                                  \
      save_scene_sized(sizeof(rt_save_options) + 1, error))                  \
    X(r10, RT_ERR_ARGUMENT,                                                  \
      rt_scene_check_precision(scene, (rt_precision)7, error))               \
    X(r11, RT_ERR_ARGUMENT,                                                  \
      rt_scene_check_precision(scene, (rt_precision)-1, error))              \
    X(r12, RT_ERR_ARGUMENT, rt_render_rows(scene, NULL, -1, 1, &image, error))\
    X(r13, RT_ERR_ARGUMENT, rt_render_rows(scene, NULL, 0, 31, &image, error))\
    X(r14, RT_ERR_ARGUMENT, rt_render_rows(scene, NULL, 2, 1, &image, error))\
    X(r15, RT_ERR_ARGUMENT, render_into(narrow_stride(), error))             \
    X(r16, RT_ERR_ARGUMENT, render_into(wrong_size(), error))                \
    X(r17, RT_ERR_ARGUMENT, view_into(narrow_stride(), error))               \
    X(r18, RT_ERR_ARGUMENT, view_into(wrong_size(), error))                  \
    X(r19, RT_ERR_ARGUMENT,                                                  \
      rt_explain_pixel(scene, NULL, -1, 0, -1, &out_tree, error))            \
    X(r20, RT_ERR_ARGUMENT,                                                  \
      rt_explain_pixel(scene, NULL, 40, 0, -1, &out_tree, error))            \
    X(r21, RT_ERR_ARGUMENT,                                                  \
      rt_explain_pixel(scene, NULL, 0, 30, -1, &out_tree, error))            \
    X(r22, RT_ERR_ARGUMENT,                                                  \
      rt_explain_pixel(scene, NULL, 0, 0, 1, &out_tree, error))              \
    X(r23, RT_ERR_ARGUMENT,                                                  \
      rt_explain_pixel(scene, NULL, 0, 0, -2, &out_tree, error))             \
    X(r24, RT_ERR_ARGUMENT,                                                  \
      rt_render_view(scene, NULL, (rt_debug_view)0, 0, &image, error))       \
    X(r25, RT_ERR_ARGUMENT,                                                  \
      rt_render_view(scene, NULL, (rt_debug_view)99, 0, &image, error))      \
    X(r26, RT_ERR_ARGUMENT,                                                  \
      rt_render_view(scene, NULL, RT_VIEW_SHADOW, 1, &image, error))         \
    X(r27, RT_ERR_ARGUMENT,                                                  \
      rt_render_view(scene, NULL, RT_VIEW_NS, -1, &image, error))            \
    X(r34, RT_ERR_ARGUMENT,                                                  \
      rt_scene_create(&(rt_scene_desc){.width = 4, .height = 4,              \
                                       .vertex_count = -1},                  \
                      &out_scene, error))                                    \
    X(r35, RT_ERR_ARGUMENT,                                                  \
      rt_scene_create(&(rt_scene_desc){.width = 4, .height = 4,              \
                                       .facet_count = 2},                    \
                      &out_scene, error))

NULL_CASES(CASE)
RANGE_CASES(CASE)

static const status_case null_cases[] = {NULL_CASES(ROW)};
static const status_case range_cases[] = {RANGE_CASES(ROW)};

/* Runs each case twice: with an rt_error, which must carry the status and
 * a message, and with NULL. */
static void run_cases(const status_case *cases, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        const status_case *c = &cases[i];
        rt_error error;
        memset(&error, 0, sizeof error);
        rt_status status = c->call(&error);
        ck_assert_msg(status == c->expected, "%s returned %s, expected %s",
                      c->what, rt_status_string(status),
                      rt_status_string(c->expected));
        ck_assert_msg(error.status == status, "%s: the rt_error says %s",
                      c->what, rt_status_string(error.status));
        ck_assert_msg(error.message[0] != '\0',
                      "%s left the message empty", c->what);
        ck_assert_msg(memchr(error.message, '\0', sizeof error.message),
                      "%s: the message is not terminated", c->what);
        status = c->call(NULL);
        ck_assert_msg(status == c->expected, "%s with a NULL rt_error "
                      "returned %s", c->what, rt_status_string(status));
    }
}

START_TEST(every_status_function_refuses_null_with_argument_and_a_message)
{
    run_cases(null_cases, sizeof null_cases / sizeof null_cases[0]);
}
END_TEST

START_TEST(out_of_range_values_are_refused_with_their_status_and_a_message)
{
    run_cases(range_cases, sizeof range_cases / sizeof range_cases[0]);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Render options                                                       */

/* A field of rt_render_options out of its domain, and a word the refusal
 * names it by. */
typedef struct option_edit {
    const char *what;
    const char *word;
    void (*edit)(rt_render_options *options);
} option_edit;

static rt_region region(int x0, int y0, int x1, int y1)
{
    return (rt_region){x0, y0, x1, y1};
}

/* Stats whose size the caller set to `size` (0 or short of the layout
 * of 0.3 are refused before any work). */
static rt_render_stats *stats_of_size(size_t size)
{
    static rt_render_stats stats;
    stats.size = size;
    return &stats;
}

#define EDIT(name, word, statement)                                          \
    static void name(rt_render_options *o) { statement; }
#define EDIT_ROW(name, word, statement) {#statement, word, name},

#define OPTION_EDITS(X)                                                      \
    X(e1, "bytes", o->size = 0)                                              \
    X(e2, "bytes", o->size = sizeof *o + 8)                                  \
    X(e3, "depth", o->max_depth = -1)                                        \
    X(e4, "threads", o->threads = -1)                                        \
    X(e5, "precision", o->precision = (rt_precision)2)                       \
    X(e6, "precision", o->precision = (rt_precision)-1)                      \
    X(e7, "samples", o->samples = 0)                                         \
    X(e8, "samples", o->samples = 2)                                         \
    X(e9, "samples", o->samples = 2025)                                      \
    X(e10, "sampling", o->sampling = (rt_sampling)2)                         \
    X(e11, "sampling", o->sampling = (rt_sampling)-1)                        \
    X(e12, "kernel", o->kernel = (rt_kernel_choice)9)                        \
    X(e13, "accel", o->accel = (rt_accel)4)                                  \
    X(e14, "aperture", o->aperture = NAN)                                    \
    X(e15, "aperture", o->aperture = INFINITY)                               \
    X(e16, "aperture", o->aperture = -INFINITY)                              \
    X(e17, "focal distance", o->focal_distance = -1)                         \
    X(e18, "focal distance", o->focal_distance = NAN)                        \
    X(e19, "focal distance", o->focal_distance = INFINITY)                   \
    X(e20, "pixels", o->width = -1)                                          \
    X(e21, "pixels", o->height = RT_MAX_IMAGE_SIDE + 1)                      \
    X(e22, "region", o->region = region(0, 0, 41, 1))                        \
    X(e23, "region", o->region = region(1, 1, 1, 1))                         \
    X(e24, "region", o->region = region(-1, 0, 1, 1))                        \
    X(e25, "render stats", o->stats = stats_of_size(0))                      \
    X(e26, "render stats",                                                   \
      o->stats = stats_of_size(offsetof(rt_render_stats, refraction_rays)))

OPTION_EDITS(EDIT)

static const option_edit option_edits[] = {OPTION_EDITS(EDIT_ROW)};

/* The functions that take render options, each called with `options` on
 * the fixture's scene and image. */
static rt_status with_render(const rt_render_options *o, rt_error *error)
{
    return rt_render(scene, o, &image, error);
}

static rt_status with_rows(const rt_render_options *o, rt_error *error)
{
    return rt_render_rows(scene, o, 0, 1, &image, error);
}

static rt_status with_explain(const rt_render_options *o, rt_error *error)
{
    rt_status status = rt_explain_pixel(scene, o, 0, 0, -1, &out_tree, error);
    rt_ray_tree_destroy(out_tree);
    return status;
}

static rt_status with_view(const rt_render_options *o, rt_error *error)
{
    return rt_render_view(scene, o, RT_VIEW_NORMAL, 0, &image, error);
}

static rt_status with_size(const rt_render_options *o, rt_error *error)
{
    return rt_render_image_size(scene, o, &out_width, &out_height, error);
}

static const struct {
    const char *name;
    rt_status (*call)(const rt_render_options *o, rt_error *error);
    int size_only;      /* reads only size, width, height and region */
} option_takers[] = {
    {"rt_render", with_render, 0},
    {"rt_render_rows", with_rows, 0},
    {"rt_explain_pixel", with_explain, 0},
    {"rt_render_view", with_view, 0},
    {"rt_render_image_size", with_size, 1},
};

START_TEST(every_function_taking_render_options_refuses_each_bad_field)
{
    size_t takers = sizeof option_takers / sizeof option_takers[0];
    size_t edits = sizeof option_edits / sizeof option_edits[0];
    for (size_t t = 0; t < takers; t++) {
        rt_render_options o;
        rt_render_options_init(&o);
        o.threads = 1;
        ck_assert_msg(option_takers[t].call(&o, NULL) == RT_OK,
                      "%s refuses the defaults", option_takers[t].name);
        for (size_t e = 0; e < edits; e++) {
            const char *word = option_edits[e].word;
            int sized = !strcmp(word, "bytes") || !strcmp(word, "pixels") ||
                        !strcmp(word, "region");
            if (option_takers[t].size_only && !sized)
                continue;
            rt_render_options_init(&o);
            o.threads = 1;
            option_edits[e].edit(&o);
            rt_error error;
            memset(&error, 0, sizeof error);
            rt_status status = option_takers[t].call(&o, &error);
            ck_assert_msg(status == RT_ERR_ARGUMENT && error.status == status,
                          "%s with %s returned %s", option_takers[t].name,
                          option_edits[e].what, rt_status_string(status));
            ck_assert_msg(strstr(error.message, word) != NULL,
                          "%s with %s: the message does not say `%s`: %s",
                          option_takers[t].name, option_edits[e].what, word,
                          error.message);
            ck_assert_int_eq(option_takers[t].call(&o, NULL),
                             RT_ERR_ARGUMENT);
        }
    }
}
END_TEST

START_TEST(a_negative_aperture_and_a_zero_focus_still_mean_the_scene_s)
{
    rt_render_options o;
    rt_render_options_init(&o);
    o.aperture = -3;
    o.focal_distance = 0;
    o.threads = 1;
    rt_error error = {0};
    ck_assert_msg(rt_render(scene, &o, &image, &error) == RT_OK, "%s",
                  error.message);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Load options                                                         */

typedef struct load_edit {
    const char *what;
    const char *word;
    void (*edit)(rt_load_options *options);
} load_edit;

static const rt_light a_light = {{0, 0, -5}, {255, 255, 255}};

#define LOAD_EDIT(name, word, statement)                                     \
    static void name(rt_load_options *o) { statement; }

#define LOAD_EDITS(X)                                                        \
    X(l1, "bytes", o->size = 0)                                              \
    X(l2, "bytes", o->size = sizeof *o + 8)                                  \
    X(l3, "format", o->format = (rt_scene_format)99)                         \
    X(l4, "format", o->format = (rt_scene_format)-7)                         \
    X(l5, "tessellation", o->tessellation = NAN)                             \
    X(l6, "tessellation", o->tessellation = -0.5)                            \
    X(l7, "tessellation", o->tessellation = 1)                               \
    X(l8, "pixels", o->width = -1)                                           \
    X(l9, "pixels", o->height = RT_MAX_IMAGE_SIDE + 1)                       \
    X(l10, "field of view", (o->fov_given = 1, o->fov = 180))                \
    X(l11, "field of view", (o->fov_given = 1, o->fov = NAN))                \
    X(l12, "look_from",                                                      \
      (o->look_from_given = 1, o->look_from.y = INFINITY))                   \
    X(l13, "look_at", (o->look_at_given = 1, o->look_at.z = NAN))            \
    X(l14, "up", (o->up_given = 1, o->up.x = NAN))                           \
    X(l15, "light count", (o->light_count = -1, o->lights = &a_light))       \
    X(l16, "lights", o->light_count = 2)

LOAD_EDITS(LOAD_EDIT)

static const load_edit load_edits[] = {LOAD_EDITS(EDIT_ROW)};

/* A scene in each format the loader reads: the refusal does not depend on
 * which one reads the field. */
static const struct {
    const char *name;
    const char *text;
} load_inputs[] = {
    {"edge.scn", rt_test_centred_facet_scene},
    {"edge.nff", "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\n"
                 "hither 1\nresolution 40 30\nl 1 1 -5\n"
                 "p 3 -1 -1 2 1 -1 2 0 1 2\n"},
    {"edge.obj", "v -1 -1 2\nv 1 -1 2\nv 0 1 2\nf 1 2 3\n"},
};

START_TEST(every_loader_refuses_each_bad_load_option_field)
{
    size_t inputs = sizeof load_inputs / sizeof load_inputs[0];
    size_t edits = sizeof load_edits / sizeof load_edits[0];
    for (size_t i = 0; i < inputs; i++) {
        const char *text = load_inputs[i].text;
        rt_scene *loaded = NULL;
        rt_error error = {0};
        ck_assert_msg(rt_scene_parse(text, strlen(text), load_inputs[i].name,
                                     NULL, &loaded, &error) == RT_OK,
                      "%s does not load: %s", load_inputs[i].name,
                      error.message);
        rt_scene_destroy(loaded);
        for (size_t e = 0; e < edits; e++) {
            rt_load_options o;
            rt_load_options_init(&o);
            load_edits[e].edit(&o);
            memset(&error, 0, sizeof error);
            rt_status status = rt_scene_parse(
                text, strlen(text), load_inputs[i].name, &o, &loaded, &error);
            ck_assert_msg(status == RT_ERR_ARGUMENT && loaded == NULL,
                          "%s with %s returned %s", load_inputs[i].name,
                          load_edits[e].what, rt_status_string(status));
            ck_assert_msg(error.status == status &&
                              strstr(error.message, load_edits[e].word),
                          "%s with %s: the message does not say `%s`: %s",
                          load_inputs[i].name, load_edits[e].what,
                          load_edits[e].word, error.message);
            ck_assert_int_eq(rt_scene_parse(text, strlen(text),
                                            load_inputs[i].name, &o, &loaded,
                                            NULL),
                             RT_ERR_ARGUMENT);
        }
    }
}
END_TEST

/* ------------------------------------------------------------------ */
/* Functions without a status                                           */

START_TEST(functions_without_a_status_take_null_as_their_headers_say)
{
    rt_cancel_destroy(NULL);
    rt_cancel_request(NULL);
    rt_cancel_reset(NULL);
    ck_assert_int_eq(rt_cancel_requested(NULL), 0);
    rt_scene_destroy(NULL);
    rt_ray_tree_destroy(NULL);
    rt_image_release(NULL);
    rt_render_options_init(NULL);
    rt_load_options_init(NULL);
    rt_save_options_init(NULL);
    ck_assert_int_eq(rt_scene_source_count(NULL), 0);
    ck_assert_str_eq(rt_status_string((rt_status)99), "unknown status");
    ck_assert_str_eq(rt_image_format_name((rt_image_format)99), "unknown");
    ck_assert_str_eq(rt_scene_format_name((rt_scene_format)99), "unknown");
    ck_assert_str_eq(rt_scene_format_name(RT_SCENE_FORMAT_AUTO), "auto");
    ck_assert_int_eq(rt_image_format_supported((rt_image_format)99), 0);
    ck_assert_int_eq(rt_channel_to_byte(NAN), 0);
    rt_rgb8 c = rt_debug_facet_color(-1);
    ck_assert(c.r >= 64 && c.g >= 64 && c.b >= 64);
    ck_assert_ptr_nonnull(rt_version_string());
    /* a flag still works after the NULL calls */
    rt_cancel *flag;
    ck_assert_int_eq(rt_cancel_create(&flag, NULL), RT_OK);
    rt_cancel_request(flag);
    ck_assert_int_eq(rt_cancel_requested(flag), 1);
    rt_cancel_reset(flag);
    ck_assert_int_eq(rt_cancel_requested(flag), 0);
    rt_cancel_destroy(flag);
}
END_TEST

/* ------------------------------------------------------------------ */

static Suite *edges_suite(void)
{
    Suite *s = suite_create("api_edges");
    TCase *tc = tcase_create("statuses");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, every_status_function_refuses_null_with_argument_and_a_message);
    tcase_add_test(tc, out_of_range_values_are_refused_with_their_status_and_a_message);
    tcase_add_test(tc, every_function_taking_render_options_refuses_each_bad_field);
    tcase_add_test(tc, every_loader_refuses_each_bad_load_option_field);
    tcase_add_test(tc, a_negative_aperture_and_a_zero_focus_still_mean_the_scene_s);
    tcase_add_test(tc, functions_without_a_status_take_null_as_their_headers_say);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(edges_suite)
