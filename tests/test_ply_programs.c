/*
 * test_ply_programs.c - PLY files by name and in the programs: an unknown
 * extension refused with the formats listed (rt_scene_load, rt-export,
 * rt-convert), a file without one still read as .scn; rt-export renders a
 * PLY byte for byte as the .scn rt-convert writes from it, and as the same
 * PLY through standard input.  Every file is generated here
 * (tests/ply_files.c).
 */
#include <check.h>
#include <stdlib.h>
#include <string.h>

#include "ply_files.h"
#include "testutil.h"
#include "raytrace/raytrace.h"

/* ------------------------------------------------------------------ */
/* Names and programs                                                   */

START_TEST(an_unknown_extension_is_refused_with_the_formats_listed)
{
    rt_scene *scene;
    rt_error error;
    static const char scn[] = "0 0 10\n0 0 5 4 0 5 8 8\n0\n0\n0 0 0\n"
                              "0 0 4 255 255 255\n";
    char *dir = rt_test_temp_dir();
    rt_test_path txt = rt_test_path_at(dir, "scene.txt");
    rt_test_path bare = rt_test_path_at(dir, "scene");
    rt_test_write_file(txt.s, scn);
    rt_test_write_file(bare.s, scn);
    ck_assert_int_eq(rt_scene_load(txt.s, NULL, &scene, &error),
                     RT_ERR_FORMAT);
    ck_assert_msg(strstr(error.message, "/scene.txt: cannot tell the scene "
                                        "format: expected the extension "
                                        ".scn, .nff, .obj or .ply (or give "
                                        "the format: --input-format)") !=
                      NULL,
                  "%s", error.message);
    /* a file without an extension is read as .scn, as it always was; so is
     * text in memory whatever its name (a label there) */
    ck_assert_int_eq(rt_scene_load(bare.s, NULL, &scene, &error), RT_OK);
    rt_scene_destroy(scene);
    ck_assert_int_eq(ply_parse_named(scn, strlen(scn), "scene 1.5 (text)", NULL,
                                 &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
    rt_scene_format format;
    ck_assert_int_eq(rt_scene_format_from_path("a/b.PLY", &format, NULL),
                     RT_OK);
    ck_assert_int_eq(format, RT_SCENE_FORMAT_PLY);
    ck_assert_str_eq(rt_scene_format_name(RT_SCENE_FORMAT_PLY), "ply");
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(rt_export_renders_a_ply_as_its_conversion_to_scn)
{
    char *dir = rt_test_temp_dir();
    ply_blob b = ply_mesh(2, "uchar", "int", 1);
    rt_test_write_bytes(rt_test_in_dir(dir, "m.ply"), b.data, b.length);
    rt_test_write_file(rt_test_in_dir(dir, "m.txt"), ply_mesh_obj);
    const char *convert[] = {"m.ply", "m.scn", NULL};
    rt_test_output out = rt_test_run(dir, RT_CONVERT_PATH, convert);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    const char *direct[] = {"m.ply", "-o", "a.ppm", NULL};
    const char *converted[] = {"m.scn", "-o", "b.ppm", NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, direct);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    out = rt_test_run(dir, RT_EXPORT_PATH, converted);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    /* a binary PLY through standard input, its format given */
    const char *piped[] = {"--input-format", "ply", "-", "-o", "s.ppm", NULL};
    rt_test_setup setup = {0};
    setup.stdin_path = rt_test_in_dir(dir, "m.ply");
    out = rt_test_run_with(dir, RT_EXPORT_PATH, piped, &setup);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    size_t na, nb, ns;
    char *a = rt_test_read_file(rt_test_in_dir(dir, "a.ppm"), &na);
    char *c = rt_test_read_file(rt_test_in_dir(dir, "b.ppm"), &nb);
    char *piped_image = rt_test_read_file(rt_test_in_dir(dir, "s.ppm"), &ns);
    ck_assert_uint_eq(na, nb);
    ck_assert_uint_eq(na, ns);
    ck_assert_uint_gt(na, 100);
    ck_assert_int_eq(memcmp(a, c, na), 0);
    ck_assert_int_eq(memcmp(a, piped_image, na), 0);
    free(a);
    free(c);
    free(piped_image);
    /* an unknown extension: both programs list the formats */
    const char *unknown_export[] = {"m.txt", "-o", "c.ppm", NULL};
    const char *unknown_convert[] = {"m.txt", "c.scn", NULL};
    const char *programs[] = {RT_EXPORT_PATH, RT_CONVERT_PATH};
    const char *const *args[] = {unknown_export, unknown_convert};
    for (int i = 0; i < 2; i++) {
        out = rt_test_run(dir, programs[i], args[i]);
        ck_assert_int_eq(out.code, 1);
        ck_assert_msg(strstr(out.err, "m.txt: cannot tell the scene format: "
                                      "expected the extension .scn, .nff, "
                                      ".obj or .ply") != NULL,
                      "%s", out.err);
        rt_test_output_free(&out);
    }
    /* --input-format reads it anyway */
    const char *forced[] = {"--input-format", "obj", "m.txt", "-o", "c.ppm",
                            NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, forced);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    free(b.data);
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *ply_programs_suite(void)
{
    Suite *s = suite_create("ply_programs");
    TCase *t = tcase_create("ply_programs");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, an_unknown_extension_is_refused_with_the_formats_listed);
    tcase_add_test(t, rt_export_renders_a_ply_as_its_conversion_to_scn);
    suite_add_tcase(s, t);
    return s;
}

RT_CHECK_MAIN(ply_programs_suite)
