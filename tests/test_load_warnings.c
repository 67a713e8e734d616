/*
 * test_load_warnings.c - what a load says and keeps about a hostile file
 * (docs/robustness-input.md, "Budgets of a load"): warnings stored as they
 * come and summarised past the first few of a kind (a count and the
 * lines), facets that repeat the one before them left out of the renderer
 * with one warning and no pixel changed, and names shown with their
 * control bytes escaped.  Inputs are generated here and small; what is
 * checked is the warnings stored and their bytes, the facets the renderer
 * keeps and its tests (render statistics), and images byte for byte.
 */
#include <check.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/reader.h"
#include "testutil.h"
#include "raytrace/raytrace.h"
#include "scene/scene_internal.h"

static rt_scene *parse_scn(const rt_test_text *t, const char *name)
{
    rt_scene *scene;
    rt_error error;
    rt_status status =
        rt_scene_parse(t->data, t->length, name, NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

/* A .scn file of one visible facet (line 9), then `count` more facet
 * lines (from line 10) made by `facet(i)`. */
static rt_test_text scn_with(int count, const char *(*facet)(int i))
{
    rt_test_text t = {0};
    rt_test_text_add(&t,
                     "0 0 10\n0 0 5 4 0 5 16 16\n4\n-1 -1 0\n1 -1 0\n0 1 0\n"
                     "3 -1 0\n%d\n1 2 3 0 200 100 50\n", count + 1);
    for (int i = 0; i < count; i++)
        rt_test_text_add(&t, "%s\n", facet(i));
    rt_test_text_add(&t, "0 0 0\n0 0 8 255 255 255\n");
    return t;
}

static const char *collinear(int i)
{
    (void)i;
    return "1 2 4 0 1 1 1";     /* (-1,-1,0), (1,-1,0), (3,-1,0) */
}

/* Zero-area facets on every other line, between facets that are no
 * repeat of the one kept before them. */
static const char *collinear_every_other(int i)
{
    return i % 2 == 0 ? "1 2 4 0 1 1 1" : i % 4 == 1 ? "2 3 1 0 0 0 0"
                                                     : "3 1 2 0 0 0 0";
}

/* ------------------------------------------------------------------ */
/* Warnings                                                             */

START_TEST(zero_area_facets_warn_eight_times_then_once_with_a_count)
{
    /* 1000 zero-area facets on lines 10..1009: once 1000 warnings of 520
     * bytes (and a warning reserved for every facet); now 9. */
    rt_test_text t = scn_with(1000, collinear);
    rt_scene *scene = parse_scn(&t, "t.scn");
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.facet_count, 1001);
    ck_assert_int_eq(info.live_facet_count, 1);
    ck_assert_int_eq(info.warning_count, RT_NOTES_SHOWN_PER_KIND + 1);
    ck_assert_str_eq(rt_scene_warning(scene, 0)->message,
                     "t.scn:10:1: warning: facet 2 has zero area (its "
                     "vertices are collinear); it is never hit");
    ck_assert_str_eq(rt_scene_warning(scene, 7)->message,
                     "t.scn:17:1: warning: facet 9 has zero area (its "
                     "vertices are collinear); it is never hit");
    const rt_warning *last = rt_scene_warning(scene, 8);
    ck_assert_str_eq(last->message, "t.scn:18:1: warning: ... and 992 more "
                                    "zero-area facets (lines 18-1009)");
    ck_assert_int_eq(last->line, 18);
    ck_assert_int_eq(last->column, 1);
    /* the scene's records: its facets and 9 warnings, not 1000 */
    ck_assert_uint_lt(rt__scene_bytes(scene),
                      sizeof(rt_scene) + 1001 * sizeof(rt_facet_info) +
                          4 * sizeof(rt_vec3) + 10 * sizeof(rt_warning) +
                          sizeof(rt_light) + 16);
    rt_scene_destroy(scene);
    free(t.data);
}
END_TEST

START_TEST(a_summary_lists_its_lines_as_ranges_and_says_when_it_stops)
{
    /* zero-area facets on every other line from 10: single lines */
    rt_test_text t = scn_with(2000, collinear_every_other);
    rt_scene *scene = parse_scn(&t, "t.scn");
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.warning_count, RT_NOTES_SHOWN_PER_KIND + 1);
    const char *m = rt_scene_warning(scene, 8)->message;
    const char *head = "t.scn:26:1: warning: ... and 992 more zero-area "
                       "facets (lines 26, 28, 30, ";
    ck_assert_msg(strncmp(m, head, strlen(head)) == 0, "%s", m);
    size_t n = strlen(m);
    ck_assert_str_eq(m + n - 6, ", ...)");
    ck_assert_uint_lt(n, RT_ERROR_MESSAGE_SIZE);
    rt_scene_destroy(scene);
    free(t.data);
}
END_TEST

START_TEST(notes_summarise_each_kind_on_its_own)
{
    rt_notes notes;
    memset(&notes, 0, sizeof notes);
    rt__notes_add(&notes, "f", 1, 1, "first");
    for (int i = 0; i < 20; i++) {
        rt__notes_add_kind(&notes, "odd things", "f", 10 + i, 2, "odd %d", i);
        if (i < 3)
            rt__notes_add_kind(&notes, "even things", "f", 100 + 2 * i, 3,
                               "even %d", i);
    }
    rt__notes_add(&notes, "f", 0, 0, "last");
    /* 1 + 8 odd + 3 even + the summary of the 12 other odd + 1 */
    ck_assert_int_eq(notes.count, 14);
    ck_assert_int_eq(notes.failed, 0);
    rt_notes copy;
    memset(&copy, 0, sizeof copy);
    rt__notes_append(&copy, &notes);
    ck_assert_int_eq(copy.count, 14);
    int summary = -1;
    for (int i = 0; i < copy.count; i++)
        if (strstr(copy.items[i].message, "... and") != NULL)
            summary = i;
    ck_assert_int_ge(summary, 0);
    ck_assert_str_eq(copy.items[summary].message,
                     "f:18:2: warning: ... and 12 more odd things (lines "
                     "18-29)");
    ck_assert_str_eq(copy.items[copy.count - 1].message, "f: warning: last");
    ck_assert_str_eq(copy.items[0].message, "f:1:1: warning: first");
    /* settling the list itself writes the same text */
    rt__notes_settle(&notes);
    ck_assert_str_eq(notes.items[summary].message,
                     copy.items[summary].message);
    rt__notes_free(&notes);
    rt__notes_free(&copy);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Repeated facets                                                      */

/* Puts the repeated facets of `s` back into its renderer, as the builder
 * kept them before it knew them: their records live again and a new
 * kernel holds them (the float kernel, built by the first float render,
 * will too). */
static void keep_repeats(rt_scene *s)
{
    for (int i = 0; i < s->facet_count; i++)
        if (s->facets[i].degenerate == RT_FACET_REPEATED) {
            s->facets[i].degenerate = 0;
            s->live_count++;
        }
    rt__kernel_destroy(s->kernel);
    rt_kernel_source source;
    rt__scene_kernel_source(s, &source);
    s->kernel = rt__kernel_double_ops.create(&source);
    ck_assert_ptr_nonnull(s->kernel);
}

/* Renders a and b at 64 x 48 with every precision, kernel and
 * acceleration; fails unless every image is the same, byte for byte. */
static void assert_same_pictures(const rt_scene *a, const rt_scene *b,
                                 const char *what)
{
    for (int precision = 0; precision < 2; precision++)
        for (int accel = 0; accel < 3; accel++) {
            rt_render_options options;
            rt_render_options_init(&options);
            options.precision = (rt_precision)precision;
            options.accel = (rt_accel)accel;
            options.kernel = accel == 1 ? RT_KERNEL_SCALAR : RT_KERNEL_AUTO;
            options.width = 64;
            options.height = 48;
            rt_image x = rt_test_render_with(a, &options);
            rt_image y = rt_test_render_with(b, &options);
            ck_assert_msg(memcmp(x.pixels, y.pixels,
                                 (size_t)x.height * x.stride) == 0,
                          "%s, precision %d, accel %d: %ld pixels differ",
                          what, precision, accel,
                          rt_test_image_diff(&x, &y, NULL));
            rt_image_release(&x);
            rt_image_release(&y);
        }
}

static const char *same_facet(int i)
{
    (void)i;
    return "1 2 3 0 200 100 50";
}

START_TEST(a_facet_repeated_ten_thousand_times_renders_as_the_facet_once)
{
    rt_test_text once = scn_with(0, same_facet),
                 many = scn_with(10000, same_facet);
    rt_scene *a = parse_scn(&once, "once.scn"), *b = parse_scn(&many,
                                                               "many.scn");
    ck_assert_int_eq(rt_test_scene_info(b).facet_count, 10001);
    ck_assert_int_eq(rt_test_scene_info(b).live_facet_count, 1);
    ck_assert_int_eq(rt_test_scene_info(b).warning_count, 1);
    ck_assert_str_eq(rt_scene_warning(b, 0)->message,
                     "many.scn:10:1: warning: 10000 facets repeat the facet "
                     "just before them exactly (the same vertices in the "
                     "same order), the first facet 2: they are never hit "
                     "and change no pixel");
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(b, 5000, &f);
    ck_assert_int_eq(f.degenerate, RT_FACET_REPEATED);
    rt_render_stats sa = {.size = sizeof sa}, sb = {.size = sizeof sb};
    rt_render_options options;
    rt_render_options_init(&options);
    options.accel = RT_ACCEL_NONE;  /* tests as brute force counts them */
    options.stats = &sa;
    rt_image ia = rt_test_render_with(a, &options);
    options.stats = &sb;
    rt_image ib = rt_test_render_with(b, &options);
    ck_assert_int_eq(rt_test_image_diff(&ia, &ib, NULL), 0);
    ck_assert_mem_eq(ia.pixels, ib.pixels, (size_t)ia.height * ia.stride);
    /* the same tests as the facet once (once every ray tested 10 001) */
    ck_assert_uint_eq(sb.ray_facet_tests, sa.ray_facet_tests);
    ck_assert_uint_ge(sb.ray_facet_tests_skipped,
                      10000 * sb.camera_rays);
    /* As the renderer drew it when it tested all 10 001: the same picture,
     * with 10 001 times the tests. */
    rt_scene *kept = parse_scn(&many, "many.scn");
    keep_repeats(kept);
    rt_render_stats sk = {.size = sizeof sk};
    options.stats = &sk;
    rt_image ik = rt_test_render_with(kept, &options);
    ck_assert_mem_eq(ia.pixels, ik.pixels, (size_t)ia.height * ia.stride);
    /* every camera ray tests the 10 001, every shadow ray the 10 000 its
     * facet is not; left out, a camera ray tests 1, a shadow ray none */
    ck_assert_uint_eq(sk.ray_facet_tests,
                      10001 * sk.camera_rays + 10000 * sk.shadow_rays);
    ck_assert_uint_eq(sb.ray_facet_tests, sb.camera_rays);
    rt_image_release(&ik);
    rt_scene_destroy(kept);
    rt_image_release(&ia);
    rt_image_release(&ib);
    rt_scene_destroy(a);
    rt_scene_destroy(b);
    free(once.data);
    free(many.data);
}
END_TEST

START_TEST(only_a_repeat_of_the_facet_kept_just_before_is_left_out)
{
    /* line: facet                             degenerate
     * 10: 1 2 3                               0
     * 11: 1 2 4 (zero area)                   ZERO_AREA
     * 12: 1 2 3 (the one kept before: 10)     REPEATED
     * 13: 5 2 3 (vertex 5 = vertex 1)         REPEATED
     * 14: 2 3 1 (the same corners, rotated)   0
     * 15: 1 2 3 (the one before is 14)        0 */
    static const char file[] =
        "0 0 10\n0 0 5 4 0 5 16 16\n5\n-1 -1 0\n1 -1 0\n0 1 0\n3 -1 0\n"
        "-1 -1 0\n6\n1 2 3 0 200 100 50\n1 2 4 0 1 1 1\n1 2 3 0.5 0 0 0\n"
        "5 2 3 0 9 9 9\n2 3 1 0 7 7 7\n1 2 3 0 5 5 5\n0 0 0\n"
        "0 0 8 255 255 255\n";
    rt_test_text t = {(char *)file, sizeof file - 1, 0};
    rt_scene *scene = parse_scn(&t, "t.scn");
    static const int expected[6] = {0, RT_FACET_ZERO_AREA, RT_FACET_REPEATED,
                                    RT_FACET_REPEATED, 0, 0};
    for (int i = 0; i < 6; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        ck_assert_msg(f.degenerate == expected[i], "facet %d: %d", i + 1,
                      f.degenerate);
    }
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.live_facet_count, 3);
    /* the repeat with k = 0.5 is not counted as reflective */
    ck_assert_int_eq(info.reflective_facet_count, 0);
    ck_assert_int_eq(info.warning_count, 2);
    ck_assert_str_eq(rt_scene_warning(scene, 1)->message,
                     "t.scn:12:1: warning: 2 facets repeat the facet just "
                     "before them exactly (the same vertices in the same "
                     "order), the first facet 3: they are never hit and "
                     "change no pixel");
    rt_scene_destroy(scene);
}
END_TEST

/* Scene s built again with rt_scene_create, every facet followed by a
 * repeat of another colour, k, t and d when `doubled`. */
static rt_scene *rebuilt(const rt_scene *s, int doubled)
{
    rt_scene_info info = rt_test_scene_info(s);
    rt_vec3 *v = malloc((size_t)info.vertex_count * sizeof *v);
    rt_facet_desc *f = calloc((size_t)info.facet_count * 2, sizeof *f);
    rt_light *l = malloc((size_t)info.light_count * sizeof *l);
    ck_assert(v && f && l);
    for (int i = 0; i < info.vertex_count; i++)
        v[i] = rt_scene_vertex(s, i);
    int n = 0;
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info r = {.size = sizeof r};
        rt_scene_facet(s, i, &r);
        rt_facet_desc d = {{r.vertex[0], r.vertex[1], r.vertex[2]},
                           r.reflection, r.color, r.transparency,
                           r.refractive_index, r.diffuse, 1};
        f[n++] = d;
        if (doubled) {
            d.color = (rt_rgb8){(unsigned char)(255 - r.color.r), 3, 250};
            d.reflection = r.reflection > 0 ? 0 : 0.5;
            d.transparency = 0.25;
            d.diffuse = 0.25;
            f[n++] = d;
        }
    }
    for (int i = 0; i < info.light_count; i++)
        rt_scene_light(s, i, &l[i]);
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    d.observer = info.camera.observer;
    d.screen_center = info.camera.screen_center;
    d.screen_right = (rt_vec3){info.camera.screen_center.x +
                                   info.camera.right.x,
                               info.camera.screen_center.y +
                                   info.camera.right.y,
                               info.camera.screen_center.z +
                                   info.camera.right.z};
    d.width = info.width;
    d.height = info.height;
    d.vertices = v;
    d.vertex_count = info.vertex_count;
    d.facets = f;
    d.facet_count = n;
    d.background = info.background;
    d.lights = l;
    d.light_count = info.light_count;
    d.aperture = info.camera.aperture;
    d.focal_distance = info.camera.focal_distance;
    rt_scene *out;
    rt_error error;
    ck_assert_msg(rt_scene_create(&d, &out, &error) == RT_OK, "%s",
                  error.message);
    free(v);
    free(f);
    free(l);
    return out;
}

/* Three facets that a ray family meets at one point within rounding: h
 * and f in the plane z = 0 (overlapping, of other vertices, so that their
 * t round apart), x across it in the plane x = 0.7; `order` lists which
 * of h (0), f (1), x (2) and a repeat of f (3) the scene holds, in file
 * order. */
static rt_scene *tie_scene(const int *order, int n)
{
    static const rt_vec3 v[9] = {
        {-3.1, -2.7, 0}, {4.3, -2.9, 0}, {0.3, 5.1, 0},     /* h */
        {-2.3, -3.3, 0}, {3.7, -2.1, 0}, {-0.1, 4.7, 0},    /* f */
        {0.7, -4, -1.3}, {0.7, 4, -1.7}, {0.7, 0.3, 1.9},   /* x */
    };
    static const int first[4] = {0, 3, 6, 3};
    rt_facet_desc f[4];
    memset(f, 0, sizeof f);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < 3; j++)
            f[i].vertex[j] = first[order[i]] + j;
        f[i].color = (rt_rgb8){(unsigned char)(60 * order[i]), 0, 0};
    }
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    d.observer = (rt_vec3){0, 0, 10};
    d.screen_center = (rt_vec3){0, 0, 5};
    d.screen_right = (rt_vec3){4, 0, 5};
    d.width = d.height = 8;
    d.vertices = v;
    d.vertex_count = 9;
    d.facets = f;
    d.facet_count = n;
    d.lights = &(rt_light){{0, 0, 9}, {255, 255, 255}};
    d.light_count = 1;
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_create(&d, &scene, &error) == RT_OK, "%s",
                  error.message);
    return scene;
}

/* Of 4096 rays aimed at the line where x crosses the plane of h and f,
 * from above, those whose nearest facet (by its place in `a` and `b`: the
 * `order` given) differs between the two scenes. */
static int ties_differing(const rt_scene *a, const int *order_a,
                          const rt_scene *b, const int *order_b)
{
    rt_test_rng rng = {12345};
    int differ = 0;
    for (int k = 0; k < 4096; k++) {
        double u[4];
        for (int j = 0; j < 4; j++)
            u[j] = rt_test_rng_uniform(&rng);
        double y = (u[0] - 0.5) * 4;
        rt_vec3 o = {(u[1] - 0.5) * 20, (u[2] - 0.5) * 20, 3 + u[3] * 10};
        rt_ray ray = {o, {0.7 - o.x, y - o.y, -o.z}};
        rt_hit ha, hb;
        int fa = rt_scene_nearest_hit(a, ray, 1e30, &ha),
            fb = rt_scene_nearest_hit(b, ray, 1e30, &hb);
        /* the same facet of the figure, or a repeat against its facet */
        int wa = fa ? order_a[ha.facet] : -1, wb = fb ? order_b[hb.facet] : -1;
        differ += wa != wb;
    }
    return differ;
}

START_TEST(a_repeat_just_after_its_facet_changes_no_hit_even_at_ties)
{
    /* h, f, g (a repeat of f), x: g is left out; put back in the
     * renderer, no ray's nearest facet changes, at the ties too. */
    static const int order[4] = {0, 1, 3, 2};
    rt_scene *left_out = tie_scene(order, 4), *kept = tie_scene(order, 4);
    ck_assert_int_eq(rt_test_scene_info(left_out).live_facet_count, 3);
    keep_repeats(kept);
    ck_assert_int_eq(rt_test_scene_info(kept).live_facet_count, 4);
    ck_assert_int_eq(ties_differing(left_out, order, kept, order), 0);
    rt_scene_destroy(left_out);
    rt_scene_destroy(kept);
}
END_TEST

START_TEST(a_repeat_apart_from_its_facet_stays_as_leaving_it_out_changes_hits)
{
    /* h, f, x, g: where the three meet within rounding, f ties with h and
     * does not replace it, x (across) does, and g - nearer than x, across
     * it - replaces x.  Without g the answer is x: the tie rule is not
     * transitive, so a repeat that does not follow its facet is kept. */
    static const int with_order[4] = {0, 1, 2, 3}, without_order[3] = {0, 1,
                                                                       2};
    rt_scene *with = tie_scene(with_order, 4),
             *without = tie_scene(without_order, 3);
    ck_assert_int_eq(rt_test_scene_info(with).live_facet_count, 4);
    ck_assert_int_gt(ties_differing(with, with_order, without, without_order),
                     0);
    rt_scene_destroy(with);
    rt_scene_destroy(without);
}
END_TEST

START_TEST(repeats_of_another_material_change_no_pixel_of_the_project_scenes)
{
    /* Each facet followed by a repeat of another colour, k, t and d: were
     * a repeat ever met first, shadowed, or reflected into, a pixel would
     * show it.  The scene with its repeats left out against the same scene
     * with them put back in its renderer: mirrors and glass included, in
     * double and float, brute force (fast and scalar) and the octree. */
    static const char *scenes[] = {"scenes/cubes.scn", "scenes/mirror.scn",
                                   "scenes/glass.scn"};
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        rt_scene *file;
        rt_error error;
        ck_assert_msg(rt_scene_load(rt_test_source_path(scenes[i]), NULL,
                                    &file, &error) == RT_OK,
                      "%s", error.message);
        rt_scene *left_out = rebuilt(file, 1), *kept = rebuilt(file, 1);
        ck_assert_int_eq(rt_test_scene_info(left_out).live_facet_count,
                         rt_test_scene_info(file).live_facet_count);
        keep_repeats(kept);
        ck_assert_int_eq(rt_test_scene_info(kept).live_facet_count,
                         2 * rt_test_scene_info(file).live_facet_count);
        assert_same_pictures(left_out, kept, scenes[i]);
        rt_scene_destroy(file);
        rt_scene_destroy(left_out);
        rt_scene_destroy(kept);
    }
}
END_TEST

/* ------------------------------------------------------------------ */
/* Names                                                                */

START_TEST(names_are_shown_with_their_control_bytes_escaped)
{
    static const struct {
        const char *name, *shown;
    } cases[] = {
        {"plain/scene.scn", "plain/scene.scn"},
        {"a\x1b[31mred", "a\\x1B[31mred"},
        {"bell\x07 tab\t nl\n del\x7f", "bell\\x07 tab\\x09 nl\\x0A del\\x7F"},
        {"back\\slash", "back\\\\slash"},
        {"sc\xC3\xA8ne.nff", "sc\xC3\xA8ne.nff"},          /* UTF-8 kept */
        {"csi\xC2\x9B" "2J", "csi\\xC2\\x9B2J"},           /* U+009B */
        {"raw\x9B" "2J", "raw\\x9B2J"},                    /* not UTF-8 */
        {"cut\xE2\x82", "cut\\xE2\\x82"},                  /* truncated */
        {"long\xF0\x9F\x98\x80!", "long\xF0\x9F\x98\x80!"}, /* U+1F600 */
        {"over\xC0\xAF", "over\\xC0\\xAF"},                 /* overlong */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char out[64];
        size_t n = rt__escape_name(cases[i].name, out, sizeof out);
        ck_assert_str_eq(out, cases[i].shown);
        ck_assert_uint_eq(n, strlen(cases[i].shown));
    }
    /* Never half an escape or half a character. */
    char small[8];
    ck_assert_uint_eq(rt__escape_name("abcd\x1b", small, sizeof small), 4);
    ck_assert_str_eq(small, "abcd");
    ck_assert_uint_eq(rt__escape_name("ab\xC3\xA8\xC3\xA8\xC3\xA8", small,
                                      sizeof small),
                      6);
    ck_assert_str_eq(small, "ab\xC3\xA8\xC3\xA8");
}
END_TEST

static int has_control_byte(const char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s < 0x20 || *s == 0x7f)
            return 1;
    return 0;
}

START_TEST(errors_and_warnings_show_a_hostile_name_escaped)
{
    const char *name = "evil\x1b]0;owned\x07.scn";
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_parse("0 0\n", 4, name, NULL, &scene, &error),
                     RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "evil\\x1B]0;owned\\x07.scn:1:4: expected 3 values for "
                     "the observer `x, y, z`, found 2");
    rt_test_text t = scn_with(1, collinear);
    scene = parse_scn(&t, name);
    ck_assert_int_eq(rt_test_scene_info(scene).warning_count, 1);
    const char *m = rt_scene_warning(scene, 0)->message;
    ck_assert(!has_control_byte(m));
    ck_assert_msg(strncmp(m, "evil\\x1B]0;owned\\x07.scn:10:1: warning: ",
                          40) == 0,
                  "%s", m);
    rt_scene_destroy(scene);
    free(t.data);
    /* NFF's own warnings too */
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_NFF;
    static const char nff[] = "v from 0 -9 0 at 0 0 0 up 0 0 1 angle 45 "
                              "hither 1 resolution 8 8\np 3 0 0 0 1 0 0 0 "
                              "0 1\n";
    ck_assert_int_eq(rt_scene_parse(nff, sizeof nff - 1, "n\x1b.nff", &options,
                                    &scene, &error),
                     RT_OK);
    for (int i = 0; i < rt_test_scene_info(scene).warning_count; i++) {
        m = rt_scene_warning(scene, i)->message;
        ck_assert_msg(!has_control_byte(m), "%s", m);
        ck_assert_msg(strncmp(m, "n\\x1B.nff", 9) == 0, "%s", m);
    }
    rt_scene_destroy(scene);
}
END_TEST

static Suite *load_warnings_suite(void)
{
    Suite *s = suite_create("load_warnings");
    TCase *c = tcase_create("warnings");
    tcase_add_test(c, zero_area_facets_warn_eight_times_then_once_with_a_count);
    tcase_add_test(c, a_summary_lists_its_lines_as_ranges_and_says_when_it_stops);
    tcase_add_test(c, notes_summarise_each_kind_on_its_own);
    suite_add_tcase(s, c);
    c = tcase_create("repeats");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, a_facet_repeated_ten_thousand_times_renders_as_the_facet_once);
    tcase_add_test(c, only_a_repeat_of_the_facet_kept_just_before_is_left_out);
    tcase_add_test(c, a_repeat_just_after_its_facet_changes_no_hit_even_at_ties);
    tcase_add_test(c,
                   a_repeat_apart_from_its_facet_stays_as_leaving_it_out_changes_hits);
    tcase_add_test(c, repeats_of_another_material_change_no_pixel_of_the_project_scenes);
    suite_add_tcase(s, c);
    c = tcase_create("names");
    tcase_add_test(c, names_are_shown_with_their_control_bytes_escaped);
    tcase_add_test(c, errors_and_warnings_show_a_hostile_name_escaped);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(load_warnings_suite)
