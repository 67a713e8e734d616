/*
 * test_in104_scene.c - the handout's parse() and this layer's freeScene()
 * and renderToPPM() (raytracer.h of the in104 layer): every field filled,
 * agreement with libraytrace's own loader and renderer on every scene,
 * errors on stderr with a non-zero return, and nothing left allocated.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "geometry.h"
#include "intersection.h"
#include "raytracer.h"
#include "testutil.h"

/* What a call wrote on stderr: stderr goes to a temporary file meanwhile.
 * Each Check test runs in its own process, so this cannot leak. */
static char captured[4096];
static int saved_stderr = -1;

static void capture_begin(void)
{
    fflush(stderr);
    saved_stderr = dup(2);
    FILE *sink = tmpfile();
    ck_assert_ptr_nonnull(sink);
    dup2(fileno(sink), 2);
    fclose(sink);                       /* fd 2 keeps it open */
}

static const char *capture_end(void)
{
    fflush(stderr);
    off_t size = lseek(2, 0, SEEK_END);
    lseek(2, 0, SEEK_SET);
    ssize_t got = read(2, captured, sizeof captured - 1);
    ck_assert_int_eq((long)got, (long)size);
    captured[got > 0 ? got : 0] = '\0';
    dup2(saved_stderr, 2);
    close(saved_stderr);
    return captured;
}

static int scene_is_zeroed(const scene *s)
{
    scene zero;
    memset(&zero, 0, sizeof zero);
    return memcmp(s, &zero, sizeof zero) == 0;
}

static void assert_same_point(point p, rt_vec3 v)
{
    ck_assert_double_eq(p.x, v.x);
    ck_assert_double_eq(p.y, v.y);
    ck_assert_double_eq(p.z, v.z);
}

static void assert_same_color(color c, rt_rgb8 expected)
{
    ck_assert_int_eq(c.r, expected.r);
    ck_assert_int_eq(c.g, expected.g);
    ck_assert_int_eq(c.b, expected.b);
}

/* parse(path) must agree with rt_scene_load(path) on every field. */
static void assert_parse_agrees_with_core(const char *path)
{
    rt_scene *core = NULL;
    rt_error error;
    ck_assert_msg(rt_scene_load(path, NULL, &core, &error) == RT_OK, "%s",
                  error.message);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(core, &info);

    scene s;
    capture_begin();                    /* zero-area warnings */
    int status = parse((char *)path, &s);
    capture_end();
    ck_assert_msg(status == 0, "parse(%s) = %d", path, status);

    ck_assert_int_eq(s.width, info.width);
    ck_assert_int_eq(s.height, info.height);
    ck_assert_int_eq(s.nbPoints, info.vertex_count);
    ck_assert_int_eq(s.nbFacets, info.facet_count);
    assert_same_point(s.obs, info.camera.observer);
    assert_same_point(s.screenA, info.camera.screen_center);
    /* screenB = A + AB (projected): exact up to the rounding of the sum */
    ck_assert_double_eq_tol(s.screenB.x - s.screenA.x, info.camera.right.x,
                            1e-12 * (1 + fabs(s.screenA.x)));
    ck_assert_double_eq_tol(s.screenB.y - s.screenA.y, info.camera.right.y,
                            1e-12 * (1 + fabs(s.screenA.y)));
    ck_assert_double_eq_tol(s.screenB.z - s.screenA.z, info.camera.right.z,
                            1e-12 * (1 + fabs(s.screenA.z)));
    assert_same_color(s.back, info.background);
    rt_light light;
    rt_scene_light(core, 0, &light);
    assert_same_point(s.s.p, light.position);
    assert_same_color(s.s.cp, light.color);
    for (int i = 0; i < s.nbPoints; i++)
        assert_same_point(s.points[i], rt_scene_vertex(core, i));
    for (int i = 0; i < s.nbFacets; i++) {
        rt_facet_info record = {.size = sizeof record};
        rt_scene_facet(core, i, &record);
        facet f = s.facets[i];
        assert_same_point(f.a, rt_scene_vertex(core, record.vertex[0]));
        assert_same_point(f.b, rt_scene_vertex(core, record.vertex[1]));
        assert_same_point(f.c, rt_scene_vertex(core, record.vertex[2]));
        ck_assert_double_eq(f.k, record.reflection);
        assert_same_color(f.cp, record.color);
        /* exactly createFacet's normal; the core's to a few roundings */
        facet made = createFacet(f.a, f.b, f.c);
        ck_assert(memcmp(&f.n, &made.n, sizeof f.n) == 0);
        ck_assert_double_eq_tol(f.n.x, record.normal.x, 1e-12);
        ck_assert_double_eq_tol(f.n.y, record.normal.y, 1e-12);
        ck_assert_double_eq_tol(f.n.z, record.normal.z, 1e-12);
    }
    freeScene(&s);
    rt_scene_destroy(core);
}

/* ---- parse -------------------------------------------------------------- */

START_TEST(parse_fills_every_field_of_the_handout_cubes_scene)
{
    const char *path = rt_test_shared_path("seed-scenes/cubes.scn");
    ck_assert_ptr_nonnull(path);
    scene s;
    ck_assert_int_eq(parse((char *)path, &s), 0);
    ck_assert_int_eq(s.width, 400);
    ck_assert_int_eq(s.height, 400);
    ck_assert_int_eq(s.nbPoints, 12);
    ck_assert_int_eq(s.nbFacets, 14);
    ck_assert(s.obs.x == 8 && s.obs.y == -8 && s.obs.z == -3);
    ck_assert(s.screenA.x == 3 && s.screenA.y == -3 && s.screenA.z == -1);
    /* The file's B = (3, -9, 0) is not perpendicular to AO: screenB is its
     * projection on the plane through A perpendicular to AO = (5, -5, -2). */
    point ab = {s.screenB.x - 3, s.screenB.y + 3, s.screenB.z + 1};
    ck_assert_double_eq_tol(ab.x * 5 - ab.y * 5 - ab.z * 2, 0, 1e-12);
    /* AB - projection = a multiple of AO: (0,-6,1) - t (5,-5,-2), t = 28/54 */
    double t = 28.0 / 54;
    ck_assert_double_eq_tol(ab.x, 0 - 5 * t, 1e-12);
    ck_assert_double_eq_tol(ab.y, -6 + 5 * t, 1e-12);
    ck_assert_double_eq_tol(ab.z, 1 + 2 * t, 1e-12);
    ck_assert(s.points[8].x == -10 && s.points[8].y == -10
              && s.points[8].z == 2);
    facet floor = s.facets[12];         /* 9,10,11,0.7,200,200,200 */
    ck_assert(floor.a.x == -10 && floor.b.y == 10 && floor.c.x == 10);
    ck_assert_double_eq(floor.k, 0.7);
    ck_assert(floor.cp.r == 200 && floor.cp.g == 200 && floor.cp.b == 200);
    ck_assert_double_eq_tol(fabs(floor.n.z), 1, 1e-15);
    ck_assert(s.facets[10].cp.g == 100);
    ck_assert(s.back.r == 10 && s.back.g == 10 && s.back.b == 10);
    ck_assert(s.s.p.x == 2 && s.s.p.y == -2 && s.s.p.z == -3);
    ck_assert(s.s.cp.r == 255 && s.s.cp.g == 255 && s.s.cp.b == 255);
    freeScene(&s);
}
END_TEST

START_TEST(parse_agrees_with_the_core_loader_on_every_scene)
{
    static const char *project[] = {"cubes", "empty", "mirror", "one-facet",
                                    "two-facets"};
    char relative[256];
    for (size_t i = 0; i < sizeof project / sizeof project[0]; i++) {
        snprintf(relative, sizeof relative, "scenes/%s.scn", project[i]);
        assert_parse_agrees_with_core(rt_test_source_path(relative));
    }
}
END_TEST

START_TEST(parse_agrees_with_the_core_loader_on_the_handouts_seed_scenes)
{
    static const char *seed[] = {"cubes", "mirror", "test1", "test2"};
    char relative[256];
    for (size_t i = 0; i < sizeof seed / sizeof seed[0]; i++) {
        snprintf(relative, sizeof relative, "seed-scenes/%s.scn", seed[i]);
        const char *path = rt_test_shared_path(relative);
        ck_assert_ptr_nonnull(path);
        assert_parse_agrees_with_core(path);
    }
}
END_TEST

START_TEST(parse_reads_what_the_core_reads_crlf_bom_and_separators)
{
    rt_test_write_file("in104_crlf.scn",
                       "\xEF\xBB\xBF# BOM, CRLF, spaces and commas mixed\r\n"
                       "0 0 10\r\n"
                       "0,0,5 , 1 0 5, 8., 6.0\r\n"
                       "\r\n"
                       "3\r\n-1 -1 0\r\n1,-1,0\r\n0 1 0   # a comment\r\n"
                       "1\r\n1 2 3 0.25 10 20 30\r\n"
                       "1 2 3\r\n"
                       "0 0 10 255 255 255\r\n");
    scene s;
    ck_assert_int_eq(parse("in104_crlf.scn", &s), 0);
    ck_assert_int_eq(s.width, 8);
    ck_assert_int_eq(s.height, 6);
    ck_assert_int_eq(s.nbFacets, 1);
    ck_assert_double_eq(s.facets[0].k, 0.25);
    ck_assert_int_eq(s.facets[0].cp.b, 30);
    ck_assert_double_eq(s.facets[0].n.z, 1);
    freeScene(&s);
    assert_parse_agrees_with_core("in104_crlf.scn");
}
END_TEST

START_TEST(parse_prints_the_loaders_message_and_returns_nonzero)
{
    const char *text = "0 0 10\n0 0 5 1 0 5 8 6\n1\n0 0 zero\n";
    rt_test_write_file("in104_bad.scn", text);
    rt_scene *core = NULL;
    rt_error error;
    rt_status expected = rt_scene_load("in104_bad.scn", NULL, &core, &error);
    ck_assert_int_ne(expected, RT_OK);

    scene s;
    s.points = (point *)&s;             /* garbage that parse must clear */
    capture_begin();
    int status = parse("in104_bad.scn", &s);
    const char *printed = capture_end();
    ck_assert_int_ne(status, 0);
    ck_assert_int_eq(status, (int)expected);
    ck_assert(scene_is_zeroed(&s));
    ck_assert_str_eq(printed, strcat(strcpy(captured + 2048, error.message),
                                     "\n"));
    ck_assert_ptr_nonnull(strstr(printed, "in104_bad.scn:4:"));
    freeScene(&s);                      /* harmless on a zeroed scene */
}
END_TEST

/* The course's struct has one light, no transparency and a pinhole: a
 * file that uses more is refused with a message that says so, and the
 * same file without the extension is read. */
START_TEST(parse_refuses_a_file_that_uses_the_extensions)
{
    static const struct {
        const char *screen, *facet, *more_light, *word;
    } cases[] = {
        {"0 0 5 1 0 5 8 6", "1 2 3 0 10 20 30", "5 5 5 255 255 255",
         "several lights"},
        {"0 0 5 1 0 5 8 6", "1 2 3 0 10 20 30 0.5 1.5", "",
         "transparent facets"},
        {"0 0 5 1 0 5 8 6 0.2 5", "1 2 3 0 10 20 30", "", "aperture"},
        {"0 0 5 1 0 5 8 6", "1 2 3 0 10 20 30 0 1 0.5", "",
         "diffuse weights"},
        {"0 0 5 1 0 5 8 6", "1 2 3 0 10 20 30 0 1 1 0.5 10", "",
         "highlights"},
        {"0 0 5 1 0 5 8 6", "1 2 3 0 10 20 30\n#n", "", "vertex normals"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[512];
        /* a facet ending in "#n": the vertices carry normals */
        int normals = strstr(cases[i].facet, "#n") != NULL;
        snprintf(text, sizeof text,
                 "0 0 10\n%s\n3\n-1 -1 0%s\n1 -1 0%s\n0 1 0%s\n1\n%s\n"
                 "1 2 3\n0 0 10 255 255 255\n%s\n",
                 cases[i].screen, normals ? " 0 0 1" : "",
                 normals ? " 0 0 1" : "", normals ? " 0 0 1" : "",
                 cases[i].facet, cases[i].more_light);
        rt_test_write_file("in104_extended.scn", text);
        scene s;
        capture_begin();
        int status = parse("in104_extended.scn", &s);
        const char *printed = capture_end();
        ck_assert_int_eq(status, RT_ERR_FORMAT);
        ck_assert(scene_is_zeroed(&s));
        ck_assert_msg(strstr(printed, "beyond the handout") != NULL &&
                          strstr(printed, cases[i].word) != NULL,
                      "case %zu: %s", i, printed);
    }
}
END_TEST

START_TEST(parse_reports_a_missing_record_and_a_missing_file)
{
    rt_test_write_file("in104_short.scn",
                       "0 0 10\n0 0 5 1 0 5 8 6\n0\n0\n1 2 3\n");
    scene s;
    capture_begin();
    int status = parse("in104_short.scn", &s);
    const char *printed = capture_end();
    ck_assert_int_ne(status, 0);
    ck_assert_ptr_nonnull(strstr(printed, "in104_short.scn:"));
    ck_assert_ptr_nonnull(strstr(printed, "light"));
    ck_assert(scene_is_zeroed(&s));

    capture_begin();
    status = parse("in104_no_such_file.scn", &s);
    printed = capture_end();
    ck_assert_int_ne(status, 0);
    ck_assert_ptr_nonnull(strstr(printed, "in104_no_such_file.scn"));
    ck_assert(scene_is_zeroed(&s));
}
END_TEST

START_TEST(parse_of_an_empty_scene_gives_null_arrays)
{
    scene s;
    ck_assert_int_eq(parse((char *)rt_test_source_path("scenes/empty.scn"),
                           &s), 0);
    ck_assert_int_eq(s.nbPoints, 0);
    ck_assert_int_eq(s.nbFacets, 0);
    ck_assert_ptr_null(s.points);
    ck_assert_ptr_null(s.facets);
    ck_assert_int_eq(s.width, 8);
    freeScene(&s);
}
END_TEST

START_TEST(parse_keeps_a_zero_area_facet_with_a_warning)
{
    rt_test_write_file("in104_flat.scn",
                       "0 0 10\n0 0 5 1 0 5 8 6\n"
                       "3\n0 0 0\n1 1 0\n2 2 0\n"
                       "1\n1 2 3 0 255 0 0\n"
                       "0 0 0\n0 0 10 255 255 255\n");
    scene s;
    capture_begin();
    int status = parse("in104_flat.scn", &s);
    const char *printed = capture_end();
    ck_assert_int_eq(status, 0);
    ck_assert_ptr_nonnull(strstr(printed, "in104_flat.scn:8:"));
    ck_assert_ptr_nonnull(strstr(printed, "warning"));
    ck_assert_int_eq(s.nbFacets, 1);
    ck_assert(s.facets[0].n.x == 0 && s.facets[0].n.y == 0
              && s.facets[0].n.z == 0);
    ck_assert(!isInFacet(s.points[1], s.facets[0]));
    freeScene(&s);
}
END_TEST

START_TEST(parse_refuses_null_arguments)
{
    scene s;
    capture_begin();
    ck_assert_int_ne(parse(NULL, &s), 0);
    ck_assert(scene_is_zeroed(&s));
    ck_assert_int_ne(parse((char *)rt_test_source_path("scenes/empty.scn"),
                           NULL), 0);
    ck_assert_ptr_nonnull(strstr(capture_end(), "parse: "));
}
END_TEST

/* ---- freeScene ---------------------------------------------------------- */

START_TEST(free_scene_releases_and_can_be_called_again)
{
    scene s;
    ck_assert_int_eq(parse((char *)rt_test_source_path("scenes/cubes.scn"),
                           &s), 0);
    freeScene(&s);
    ck_assert_ptr_null(s.points);
    ck_assert_ptr_null(s.facets);
    ck_assert_int_eq(s.nbPoints, 0);
    ck_assert_int_eq(s.nbFacets, 0);
    freeScene(&s);
    freeScene(NULL);
}
END_TEST

/* ---- renderToPPM -------------------------------------------------------- */

/* Renders `path` through parse + renderToPPM and through the core; the
 * images must be identical. */
static void assert_render_matches_core(const char *path)
{
    scene s;
    capture_begin();
    ck_assert_int_eq(parse((char *)path, &s), 0);
    capture_end();
    ck_assert_int_eq(renderToPPM(&s, "in104_render.ppm"), 0);
    freeScene(&s);

    rt_image got, expected;
    rt_error error;
    ck_assert_msg(rt_ppm_load("in104_render.ppm", &got, &error) == RT_OK,
                  "%s", error.message);
    rt_scene *core = NULL;
    ck_assert(rt_scene_load(path, NULL, &core, &error) == RT_OK);
    expected = rt_test_render(core, RT_DEFAULT_DEPTH, 0);
    ck_assert_int_eq(got.width, expected.width);
    ck_assert_int_eq(got.height, expected.height);
    int max_diff = 0;
    long differing = rt_test_image_diff(&got, &expected, &max_diff);
    ck_assert_msg(differing == 0, "%s: %ld pixels differ (by up to %d)",
                  path, differing, max_diff);
    rt_image_release(&got);
    rt_image_release(&expected);
    rt_scene_destroy(core);
}

START_TEST(render_to_ppm_gives_the_core_renderers_image)
{
    static const char *scenes[] = {"scenes/one-facet.scn",
                                   "scenes/two-facets.scn",
                                   "scenes/empty.scn", "scenes/cubes.scn",
                                   "scenes/mirror.scn"};
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        assert_render_matches_core(rt_test_source_path(scenes[i]));
}
END_TEST

START_TEST(render_to_ppm_writes_the_handouts_p3_format)
{
    scene s;
    ck_assert_int_eq(parse((char *)rt_test_source_path("scenes/empty.scn"),
                           &s), 0);
    ck_assert_int_eq(renderToPPM(&s, "in104_p3.ppm"), 0);
    FILE *file = fopen("in104_p3.ppm", "rb");
    ck_assert_ptr_nonnull(file);
    char magic[3] = {0};
    ck_assert_int_eq((int)fread(magic, 1, 2, file), 2);
    fclose(file);
    ck_assert_str_eq(magic, "P3");
    freeScene(&s);
}
END_TEST

/* One facet filling the view, facing the camera, lit from the observer:
 * the centre pixel is the facet's colour times N.S = 1. */
static scene hand_made_scene(facet *storage)
{
    scene s;
    memset(&s, 0, sizeof s);
    s.width = 3;
    s.height = 3;
    s.obs = (point){0, 0, 10};
    s.screenA = (point){0, 0, 5};
    s.screenB = (point){1, 0, 5};
    *storage = createFacet((point){-100, -100, 0}, (point){100, -100, 0},
                           (point){0, 100, 0});
    storage->cp = (color){200, 100, 50};
    s.facets = storage;
    s.nbFacets = 1;
    s.back = (color){1, 2, 3};
    s.s.p = (point){0, 0, 10};
    s.s.cp = (color){255, 255, 255};
    return s;
}

START_TEST(render_to_ppm_renders_a_scene_built_by_hand)
{
    facet storage;
    scene s = hand_made_scene(&storage);
    ck_assert_int_eq(renderToPPM(&s, "in104_hand.ppm"), 0);
    rt_image image;
    rt_error error;
    ck_assert(rt_ppm_load("in104_hand.ppm", &image, &error) == RT_OK);
    const unsigned char *centre = rt_image_pixel(&image, 1, 1);
    ck_assert_int_eq(centre[0], 200);
    ck_assert_int_eq(centre[1], 100);
    ck_assert_int_eq(centre[2], 50);
    rt_image_release(&image);

    /* the facets array is the truth: no facet, only the background */
    s.nbFacets = 0;
    ck_assert_int_eq(renderToPPM(&s, "in104_hand.ppm"), 0);
    ck_assert(rt_ppm_load("in104_hand.ppm", &image, &error) == RT_OK);
    centre = rt_image_pixel(&image, 1, 1);
    ck_assert(centre[0] == 1 && centre[1] == 2 && centre[2] == 3);
    rt_image_release(&image);
}
END_TEST

START_TEST(render_to_ppm_refuses_a_bad_scene_and_writes_nothing)
{
    facet storage;
    scene s = hand_made_scene(&storage);
    unlink("in104_never.ppm");

    s.width = 0;
    capture_begin();
    ck_assert_int_ne(renderToPPM(&s, "in104_never.ppm"), 0);
    ck_assert_ptr_nonnull(strstr(capture_end(), "renderToPPM: "));

    s.width = 3;
    s.screenB = s.screenA;              /* degenerate camera */
    capture_begin();
    ck_assert_int_ne(renderToPPM(&s, "in104_never.ppm"), 0);
    capture_end();

    s = hand_made_scene(&storage);
    storage.k = 1.5;                    /* k outside [0, 1] */
    capture_begin();
    ck_assert_int_ne(renderToPPM(&s, "in104_never.ppm"), 0);
    capture_end();

    s = hand_made_scene(&storage);
    s.facets = NULL;                    /* counts that lie */
    capture_begin();
    ck_assert_int_ne(renderToPPM(&s, "in104_never.ppm"), 0);
    ck_assert_int_ne(renderToPPM(NULL, "in104_never.ppm"), 0);
    ck_assert_int_ne(renderToPPM(&s, NULL), 0);
    capture_end();
    ck_assert_int_ne(access("in104_never.ppm", F_OK), 0);
}
END_TEST

static Suite *in104_scene_suite(void)
{
    Suite *suite = suite_create("in104_scene");
    TCase *parsing = tcase_create("parse");
    tcase_add_test(parsing, parse_agrees_with_the_core_loader_on_every_scene);
    tcase_add_test(parsing, parse_reads_what_the_core_reads_crlf_bom_and_separators);
    tcase_add_test(parsing, parse_prints_the_loaders_message_and_returns_nonzero);
    tcase_add_test(parsing, parse_reports_a_missing_record_and_a_missing_file);
    tcase_add_test(parsing, parse_refuses_a_file_that_uses_the_extensions);
    tcase_add_test(parsing, parse_of_an_empty_scene_gives_null_arrays);
    tcase_add_test(parsing, parse_keeps_a_zero_area_facet_with_a_warning);
    tcase_add_test(parsing, parse_refuses_null_arguments);
    tcase_add_test(parsing, free_scene_releases_and_can_be_called_again);
    suite_add_tcase(suite, parsing);

    TCase *rendering = tcase_create("renderToPPM");
    tcase_set_timeout(rendering, 60);
    tcase_add_test(rendering, render_to_ppm_gives_the_core_renderers_image);
    tcase_add_test(rendering, render_to_ppm_writes_the_handouts_p3_format);
    tcase_add_test(rendering, render_to_ppm_renders_a_scene_built_by_hand);
    tcase_add_test(rendering, render_to_ppm_refuses_a_bad_scene_and_writes_nothing);
    suite_add_tcase(suite, rendering);
    return suite;
}

/* The handout's seed scenes: their own ctest entry, skipped when absent. */
static Suite *in104_scene_shared_suite(void)
{
    Suite *suite = suite_create("in104_scene-shared");
    TCase *parsing = tcase_create("parse");
    tcase_add_test(parsing, parse_fills_every_field_of_the_handout_cubes_scene);
    tcase_add_test(parsing,
                   parse_agrees_with_the_core_loader_on_the_handouts_seed_scenes);
    suite_add_tcase(suite, parsing);
    return suite;
}

RT_CHECK_MAIN_WITH_SHARED(in104_scene_suite, in104_scene_shared_suite)
