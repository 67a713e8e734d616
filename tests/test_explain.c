/*
 * test_explain.c - the ray tree of a pixel and the debug views
 * (raytrace/explain.h): the explained value is the rendered one, bit for
 * bit, for every pixel of the project's scenes; the blocker reported really
 * blocks; the views of one-facet.scn match values worked out from its
 * geometry; rt-export --explain names the blocking facet and its line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"
#include "testutil.h"

static const char *const scenes[] = {
    "scenes/cubes.scn", "scenes/empty.scn", "scenes/focus.scn",
    "scenes/glass.scn", "scenes/mirror.scn", "scenes/one-facet.scn",
    "scenes/two-facets.scn"};
#define SCENE_COUNT (int)(sizeof scenes / sizeof scenes[0])

/*
 * Every pixel of a `width` x `height` render with `options`: the explained
 * value is bit for bit what the render path computes without a recorder,
 * and rounds to the rendered byte.  Returns 0 when the render refuses the
 * precision (RT_ERR_RANGE).
 */
static int check_every_pixel(const rt_scene *scene, rt_render_options *o,
                             const char *what)
{
    rt_image image;
    int width, height;
    ck_assert_int_eq(rt_render_image_size(scene, o, &width, &height, NULL),
                     RT_OK);
    ck_assert_int_eq(rt_image_init(&image, width, height, NULL), RT_OK);
    rt_error error;
    rt_status status = rt_render(scene, o, &image, &error);
    if (status == RT_ERR_RANGE) {
        rt_image_release(&image);
        return 0;
    }
    ck_assert_msg(status == RT_OK, "%s: %s", what, error.message);
    rt_frame frame;
    int frame_width, frame_height, samples;
    ck_assert_int_eq(rt__frame_setup(scene, o, &frame, &frame_width,
                                     &frame_height, &samples, NULL),
                     RT_OK);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            rt_ray_tree *tree;
            status = rt_explain_pixel(scene, o, x, y, -1, &tree, &error);
            ck_assert_msg(status == RT_OK, "%s: %s", what, error.message);
            rt_color value = rt_ray_tree_value(tree);
            rt_counters counters = {0};
            rt_color plain = rt__frame_pixel(&frame, x, y, -1, &counters);
            ck_assert_msg(memcmp(&value, &plain, sizeof value) == 0,
                          "%s pixel %d,%d: explained %.17g %.17g %.17g, "
                          "rendered %.17g %.17g %.17g", what, x, y, value.r,
                          value.g, value.b, plain.r, plain.g, plain.b);
            const unsigned char *p = rt_image_pixel(&image, x, y);
            ck_assert_msg(rt_channel_to_byte(value.r) == p[0] &&
                              rt_channel_to_byte(value.g) == p[1] &&
                              rt_channel_to_byte(value.b) == p[2],
                          "%s pixel %d,%d: explained %g %g %g, image %d %d "
                          "%d", what, x, y, value.r, value.g, value.b, p[0],
                          p[1], p[2]);
            size_t count;
            const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
            ck_assert_uint_ge(count, 1);
            ck_assert_int_eq(nodes[0].kind, RT_RAY_CAMERA);
            rt_ray_tree_destroy(tree);
        }
    rt_image_release(&image);
    return 1;
}

START_TEST(explained_value_is_the_rendered_pixel_in_every_scene)
{
    int fast = rt_test_memcheck();
    for (int s = 0; s < SCENE_COUNT; s++) {
        rt_scene *scene = rt_test_load_source_scene(scenes[s]);
        for (int precision = 0; precision < 2; precision++)
            for (int depth = 0; depth <= 5; depth += fast ? 5 : 1) {
                rt_render_options o;
                rt_render_options_init(&o);
                o.width = fast ? 8 : 40;
                o.height = fast ? 6 : 30;
                o.threads = 1;
                o.max_depth = depth;
                o.precision = (rt_precision)precision;
                char what[160];
                snprintf(what, sizeof what, "%s %s depth %d", scenes[s],
                         precision ? "float" : "double", depth);
                check_every_pixel(scene, &o, what);
            }
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(explained_value_is_the_rendered_pixel_with_samples_and_lens)
{
    int fast = rt_test_memcheck();
    const char *names[] = {"scenes/cubes.scn", "scenes/focus.scn",
                           "scenes/glass.scn"};
    for (int s = 0; s < 3; s++) {
        rt_scene *scene = rt_test_load_source_scene(names[s]);
        for (int precision = 0; precision < 2; precision++) {
            rt_render_options o;
            rt_render_options_init(&o);
            o.width = fast ? 6 : 24;
            o.height = fast ? 4 : 18;
            o.samples = 4;
            o.sampling = RT_SAMPLING_STRATIFIED;
            o.precision = (rt_precision)precision;
            if (s == 0)
                o.aperture = 0.05;  /* a lens on a pinhole scene too */
            check_every_pixel(scene, &o, names[s]);
            o.fast_inv_sqrt = 1;
            o.kernel = RT_KERNEL_SCALAR;
            o.accel = RT_ACCEL_OCTREE;
            check_every_pixel(scene, &o, names[s]);
        }
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(a_region_explains_its_own_pixels)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_render_options o;
    rt_render_options_init(&o);
    o.width = 40;
    o.height = 30;
    o.region = (rt_region){10, 5, 22, 14};
    check_every_pixel(scene, &o, "cubes region");
    rt_ray_tree *tree = NULL;
    rt_error error;
    ck_assert_int_eq(rt_explain_pixel(scene, &o, 12, 0, -1, &tree, &error),
                     RT_ERR_ARGUMENT);
    ck_assert_ptr_null(tree);
    ck_assert_int_eq(rt_explain_pixel(scene, &o, 0, 0, 1, &tree, &error),
                     RT_ERR_ARGUMENT);
    o.max_depth = -1;
    ck_assert_int_eq(rt_explain_pixel(scene, &o, 0, 0, -1, &tree, &error),
                     RT_ERR_ARGUMENT);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(one_sample_is_explained_alone_and_the_samples_add_up)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_render_options o;
    rt_render_options_init(&o);
    o.width = 40;
    o.height = 30;
    o.samples = 4;
    o.sampling = RT_SAMPLING_STRATIFIED;
    rt_ray_tree *all, *one;
    ck_assert_int_eq(rt_explain_pixel(scene, &o, 20, 20, -1, &all, NULL),
                     RT_OK);
    rt_color sum = {0, 0, 0};
    for (int s = 0; s < 4; s++) {
        ck_assert_int_eq(rt_explain_pixel(scene, &o, 20, 20, s, &one, NULL),
                         RT_OK);
        size_t count;
        const rt_ray_node *n = rt_ray_tree_nodes(one, &count);
        ck_assert_int_eq(n[0].sample, s);
        rt_color c = rt_ray_tree_value(one);
        /* the subtotals are summed afterwards, in another order: equal
         * to rounding */
        ck_assert_double_eq_tol(c.r, n[0].subtotal.r, 1e-9 * (1 + c.r));
        sum.r += c.r, sum.g += c.g, sum.b += c.b;
        rt_ray_tree_destroy(one);
    }
    rt_color mean = rt_ray_tree_value(all);
    ck_assert_double_eq(mean.r, sum.r * 0.25);
    ck_assert_double_eq(mean.g, sum.g * 0.25);
    ck_assert_double_eq(mean.b, sum.b * 0.25);
    rt_ray_tree_destroy(all);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_reported_blocker_really_blocks)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_render_options o;
    rt_render_options_init(&o);
    o.width = 40;
    o.height = 30;
    int blocked = 0;
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++) {
            rt_ray_tree *tree;
            ck_assert_int_eq(rt_explain_pixel(scene, &o, x, y, -1, &tree,
                                              NULL), RT_OK);
            size_t count;
            const rt_ray_node *n = rt_ray_tree_nodes(tree, &count);
            for (size_t i = 0; i < count; i++) {
                if (n[i].kind != RT_RAY_SHADOW || !n[i].cast || n[i].e > 0)
                    continue;
                ck_assert_int_ge(n[i].blocker, 0);
                rt_facet_info f = {.size = sizeof f};
                rt_scene_facet(scene, n[i].blocker, &f);
                ck_assert_int_eq(n[i].blocker_line, f.line);
                ck_assert_int_gt(f.line, 0);
                rt_hit hit;
                rt_ray segment = {n[i].origin, n[i].direction};
                ck_assert(rt_scene_nearest_hit(scene, segment, 1.0, &hit));
                ck_assert_int_eq(hit.facet, n[i].blocker);
                rt_vec3 to = {n[i].origin.x + n[i].direction.x,
                              n[i].origin.y + n[i].direction.y,
                              n[i].origin.z + n[i].direction.z};
                ck_assert(rt_scene_occluded(scene, n[i].origin, to,
                                            n[n[i].parent].facet));
                ck_assert_double_eq(n[i].own.r, 0);
                blocked++;
            }
            rt_ray_tree_destroy(tree);
        }
    ck_assert_int_gt(blocked, 0);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_tree_says_what_the_formula_adds)
{
    /* one-facet.scn, pixel (32, 23): 0.5 * 20 + 0.5 * 1 * 255 * 201 / 255
     * = 110.5 in red (the scene's comment), N.S = 1 exactly. */
    rt_scene *scene = rt_test_load_source_scene("scenes/one-facet.scn");
    rt_ray_tree *tree;
    ck_assert_int_eq(rt_explain_pixel(scene, NULL, 32, 23, -1, &tree, NULL),
                     RT_OK);
    size_t count;
    const rt_ray_node *n = rt_ray_tree_nodes(tree, &count);
    ck_assert_uint_eq(count, 3);    /* camera, shadow, reflected (no hit) */
    ck_assert_int_eq(n[0].kind, RT_RAY_CAMERA);
    ck_assert_int_eq(n[0].facet, 0);
    ck_assert_int_eq(n[0].line, 26);   /* "1, 2, 3, 0.5, ..." */
    ck_assert_double_eq(n[0].reflection, 0.5);
    ck_assert_int_eq(n[1].kind, RT_RAY_SHADOW);
    ck_assert_double_eq(n[1].n_dot_s, 1.0);
    ck_assert_double_eq(n[1].e, 1.0);
    ck_assert_double_eq(n[1].own.r, 100.5);
    ck_assert_int_eq(n[2].kind, RT_RAY_REFLECTED);
    ck_assert_int_eq(n[2].parent, 0);
    ck_assert_double_eq(n[2].weight, 0.5);
    ck_assert_int_eq(n[2].hit, 0);
    ck_assert_double_eq(n[2].own.r, 10.0);
    ck_assert_double_eq(n[0].subtotal.r, 110.5);
    ck_assert_double_eq(rt_ray_tree_value(tree).r, 110.5);
    rt_ray_tree_destroy(tree);
    rt_scene_destroy(scene);
}
END_TEST

/* one-facet.scn: the plane point pixel (i, j) sees (the scene's comment),
 * and whether it lies in the triangle (-6,-4), (6,-4), (0,5). */
static int one_facet_point(int i, int j, double *x, double *y)
{
    *x = -8 + 0.25 * (i + 0.5);
    *y = 6 - 0.25 * (j + 0.5);
    double ex[3] = {-6, 6, 0}, ey[3] = {-4, -4, 5};
    for (int e = 0; e < 3; e++) {
        int f = (e + 1) % 3;
        double cross = (ex[f] - ex[e]) * (*y - ey[e]) -
                       (ey[f] - ey[e]) * (*x - ex[e]);
        if (cross < 0)
            return 0;
    }
    return 1;
}

static rt_image view_of(const rt_scene *scene, rt_debug_view view)
{
    rt_image image;
    rt_error error;
    ck_assert_int_eq(rt_image_init(&image, 64, 48, NULL), RT_OK);
    rt_status status = rt_render_view(scene, NULL, view, 0, &image, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return image;
}

static void assert_near(const unsigned char *p, double r, double g, double b,
                        int i, int j)
{
    double want[3] = {r, g, b};
    for (int c = 0; c < 3; c++)
        ck_assert_msg(abs(p[c] - rt_channel_to_byte(want[c])) <= 1,
                      "pixel %d,%d channel %d: %d, expected %g", i, j, c,
                      p[c], want[c]);
}

START_TEST(debug_views_of_one_facet_match_its_geometry)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/one-facet.scn");
    rt_image normal = view_of(scene, RT_VIEW_NORMAL),
             depth = view_of(scene, RT_VIEW_DEPTH),
             facet = view_of(scene, RT_VIEW_FACET),
             shadow = view_of(scene, RT_VIEW_SHADOW),
             bounces = view_of(scene, RT_VIEW_BOUNCES),
             ns = view_of(scene, RT_VIEW_NS);
    /* t = |P - O| with O = (0, 0, 10): near and far over the hit pixels */
    double near = INFINITY, far = 0, x, y;
    for (int j = 0; j < 48; j++)
        for (int i = 0; i < 64; i++)
            if (one_facet_point(i, j, &x, &y)) {
                double t = sqrt(x * x + y * y + 100);
                near = fmin(near, t);
                far = fmax(far, t);
            }
    rt_rgb8 id = rt_debug_facet_color(0);
    for (int j = 0; j < 48; j++)
        for (int i = 0; i < 64; i++) {
            int in = one_facet_point(i, j, &x, &y);
            if (!in) {
                assert_near(rt_image_pixel(&normal, i, j), 0, 0, 0, i, j);
                assert_near(rt_image_pixel(&depth, i, j), 0, 0, 0, i, j);
                assert_near(rt_image_pixel(&facet, i, j), 0, 0, 0, i, j);
                assert_near(rt_image_pixel(&bounces, i, j), 0, 0, 0, i, j);
                continue;
            }
            /* N = (0, 0, 1) towards the camera above: (n + 1) / 2 x 255 */
            assert_near(rt_image_pixel(&normal, i, j), 127.5, 127.5, 255, i,
                        j);
            double t = sqrt(x * x + y * y + 100);
            double d = 255 * (far - t) / (far - near);
            assert_near(rt_image_pixel(&depth, i, j), d, d, d, i, j);
            const unsigned char *f = rt_image_pixel(&facet, i, j);
            ck_assert(f[0] == id.r && f[1] == id.g && f[2] == id.b);
            /* nothing between the plane and the light 4 above it */
            assert_near(rt_image_pixel(&shadow, i, j), 255, 255, 255, i, j);
            /* N.S = 4 / |L - P|, L = (0.125, 0.125, 4) */
            double lx = 0.125 - x, ly = 0.125 - y;
            double v = 255 * 4 / sqrt(lx * lx + ly * ly + 16);
            assert_near(rt_image_pixel(&ns, i, j), v, v, v, i, j);
            /* k = 0.5: one reflection (to the sky) of depth 5: 255 / 5 */
            assert_near(rt_image_pixel(&bounces, i, j), 51, 51, 51, i, j);
        }
    rt_image images[] = {normal, depth, facet, shadow, bounces, ns};
    for (int k = 0; k < 6; k++)
        rt_image_release(&images[k]);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(render_view_refuses_bad_arguments)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/one-facet.scn");
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 64, 48, NULL), RT_OK);
    rt_error error;
    ck_assert_int_eq(rt_render_view(scene, NULL, (rt_debug_view)99, 0,
                                    &image, &error), RT_ERR_ARGUMENT);
    ck_assert_int_eq(rt_render_view(scene, NULL, RT_VIEW_SHADOW, 1, &image,
                                    &error), RT_ERR_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(error.message, "light 1"));
    rt_image_release(&image);
    ck_assert_int_eq(rt_image_init(&image, 10, 10, NULL), RT_OK);
    ck_assert_int_eq(rt_render_view(scene, NULL, RT_VIEW_NORMAL, 0, &image,
                                    &error), RT_ERR_ARGUMENT);
    rt_image_release(&image);
    rt_ray_tree_destroy(NULL);
    rt_scene_destroy(scene);
}
END_TEST

/* Runs a command, returns its standard output (malloc'd). */
static char *run(const char *command)
{
    FILE *pipe = popen(command, "r");
    ck_assert_ptr_nonnull(pipe);
    size_t size = 0, capacity = 1 << 16;
    char *out = malloc(capacity);
    ck_assert_ptr_nonnull(out);
    size_t got;
    while ((got = fread(out + size, 1, capacity - 1 - size, pipe)) > 0)
        size += got;
    out[size] = '\0';
    ck_assert_int_eq(pclose(pipe), 0);
    return out;
}

START_TEST(rt_export_explain_names_the_blocking_facet_and_its_line)
{
    /* Pixel 269,172 of cubes.scn lies on the floor (facet 13, line 51) in
     * the shadow of facet 8, the record on line 46. */
    char command[2048];
    snprintf(command, sizeof command, "'%s' --explain 269,172 '%s'",
             RT_EXPORT_PATH, rt_test_source_path("scenes/cubes.scn"));
    char *out = run(command);
    ck_assert_msg(strstr(out, "hits facet 13 (line 51)") != NULL, "%s", out);
    ck_assert_msg(strstr(out, "shadowed by facet 8 (line 46)") != NULL, "%s",
                  out);
    ck_assert_msg(strstr(out, "pixel value") != NULL, "%s", out);
    free(out);
    snprintf(command, sizeof command, "'%s' --explain 269,172 --explain-json "
             "'%s'", RT_EXPORT_PATH, rt_test_source_path("scenes/cubes.scn"));
    out = run(command);
    ck_assert_msg(out[0] == '{' && strstr(out, "\"blocker_line\"") != NULL,
                  "%s", out);
    free(out);
}
END_TEST

static Suite *explain_suite(void)
{
    Suite *s = suite_create("explain");
    TCase *c = tcase_create("explain");
    tcase_set_timeout(c, 600);
    tcase_add_test(c, explained_value_is_the_rendered_pixel_in_every_scene);
    tcase_add_test(c,
                   explained_value_is_the_rendered_pixel_with_samples_and_lens);
    tcase_add_test(c, a_region_explains_its_own_pixels);
    tcase_add_test(c, one_sample_is_explained_alone_and_the_samples_add_up);
    tcase_add_test(c, the_reported_blocker_really_blocks);
    tcase_add_test(c, the_tree_says_what_the_formula_adds);
    tcase_add_test(c, debug_views_of_one_facet_match_its_geometry);
    tcase_add_test(c, render_view_refuses_bad_arguments);
    tcase_add_test(c, rt_export_explain_names_the_blocking_facet_and_its_line);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(explain_suite)
