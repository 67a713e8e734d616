/*
 * test_prepared.c - what a render prepares once and reuses: the eye a
 * scene keeps per precision (built by the first render that reads it, the
 * same for every later render and band), the team of threads
 * (base/workers.h: every place of a job run, nested and forked jobs on
 * threads of their own, signals blocked, no thread left once idle or
 * destroyed), and the statistics the counters table (RT_STATS_MAP)
 * generates: the struct laid out as in 0.2, the threads' counters the
 * same whatever their number.
 */
#include <check.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "base/workers.h"
#include "scene/scene_internal.h"
#include "testutil.h"

/* A half-mirror ground and a matte triangle above it that the ground
 * reflects, lit from the side (the handout's format). */
static const char *const TWO_FACETS =
    "0,0,10\n0,0,5, 4,0,5, 40,30\n6\n"
    "-9,-6,0\n9,-6,0\n0,9,0\n-1,-1,2\n1.5,-1,2\n0,1.5,2\n2\n"
    "1,2,3, 0.5, 200,100,50\n4,5,6, 0, 50,100,200\n"
    "10,20,30\n-4,0,6, 255,255,255\n";

/* ---- the eye -------------------------------------------------------- */

START_TEST(the_eye_is_built_once_for_every_render_and_band)
{
    rt_scene *scene = rt_test_scene_from_string(TWO_FACETS);
    for (int p = 0; p < 2; p++) {
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        ck_assert_ptr_null(atomic_load(&scene->eyes[precision]));
        rt_render_options options;
        rt_render_options_init(&options);
        options.precision = precision;
        options.accel = RT_ACCEL_NONE;  /* the fast brute force reads it */
        rt_image whole = rt_test_render_with(scene, &options);
        const rt_kernel_eye *eye = atomic_load(&scene->eyes[precision]);
        ck_assert_ptr_nonnull(eye);
        rt_image bands;
        ck_assert_int_eq(rt_image_init(&bands, whole.width, whole.height,
                                       NULL), RT_OK);
        for (int row = 0; row < whole.height; row += 7) {
            int end = row + 7 < whole.height ? row + 7 : whole.height;
            ck_assert_int_eq(rt_render_rows(scene, &options, row, end,
                                            &bands, NULL), RT_OK);
            ck_assert_ptr_eq(atomic_load(&scene->eyes[precision]), eye);
        }
        ck_assert_int_eq(rt_test_image_diff(&whole, &bands, NULL), 0);
        ck_assert_ptr_eq(rt__scene_eye(scene, precision), eye);
        rt_image_release(&whole);
        rt_image_release(&bands);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(an_octree_or_scalar_render_builds_no_eye)
{
    rt_scene *scene = rt_test_scene_from_string(TWO_FACETS);
    rt_render_options options;
    rt_render_options_init(&options);
    options.accel = RT_ACCEL_OCTREE;
    rt_image a = rt_test_render_with(scene, &options);
    options.accel = RT_ACCEL_NONE;
    options.kernel = RT_KERNEL_SCALAR;
    rt_image b = rt_test_render_with(scene, &options);
    ck_assert_ptr_null(atomic_load(&scene->eyes[RT_PRECISION_DOUBLE]));
    ck_assert_int_eq(rt_test_image_diff(&a, &b, NULL), 0);
    rt_image_release(&a);
    rt_image_release(&b);
    rt_scene_destroy(scene);
}
END_TEST

/* ---- the team of threads -------------------------------------------- */

typedef struct tally {
    atomic_int runs;
    atomic_int unblocked;       /* runs on a thread not blocking SIGINT,
                                   other than the caller's */
    pthread_t caller;
    rt_workers *team;           /* for the nested job, or NULL */
    atomic_int inner_runs;
} tally;

static void count_inner(void *argument)
{
    tally *t = argument;
    atomic_fetch_add(&t->inner_runs, 1);
}

static void count_run(void *argument)
{
    tally *t = argument;
    atomic_fetch_add(&t->runs, 1);
    sigset_t mask;
    pthread_sigmask(SIG_BLOCK, NULL, &mask);
    if (!pthread_equal(pthread_self(), t->caller) &&
        !sigismember(&mask, SIGINT))
        atomic_fetch_add(&t->unblocked, 1);
    if (t->team != NULL)
        rt__workers_run(t->team, 3, count_inner, t);
}

static void run_counted(rt_workers *team, int count, tally *t)
{
    atomic_init(&t->runs, 0);
    atomic_init(&t->unblocked, 0);
    atomic_init(&t->inner_runs, 0);
    t->caller = pthread_self();
    rt__workers_run(team, count, count_run, t);
}

START_TEST(a_team_runs_every_place_of_every_job)
{
    rt_workers *team = rt__workers_create();
    ck_assert_ptr_nonnull(team);
    tally t = {.team = NULL};
    for (int round = 0; round < 40; round++) {
        int count = 1 + round % 6;
        run_counted(team, count, &t);
        ck_assert_int_eq(atomic_load(&t.runs), count);
        ck_assert_int_eq(atomic_load(&t.unblocked), 0);
    }
    rt__workers_destroy(team);
}
END_TEST

START_TEST(a_job_started_inside_a_job_runs_on_threads_of_its_own)
{
    rt_workers *team = rt__workers_create();
    ck_assert_ptr_nonnull(team);
    tally t = {.team = team};
    run_counted(team, 4, &t);
    ck_assert_int_eq(atomic_load(&t.runs), 4);
    ck_assert_int_eq(atomic_load(&t.inner_runs), 4 * 3);
    rt__workers_destroy(team);
}
END_TEST

START_TEST(a_job_without_a_team_still_runs_on_every_thread)
{
    tally t = {.team = NULL};
    run_counted(NULL, 5, &t);
    ck_assert_int_eq(atomic_load(&t.runs), 5);
    /* threads started for one job block every signal as the team's do */
    ck_assert_int_eq(atomic_load(&t.unblocked), 0);
}
END_TEST

START_TEST(a_forked_child_runs_its_job_on_threads_of_its_own)
{
    rt_workers *team = rt__workers_create();
    ck_assert_ptr_nonnull(team);
    tally t = {.team = NULL};
    run_counted(team, 4, &t);   /* the team has threads now */
    pid_t child = fork();
    ck_assert_int_ne(child, -1);
    if (child == 0) {
        run_counted(team, 4, &t);
        int ran = atomic_load(&t.runs);
        rt__workers_destroy(team);  /* none of its threads to wait for */
        _exit(ran == 4 ? 0 : 1);
    }
    int status;
    ck_assert_int_eq(waitpid(child, &status, 0), child);
    ck_assert(WIFEXITED(status));
    ck_assert_int_eq(WEXITSTATUS(status), 0);
    rt__workers_destroy(team);
}
END_TEST

START_TEST(a_team_holds_no_thread_once_idle_or_destroyed)
{
    int before = rt_test_baseline_thread_count();
    rt_workers *team = rt__workers_create();
    ck_assert_ptr_nonnull(team);
    tally t = {.team = NULL};
    run_counted(team, 4, &t);
    /* idle: its threads end after RT_WORKERS_LINGER */
    ck_assert_int_eq(rt_test_settled_thread_count(before, 10), before);
    run_counted(team, 4, &t);   /* and start again when needed */
    ck_assert_int_eq(atomic_load(&t.runs), 4);
    rt__workers_destroy(team);
    ck_assert_int_eq(rt_test_settled_thread_count(before, 10), before);
}
END_TEST

/* ---- the statistics ------------------------------------------------- */

/* rt_render_stats as 0.3 declares it, field by field: the `size` that 0.3
 * put first (no counter: RT_STATS_MAP leaves it out), then the counters of
 * 0.2 in 0.2's order.  The table must keep this layout; counters are only
 * ever appended. */
typedef struct stats_0_3 {
    size_t size;
    uint64_t camera_rays;
    uint64_t shadow_rays;
    uint64_t reflection_rays;
    uint64_t ray_facet_tests;
    uint64_t shadow_rays_skipped;
    uint64_t reflection_rays_skipped;
    uint64_t pixels;
    double seconds;
    uint64_t ray_facet_tests_skipped;
    int accel_used;
    double accel_build_seconds;
    uint64_t accel_nodes;
    uint64_t accel_leaves;
    int accel_depth;
    uint64_t accel_references;
    uint64_t accel_always;
    uint64_t accel_bytes;
    uint64_t accel_queries;
    uint64_t accel_leaves_visited;
    uint64_t accel_facet_tests;
    uint64_t accel_fallbacks;
    uint64_t accel_facets;
    uint64_t refraction_rays;
    uint64_t refraction_rays_skipped;
} stats_0_3;

/* The counters of 0.3, by name. */
#define FIELDS_0_3(X) X(camera_rays) X(shadow_rays) X(reflection_rays)       \
    X(ray_facet_tests) X(shadow_rays_skipped) X(reflection_rays_skipped)     \
    X(pixels) X(seconds) X(ray_facet_tests_skipped) X(accel_used)            \
    X(accel_build_seconds) X(accel_nodes) X(accel_leaves) X(accel_depth)     \
    X(accel_references) X(accel_always) X(accel_bytes) X(accel_queries)      \
    X(accel_leaves_visited) X(accel_facet_tests) X(accel_fallbacks)          \
    X(accel_facets) X(refraction_rays) X(refraction_rays_skipped)

START_TEST(the_stats_keep_the_layout_of_0_3)
{
    /* 0.3's fields where 0.3 put them, the later ones appended */
    ck_assert_uint_ge(sizeof(rt_render_stats), sizeof(stats_0_3));
    ck_assert_uint_eq(offsetof(rt_render_stats, size), 0);
    ck_assert_uint_eq(sizeof(((rt_render_stats *)0)->size), sizeof(size_t));
    int fields = 0;
#define SAME_FIELD(name)                                                     \
    ck_assert_msg(offsetof(rt_render_stats, name) ==                         \
                          offsetof(stats_0_3, name) &&                       \
                      sizeof(((rt_render_stats *)0)->name) ==                \
                          sizeof(((stats_0_3 *)0)->name),                    \
                  "field %s moved", #name);                                 \
    fields++;
    FIELDS_0_3(SAME_FIELD)
#undef SAME_FIELD
    ck_assert_int_eq(fields, 24);
    int all = 0;
#define COUNT_FIELD(type, name, origin, merge, group, key, title) all++;
    RT_STATS_MAP(COUNT_FIELD)
#undef COUNT_FIELD
    /* 0.3's, then accel_kdtree and accel_steps after them */
    ck_assert_int_eq(all, 26);
    ck_assert_uint_ge(offsetof(rt_render_stats, accel_kdtree),
                      sizeof(stats_0_3));
    ck_assert_uint_gt(offsetof(rt_render_stats, accel_steps),
                      offsetof(rt_render_stats, accel_kdtree));
}
END_TEST

/* rt_render_stats_rays sums the group `rays` (camera, shadow, reflection,
 * refraction) and nothing else. */
START_TEST(the_rays_of_the_stats_are_the_sum_of_the_rays_group)
{
    rt_render_stats stats = {.size = sizeof stats, .camera_rays = 1,
                             .shadow_rays = 2, .reflection_rays = 4,
                             .refraction_rays = 8, .pixels = 16,
                             .shadow_rays_skipped = 32,
                             .reflection_rays_skipped = 64,
                             .refraction_rays_skipped = 128,
                             .ray_facet_tests = 256, .accel_queries = 512};
    ck_assert_uint_eq(rt_render_stats_rays(&stats), 15);
}
END_TEST

static rt_render_stats stats_with_threads(const rt_scene *scene, int threads)
{
    rt_render_stats stats = {.size = sizeof stats};
    rt_render_options options;
    rt_render_options_init(&options);
    options.threads = threads;
    options.samples = 4;
    options.accel = RT_ACCEL_OCTREE;
    options.stats = &stats;
    rt_image image = rt_test_render_with(scene, &options);
    rt_image_release(&image);
    return stats;
}

START_TEST(the_threads_counters_sum_to_the_same_stats_for_any_count)
{
    rt_scene *scene = rt_test_scene_from_string(TWO_FACETS);
    rt_render_stats one = stats_with_threads(scene, 1);
    ck_assert_uint_eq(one.pixels, 40 * 30);
    ck_assert_uint_eq(one.camera_rays, 40 * 30 * 4);
    ck_assert_uint_gt(one.reflection_rays, 0);
    ck_assert_uint_gt(one.accel_queries, 0);
    for (int threads = 2; threads <= 4; threads++) {
        rt_render_stats many = stats_with_threads(scene, threads);
#define SAME_COUNT_THREAD(name)                                              \
    ck_assert_msg(one.name == many.name, "%s: %llu on 1 thread, %llu on %d", \
                  #name, (unsigned long long)one.name,                       \
                  (unsigned long long)many.name, threads);
#define SAME_COUNT_RENDER(name)
#define SAME_COUNT_OCTREE(name)
#define SAME_COUNT(type, name, origin, merge, group, key, title)             \
    SAME_COUNT_##origin(name)
        RT_STATS_MAP(SAME_COUNT)
#undef SAME_COUNT
#undef SAME_COUNT_THREAD
#undef SAME_COUNT_RENDER
#undef SAME_COUNT_OCTREE
        ck_assert_uint_eq(one.ray_facet_tests_skipped,
                          many.ray_facet_tests_skipped);
    }
    rt_scene_destroy(scene);
}
END_TEST

static Suite *prepared_suite(void)
{
    Suite *s = suite_create("prepared");
    TCase *eye = tcase_create("eye");
    tcase_add_test(eye, the_eye_is_built_once_for_every_render_and_band);
    tcase_add_test(eye, an_octree_or_scalar_render_builds_no_eye);
    suite_add_tcase(s, eye);
    TCase *team = tcase_create("team");
    tcase_set_timeout(team, 60);
    tcase_add_test(team, a_team_runs_every_place_of_every_job);
    tcase_add_test(team, a_job_started_inside_a_job_runs_on_threads_of_its_own);
    tcase_add_test(team, a_job_without_a_team_still_runs_on_every_thread);
    tcase_add_test(team, a_forked_child_runs_its_job_on_threads_of_its_own);
    tcase_add_test(team, a_team_holds_no_thread_once_idle_or_destroyed);
    suite_add_tcase(s, team);
    TCase *stats = tcase_create("stats");
    tcase_add_test(stats, the_stats_keep_the_layout_of_0_3);
    tcase_add_test(stats, the_rays_of_the_stats_are_the_sum_of_the_rays_group);
    tcase_add_test(stats,
                   the_threads_counters_sum_to_the_same_stats_for_any_count);
    suite_add_tcase(s, stats);
    return s;
}

RT_CHECK_MAIN(prepared_suite)
