/*
 * test_api_accessors.c - the public functions that return a value, not a
 * status, called outside their domain: a NULL scene, tree, camera or
 * out-pointer, an index outside 0..count-1.
 *
 * The rule (docs/api.md, "Arguments at the edges"): a programmer's error,
 * so an assert stops a debug build inside the call, naming the function;
 * where NDEBUG compiles asserts out (a Release build) the call reads
 * nothing out of bounds and returns the zero value its header documents.
 *
 * One program, two ctest entries, each a visible skip (77) where it does
 * not apply: without arguments (test_api_accessors) each bad call runs in a
 * child that must die of SIGABRT with the function's name on its standard
 * error, in a debug build such as the sanitizer pass's; with `fallbacks`
 * (test_api_accessors_fallbacks) each returns its zero value, in a build
 * with NDEBUG.
 */
#include <check.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "testutil.h"

static rt_scene *scene;

static void setup(void)
{
    ck_assert_int_eq(rt_scene_parse(rt_test_centred_facet_scene,
                                    strlen(rt_test_centred_facet_scene), NULL,
                                    NULL, &scene, NULL),
                     RT_OK);
}

static void teardown(void)
{
    rt_scene_destroy(scene);
}

/* A bad call of a function that returns a value; `zero` says whether what
 * it returned is the documented zero value (used where NDEBUG is defined;
 * a debug build must abort inside the call). */
typedef struct accessor_case {
    const char *function;   /* the name the assert message gives */
    const char *call;
    int (*zero)(void);
} accessor_case;

/* A facet info full of 0x7f bytes but its size, `size`. */
static rt_facet_info filled_facet(size_t size)
{
    rt_facet_info f;
    memset(&f, 0x7f, sizeof f);
    f.size = size;
    return f;
}

static int all_bytes(const void *data, size_t size, unsigned char value)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < size; i++)
        if (b[i] != value)
            return 0;
    return 1;
}

static int is_zero(const void *data, size_t size)
{
    return all_bytes(data, size, 0);
}

/* A filled struct's zero value: its size kept, every other byte 0. */
#define SIZED_IS_ZERO(s)                                                     \
    ((s).size == sizeof(s) &&                                                \
     is_zero((const char *)&(s) + sizeof(s).size, sizeof(s) - sizeof(s).size))

/* What a call left untouched: its size and every 0x7f byte after it. */
#define SIZED_UNTOUCHED(s, expected_size)                                    \
    ((s).size == (expected_size) &&                                          \
     all_bytes((const char *)&(s) + sizeof(s).size,                          \
               sizeof(s) - sizeof(s).size, 0x7f))

static const rt_ray some_ray = {{0, 0, -5}, {0, 0, 1}};

#define ACCESSOR(name, function, expression)                                 \
    static int name(void) { return (expression); }
#define ACCESSOR_ROW(name, function, expression) {function, #expression, name},

static int vertex_is_zero(int i)
{
    rt_vec3 v = rt_scene_vertex(scene, i);
    return v.x == 0 && v.y == 0 && v.z == 0;
}

static int facet_is_zero(int i)
{
    rt_facet_info f = filled_facet(sizeof f);
    rt_scene_facet(scene, i, &f);
    return SIZED_IS_ZERO(f);
}

/* A size the library refuses (0, or short of the layout of 0.3): nothing
 * is written. */
static int facet_with_size_is_untouched(size_t size)
{
    rt_facet_info f = filled_facet(size);
    rt_scene_facet(scene, 0, &f);
    return SIZED_UNTOUCHED(f, size);
}

static int light_is_zero(int i)
{
    rt_light l;
    memset(&l, 0x7f, sizeof l);
    rt_scene_light(scene, i, &l);
    return is_zero(&l, sizeof l);
}

static int info_is_zero(void)
{
    rt_scene_info info;
    memset(&info, 0x7f, sizeof info);
    info.size = sizeof info;
    rt_scene_get_info(NULL, &info);
    return SIZED_IS_ZERO(info);
}

static int info_with_size_is_untouched(size_t size)
{
    rt_scene_info info;
    memset(&info, 0x7f, sizeof info);
    info.size = size;
    rt_scene_get_info(scene, &info);
    return SIZED_UNTOUCHED(info, size);
}

static int camera_ray_is_zero(void)
{
    rt_ray r = rt_camera_ray(NULL, 0, 0);
    return is_zero(&r, sizeof r);
}

static int trace_is_zero(void)
{
    rt_color c = rt_trace(NULL, some_ray, 1);
    return c.r == 0 && c.g == 0 && c.b == 0;
}

static int tree_nodes_are_none(void)
{
    size_t count = 7;
    return rt_ray_tree_nodes(NULL, &count) == NULL && count == 0;
}

static int tree_value_is_zero(void)
{
    rt_color c = rt_ray_tree_value(NULL);
    return c.r == 0 && c.g == 0 && c.b == 0;
}

/* The rays of stats of `size` bytes that count rays of every kind. */
static uint64_t stats_rays_with_size(size_t size)
{
    rt_render_stats stats = {.size = size, .camera_rays = 1,
                             .shadow_rays = 2, .reflection_rays = 4,
                             .refraction_rays = 8};
    return rt_render_stats_rays(&stats);
}

#define ACCESSOR_CASES(X)                                                    \
    X(a1, "rt_scene_vertex", vertex_is_zero(-1))                             \
    X(a2, "rt_scene_vertex", vertex_is_zero(3))                              \
    X(a3, "rt_scene_vertex", (rt_scene_vertex(NULL, 0).x == 0))              \
    X(a4, "rt_scene_facet", facet_is_zero(-1))                               \
    X(a5, "rt_scene_facet", facet_is_zero(1))                                \
    X(a6, "rt_scene_facet", (rt_scene_facet(scene, 0, NULL), 1))             \
    X(a7, "rt_scene_light", light_is_zero(-1))                               \
    X(a8, "rt_scene_light", light_is_zero(1))                                \
    X(a9, "rt_scene_light", (rt_scene_light(scene, 0, NULL), 1))             \
    X(a10, "rt_scene_warning", rt_scene_warning(scene, -1) == NULL)          \
    X(a11, "rt_scene_warning", rt_scene_warning(scene, 0) == NULL)           \
    X(a12, "rt_scene_source_at", rt_scene_source_at(scene, -1) == NULL)      \
    X(a13, "rt_scene_source_at", rt_scene_source_at(scene, 0) == NULL)       \
    X(a14, "rt_scene_get_info", info_is_zero())                              \
    X(a15, "rt_scene_get_info", (rt_scene_get_info(scene, NULL), 1))         \
    X(a16, "rt_scene_nearest_hit",                                           \
      rt_scene_nearest_hit(NULL, some_ray, 10, &(rt_hit){0}) == 0)           \
    X(a17, "rt_scene_nearest_hit",                                           \
      rt_scene_nearest_hit(scene, some_ray, 10, NULL) == 0)                  \
    X(a18, "rt_scene_occluded",                                              \
      rt_scene_occluded(NULL, some_ray.origin, some_ray.direction, -1) == 0) \
    X(a19, "rt_camera_ray", camera_ray_is_zero())                            \
    X(a20, "rt_trace", trace_is_zero())                                      \
    X(a21, "rt_ray_tree_nodes", tree_nodes_are_none())                       \
    X(a22, "rt_ray_tree_value", tree_value_is_zero())                        \
    X(a23, "rt_ray_tree_truncated", rt_ray_tree_truncated(NULL) == 0)      \
    X(a24, "rt_scene_facet", facet_with_size_is_untouched(0))                \
    X(a25, "rt_scene_facet",                                                 \
      facet_with_size_is_untouched(offsetof(rt_facet_info, highlight) -     \
                                   sizeof(double)))                         \
    X(a26, "rt_scene_get_info", info_with_size_is_untouched(0))              \
    X(a27, "rt_scene_get_info",                                              \
      info_with_size_is_untouched(offsetof(rt_scene_info, light_count)))    \
    X(a28, "rt_render_stats_rays", rt_render_stats_rays(NULL) == 0)          \
    X(a29, "rt_render_stats_rays", stats_rays_with_size(0) == 0)             \
    X(a30, "rt_render_stats_rays",                                           \
      stats_rays_with_size(offsetof(rt_render_stats, refraction_rays)) == 0)

ACCESSOR_CASES(ACCESSOR)

static const accessor_case accessor_cases[] = {ACCESSOR_CASES(ACCESSOR_ROW)};
#define ACCESSOR_COUNT (sizeof accessor_cases / sizeof accessor_cases[0])

/* The job of a child that makes the bad call (an abort ends it). */
static int make_the_call(void *arg, char *note, size_t size)
{
    (void)note, (void)size;
    const accessor_case *c = arg;
    signal(SIGABRT, SIG_DFL);
    (void)c->zero();
    return 0;
}

/* Makes the bad call in a child with its standard error in a pipe:
 * returns the wait status and what the child wrote. */
static int call_in_child(const accessor_case *c, char *said, size_t size)
{
    rt_test_child child =
        rt_test_child_start_with_stderr(make_the_call, (void *)c);
    ck_assert_msg(child.pid > 0, "fork: %s", strerror(errno));
    return rt_test_child_finish(&child, said, size);
}

START_TEST(each_accessor_asserts_its_index_and_pointers)
{
    for (size_t i = 0; i < ACCESSOR_COUNT; i++) {
        const accessor_case *c = &accessor_cases[i];
        char said[4096];
        int status = call_in_child(c, said, sizeof said);
        ck_assert_msg(WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT,
                      "%s did not abort (wait status %d)", c->call, status);
        ck_assert_msg(strstr(said, c->function) != NULL,
                      "%s aborted without naming %s: %s", c->call,
                      c->function, said);
    }
}
END_TEST

START_TEST(each_accessor_returns_a_zero_value_where_asserts_are_compiled_out)
{
    for (size_t i = 0; i < ACCESSOR_COUNT; i++)
        ck_assert_msg(accessor_cases[i].zero(), "%s returned something else "
                      "than its zero value", accessor_cases[i].call);
}
END_TEST

static Suite *accessor_suite(int asserts)
{
    Suite *s = suite_create(asserts ? "api_accessors"
                                    : "api_accessors_fallbacks");
    TCase *tc = tcase_create("accessors");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_set_timeout(tc, 60);
    if (asserts)
        tcase_add_test(tc, each_accessor_asserts_its_index_and_pointers);
    else
        tcase_add_test(tc, each_accessor_returns_a_zero_value_where_asserts_are_compiled_out);
    suite_add_tcase(s, tc);
    return s;
}

int main(int argc, char **argv)
{
#ifdef NDEBUG
    int asserts_on = 0;
#else
    int asserts_on = 1;
#endif
    int fallbacks = argc > 1 && strcmp(argv[1], "fallbacks") == 0;
    if (fallbacks == asserts_on) {
        printf(asserts_on ? "skipped: a debug build, where the bad calls "
                            "abort (test_api_accessors checks that)\n"
                          : "skipped: NDEBUG is defined (a release build), "
                            "so the accessors' asserts are compiled out "
                            "(test_api_accessors_fallbacks checks their zero "
                            "values)\n");
        return RT_TEST_SKIPPED;
    }
    return rt_test_run_suite(accessor_suite(!fallbacks));
}
