/*
 * test_robust.c - the numerical robustness cases of robust/cases.c
 * (docs/robustness.md) as Check tests, one table of groups: `test_robust
 * <group>` runs every case of that group in double and in float, each with
 * no failure and no NaN allowed (a precision a case does not apply to
 * passes, with its reason in docs/robustness.md).  Without an argument it
 * checks the table itself: every case of robust/cases.c is in exactly one
 * group, so that none is left out of ctest.  tests/robustness.cmake gives
 * each group its own ctest entry, run once with the octree forced off and
 * once forced on (RT_TEST_ACCEL).
 */
#include "testutil.h"
#include "robust/robust_check.h"

#include <stdio.h>
#include <string.h>

/* One test: a case id and the sentence that names its assertion. */
typedef struct robust_test {
    const char *id;
    const char *name;
} robust_test;

typedef struct robust_group {
    const char *name;           /* the command-line argument */
    const char *about;          /* what the group asserts, one sentence */
    const robust_test *tests;   /* terminated by an id of NULL */
} robust_group;

static const robust_test watertight[] = {
    {"W1", "rays_at_shared_edges_of_a_sphere_of_radius_1e_3_all_hit"},
    {"W2", "rays_at_shared_edges_of_a_sphere_of_radius_1_all_hit"},
    {"W3", "rays_at_shared_edges_of_a_sphere_of_radius_1e3_all_hit"},
    {"W4", "rays_through_the_apex_of_a_fan_of_64_facets_all_hit"},
    {"W5", "rays_at_shared_edges_of_a_tilted_grid_near_1e6_all_hit"},
    {NULL, NULL}};

static const robust_test facets[] = {
    {"D1", "zero_area_facets_are_never_hit"},
    {"D2", "cap_slivers_of_aspect_1e8_are_hit_where_aimed"},
    {"D3", "cap_slivers_of_aspect_1e12_are_hit_where_aimed"},
    {"D4", "needles_of_aspect_1e12_are_hit_where_aimed"},
    {"D5", "sliver_normals_are_within_1e_9_of_exact"},
    {NULL, NULL}};

static const robust_test invariance[] = {
    {"T1", "translation_by_1e6_changes_only_edge_pixels"},
    {"T2", "scaling_by_1e_6_changes_only_edge_pixels"},
    {"T3", "scaling_by_1e6_changes_only_edge_pixels"},
    {"T4", "scaling_by_1e_150_changes_only_edge_pixels"},
    {"T5", "scaling_by_1e150_changes_only_edge_pixels"},
    {NULL, NULL}};

static const robust_test shadows[] = {
    {"S1", "contact_shadow_is_dark_and_floor_clean_at_scale_1e_6"},
    {"S2", "contact_shadow_is_dark_and_floor_clean_at_scale_1e_3"},
    {"S3", "contact_shadow_is_dark_and_floor_clean_at_scale_1"},
    {"S4", "contact_shadow_is_dark_and_floor_clean_at_scale_1e3"},
    {"S5", "contact_shadow_is_dark_and_floor_clean_at_scale_1e6"},
    {"S6", "contact_shadow_is_dark_and_floor_clean_near_1e12"},
    {NULL, NULL}};

static const robust_test lights[] = {
    {"L1", "light_in_the_plane_of_a_floor_gives_it_no_light"},
    {"L2", "light_in_a_tilted_floor_plane_gives_it_no_visible_light"},
    {"L3", "light_on_a_shared_vertex_lights_the_floor_below"},
    {"L4", "light_on_a_wall_lights_the_floor_on_both_sides"},
    {"L5", "grazing_light_at_1e_6_rad_gives_no_acne"},
    {"L6", "grazing_light_at_1e_12_rad_gives_no_acne"},
    {NULL, NULL}};

static const robust_test camera[] = {
    {"C1", "camera_on_the_floor_never_sees_the_floor"},
    {"C2", "rays_in_a_facets_plane_never_hit_it"},
    {"C3", "grazing_rays_at_shared_edges_all_hit"},
    {NULL, NULL}};

static const robust_test recursion[] = {
    {"R1", "facing_mirrors_at_depth_100000_finish_black_in_linear_work"},
    {"R2", "no_ray_escapes_a_closed_mirror_box"},
    {NULL, NULL}};

static const robust_test special[] = {
    {"V1", "non_finite_inputs_are_refused_by_the_loader"},
    {"V2", "ray_magnitude_does_not_change_the_hit_and_non_rays_hit_nothing"},
    {"V3", "light_beyond_floats_range_gives_the_same_image"},
    {"V4", "facets_collapsed_in_float_give_no_nan"},
    {"V5", "subnormal_scene_gives_no_nan"},
    {NULL, NULL}};

static const robust_test determinism[] = {
    {"Q1", "duplicate_facets_first_in_the_file_wins"},
    {"Q2", "duplicate_facets_with_rotated_vertices_first_wins"},
    {"X1", "thread_counts_give_identical_images"},
    {"X2", "scalar_and_avx2_loops_give_identical_images"},
    {NULL, NULL}};

static const robust_test transparency[] = {
    {"G1", "a_glass_slab_displaces_rays_by_the_analytic_shift_up_to_grazing"},
    {"G2", "a_prism_reflects_totally_beyond_the_critical_angle_only"},
    {"G3", "rays_at_shared_edges_enter_and_leave_a_closed_glass_cube"},
    {"G4", "a_light_inside_a_glass_cube_lights_only_the_inside"},
    {NULL, NULL}};

static const robust_group groups[] = {
    {"watertight", "no ray falls through a closed mesh: rays aimed exactly "
                   "at shared edges and vertices, at every scale",
     watertight},
    {"facets", "zero-area facets are never hit; slivers of aspect 1e8 to "
               "1e12 are hit where aimed and have accurate normals",
     facets},
    {"invariance", "a scene and its copy translated or scaled give the same "
                   "picture but for edge pixels",
     invariance},
    {"shadows", "secondary rays neither leak through a close occluder nor "
                "hit their own surface, at every scale",
     shadows},
    {"lights", "lights in a facet's plane, on a vertex, on a facet, and at "
               "grazing angles",
     lights},
    {"camera", "the camera on a facet, rays in a facet's plane, grazing "
               "camera rays",
     camera},
    {"recursion", "facing mirrors at depth 100,000 in linear time and "
                  "constant stack; no ray escapes a closed mirror box",
     recursion},
    {"special", "NaN and infinities in inputs, rays of every magnitude, far "
                "lights, float's lost shapes, subnormal scenes",
     special},
    {"determinism", "coincident facets obey the tie rule; images are the "
                    "same for every thread count and loop",
     determinism},
    {"transparency", "a glass slab at grazing incidence, total internal "
                     "reflection in a prism, rays through the shared edges "
                     "of a closed glass cube, a light inside a glass cube",
     transparency},
};

enum { GROUP_COUNT = sizeof groups / sizeof groups[0] };

/* The group this run checks, chosen once in main before the suite runs. */
static const robust_group *current;

static int test_count(const robust_test *tests)
{
    int n = 0;
    while (tests[n].id != NULL)
        n++;
    return n;
}

/* Test _i is case _i / 2 of the group, in double then in float. */
START_TEST(robustness_case_holds)
{
    const robust_test *t = &current->tests[_i / 2];
    rt_precision precision =
        _i % 2 == 0 ? RT_PRECISION_DOUBLE : RT_PRECISION_FLOAT;
    printf("%s: %s_in_%s\n", t->id, t->name,
           precision == RT_PRECISION_FLOAT ? "float" : "double");
    rb_check_case(t->id, precision);
}
END_TEST

/* Every case of robust/cases.c is in exactly one group, and every id of the
 * table is a case. */
START_TEST(every_case_is_in_exactly_one_group)
{
    for (int c = 0; c < rb_case_count; c++) {
        int found = 0;
        for (int g = 0; g < GROUP_COUNT; g++)
            for (const robust_test *t = groups[g].tests; t->id != NULL; t++)
                found += strcmp(t->id, rb_cases[c].id) == 0;
        ck_assert_msg(found == 1, "case %s is in %d groups of test_robust.c",
                      rb_cases[c].id, found);
    }
    for (int g = 0; g < GROUP_COUNT; g++)
        for (const robust_test *t = groups[g].tests; t->id != NULL; t++)
            ck_assert_msg(rb_case_find(t->id) != NULL,
                          "%s (group %s) is not a case of robust/cases.c",
                          t->id, groups[g].name);
}
END_TEST

static Suite *group_suite(const robust_group *group)
{
    /* Check keeps the name's pointer until the suite is freed: static,
     * since one group's suite runs per process. */
    static char name[64];
    snprintf(name, sizeof name, "robust_%s", group->name);
    Suite *s = suite_create(name);
    TCase *tc = rb_tcase("cases");
    current = group;
    tcase_add_loop_test(tc, robustness_case_holds, 0,
                        2 * test_count(group->tests));
    suite_add_tcase(s, tc);
    return s;
}

static Suite *table_suite(void)
{
    Suite *s = suite_create("robust_table");
    TCase *tc = tcase_create("table");
    tcase_add_test(tc, every_case_is_in_exactly_one_group);
    suite_add_tcase(s, tc);
    return s;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return rt_test_run_suite(table_suite());
    for (int g = 0; g < GROUP_COUNT; g++)
        if (strcmp(argv[1], groups[g].name) == 0) {
            printf("robust_%s: %s\n", groups[g].name, groups[g].about);
            return rt_test_run_suite(group_suite(&groups[g]));
        }
    fprintf(stderr, "test_robust: no group '%s'; the groups:", argv[1]);
    for (int g = 0; g < GROUP_COUNT; g++)
        fprintf(stderr, " %s", groups[g].name);
    fprintf(stderr, "\n");
    return 2;
}
