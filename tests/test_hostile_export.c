/*
 * test_hostile_export.c - rt-export and rt-bench under faults: exit codes
 * that say what went wrong, a refusal to write over the scene, a destination
 * that cannot be written and SIGKILL mid-render each keep the previous
 * image.
 *
 * The programs run through the support library (support/programs.h), so
 * that the tests also hold under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* rt-export: exit codes, refusals, interruptions                        */

/*
 * Runs `program` with `args` (NULL-terminated) in `dir`, its standard
 * output and error captured (their text in *out and *err, malloc'd).  A
 * non-negative `kill_after` sends SIGKILL once the process has used that
 * much CPU time (or after 30 seconds); `file_size_limit` other than
 * RLIM_INFINITY is its RLIMIT_FSIZE.  Returns the exit status, or 128 +
 * the signal.
 */
static int run_program(const char *program, const char *dir,
                       const char *const *args, double kill_after,
                       rlim_t file_size_limit, char **out, char **err)
{
    rt_test_setup setup = {NULL};
    if (file_size_limit != RLIM_INFINITY)
        setup.file_size_limit = (long long)file_size_limit;
    rt_test_process process = rt_test_start(dir, program, args, &setup);
    if (kill_after >= 0) {
        double start = rt_test_now();
        while (rt_test_running(&process) &&
               rt_test_cpu_seconds(&process) < kill_after &&
               rt_test_now() - start <= 30)
            rt_test_sleep_ms(5);
        if (!process.reaped)
            kill(process.pid, SIGKILL);
    }
    rt_test_output r = rt_test_finish(&process);
    *out = r.out;
    *err = r.err;
    return r.code;
}

static int run_export(const char *dir, const char *const *args,
                      double kill_after, rlim_t file_size_limit, char **out,
                      char **err)
{
    return run_program(RT_EXPORT_PATH, dir, args, kill_after,
                       file_size_limit, out, err);
}

START_TEST(export_refuses_to_write_over_its_own_scene)
{
    char *dir = rt_test_temp_dir();
    char *scene = rt_test_join(dir, "scene.scn");
    rt_test_write_bytes(scene, rt_test_small_scene,
                        strlen(rt_test_small_scene));
    char *out, *err;
    /* the same file by its name, another spelling, and a symbolic link */
    const char *outputs[] = {"scene.scn", "./scene.scn", "link.scn"};
    char *link_path = rt_test_join(dir, "link.scn");
    ck_assert_int_eq(symlink("scene.scn", link_path), 0);
    for (int i = 0; i < 3; i++) {
        const char *args[] = {"scene.scn", "-o", outputs[i], "--format",
                              "p6", "-q", NULL};
        int code = run_export(dir, args, -1, RLIM_INFINITY, &out, &err);
        ck_assert_int_eq(code, 1);
        char expected[256];
        snprintf(expected, sizeof expected,
                 "rt-export: %s: refusing to write the image over "
                 "scene.scn, the scene it comes from (the same file)\n",
                 outputs[i]);
        ck_assert_str_eq(err, expected);
        ck_assert_str_eq(out, "");
        free(out);
        free(err);
        size_t size;
        char *data = rt_test_read_file(scene, &size);
        ck_assert_str_eq(data, rt_test_small_scene);
        free(data);
        rt_test_assert_dir_holds(dir, "link.scn scene.scn");
    }
    free(link_path);
    free(scene);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(export_exit_codes_say_what_went_wrong)
{
    char *dir = rt_test_temp_dir();
    char *scene = rt_test_join(dir, "scene.scn");
    rt_test_write_bytes(scene, rt_test_small_scene,
                        strlen(rt_test_small_scene));
    char *bad = rt_test_join(dir, "bad.scn");
    rt_test_write_bytes(bad, "0 0 10\n0 0 5 4 0 5 8 8\n3\n", 25);
    char *out, *err;
    struct {
        const char *args[6];
        int code;
        const char *message;
    } cases[] = {
        {{"bad.scn", "-q", NULL}, 1,
         "rt-export: bad.scn:3:1: expected a vertex count of at most 0 (the "
         "lines left in the file), found `3`\n"},
        {{"absent.scn", NULL}, 1,
         "rt-export: absent.scn: cannot open: No such file or directory\n"},
        {{"scene.scn", "-o", "no/such/dir/x.ppm", "-q", NULL}, 1,
         "rt-export: no/such/dir/x.ppm: cannot write the image: the "
         "folder no/such/dir/ does not exist\n"},
        {{"scene.scn", "--depth", "-1", NULL}, 2,
         "rt-export: --depth: expected an integer in 0..1000000, found "
         "-1\n"
         "Try 'rt-export --help'.\n"},
        {{NULL}, 2,
         "rt-export: expected a scene file\nTry 'rt-export --help'.\n"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        int code = run_export(dir, cases[i].args, -1, RLIM_INFINITY, &out,
                              &err);
        ck_assert_msg(code == cases[i].code, "case %zu: exit %d, expected %d",
                      i, code, cases[i].code);
        ck_assert_str_eq(err, cases[i].message);
        ck_assert_str_eq(out, "");
        free(out);
        free(err);
    }
    rt_test_assert_dir_holds(dir, "bad.scn scene.scn");
    free(bad);
    free(scene);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(export_that_cannot_write_keeps_the_previous_image)
{
    char *dir = rt_test_temp_dir();
    char *scene = rt_test_join(dir, "scene.scn");
    rt_test_write_bytes(scene, rt_test_small_scene,
                        strlen(rt_test_small_scene));
    char *image = rt_test_join(dir, "out.ppm");
    rt_test_write_bytes(image, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    char *out, *err;
    /* the 40 x 30 P3 image is about 10 KB: a 2 KB limit stops it */
    const char *args[] = {"scene.scn", "-o", "out.ppm", "--format", "p3",
                          NULL};
    int code = run_export(dir, args, -1, 2048, &out, &err);
    ck_assert_int_eq(code, 1);
    /* the rescue (cli_keep_image) meets the same limit everywhere */
    static const char expected[] =
        "rt-export: out.ppm: cannot write the image: File too large\n"
        "rt-export: the image could not be kept either: ";
    ck_assert_msg(strncmp(err, expected, sizeof expected - 1) == 0, "%s",
                  err);
    ck_assert_msg(strstr(err + sizeof expected - 1, ": File too large\n"),
                  "%s", err);
    ck_assert_str_eq(out, "");
    free(out);
    free(err);
    rt_test_assert_previous_intact(image);
    rt_test_assert_dir_holds(dir, "out.ppm scene.scn");
    free(image);
    free(scene);
    rt_test_remove_dir(dir);
}
END_TEST

/* A scene that takes seconds to render: a wide image of many reflective
 * facets facing the camera. */
static char *slow_scene(void)
{
    int facets = 3000;
    size_t capacity = 256 + (size_t)facets * 120;
    char *text = malloc(capacity);
    ck_assert_ptr_nonnull(text);
    size_t n = (size_t)sprintf(text, "0 0 10\n0 0 5 4 0 5 2048 2048\n%d\n",
                               facets * 3);
    for (int i = 0; i < facets; i++) {
        double x = -8.0 + 16.0 * (double)(i % 60) / 60.0;
        double y = -8.0 + 16.0 * (double)(i / 60) / 50.0;
        double z = -(double)(i % 7) * 0.1;
        n += (size_t)sprintf(text + n, "%g %g %g\n%g %g %g\n%g %g %g\n", x,
                             y, z, x + 0.5, y, z + 0.2, x, y + 0.5, z - 0.2);
    }
    n += (size_t)sprintf(text + n, "%d\n", facets);
    for (int i = 0; i < facets; i++)
        n += (size_t)sprintf(text + n, "%d %d %d 0.5 200 150 100\n",
                             3 * i + 1, 3 * i + 2, 3 * i + 3);
    sprintf(text + n, "20 20 20\n0 0 20 255 255 255\n");
    return text;
}

START_TEST(export_killed_mid_render_keeps_the_previous_image)
{
    char *dir = rt_test_temp_dir();
    char *scene = rt_test_join(dir, "slow.scn");
    char *text = slow_scene();
    rt_test_write_bytes(scene, text, strlen(text));
    free(text);
    char *image = rt_test_join(dir, "out.ppm");
    rt_test_write_bytes(image, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    char *out, *err;
    const char *args[] = {"slow.scn", "-o", "out.ppm", "-q", NULL};
    int code = run_export(dir, args, 0.3, RLIM_INFINITY, &out, &err);
    ck_assert_msg(code == 128 + SIGKILL,
                  "rt-export finished (exit %d) before it was killed: the "
                  "scene is not slow enough; stderr: %s", code, err);
    free(out);
    free(err);
    rt_test_assert_previous_intact(image);
    rt_test_assert_dir_holds(dir, "out.ppm slow.scn");
    free(image);
    free(scene);
    rt_test_remove_dir(dir);
}
END_TEST

/*
 * rt-bench's files (two CSV files and an SVG plot) follow the same rule as
 * images: a run that cannot write them leaves the previous ones whole.
 */
START_TEST(bench_that_cannot_write_keeps_the_previous_files)
{
#ifndef RT_BENCH_PATH
    fprintf(stderr, "test_hostile_export: rt-bench is not built; skipped\n");
#else
    char *dir = rt_test_temp_dir();
    char *scene = rt_test_join(dir, "scene.scn");
    rt_test_write_bytes(scene, rt_test_small_scene,
                        strlen(rt_test_small_scene));
    const char *args[] = {"scene.scn", "--size", "16x12", "--runs", "5",
                          "--ref-samples", "16", "--max-samples", "4",
                          "--threads", "1", "-q", NULL};
    char *out, *err;
    int code = run_program(RT_BENCH_PATH, dir, args, -1, RLIM_INFINITY, &out,
                           &err);
    ck_assert_msg(code == 0, "rt-bench failed (%d): %s", code, err);
    free(out);
    free(err);
    static const char *const files[] = {"accuracy-scene-16x12.csv",
                                        "accuracy-scene-16x12-depth.csv",
                                        "accuracy-scene-16x12.svg"};
    char *before[3];
    size_t sizes[3];
    for (int i = 0; i < 3; i++) {
        char *path = rt_test_join(dir, files[i]);
        before[i] = rt_test_read_file(path, &sizes[i]);
        ck_assert_msg(before[i] != NULL, "rt-bench wrote no %s", files[i]);
        free(path);
    }
    char *listing = rt_test_dir_names(dir);
    ck_assert_ptr_nonnull(listing);
    /* every file is larger than 100 bytes: a 100-byte limit fails each
     * write; then one that lets the small depth CSV through */
    rlim_t limits[2] = {100, 1024};
    for (int l = 0; l < 2; l++) {
        code = run_program(RT_BENCH_PATH, dir, args, -1, limits[l], &out,
                           &err);
        ck_assert_msg(code == 1, "rt-bench exit %d with a %d-byte file "
                      "limit, expected 1", code, (int)limits[l]);
        for (int i = 0; i < 3; i++) {
            char *path = rt_test_join(dir, files[i]);
            size_t size;
            char *now = rt_test_read_file(path, &size);
            ck_assert_msg(now != NULL && size == sizes[i] &&
                              memcmp(now, before[i], size) == 0,
                          "%s was changed by a run that failed to write "
                          "(%zu bytes, was %zu)", files[i],
                          now ? size : 0, sizes[i]);
            free(now);
            free(path);
        }
        char *names = rt_test_dir_names(dir);
        ck_assert_ptr_nonnull(names);
        ck_assert_msg(strcmp(names, listing) == 0,
                      "the directory holds `%s`, was `%s`", names, listing);
        free(names);
        ck_assert_msg(strstr(err, "File too large") != NULL,
                      "the message does not say why: %s", err);
        free(out);
        free(err);
    }
    free(listing);
    for (int i = 0; i < 3; i++)
        free(before[i]);
    free(scene);
    rt_test_remove_dir(dir);
#endif
}

static Suite *hostile_export_suite(void)
{
    Suite *s = suite_create("hostile_export");
    TCase *tc = tcase_create("rt-export");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, export_refuses_to_write_over_its_own_scene);
    tcase_add_test(tc, export_exit_codes_say_what_went_wrong);
    tcase_add_test(tc, export_that_cannot_write_keeps_the_previous_image);
    tcase_add_test(tc, export_killed_mid_render_keeps_the_previous_image);
    tcase_add_test(tc, bench_that_cannot_write_keeps_the_previous_files);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(hostile_export_suite)
