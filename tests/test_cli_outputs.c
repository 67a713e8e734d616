/*
 * test_cli_outputs.c - what the programs write, as a user sees it:
 *
 *   - nothing over what was read: rt-export and rt-convert refuse an output
 *     that is, by any name (another spelling, a symbolic or a hard link,
 *     /dev/stdout, standard output redirected onto it), the scene or the
 *     standard input the scene came from, with a message naming both, and
 *     leave it intact; `test_cli_outputs sources` does the same for an
 *     OBJ's material library, once the loader lists the files it read
 *     (rt_scene_source_at; until then that entry exits 77, a skip);
 *   - rt-convert on the programs' option table: --help, --version,
 *     --opt=value, `--', the same words, a .scn name unless --force-name,
 *     and "the scene" in its messages;
 *   - a late failure keeps the work: a folder removed during the render,
 *     an output that has become the scene during the render, a full
 *     device: the image goes to a named file (next to the output, or in
 *     $TMPDIR), byte for byte the image a normal render writes.
 *
 * The render a test changes things under is stopped (SIGSTOP) when its
 * first progress line appears, changed, and continued (SIGCONT): the test
 * waits on what the program writes, never on a clock.
 */
#include <check.h>
#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"

static const char *cubes(void)
{
    static char path[4096];
    snprintf(path, sizeof path, "%s", rt_test_source_path("scenes/cubes.scn"));
    return path;
}

/* Copies the project's file `relative` to dir/name. */
static void copy_in(const char *dir, const char *relative, const char *name)
{
    char *text = rt_test_read_file(rt_test_source_path(relative), NULL);
    ck_assert_ptr_nonnull(text);
    rt_test_write_file(rt_test_in_dir(dir, name), text);
    free(text);
}

/* Fails unless dir/name holds exactly the project's file `relative`. */
static void assert_intact(const char *dir, const char *name,
                          const char *relative)
{
    size_t a_size, b_size;
    char *a = rt_test_read_file(rt_test_in_dir(dir, name), &a_size);
    char *b = rt_test_read_file(rt_test_source_path(relative), &b_size);
    ck_assert_msg(a != NULL && b != NULL && a_size == b_size &&
                      memcmp(a, b, a_size) == 0,
                  "%s was changed", name);
    free(a);
    free(b);
}

/* Fails unless r refused with exit 1 and, as the last line of its
 * messages (after the scene's warnings), exactly "PROGRAM: OUT: refusing
 * to write WHAT over IN, WHICH (the same file)". */
static void assert_refused(const rt_test_output *r, const char *program,
                           const char *out, const char *what,
                           const char *in, const char *which)
{
    char expected[1024];
    snprintf(expected, sizeof expected, "%s: %s: refusing to write %s over "
             "%s, %s (the same file)\n", program, out, what, in, which);
    ck_assert_msg(r->code == 1, "%s -o %s: exit %d: %s", program, out,
                  r->code, r->err);
    size_t length = strlen(r->err), want = strlen(expected);
    ck_assert_msg(length >= want &&
                      strcmp(r->err + length - want, expected) == 0 &&
                      (length == want || r->err[length - want - 1] == '\n'),
                  "%s, expected %s", r->err, expected);
}

/* ------------------------------------------------------------------ */
/* Nothing over the scene                                              */

/* dir/s.scn (the cubes), with a symbolic link link.scn and a hard link
 * hard.scn to it. */
static void scene_with_links(const char *dir)
{
    copy_in(dir, "scenes/cubes.scn", "s.scn");
    ck_assert_int_eq(symlink("s.scn", rt_test_in_dir(dir, "link.scn")), 0);
    ck_assert_int_eq(link(rt_test_in_dir(dir, "s.scn"),
                          rt_test_in_dir(dir, "hard.scn")), 0);
}

/* Where the output's name goes in assert_every_name_refused's args. */
#define NAME "<name>"

/* Runs `program` in dir once for each of names (NULL-terminated), with
 * `args` where the entry NAME is that name; each must be refused as an
 * output over s.scn, which stays as it was. */
static void assert_every_name_refused(const char *dir, const char *program,
                                      const char *const *args,
                                      const char *const *names)
{
    int convert = strcmp(program, RT_CONVERT_PATH) == 0;
    for (size_t i = 0; names[i] != NULL; i++) {
        const char *with[16];
        size_t n = 0;
        for (; args[n] != NULL && n < 15; n++)
            with[n] = strcmp(args[n], NAME) ? args[n] : names[i];
        with[n] = NULL;
        rt_test_output r = rt_test_run(dir, program, with);
        assert_refused(&r, convert ? "rt-convert" : "rt-export", names[i],
                       convert ? "the scene" : "the image", "s.scn",
                       "the scene it comes from");
        ck_assert_str_eq(r.out, "");
        rt_test_output_free(&r);
        assert_intact(dir, "s.scn", "scenes/cubes.scn");
    }
}

START_TEST(export_refuses_its_scene_by_every_name)
{
    char *dir = rt_test_temp_dir();
    scene_with_links(dir);
    const char *names[] = {"s.scn", "./s.scn", "link.scn", "hard.scn",
                           NULL};
    const char *args[] = {"s.scn", "-o", NAME, "--format", "p6", "-q", NULL};
    assert_every_name_refused(dir, RT_EXPORT_PATH, args, names);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(export_refuses_a_standard_output_that_is_its_scene)
{
    char *dir = rt_test_temp_dir();
    copy_in(dir, "scenes/cubes.scn", "s.scn");
    /* `rt-export s.scn -o - >> s.scn`, and -o /dev/stdout the same */
    const char *outputs[] = {"-", "/dev/stdout"};
    const char *shown[] = {"<stdout>", "/dev/stdout"};
    for (size_t i = 0; i < 2; i++) {
        const char *args[] = {"s.scn", "-o", outputs[i], "--format", "p3",
                              "-q", NULL};
        rt_test_setup setup = {NULL, rt_test_in_dir(dir, "s.scn"), NULL};
        rt_test_output r = rt_test_run_with(dir, RT_EXPORT_PATH, args, &setup);
        assert_refused(&r, "rt-export", shown[i], "the image", "s.scn",
                       "the scene it comes from");
        rt_test_output_free(&r);
        assert_intact(dir, "s.scn", "scenes/cubes.scn");
    }
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(export_refuses_the_standard_input_its_scene_came_from)
{
    char *dir = rt_test_temp_dir();
    copy_in(dir, "scenes/cubes.scn", "s.scn");
    const char *args[] = {"-", "-o", "s.scn", "--format", "p6", "-q", NULL};
    rt_test_setup setup = {rt_test_in_dir(dir, "s.scn"), NULL, NULL};
    rt_test_output r = rt_test_run_with(dir, RT_EXPORT_PATH, args, &setup);
    assert_refused(&r, "rt-export", "s.scn", "the image", "standard input",
                   "where the scene was read from");
    rt_test_output_free(&r);
    assert_intact(dir, "s.scn", "scenes/cubes.scn");
    rt_test_remove_dir(dir);
}
END_TEST

/* m.obj naming its library m.mtl, both in dir. */
static void write_obj(const char *dir)
{
    char *obj = rt_test_read_file(rt_test_source_path(
                                      "tests/data/obj/cube.obj"), NULL);
    ck_assert_ptr_nonnull(obj);
    char *at = strstr(obj, "mtllib cube.mtl");
    ck_assert_ptr_nonnull(at);
    memcpy(at, "mtllib    m.mtl", 15);
    rt_test_write_file(rt_test_in_dir(dir, "m.obj"), obj);
    free(obj);
    copy_in(dir, "tests/data/obj/cube.mtl", "m.mtl");
}

static void assert_obj_intact(const char *dir)
{
    char *obj = rt_test_read_file(rt_test_in_dir(dir, "m.obj"), NULL);
    ck_assert_ptr_nonnull(obj);
    ck_assert_ptr_nonnull(strstr(obj, "mtllib    m.mtl"));
    free(obj);
    assert_intact(dir, "m.mtl", "tests/data/obj/cube.mtl");
}

START_TEST(convert_refuses_its_scene_by_every_name)
{
    char *dir = rt_test_temp_dir();
    write_obj(dir);
    /* m.obj m.obj: refused by its name first, then by what it is */
    const char *by_name[] = {"m.obj", "m.obj", NULL};
    rt_test_output r = rt_test_run(dir, RT_CONVERT_PATH, by_name);
    ck_assert_int_eq(r.code, 2);
    ck_assert_ptr_nonnull(strstr(r.err, "expected an output named .scn"));
    rt_test_output_free(&r);
    assert_obj_intact(dir);
    const char *forced[] = {"m.obj", "m.obj", "--force-name", NULL};
    r = rt_test_run(dir, RT_CONVERT_PATH, forced);
    assert_refused(&r, "rt-convert", "m.obj", "the scene", "m.obj",
                   "the scene it comes from");
    rt_test_output_free(&r);
    assert_obj_intact(dir);
    /* a .scn over itself, through a link named .scn */
    scene_with_links(dir);
    const char *names[] = {"s.scn", "link.scn", "hard.scn", NULL};
    const char *args[] = {"s.scn", NAME, "--extended", NULL};
    assert_every_name_refused(dir, RT_CONVERT_PATH, args, names);
    rt_test_remove_dir(dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Nothing over a library (pending: the loader lists what it read)     */

START_TEST(export_refuses_the_material_library_its_obj_read)
{
    char *dir = rt_test_temp_dir();
    write_obj(dir);
    ck_assert_int_eq(link(rt_test_in_dir(dir, "m.mtl"),
                          rt_test_in_dir(dir, "hard.mtl")), 0);
    const char *names[] = {"m.mtl", "./m.mtl", "hard.mtl"};
    for (size_t i = 0; i < 3; i++) {
        const char *args[] = {"m.obj", "--format", "p6", "-o", names[i],
                              "-q", NULL};
        rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
        ck_assert_msg(r.code == 1, "-o %s: exit %d", names[i], r.code);
        char expected[256];
        snprintf(expected, sizeof expected, "rt-export: %s: refusing to "
                 "write the image over ", names[i]);
        /* the library as the loader names it (after the warnings) */
        const char *line = strstr(r.err, expected);
        ck_assert_msg(line != NULL &&
                          strstr(line, "m.mtl, a file the scene read (the "
                                       "same file)\n"),
                      "%s", r.err);
        rt_test_output_free(&r);
        assert_obj_intact(dir);
    }
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(convert_refuses_the_material_library_its_obj_read)
{
    char *dir = rt_test_temp_dir();
    write_obj(dir);
    const char *plain[] = {"m.obj", "m.mtl", NULL};
    rt_test_output r = rt_test_run(dir, RT_CONVERT_PATH, plain);
    ck_assert_int_ne(r.code, 0);
    rt_test_output_free(&r);
    assert_obj_intact(dir);
    const char *forced[] = {"m.obj", "m.mtl", "--force-name", NULL};
    r = rt_test_run(dir, RT_CONVERT_PATH, forced);
    ck_assert_int_eq(r.code, 1);
    const char *line = strstr(r.err, "rt-convert: m.mtl: refusing to write "
                                     "the scene over ");
    ck_assert_msg(line != NULL && strstr(line, "m.mtl, a file the scene read "
                                               "(the same file)\n"),
                  "%s", r.err);
    rt_test_output_free(&r);
    assert_obj_intact(dir);
    rt_test_remove_dir(dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* rt-convert on the option table                                      */

START_TEST(convert_takes_the_tables_forms_and_words)
{
    char *dir = rt_test_temp_dir();
    copy_in(dir, "scenes/cubes.scn", "-weird.scn");
    const char *help[] = {"--help", NULL};
    rt_test_output r = rt_test_run(dir, RT_CONVERT_PATH, help);
    ck_assert_int_eq(r.code, 0);
    ck_assert_msg(strncmp(r.out, "usage: rt-convert [OPTION]... IN OUT.scn",
                          40) == 0, "%s", r.out);
    ck_assert_ptr_nonnull(strstr(r.out, "--force-name"));
    ck_assert_ptr_nonnull(strstr(r.out, "--input-format=F"));
    ck_assert_ptr_null(strstr(r.out, "--look-from"));
    rt_test_output_free(&r);
    const char *version[] = {"--version", NULL};
    r = rt_test_run(dir, RT_CONVERT_PATH, version);
    ck_assert_int_eq(r.code, 0);
    ck_assert_msg(strncmp(r.out, "rt-convert (libraytrace) ", 25) == 0, "%s",
                  r.out);
    rt_test_output_free(&r);
    /* `--' ends the options; --opt=value */
    const char *weird[] = {"--input-format=scn", "--", "-weird.scn",
                           "out.scn", NULL};
    r = rt_test_run(dir, RT_CONVERT_PATH, weird);
    ck_assert_msg(r.code == 0, "%s", r.err);
    ck_assert_str_eq(r.out, "out.scn\n");
    rt_test_output_free(&r);
    /* the same limits and words as rt-export */
    static const struct {
        const char *args[4];
        const char *message;
    } cases[] = {
        {{"--tessellate=0", "a.scn", "b.scn", NULL},
         "--tessellate: expected a number in (0, 1), found 0"},
        {{"--input-format=stl", "a.scn", "b.scn", NULL},
         "--input-format: expected scn, nff, obj or ply, found 'stl'"},
        {{"--nope", "a.scn", "b.scn", NULL},
         "unknown or ambiguous option '--nope'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        const char *const programs[] = {RT_CONVERT_PATH, RT_EXPORT_PATH};
        for (int p = 0; p < 2; p++) {
            const char *name = p ? "rt-export" : "rt-convert";
            r = rt_test_run(dir, programs[p], cases[i].args);
            char expected[512];
            snprintf(expected, sizeof expected,
                     "%s: %s\nTry '%s --help'.\n", name, cases[i].message,
                     name);
            ck_assert_msg(r.code == 2, "%s case %zu: exit %d", name, i,
                          r.code);
            if (p == 0 || i != 2) /* rt-export: a.scn b.scn is also wrong */
                ck_assert_str_eq(r.err, expected);
            rt_test_output_free(&r);
        }
    }
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(convert_refuses_a_name_not_ending_in_scn_unless_forced)
{
    char *dir = rt_test_temp_dir();
    const char *png[] = {cubes(), "out.png", NULL};
    rt_test_output r = rt_test_run(dir, RT_CONVERT_PATH, png);
    ck_assert_int_eq(r.code, 2);
    ck_assert_str_eq(r.err, "rt-convert: expected an output named .scn "
                            "(rt-convert writes .scn text), found 'out.png'; "
                            "--force-name writes it there anyway\n"
                            "Try 'rt-convert --help'.\n");
    rt_test_output_free(&r);
    ck_assert_int_eq(access(rt_test_in_dir(dir, "out.png"), F_OK), -1);
    const char *forced[] = {cubes(), "out.png", "--force-name", NULL};
    const char *upper[] = {cubes(), "OUT.SCN", NULL};
    const char *device[] = {cubes(), "/dev/null", NULL};
    const char *const *accepted[] = {forced, upper, device};
    for (size_t i = 0; i < 3; i++) {
        r = rt_test_run(dir, RT_CONVERT_PATH, accepted[i]);
        ck_assert_msg(r.code == 0, "%s: %s", accepted[i][1], r.err);
        rt_test_output_free(&r);
    }
    char *text = rt_test_read_file(rt_test_in_dir(dir, "out.png"), NULL);
    ck_assert_ptr_nonnull(text);
    ck_assert_msg(strncmp(text, "# written by libraytrace", 24) == 0, "%s",
                  text);
    free(text);
    ck_assert_int_eq(access(rt_test_in_dir(dir, "OUT.SCN"), F_OK), 0);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(convert_calls_what_it_writes_the_scene)
{
    char *dir = rt_test_temp_dir();
    ck_assert_int_eq(mkdir(rt_test_in_dir(dir, "folder.scn"), 0755), 0);
    const char *missing[] = {cubes(), "no/such/x.scn", NULL};
    rt_test_output r = rt_test_run(dir, RT_CONVERT_PATH, missing);
    ck_assert_int_eq(r.code, 1);
    ck_assert_str_eq(r.err, "rt-convert: no/such/x.scn: cannot write the "
                            "scene: the folder no/such/ does not exist\n");
    rt_test_output_free(&r);
    const char *folder[] = {cubes(), "folder.scn", NULL};
    r = rt_test_run(dir, RT_CONVERT_PATH, folder);
    ck_assert_int_eq(r.code, 1);
    ck_assert_str_eq(r.err, "rt-convert: folder.scn: cannot write the "
                            "scene: is a directory\n");
    ck_assert_ptr_null(strstr(r.err, "image"));
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* A late failure keeps the work                                       */

/* The render the rescue tests stop and change things under: long enough
 * that half a second of its CPU time (mid_render: off a terminal the
 * progress line comes only at the end) comes well before its end - about
 * 1.5 s optimised, and the same work would take
 * minutes under AddressSanitizer, whose programs run some 30 times slower:
 * there a sixteenth of it does. */
#if RT_TEST_UNDER_ASAN
#define SLOW "--samples", "4", "-j", "1"
#else
#define SLOW "--samples", "64", "-j", "1"
#endif

/* Bytes of the file `path`, which must exist. */
static char *bytes_of(const char *path, size_t *size)
{
    char *data = rt_test_read_file(path, size);
    ck_assert_msg(data != NULL, "%s does not exist", path);
    return data;
}

/* The name in "PROGRAM: the image is kept in NAME\n" of err, malloc'd. */
static char *kept_name(const char *err, const char *program)
{
    char tag[128];
    snprintf(tag, sizeof tag, "%s: the image is kept in ", program);
    const char *at = strstr(err, tag);
    ck_assert_msg(at != NULL, "no image kept: %s", err);
    at += strlen(tag);
    return strndup(at, strcspn(at, "\n"));
}

/* Fails unless `kept` holds exactly what rt-export writes for `args` in
 * dir (a normal render to ref.ppm). */
static void assert_same_as_a_normal_render(const char *dir, const char *kept,
                                           const char *const *args)
{
    const char *all[24];
    int n = 0;
    for (int i = 0; args[i] != NULL; i++)
        all[n++] = args[i];
    all[n++] = "-o";
    all[n++] = "ref.img";
    all[n] = NULL;
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, all);
    ck_assert_msg(r.code == 0, "%s", r.err);
    rt_test_output_free(&r);
    size_t a_size, b_size;
    char *a = bytes_of(kept, &a_size);
    char *b = bytes_of(rt_test_in_dir(dir, "ref.img"), &b_size);
    ck_assert_msg(a_size == b_size && memcmp(a, b, a_size) == 0,
                  "%s is not the image a normal render writes", kept);
    free(a);
    free(b);
}

/* Waits until `s` has rendered for half a second of CPU time (the load of
 * the cubes takes milliseconds), then stops it (SIGSTOP); fails the test
 * when it ended first. */
static void stop_mid_render(rt_test_process *s)
{
    while (rt_test_running(s) && rt_test_cpu_seconds(s) < 0.5)
        nanosleep(&(struct timespec){0, 10000000}, NULL);
    ck_assert_msg(rt_test_running(s), "the render ended before 0.5 s of "
                                      "CPU time: %s", s->err ? s->err : "");
    ck_assert_int_eq(kill(s->pid, SIGSTOP), 0);
}

START_TEST(export_keeps_the_image_when_its_folder_is_removed_mid_render)
{
    char *dir = rt_test_temp_dir();
    ck_assert_int_eq(mkdir(rt_test_in_dir(dir, "tmp"), 0755), 0);
    ck_assert_int_eq(mkdir(rt_test_in_dir(dir, "sub"), 0755), 0);
    const char *args[] = {cubes(), SLOW, "--progress", "--format", "p6",
                          "-o", "sub/out.ppm", NULL};
    rt_test_setup setup = {NULL, NULL, rt_test_in_dir(dir, "tmp")};
    rt_test_process s = rt_test_start_piped(dir, RT_EXPORT_PATH, args, &setup);
    /* the output was checked before the render: its folder is there */
    stop_mid_render(&s);
    ck_assert_int_eq(rmdir(rt_test_in_dir(dir, "sub")), 0);
    ck_assert_int_eq(kill(s.pid, SIGCONT), 0);
    rt_test_output r = rt_test_finish(&s);
    ck_assert_int_eq(r.code, 1);
    ck_assert_msg(strstr(r.err, "rt-export: sub/out.ppm: cannot write the "
                                "image: the folder sub/ does not exist\n"),
                  "%s", r.err);
    ck_assert_str_eq(r.out, "");
    char *kept = kept_name(r.err, "rt-export");
    char prefix[4200];
    snprintf(prefix, sizeof prefix, "%s/out.rescue-",
             rt_test_in_dir(dir, "tmp"));
    ck_assert_msg(strncmp(kept, prefix, strlen(prefix)) == 0 &&
                      strlen(kept) == strlen(prefix) + 6 + 4 &&
                      strcmp(kept + strlen(kept) - 4, ".ppm") == 0,
                  "%s", kept);
    const char *normal[] = {cubes(), SLOW, "-q", "--format", "p6", NULL};
    assert_same_as_a_normal_render(dir, kept, normal);
    free(kept);
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(export_keeps_the_image_when_its_output_becomes_the_scene)
{
    char *dir = rt_test_temp_dir();
    copy_in(dir, "scenes/cubes.scn", "s.scn");
    const char *args[] = {"s.scn", SLOW, "--progress", "--format", "png",
                          "-o", "out.png", NULL};
    rt_test_process s = rt_test_start_piped(dir, RT_EXPORT_PATH, args, NULL);
    stop_mid_render(&s);
    /* out.png is now the scene itself, under another name */
    ck_assert_int_eq(link(rt_test_in_dir(dir, "s.scn"),
                          rt_test_in_dir(dir, "out.png")), 0);
    ck_assert_int_eq(kill(s.pid, SIGCONT), 0);
    rt_test_output r = rt_test_finish(&s);
    ck_assert_int_eq(r.code, 1);
    ck_assert_msg(strstr(r.err, "rt-export: out.png: refusing to write the "
                                "image over s.scn, the scene it comes from "
                                "(the same file)\n"), "%s", r.err);
    assert_intact(dir, "s.scn", "scenes/cubes.scn");
    char *kept = kept_name(r.err, "rt-export");
    ck_assert_msg(strncmp(kept, "out.rescue-", 11) == 0 &&
                      strcmp(kept + strlen(kept) - 4, ".png") == 0,
                  "%s", kept);
    const char *normal[] = {"s.scn", SLOW, "-q", "--format", "png", NULL};
    assert_same_as_a_normal_render(dir, rt_test_in_dir(dir, kept), normal);
    struct stat st;
    ck_assert_int_eq(stat(rt_test_in_dir(dir, kept), &st), 0);
    ck_assert_int_eq(st.st_mode & 0777, 0600);
    free(kept);
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(export_keeps_the_image_a_full_device_did_not_take)
{
    if (access("/dev/full", W_OK) != 0) {
        fprintf(stderr, "test_cli_outputs: no /dev/full: not checked\n");
        return;
    }
    char *dir = rt_test_temp_dir();
    ck_assert_int_eq(mkdir(rt_test_in_dir(dir, "tmp"), 0755), 0);
    /* -o /dev/full, and -o - into /dev/full */
    static const struct {
        const char *output, *stdout_path, *failure, *stem;
    } cases[] = {
        {"/dev/full", NULL, "rt-export: /dev/full: cannot write the image: ",
         "full.rescue-"},
        {"-", "/dev/full", "rt-export: <stdout>: ", "image.rescue-"},
    };
    for (size_t i = 0; i < 2; i++) {
        const char *args[] = {cubes(), "--size", "64x48", "--format", "p3",
                              "-q", "-o", cases[i].output, NULL};
        rt_test_setup setup = {NULL, cases[i].stdout_path,
                               rt_test_in_dir(dir, "tmp")};
        rt_test_output r = rt_test_run_with(dir, RT_EXPORT_PATH, args, &setup);
        ck_assert_int_eq(r.code, 1);
        ck_assert_msg(strncmp(r.err, cases[i].failure,
                              strlen(cases[i].failure)) == 0, "%s", r.err);
        char *kept = kept_name(r.err, "rt-export");
        char prefix[4200];
        snprintf(prefix, sizeof prefix, "%s/%s", rt_test_in_dir(dir, "tmp"),
                 cases[i].stem);
        ck_assert_msg(strncmp(kept, prefix, strlen(prefix)) == 0, "%s",
                      kept);
        const char *normal[] = {cubes(), "--size", "64x48", "--format", "p3",
                                "-q", NULL};
        assert_same_as_a_normal_render(dir, kept, normal);
        unlink(kept);
        free(kept);
        rt_test_output_free(&r);
    }
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *outputs_suite(void)
{
    Suite *s = suite_create("cli_outputs");
    TCase *c = tcase_create("inputs");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, export_refuses_its_scene_by_every_name);
    tcase_add_test(c, export_refuses_a_standard_output_that_is_its_scene);
    tcase_add_test(c, export_refuses_the_standard_input_its_scene_came_from);
    tcase_add_test(c, convert_refuses_its_scene_by_every_name);
    suite_add_tcase(s, c);
    c = tcase_create("convert");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, convert_takes_the_tables_forms_and_words);
    tcase_add_test(c, convert_refuses_a_name_not_ending_in_scn_unless_forced);
    tcase_add_test(c, convert_calls_what_it_writes_the_scene);
    suite_add_tcase(s, c);
    c = tcase_create("rescue");
    tcase_set_timeout(c, 240);
    tcase_add_test(c, export_keeps_the_image_when_its_folder_is_removed_mid_render);
    tcase_add_test(c, export_keeps_the_image_when_its_output_becomes_the_scene);
    tcase_add_test(c, export_keeps_the_image_a_full_device_did_not_take);
    suite_add_tcase(s, c);
    return s;
}

static Suite *sources_suite(void)
{
    Suite *s = suite_create("cli_outputs_sources");
    TCase *c = tcase_create("libraries");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, export_refuses_the_material_library_its_obj_read);
    tcase_add_test(c, convert_refuses_the_material_library_its_obj_read);
    suite_add_tcase(s, c);
    return s;
}

/* `test_cli_outputs` runs the main suite; `test_cli_outputs sources` the
 * cases that need the loader's list of the files it read, or exits 77
 * while the loader lists none. */
int main(int argc, char **argv)
{
    return rt_test_main_with_sources(argc, argv, outputs_suite, sources_suite);
}
