/*
 * test_obj_view.c - what the Wavefront OBJ reader (src/formats/obj.c)
 * gives a render: the automatic camera (every vertex inside the image, at
 * any image shape), the view and light options in its place, a small cube
 * rendered framed and lit, an OBJ written as .scn rendering the same
 * bytes.  Models from elsewhere are the entry `models`
 * (test_obj_view_models), run when the folder named by RAYTRACE_OBJ_MODELS
 * holds some, a visible skip (77) otherwise.
 */
#include <check.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* The automatic camera and light                                       */

/* Pixel coordinates of p seen by the camera (x right, y down, in
 * [0, w] x [0, h] when inside the image); returns 0 behind the observer. */
static int project(const rt_camera *c, rt_vec3 p, double *x, double *y)
{
    rt_vec3 ao = {c->screen_center.x - c->observer.x,
                  c->screen_center.y - c->observer.y,
                  c->screen_center.z - c->observer.z};
    rt_vec3 op = {p.x - c->observer.x, p.y - c->observer.y,
                  p.z - c->observer.z};
    double along = op.x * ao.x + op.y * ao.y + op.z * ao.z;
    double ao2 = ao.x * ao.x + ao.y * ao.y + ao.z * ao.z;
    if (!(along > 0))
        return 0;
    double s = ao2 / along;
    rt_vec3 q = {op.x * s - ao.x, op.y * s - ao.y, op.z * s - ao.z};
    const rt_vec3 *r = &c->right, *u = &c->up;
    double u_ = (q.x * r->x + q.y * r->y + q.z * r->z) /
                (r->x * r->x + r->y * r->y + r->z * r->z);
    double v_ = (q.x * u->x + q.y * u->y + q.z * u->z) /
                (u->x * u->x + u->y * u->y + u->z * u->z);
    *x = (u_ + 1) * c->width / 2;
    *y = (1 - v_ * c->width / c->height) * c->height / 2;
    return 1;
}

static void every_vertex_inside_the_image(const char *text, int width,
                                          int height)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.width = width;
    options.height = height;
    rt_scene *scene = NULL;
    rt_error error;
    ck_assert_msg(rt_test_parse_obj(text, &options, &scene, &error) == RT_OK,
                  "%s", error.message);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.width, width > 0 ? width : height > 0 ? height : 512);
    ck_assert_int_eq(info.height, height > 0 ? height : info.width);
    for (int i = 0; i < info.vertex_count; i++) {
        double x, y;
        ck_assert(project(&info.camera, rt_scene_vertex(scene, i), &x, &y));
        ck_assert_msg(x >= 0 && x <= info.width && y >= 0 &&
                          y <= info.height,
                      "vertex %d at pixel (%g, %g) of %dx%d", i, x, y,
                      info.width, info.height);
    }
    rt_scene_destroy(scene);
}

START_TEST(the_automatic_camera_sees_every_vertex_at_any_image_shape)
{
    /* A long thin box, off the origin, and a cloud of points. */
    char text[4096];
    size_t used = 0;
    for (int i = 0; i < 8; i++)
        used += (size_t)sprintf(text + used, "v %g %g %g\n",
                                i & 1 ? 1000.0 : -20.0, i & 2 ? 3.0 : 1.0,
                                i & 4 ? 7.0 : 5.0);
    used += (size_t)sprintf(text + used, "f 1 2 4 3\nf 5 6 8 7\n"
                                          "f 1 2 6 5\nf 3 4 8 7\n");
    int sizes[][2] = {{0, 0}, {640, 120}, {90, 700}, {1, 1}, {300, 0}};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        every_vertex_inside_the_image(text, sizes[i][0], sizes[i][1]);
    used = 0;
    rt_test_rng rng = {12345};
    for (int i = 0; i < 60; i++) {
        double c[3];
        for (int k = 0; k < 3; k++)
            c[k] = rt_test_rng_below(&rng, 20001) / 100.0 - 100.0;
        used += (size_t)sprintf(text + used, "v %g %g %g\n", c[0] * 1e-5,
                                c[1] * 1e-5 + 3, c[2] * 1e-5);
    }
    for (int i = 0; i + 2 < 60; i += 3)
        used += (size_t)sprintf(text + used, "f %d %d %d\n", i + 1, i + 2,
                                i + 3);
    every_vertex_inside_the_image(text, 200, 100);
    every_vertex_inside_the_image(text, 100, 200);
}
END_TEST

START_TEST(the_view_and_light_options_replace_the_automatic_ones)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.look_from_given = 1;
    options.look_from = (rt_vec3){0, 0, 10};
    options.look_at_given = 1;
    options.look_at = (rt_vec3){0, 0, 0};
    rt_light light = {{1, 2, 3}, {10, 20, 30}};
    options.lights = &light;
    options.light_count = 1;
    rt_scene *scene = NULL;
    rt_error error;
    ck_assert_int_eq(rt_test_parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                                       &options, &scene, &error),
                     RT_OK);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert(info.camera.observer.z == 10 && info.camera.observer.x == 0);
    ck_assert_int_eq(info.light_count, 1);
    rt_light first;
    rt_scene_light(scene, 0, &first);
    ck_assert(first.position.x == 1 && first.color.b == 30);
    rt_scene_destroy(scene);
}
END_TEST

static int is_background(const rt_image *image, int x, int y,
                         rt_rgb8 background)
{
    const unsigned char *p = rt_image_pixel(image, x, y);
    return p[0] == background.r && p[1] == background.g &&
           p[2] == background.b;
}

START_TEST(a_cube_renders_framed_with_its_red_top_lit)
{
    rt_scene *scene = rt_test_load_source_scene("tests/data/obj/cube.obj");
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 12);
    ck_assert_int_eq(info.live_facet_count, 12);
    ck_assert_int_eq(info.width, 512);
    ck_assert_int_eq(info.height, 512);
    rt_image image = rt_test_render(scene, 5, 2);
    /* The border of the image is background, the centre is not. */
    for (int i = 0; i < 512; i++) {
        ck_assert(is_background(&image, i, 0, info.background));
        ck_assert(is_background(&image, i, 511, info.background));
        ck_assert(is_background(&image, 0, i, info.background));
        ck_assert(is_background(&image, 511, i, info.background));
    }
    ck_assert(!is_background(&image, 256, 256, info.background));
    /* The top (y = 1, red) is seen from above and lit: find red pixels in
     * the upper half, and lit white ones too. */
    long red = 0, white = 0;
    for (int y = 0; y < 512; y++)
        for (int x = 0; x < 512; x++) {
            const unsigned char *p = rt_image_pixel(&image, x, y);
            red += p[0] > 60 && p[1] < p[0] / 4 && p[2] < p[0] / 4 &&
                   y < 256;
            white += p[0] > 60 && p[0] == p[1] && p[1] == p[2];
        }
    ck_assert_msg(red > 2000, "%ld red pixels", red);
    ck_assert_msg(white > 2000, "%ld white pixels", white);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(an_obj_written_as_scn_renders_the_same_bytes)
{
    static const char *const files[] = {"tests/data/obj/cube.obj",
                                        "tests/data/obj/materials.obj"};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        rt_scene *scene = rt_test_load_source_scene(files[i]);
        rt_test_bytes b = {NULL, 0, 0};
        rt_error error;
        unsigned dropped = 0;
        ck_assert_int_eq(rt_scene_write_scn(scene, 1, rt_test_bytes_add, &b,
                                            &dropped, &error),
                         RT_OK);
        rt_scene *again = NULL;
        ck_assert_msg(rt_scene_parse((const char *)b.data, b.size,
                                     "converted.scn", NULL, &again,
                                     &error) == RT_OK,
                      "%s", error.message);
        rt_image direct = rt_test_render(scene, 5, 2);
        rt_image converted = rt_test_render(again, 5, 2);
        ck_assert_int_eq(rt_test_image_diff(&direct, &converted, NULL), 0);
        rt_image_release(&direct);
        rt_image_release(&converted);
        rt_scene_destroy(again);
        rt_scene_destroy(scene);
        free(b.data);
    }
}
END_TEST

/* ------------------------------------------------------------------ */
/* Models from elsewhere                                                */

START_TEST(real_models_in_raytrace_obj_models_load_and_render)
{
    const char *folder = getenv("RAYTRACE_OBJ_MODELS");
    DIR *dir = opendir(folder);
    ck_assert_msg(dir != NULL, "cannot read %s", folder);
    int models = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        size_t n = strlen(entry->d_name);
        if (n < 5 || strcmp(entry->d_name + n - 4, ".obj") != 0)
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", folder, entry->d_name);
        rt_load_options options;
        rt_load_options_init(&options);
        options.width = options.height = 64;
        rt_scene *scene = NULL;
        rt_error error;
        ck_assert_msg(rt_scene_load(path, &options, &scene, &error) == RT_OK,
                      "%s", error.message);
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        ck_assert_int_gt(info.live_facet_count, 0);
        rt_image image = rt_test_render(scene, 1, 2);
        long covered = 0;
        for (int y = 0; y < 64; y++)
            for (int x = 0; x < 64; x++)
                covered += !is_background(&image, x, y, info.background);
        ck_assert_msg(covered > 64 * 64 / 20, "%s covers %ld pixels", path,
                      covered);
        printf("test_obj_view: %s: %d facets, %ld of 4096 pixels covered\n",
               entry->d_name, info.facet_count, covered);
        rt_image_release(&image);
        rt_scene_destroy(scene);
        models++;
    }
    closedir(dir);
    ck_assert_msg(models > 0, "no .obj file in %s", folder);
}
END_TEST

static Suite *obj_view_suite(void)
{
    Suite *s = suite_create("obj_view");
    TCase *c = tcase_create("view");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, the_automatic_camera_sees_every_vertex_at_any_image_shape);
    tcase_add_test(c, the_view_and_light_options_replace_the_automatic_ones);
    tcase_add_test(c, a_cube_renders_framed_with_its_red_top_lit);
    tcase_add_test(c, an_obj_written_as_scn_renders_the_same_bytes);
    suite_add_tcase(s, c);
    return s;
}

/* Models from elsewhere: their own ctest entry, test_obj_view_models. */
static Suite *models_suite(void)
{
    Suite *s = suite_create("obj_view, models");
    TCase *c = tcase_create("models");
    tcase_set_timeout(c, 600);
    tcase_add_test(c, real_models_in_raytrace_obj_models_load_and_render);
    suite_add_tcase(s, c);
    return s;
}

/* Why the models cannot be checked, or NULL. */
static const char *no_models(void)
{
    const char *folder = getenv("RAYTRACE_OBJ_MODELS");
    DIR *dir = folder && *folder ? opendir(folder) : NULL;
    int models = 0;
    struct dirent *entry;
    while (dir != NULL && (entry = readdir(dir)) != NULL) {
        size_t n = strlen(entry->d_name);
        models += n >= 5 && strcmp(entry->d_name + n - 4, ".obj") == 0;
    }
    if (dir != NULL)
        closedir(dir);
    if (models == 0)
        return "set RAYTRACE_OBJ_MODELS to a folder of .obj files (e.g. "
               "github.com/alecjacobson/common-3d-test-models data/) to run "
               "real_models_in_raytrace_obj_models_load_and_render";
    return NULL;
}

int main(int argc, char **argv)
{
    return rt_test_main_with_entry(argc, argv, obj_view_suite, "models",
                                   models_suite, no_models);
}
