/*
 * test_mesh_convert.c - SPEC section 8's promise for the mesh readers:
 * `rt-convert --extended` of an OBJ with and without vertex normals (and an
 * MTL with Ks and Ns) and of a PLY with normals writes a .scn that renders
 * byte for byte as the model itself.  It needs the extended .scn records
 * of section 8 (vertex normals; d, s, p on a facet), which the .scn writer
 * and reader carry.
 */
#include <check.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static void renders_as_its_conversion(const char *name, const char *text,
                                      size_t length)
{
    char *dir = rt_test_temp_dir();
    rt_test_write_file(rt_test_in_dir(dir, "shiny.mtl"),
                       "newmtl shiny\nKd 0.8 0.3 0.2\nKs 0.5 0.6 0.7\n"
                       "Ns 40\nillum 2\n"
                       "newmtl mirror\nKd 0.2 0.2 0.2\nKs 0.4\nNs 8\n"
                       "illum 3\n");
    rt_test_write_bytes(rt_test_in_dir(dir, name), text, length);
    const char *convert[] = {"--extended", name, "m.scn", NULL};
    rt_test_output out = rt_test_run(dir, RT_CONVERT_PATH, convert);
    ck_assert_msg(out.code == 0, "%s: %s", name, out.err);
    rt_test_output_free(&out);
    const char *direct[] = {name, "-q", "--size", "48x40", "-o", "a.ppm",
                            NULL};
    const char *converted[] = {"m.scn", "-q", "--size", "48x40", "-o",
                               "b.ppm", NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, direct);
    ck_assert_msg(out.code == 0, "%s: %s", name, out.err);
    rt_test_output_free(&out);
    out = rt_test_run(dir, RT_EXPORT_PATH, converted);
    ck_assert_msg(out.code == 0, "%s converted: %s", name, out.err);
    rt_test_output_free(&out);
    size_t na, nb;
    char *a = rt_test_read_file(rt_test_in_dir(dir, "a.ppm"), &na);
    char *b = rt_test_read_file(rt_test_in_dir(dir, "b.ppm"), &nb);
    ck_assert_ptr_nonnull(a);
    ck_assert_ptr_nonnull(b);
    ck_assert_uint_gt(na, 100);
    ck_assert_msg(na == nb && memcmp(a, b, na) == 0,
                  "%s and its --extended conversion render different bytes",
                  name);
    free(a);
    free(b);
    rt_test_remove_dir(dir);
}

/* An octahedron: smooth (its normals at the corners), a cube corner with a
 * normal per face (copies), and a flat face, in two materials. */
static const char smooth_obj[] =
    "mtllib shiny.mtl\n"
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
    "vn 1 0 0\nvn -1 0 0\nvn 0 1 0\nvn 0 -1 0\nvn 0 0 1\nvn 0 0 -1\n"
    "vn 1 1 1\n"
    "usemtl shiny\n"
    "f 1//1 3//3 5//5\nf 3//3 2//2 5//5\nf 2//2 4//4 5//5\n"
    "f 4//4 1//1 5//5\nf 3//7 1//7 6//7\n"
    "usemtl mirror\n"
    "f 2//2 3//3 6//6\nf 4//4 2//2 6//6\nf 1 4 6\n";

static const char flat_obj[] =
    "mtllib shiny.mtl\n"
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
    "usemtl shiny\n"
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\n"
    "usemtl mirror\n"
    "f 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

static const char normals_ply[] =
    "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\n"
    "property float y\nproperty float z\nproperty float nx\n"
    "property float ny\nproperty float nz\nelement face 8\n"
    "property list uchar int vertex_indices\nend_header\n"
    "1 0 0 1 0 0\n-1 0 0 -1 0 0\n0 1 0 0 1 0\n0 -1 0 0 -1 0\n"
    "0 0 1 0 0 1\n0 0 -1 0 0 0\n"
    "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n"
    "3 0 3 5\n";

START_TEST(an_obj_with_normals_and_highlights_renders_as_its_conversion)
{
    renders_as_its_conversion("smooth.obj", smooth_obj, strlen(smooth_obj));
}
END_TEST

START_TEST(an_obj_without_normals_renders_as_its_conversion)
{
    renders_as_its_conversion("flat.obj", flat_obj, strlen(flat_obj));
}
END_TEST

START_TEST(a_ply_with_normals_renders_as_its_conversion)
{
    renders_as_its_conversion("normals.ply", normals_ply,
                              strlen(normals_ply));
}
END_TEST

static Suite *mesh_convert_suite(void)
{
    Suite *s = suite_create("mesh_convert");
    TCase *c = tcase_create("extended");
    tcase_add_test(c,
                   an_obj_with_normals_and_highlights_renders_as_its_conversion);
    tcase_add_test(c, an_obj_without_normals_renders_as_its_conversion);
    tcase_add_test(c, a_ply_with_normals_renders_as_its_conversion);
    tcase_set_timeout(c, 60);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(mesh_convert_suite)
