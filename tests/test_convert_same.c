/*
 * test_convert_same.c - a scene written as an extended .scn file
 * (rt_scene_write_scn, what `rt-convert --extended` writes) reads back as
 * the same scene, bit for bit (vertices, vertex normals, every facet
 * parameter, the camera and the lights), and renders the same bytes:
 * NFF models with spheres, cones, patches, glass and highlights, the
 * shipped scenes/nff-sphere.nff and the SPD scenes of ../shared/formats
 * (their own ctest entry, a visible skip without ../shared).  Written
 * without --extended, what the course's records cannot hold is reported.
 * The renders are small (64 x 48) to keep the suite quick.
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* A growing text buffer, the sink of rt_scene_write_scn. */
typedef struct text {
    char *bytes;
    size_t length, capacity;
} text;

static int append(void *user, const void *data, size_t size)
{
    text *t = user;
    if (t->length + size + 1 > t->capacity) {
        size_t bigger = 2 * (t->length + size + 1);
        char *grown = realloc(t->bytes, bigger);
        if (grown == NULL)
            return 0;
        t->bytes = grown;
        t->capacity = bigger;
    }
    memcpy(t->bytes + t->length, data, size);
    t->length += size;
    t->bytes[t->length] = '\0';
    return 1;
}

static text write_scn(const rt_scene *scene, int extended, unsigned *dropped)
{
    text t = {NULL, 0, 0};
    rt_error error;
    rt_status status =
        rt_scene_write_scn(scene, extended, append, &t, dropped, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return t;
}

static rt_scene *parse_as(const char *bytes, size_t length, const char *name,
                          rt_scene_format format)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = format;
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status =
        rt_scene_parse(bytes, length, name, &options, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

static int same_vec(rt_vec3 a, rt_vec3 b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Fails unless both scenes hold the same doubles and bytes. */
static void assert_same_scene(const rt_scene *a, const rt_scene *b)
{
    rt_scene_info x = {.size = sizeof x}, y = {.size = sizeof y};
    rt_scene_get_info(a, &x);
    rt_scene_get_info(b, &y);
    ck_assert_int_eq(x.vertex_count, y.vertex_count);
    ck_assert_int_eq(x.facet_count, y.facet_count);
    ck_assert_int_eq(x.light_count, y.light_count);
    ck_assert_int_eq(x.smooth_facet_count, y.smooth_facet_count);
    ck_assert_int_eq(x.highlight_facet_count, y.highlight_facet_count);
    ck_assert_int_eq(x.transparent_facet_count, y.transparent_facet_count);
    ck_assert(x.width == y.width && x.height == y.height);
    ck_assert(same_vec(x.camera.observer, y.camera.observer));
    ck_assert(same_vec(x.camera.screen_center, y.camera.screen_center));
    for (int i = 0; i < x.vertex_count; i++) {
        ck_assert_msg(same_vec(rt_scene_vertex(a, i), rt_scene_vertex(b, i)),
                      "vertex %d", i);
        ck_assert_msg(same_vec(rt_scene_vertex_normal(a, i),
                               rt_scene_vertex_normal(b, i)),
                      "vertex normal %d", i);
    }
    for (int i = 0; i < x.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f}, g = {.size = sizeof g};
        rt_scene_facet(a, i, &f);
        rt_scene_facet(b, i, &g);
        ck_assert(memcmp(f.vertex, g.vertex, sizeof f.vertex) == 0);
        ck_assert_msg(f.reflection == g.reflection &&
                          f.transparency == g.transparency &&
                          f.refractive_index == g.refractive_index &&
                          f.diffuse == g.diffuse &&
                          f.highlight == g.highlight &&
                          f.highlight_exponent == g.highlight_exponent &&
                          f.smooth == g.smooth &&
                          memcmp(&f.color, &g.color, sizeof f.color) == 0,
                      "facet %d", i);
    }
    for (int i = 0; i < x.light_count; i++) {
        rt_light l, m;
        rt_scene_light(a, i, &l);
        rt_scene_light(b, i, &m);
        ck_assert(same_vec(l.position, m.position) &&
                  memcmp(&l.color, &m.color, sizeof l.color) == 0);
    }
}

static rt_image render_small(const rt_scene *scene)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = 64;
    options.height = 48;
    options.threads = 2;
    rt_image image;
    rt_error error;
    ck_assert_int_eq(rt_image_init(&image, 64, 48, &error), RT_OK);
    rt_status status = rt_render(scene, &options, &image, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return image;
}

static void assert_same_render(const rt_scene *a, const rt_scene *b,
                               const char *what)
{
    rt_image x = render_small(a), y = render_small(b);
    int differing = 0;
    for (int row = 0; row < x.height; row++)
        differing += memcmp(rt_image_pixel(&x, 0, row),
                            rt_image_pixel(&y, 0, row),
                            3 * (size_t)x.width) != 0;
    rt_image_release(&x);
    rt_image_release(&y);
    ck_assert_msg(differing == 0, "%s: %d rows differ", what, differing);
}

/* The NFF text converted and read back: the same scene and render.
 * Returns the scene's counts through *info for the caller's checks. */
static void check_round_trip(const char *bytes, size_t length,
                             const char *what, rt_scene_info *info)
{
    rt_scene *nff = parse_as(bytes, length, what, RT_SCENE_FORMAT_NFF);
    unsigned dropped = ~0u;
    text scn = write_scn(nff, 1, &dropped);
    ck_assert_uint_eq(dropped, 0);
    rt_scene *back =
        parse_as(scn.bytes, scn.length, "back.scn", RT_SCENE_FORMAT_SCN);
    assert_same_scene(nff, back);
    assert_same_render(nff, back, what);
    /* and a second conversion writes the same text */
    text again = write_scn(back, 1, NULL);
    ck_assert(again.length == scn.length &&
              memcmp(again.bytes, scn.bytes, scn.length) == 0);
    info->size = sizeof *info;
    rt_scene_get_info(nff, info);
    free(scn.bytes);
    free(again.bytes);
    rt_scene_destroy(back);
    rt_scene_destroy(nff);
}

#define VIEW                                                                 \
    "v\nfrom 0 -10 2\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\n"              \
    "resolution 64 48\nl 3 -8 6\nl -4 -6 3 1 0.8 0.6\nb 0.1 0.2 0.3\n"

START_TEST(nff_models_convert_to_an_extended_scn_that_renders_the_same)
{
    static const struct {
        const char *what, *body;
    } models[] = {
        {"a sphere with a highlight",
         "f 0.9 0.3 0.2 0.7 0.3 25 0 1\ns 0 0 0 2\n"},
        {"a glass sphere before a wall",
         "f 1 1 1 0.1 0.1 80 0.85 1.5\ns 0 0 0 1.5\n"
         "f 0.2 0.8 0.2 1 0 0 0 0\np 4\n-6 4 -4\n6 4 -4\n6 4 6\n-6 4 6\n"},
        {"cones, a cylinder and an inward sphere",
         "f 0.8 0.8 0.2 0.6 0.4 10 0 0\nc -2 0 -1 1 -2 0 2 0\n"
         "c 2 0 -1 1 2 0 2 0.5\nc 0 1 -2 0.7 0 1 2 0.7\n"
         "f 0.5 0.5 1 1 0.2 3.5 0 0\ns 0 3 0 -1.5\n"},
        {"patches with their normals",
         "f 1 0.6 0.2 0.9 0.5 12 0 0\n"
         "pp 4\n-2 0 -2 -1 -1 -1\n2 0 -2 1 -1 -1\n2 0 2 1 -1 1\n"
         "-2 0 2 -1 -1 1\n"
         "pp 3\n-1 -1 1 0 -1 0.2\n1 -1 1 0.3 -1 0\n0 -1 2 0 -0.8 0.6\n"},
        {"Shine below 1 and Ks + T above 1",
         "f 0.4 0.4 0.9 0.5 0.8 0.5 0.6 1.3\ns 0 0 0 1.8\n"},
    };
    for (size_t i = 0; i < sizeof models / sizeof models[0]; i++) {
        char nff[2048];
        snprintf(nff, sizeof nff, VIEW "%s", models[i].body);
        rt_scene_info info;
        check_round_trip(nff, strlen(nff), models[i].what, &info);
        ck_assert_msg(info.smooth_facet_count > 0, "%s", models[i].what);
        ck_assert_msg(info.highlight_facet_count > 0, "%s", models[i].what);
    }
}
END_TEST

static char *read_whole(const char *path, size_t *length)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    char *bytes = NULL;
    size_t used = 0, capacity = 0, n;
    do {
        if (used + 65536 > capacity) {
            capacity = 2 * (used + 65536);
            bytes = realloc(bytes, capacity);
            ck_assert_ptr_nonnull(bytes);
        }
        n = fread(bytes + used, 1, capacity - used, f);
        used += n;
    } while (n > 0);
    fclose(f);
    *length = used;
    return bytes;
}

START_TEST(the_shipped_nff_sphere_converts_to_the_same_render)
{
    size_t length;
    char *bytes = read_whole(rt_test_source_path("scenes/nff-sphere.nff"),
                             &length);
    rt_scene_info info;
    check_round_trip(bytes, length, "nff-sphere.nff", &info);
    ck_assert_int_eq(info.smooth_facet_count, info.facet_count);
    free(bytes);
}
END_TEST

/* Without --extended the course's records drop normals and highlights,
 * and say so. */
START_TEST(a_plain_scn_reports_the_normals_and_highlights_it_drops)
{
    const char *nff = VIEW "f 1 1 1 1 0.2 9 0 0\ns 0 0 0 1\n";
    rt_scene *scene = parse_as(nff, strlen(nff), "t.nff", RT_SCENE_FORMAT_NFF);
    unsigned dropped = 0;
    text scn = write_scn(scene, 0, &dropped);
    ck_assert_uint_eq(dropped & RT_SCN_DROPPED_NORMALS, RT_SCN_DROPPED_NORMALS);
    ck_assert_uint_eq(dropped & RT_SCN_DROPPED_HIGHLIGHTS,
                      RT_SCN_DROPPED_HIGHLIGHTS);
    ck_assert_uint_eq(dropped & RT_SCN_DROPPED_DIFFUSE,
                      RT_SCN_DROPPED_DIFFUSE);
    rt_scene *back =
        parse_as(scn.bytes, scn.length, "plain.scn", RT_SCENE_FORMAT_SCN);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(back, &info);
    ck_assert_int_eq(info.smooth_facet_count, 0);
    ck_assert_int_eq(info.highlight_facet_count, 0);
    free(scn.bytes);
    rt_scene_destroy(back);
    rt_scene_destroy(scene);
}
END_TEST

/* A facet with d = 1 - k - t, s = 0 and p = 1 keeps its short record,
 * a vertex without a normal its three numbers; a normal is written with
 * its vertex, and d before s, p. */
START_TEST(the_extended_writer_writes_a_value_only_where_needed)
{
    const char *scn = "0 0 10\n0 0 5 1 0 5 8 6\n4\n-1 -1 0\n1 -1 0\n"
                      "0 1 0 0 0 1\n0 0 -1\n3\n1 2 3 0.5 10 20 30\n"
                      "1 2 4 0 10 20 30 0 1 0.5\n"
                      "1 3 4 0.25 10 20 30 0 1 0.75 0.5 20\n"
                      "0 0 0\n0 0 10 255 255 255\n";
    rt_scene *scene = parse_as(scn, strlen(scn), "t.scn", RT_SCENE_FORMAT_SCN);
    text out = write_scn(scene, 1, NULL);
    ck_assert_ptr_nonnull(strstr(out.bytes, "\n-1, -1, 0\n"));
    ck_assert_ptr_nonnull(strstr(out.bytes, "\n0, 1, 0, 0, 0, 1\n"));
    ck_assert_ptr_nonnull(strstr(out.bytes, "\n1, 2, 3, 0.5, 10, 20, 30\n"));
    ck_assert_ptr_nonnull(
        strstr(out.bytes, "\n1, 2, 4, 0, 10, 20, 30, 0, 1, 0.5\n"));
    ck_assert_ptr_nonnull(strstr(
        out.bytes, "\n1, 3, 4, 0.25, 10, 20, 30, 0, 1, 0.75, 0.5, 20\n"));
    rt_scene *back = parse_as(out.bytes, out.length, "b.scn",
                              RT_SCENE_FORMAT_SCN);
    assert_same_scene(scene, back);
    free(out.bytes);
    rt_scene_destroy(back);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_spd_scenes_convert_to_the_same_render)
{
    static const char *const files[] = {"formats/tetra-s2.nff",
                                        "formats/mount-s2.nff",
                                        "formats/rings-s2.nff"};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        const char *path = rt_test_shared_path(files[i]);
        ck_assert_ptr_nonnull(path);
        size_t length;
        char *bytes = read_whole(path, &length);
        rt_scene_info info;
        check_round_trip(bytes, length, files[i], &info);
        free(bytes);
    }
}
END_TEST

static Suite *convert_same_suite(void)
{
    Suite *s = suite_create("convert-same");
    TCase *c = tcase_create("round trip");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, nff_models_convert_to_an_extended_scn_that_renders_the_same);
    tcase_add_test(c, the_shipped_nff_sphere_converts_to_the_same_render);
    tcase_add_test(c, a_plain_scn_reports_the_normals_and_highlights_it_drops);
    tcase_add_test(c, the_extended_writer_writes_a_value_only_where_needed);
    suite_add_tcase(s, c);
    return s;
}

static Suite *convert_same_shared_suite(void)
{
    Suite *s = suite_create("convert-same-shared");
    TCase *c = tcase_create("shared");
    tcase_set_timeout(c, 240);
    tcase_add_test(c, the_spd_scenes_convert_to_the_same_render);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN_WITH_SHARED(convert_same_suite, convert_same_shared_suite)
