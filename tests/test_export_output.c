/*
 * test_export_output.c - where rt-export's image goes, as a user sees it:
 * standard output (`-o -`, `-o /dev/stdout`), a scene read from standard
 * input (`-`), the format chosen from the extension, PNG whose pixels are
 * the PPM's, a FIFO, an output refused before rendering, and a save
 * interrupted by a signal, and scenes converted by rt-convert.  Each case
 * runs the real programs.
 */
#include <check.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#if RT_TEST_HAVE_PNG
#include <png.h>
#endif

#include "testutil.h"

/* A fresh directory for one test; remove with remove_tree. */
static char *fresh_dir(void)
{
    char *dir = strdup("/tmp/rt-export-output-XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(dir));
    return dir;
}

static void remove_tree(char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    while (d && (entry = readdir(d)) != NULL) {
        if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, entry->d_name);
        if (unlink(path) != 0)
            rmdir(path);    /* the tests make only empty folders */
    }
    if (d)
        closedir(d);
    rmdir(dir);
    free(dir);
}

/* Writes `text` to dir/name; returns the path in a static buffer. */
static const char *write_text(const char *dir, const char *name,
                              const char *text)
{
    static char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *file = fopen(path, "w");
    ck_assert_ptr_nonnull(file);
    ck_assert_int_ge(fputs(text, file), 0);
    ck_assert_int_eq(fclose(file), 0);
    return path;
}

/* Names in `dir` (no dot files except .rt-save-*), sorted, space-separated. */
static void list_dir(const char *dir, char *out, size_t size)
{
    struct dirent **names;
    int n = scandir(dir, &names, NULL, alphasort);
    ck_assert_int_ge(n, 0);
    out[0] = '\0';
    for (int i = 0; i < n; i++) {
        const char *name = names[i]->d_name;
        if (strcmp(name, ".") && strcmp(name, "..") &&
            (name[0] != '.' || !strncmp(name, ".rt-save-", 9))) {
            if (out[0])
                strncat(out, " ", size - strlen(out) - 1);
            strncat(out, name, size - strlen(out) - 1);
        }
        free(names[i]);
    }
    free(names);
}

/* A finished run: exit status (128 + signal when killed) and its output. */
typedef struct run {
    int code;
    char *out;              /* standard output */
    size_t out_size;
    char *err;              /* standard error */
} run;

static void run_free(run *r)
{
    free(r->out);
    free(r->err);
}

/*
 * Starts rt-export in `dir` with `args` (NULL-terminated), standard input
 * from `input` (or /dev/null), the termination signals at their default
 * action (a test runner may ignore SIGINT), and standard output and error to
 * files in `dir`.  Returns the pid; finish with wait_export.
 */
static pid_t start_program(const char *program, const char *dir,
                           const char *const *args, const char *input)
{
    static char out_path[4096], err_path[4096];
    snprintf(out_path, sizeof out_path, "%s/..out", dir);
    snprintf(err_path, sizeof err_path, "%s/..err", dir);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, input ? input : "/dev/null",
                                     O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, out_path,
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_path,
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    sigaddset(&defaults, SIGHUP);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);

    char *argv[24];
    int argc = 0;
    argv[argc++] = (char *)program;
    for (int i = 0; args[i] != NULL && argc < 23; i++)
        argv[argc++] = (char *)args[i];
    argv[argc] = NULL;
    char cwd[4096];
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    ck_assert_int_eq(chdir(dir), 0);
    pid_t pid;
    extern char **environ;
    int failed = posix_spawn(&pid, program, &actions, &attributes,
                             argv, environ);
    ck_assert_int_eq(chdir(cwd), 0);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ck_assert_msg(failed == 0, "cannot start %s: %s", program,
                  strerror(failed));
    return pid;
}

static pid_t start_export(const char *dir, const char *const *args,
                          const char *input)
{
    return start_program(RT_EXPORT_PATH, dir, args, input);
}

static run wait_export(const char *dir, pid_t pid)
{
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    run r;
    r.code = WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                                 : WEXITSTATUS(status);
    char path[4096];
    snprintf(path, sizeof path, "%s/..out", dir);
    r.out = rt_test_read_file(path, &r.out_size);
    unlink(path);
    snprintf(path, sizeof path, "%s/..err", dir);
    r.err = rt_test_read_file(path, NULL);
    unlink(path);
    ck_assert_ptr_nonnull(r.out);
    ck_assert_ptr_nonnull(r.err);
    return r;
}

static run export_in(const char *dir, const char *const *args,
                     const char *input)
{
    return wait_export(dir, start_export(dir, args, input));
}

static const char *cubes(void)
{
    static char path[4096];
    snprintf(path, sizeof path, "%s", rt_test_source_path("scenes/cubes.scn"));
    return path;
}

/* Renders cubes to dir/reference.ppm with the plain file output. */
static char *reference_image(const char *dir, size_t *size)
{
    const char *args[] = {cubes(), "-o", "reference.ppm", "-q", NULL};
    run r = export_in(dir, args, NULL);
    ck_assert_msg(r.code == 0, "rt-export failed: %s", r.err);
    ck_assert_str_eq(r.out, "reference.ppm\n");
    run_free(&r);
    char path[4096];
    snprintf(path, sizeof path, "%s/reference.ppm", dir);
    char *bytes = rt_test_read_file(path, size);
    ck_assert_ptr_nonnull(bytes);
    return bytes;
}

/* `-o -` and `-o /dev/stdout` (a link into /proc): the image bytes and
 * nothing else on standard output; no file named "-", the link stays. */
START_TEST(standard_output_gets_exactly_the_image_bytes)
{
    static const char *const outputs[] = {"-", "/dev/stdout"};
    char *dir = fresh_dir();
    size_t expected_size;
    char *expected = reference_image(dir, &expected_size);
    const char *args[] = {cubes(), "-o", outputs[_i], "-q", NULL};
    run r = export_in(dir, args, NULL);
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_uint_eq(r.out_size, expected_size);
    ck_assert(memcmp(r.out, expected, expected_size) == 0);
    char names[512];
    list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "reference.ppm");
    struct stat st;
    ck_assert_int_eq(lstat("/dev/stdout", &st), 0);
    ck_assert(S_ISLNK(st.st_mode));
    run_free(&r);
    free(expected);
    remove_tree(dir);
}
END_TEST

START_TEST(scene_from_standard_input_renders_as_the_file_does)
{
    char *dir = fresh_dir();
    size_t expected_size;
    char *expected = reference_image(dir, &expected_size);
    const char *args[] = {"-", "-o", "piped.ppm", NULL};
    run r = export_in(dir, args, cubes());
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_str_eq(r.out, "piped.ppm\n");
    char path[4096];
    snprintf(path, sizeof path, "%s/piped.ppm", dir);
    size_t size;
    char *bytes = rt_test_read_file(path, &size);
    ck_assert_uint_eq(size, expected_size);
    ck_assert(memcmp(bytes, expected, size) == 0);
    free(bytes);
    run_free(&r);
    free(expected);
    remove_tree(dir);
}
END_TEST

START_TEST(errors_in_a_scene_from_standard_input_name_stdin)
{
    char *dir = fresh_dir();
    const char *path = write_text(dir, "bad.scn", "1,2\n");
    const char *args[] = {"-", "-o", "out.ppm", NULL};
    run r = export_in(dir, args, path);
    ck_assert_int_eq(r.code, 1);
    ck_assert_msg(strncmp(r.err, "rt-export: <stdin>:1:", 21) == 0,
                  "message: %s", r.err);
    run_free(&r);
    /* Without -o there is no name to derive: a usage error. */
    const char *no_output[] = {"-", NULL};
    r = export_in(dir, no_output, cubes());
    ck_assert_int_eq(r.code, 2);
    ck_assert_msg(strstr(r.err, "-o") != NULL, "message: %s", r.err);
    run_free(&r);
    char names[512];
    list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "bad.scn");
    remove_tree(dir);
}
END_TEST

/* The first bytes of dir/name, or "" when it does not exist. */
static void magic(const char *dir, const char *name, char out[9])
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    memset(out, 0, 9);
    FILE *file = fopen(path, "rb");
    if (file) {
        if (fread(out, 1, 8, file) == 0)
            out[0] = '\0';
        fclose(file);
    }
}

START_TEST(format_follows_the_extension_unless_given)
{
    char *dir = fresh_dir();
    static const struct {
        const char *output, *format, *start;
    } cases[] = {
        {"a.ppm", NULL, "P6\n"},
        {"b.PNM", NULL, "P6\n"},
        {"c", NULL, "P6\n"},                /* no extension: P6 */
        {"d.png", "p3", "P3\n"},            /* --format wins */
        {"e.ppm", "p3", "P3\n"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *args[] = {cubes(), "-o", cases[i].output, "-q",
                              cases[i].format ? "--format" : NULL,
                              cases[i].format, NULL};
        run r = export_in(dir, args, NULL);
        ck_assert_msg(r.code == 0, "%s: exit %d: %s", cases[i].output,
                      r.code, r.err);
        char start[9];
        magic(dir, cases[i].output, start);
        ck_assert_msg(strncmp(start, cases[i].start, 3) == 0,
                      "%s starts with %.3s", cases[i].output, start);
        run_free(&r);
    }
    remove_tree(dir);
}
END_TEST

START_TEST(unknown_extension_is_a_usage_error_listing_the_formats)
{
    char *dir = fresh_dir();
    const char *args[] = {cubes(), "-o", "picture.jpg", NULL};
    run r = export_in(dir, args, NULL);
    ck_assert_int_eq(r.code, 2);
    ck_assert_msg(strstr(r.err, ".png") && strstr(r.err, ".ppm") &&
                      strstr(r.err, "p3"),
                  "message: %s", r.err);
    char names[512];
    list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "");
    run_free(&r);
    remove_tree(dir);
}
END_TEST

#if RT_TEST_HAVE_PNG
/* Decodes a PNG file into 8-bit RGB (malloc'd). */
static unsigned char *decode_png(const char *path, int *width, int *height)
{
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path))
        return NULL;
    image.format = PNG_FORMAT_RGB;
    unsigned char *pixels = malloc(PNG_IMAGE_SIZE(image));
    if (pixels == NULL ||
        !png_image_finish_read(&image, NULL, pixels, 0, NULL)) {
        free(pixels);
        png_image_free(&image);
        return NULL;
    }
    *width = (int)image.width;
    *height = (int)image.height;
    return pixels;
}
#endif

START_TEST(png_holds_the_pixels_of_the_ppm)
{
    char *dir = fresh_dir();
    size_t size;
    free(reference_image(dir, &size));
    const char *args[] = {cubes(), "-o", "cubes.png", "-q", NULL};
    run r = export_in(dir, args, NULL);
#if RT_TEST_HAVE_PNG
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_str_eq(r.out, "cubes.png\n");
    char path[4096];
    snprintf(path, sizeof path, "%s/cubes.png", dir);
    int width = 0, height = 0;
    unsigned char *pixels = decode_png(path, &width, &height);
    ck_assert_msg(pixels != NULL, "libpng cannot read %s", path);
    snprintf(path, sizeof path, "%s/reference.ppm", dir);
    rt_image ppm;
    ck_assert_int_eq(rt_ppm_load(path, &ppm, NULL), RT_OK);
    ck_assert_int_eq(width, ppm.width);
    ck_assert_int_eq(height, ppm.height);
    ck_assert(memcmp(pixels, ppm.pixels, (size_t)width * height * 3) == 0);
    rt_image_release(&ppm);
    free(pixels);
#else
    /* A build without libpng says so, and writes nothing. */
    ck_assert_int_eq(r.code, 1);
    ck_assert_msg(strstr(r.err, "libpng") != NULL, "message: %s", r.err);
#endif
    run_free(&r);
    remove_tree(dir);
}
END_TEST

/* A scene whose render would take hours: only a refusal before rendering
 * lets these cases finish within the test's timeout. */
static const char endless_scene[] =
    "0,0,-5\n0,0,0, 1,0,0, 16384,16384\n3\n-1,-1,0\n1,-1,0\n0,1,0\n"
    "1\n1,2,3, 0.5, 200,100,50\n0,0,0\n0,0,-5, 255,255,255\n";

START_TEST(bad_output_fails_before_rendering)
{
    char *dir = fresh_dir();
    write_text(dir, "endless.scn", endless_scene);
    char path[4096];
    snprintf(path, sizeof path, "%s/folder.ppm", dir);
    ck_assert_int_eq(mkdir(path, 0755), 0);
    static const struct {
        const char *output, *reason;
    } cases[] = {
        {"missing/dir/x.ppm", "the folder missing/dir/ does not exist"},
        {"folder.ppm", "is a directory"},
        {"endless.scn/x.ppm", "endless.scn/ is not a folder"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *args[] = {"endless.scn", "-o", cases[i].output,
                              "--samples", "1024", NULL};
        run r = export_in(dir, args, NULL);
        ck_assert_msg(r.code == 1, "%s: exit %d", cases[i].output, r.code);
        ck_assert_msg(strstr(r.err, cases[i].output) &&
                          strstr(r.err, cases[i].reason),
                      "%s: message: %s", cases[i].output, r.err);
        run_free(&r);
    }
    char names[512];
    list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "endless.scn folder.ppm");
    remove_tree(dir);
}
END_TEST

typedef struct fifo_reader {
    const char *path;
    char *bytes;
    size_t size;
} fifo_reader;

static void *read_fifo(void *arg)
{
    fifo_reader *reader = arg;
    reader->bytes = rt_test_read_file(reader->path, &reader->size);
    return NULL;
}

START_TEST(fifo_output_is_streamed_to_its_reader)
{
    char *dir = fresh_dir();
    size_t expected_size;
    char *expected = reference_image(dir, &expected_size);
    char path[4096];
    snprintf(path, sizeof path, "%s/pipe", dir);
    ck_assert_int_eq(mkfifo(path, 0644), 0);
    fifo_reader reader = {path, NULL, 0};
    pthread_t thread;
    ck_assert_int_eq(pthread_create(&thread, NULL, read_fifo, &reader), 0);
    const char *args[] = {cubes(), "-o", "pipe", "-q", NULL};
    run r = export_in(dir, args, NULL);
    pthread_join(thread, NULL);
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_ptr_nonnull(reader.bytes);
    ck_assert_uint_eq(reader.size, expected_size);
    ck_assert(memcmp(reader.bytes, expected, expected_size) == 0);
    struct stat st;
    ck_assert_int_eq(lstat(path, &st), 0);
    ck_assert(S_ISFIFO(st.st_mode));
    char names[512];
    list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "pipe reference.ppm");
    free(reader.bytes);
    run_free(&r);
    free(expected);
    remove_tree(dir);
}
END_TEST

/* Non-zero once dir holds a temporary file of the save with bytes in it
 * (the empty one of the check before rendering does not count). */
static int saving(const char *dir)
{
    char names[512];
    list_dir(dir, names, sizeof names);
    const char *temp = strstr(names, ".rt-save-");
    if (temp == NULL)
        return 0;
    char path[4096];
    snprintf(path, sizeof path, "%s/%.15s", dir, temp);
    struct stat st;
    return stat(path, &st) == 0 && st.st_size > 0;
}

/* A 3000 x 3000 P3 image takes long enough to write to be caught in the
 * middle of it by a signal. */
static void interrupt_the_save(int signal_number)
{
    char *dir = fresh_dir();
    write_text(dir, "big.scn",
               "0,0,-5\n0,0,0, 1,0,0, 3000,3000\n3\n-1,-1,0\n1,-1,0\n"
               "0,1,0\n1\n1,2,3, 0.5, 200,100,50\n0,0,0\n"
               "0,0,-5, 255,255,255\n");
    static const char previous[] = "P3\n1 1\n255\n1 2 3\n";
    char path[4096];
    snprintf(path, sizeof path, "%s", write_text(dir, "out.ppm", previous));

    const char *args[] = {"big.scn", "-o", "out.ppm", "--format", "p3", "-q",
                          NULL};
    pid_t pid = start_export(dir, args, NULL);
    struct timespec pause = {0, 1000000};
    int seen = 0;
    for (int i = 0; i < 60000 && !seen; i++) {
        seen = saving(dir);
        if (!seen) {
            int status;
            ck_assert_msg(waitpid(pid, &status, WNOHANG) == 0,
                          "rt-export ended before its save was seen");
            nanosleep(&pause, NULL);
        }
    }
    ck_assert_msg(seen, "no temporary file appeared within a minute");
    kill(pid, signal_number);
    run r = wait_export(dir, pid);
    ck_assert_msg(r.code == 128 + signal_number,
                  "exit %d, expected %d (killed by the signal): %s", r.code,
                  128 + signal_number, r.err);
    char *bytes = rt_test_read_file(path, NULL);
    ck_assert_ptr_nonnull(bytes);
    ck_assert_str_eq(bytes, previous);
    free(bytes);
    char names[512];
    list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "big.scn out.ppm");
    run_free(&r);
    remove_tree(dir);
}

START_TEST(signal_during_the_save_keeps_the_previous_file)
{
    static const int signals[] = {SIGINT, SIGTERM, SIGHUP};
    interrupt_the_save(signals[_i]);
}
END_TEST

/* rt-convert --extended then rt-export gives the bytes of the direct
 * render, for a scene of each format (and the lens, glass and lights of
 * the extension); without --extended what .scn cannot hold is dropped
 * with a warning. */
START_TEST(converted_scenes_render_as_the_originals)
{
    static const struct {
        const char *path, *samples;
    } scenes[] = {
        {"scenes/cubes.scn", "1"},      {"scenes/glass.scn", "1"},
        {"scenes/focus.scn", "4"},      {"scenes/nff-sphere.nff", "1"},
        {"tests/data/obj/cube.obj", "1"},
    };
    char *dir = fresh_dir();
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        char source[4096];
        snprintf(source, sizeof source, "%s",
                 rt_test_source_path(scenes[i].path));
        const char *convert[] = {source, "converted.scn", "--extended",
                                 NULL};
        run r = wait_export(dir, start_program(RT_CONVERT_PATH, dir,
                                               convert, NULL));
        ck_assert_msg(r.code == 0, "%s: rt-convert exit %d: %s",
                      scenes[i].path, r.code, r.err);
        run_free(&r);
        const char *direct[] = {source, "-o", "direct.ppm", "-q",
                                "--samples", scenes[i].samples, NULL};
        const char *again[] = {"converted.scn", "-o", "again.ppm", "-q",
                               "--samples", scenes[i].samples, NULL};
        r = export_in(dir, direct, NULL);
        ck_assert_msg(r.code == 0, "%s: %s", scenes[i].path, r.err);
        run_free(&r);
        r = export_in(dir, again, NULL);
        ck_assert_msg(r.code == 0, "%s converted: %s", scenes[i].path, r.err);
        run_free(&r);
        char a[4096], b[4096];
        snprintf(a, sizeof a, "%s/direct.ppm", dir);
        snprintf(b, sizeof b, "%s/again.ppm", dir);
        size_t na, nb;
        char *da = rt_test_read_file(a, &na), *db = rt_test_read_file(b, &nb);
        ck_assert_msg(da && db && na == nb && memcmp(da, db, na) == 0,
                      "%s: the converted scene renders differently",
                      scenes[i].path);
        free(da);
        free(db);
    }
    /* plain .scn: the second light and the glass are dropped, said so */
    char glass[4096];
    snprintf(glass, sizeof glass, "%s", rt_test_source_path("scenes/glass.scn"));
    const char *plain[] = {glass, "plain.scn", NULL};
    run r = wait_export(dir, start_program(RT_CONVERT_PATH, dir, plain,
                                           NULL));
    ck_assert_int_eq(r.code, 0);
    ck_assert_msg(strstr(r.err, "dropped the lights after the first") &&
                      strstr(r.err, "dropped the facets' transparency"),
                  "warnings: %s", r.err);
    run_free(&r);
    remove_tree(dir);
}
END_TEST

static Suite *export_output_suite(void)
{
    Suite *s = suite_create("export_output");
    TCase *c = tcase_create("streams");
    tcase_set_timeout(c, 240);
    tcase_add_loop_test(c, standard_output_gets_exactly_the_image_bytes, 0,
                        2);
    tcase_add_test(c, scene_from_standard_input_renders_as_the_file_does);
    tcase_add_test(c, errors_in_a_scene_from_standard_input_name_stdin);
    tcase_add_test(c, fifo_output_is_streamed_to_its_reader);
    suite_add_tcase(s, c);
    c = tcase_create("formats");
    tcase_set_timeout(c, 240);
    tcase_add_test(c, format_follows_the_extension_unless_given);
    tcase_add_test(c, unknown_extension_is_a_usage_error_listing_the_formats);
    tcase_add_test(c, png_holds_the_pixels_of_the_ppm);
    tcase_add_test(c, bad_output_fails_before_rendering);
    tcase_add_test(c, converted_scenes_render_as_the_originals);
    suite_add_tcase(s, c);
    c = tcase_create("signals");
    tcase_set_timeout(c, 240);
    tcase_add_loop_test(c, signal_during_the_save_keeps_the_previous_file, 0,
                        3);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(export_output_suite)
