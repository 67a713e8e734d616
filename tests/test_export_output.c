/*
 * test_export_output.c - where rt-export's image goes, as a user sees it:
 * standard output (`-o -`, `-o /dev/stdout`), a scene read from standard
 * input (`-`), the format chosen from the extension, PNG whose pixels are
 * the PPM's, a FIFO, an output refused before rendering, and a save
 * interrupted by a signal, and scenes converted by rt-convert.  Each case
 * runs the real programs.
 */
#include <check.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#if RT_TEST_HAVE_PNG
#include <png.h>
#endif

#include "testutil.h"

/* Writes `text` to dir/name; returns the path (rt_test_in_dir's). */
static const char *write_text(const char *dir, const char *name,
                              const char *text)
{
    const char *path = rt_test_in_dir(dir, name);
    rt_test_write_file(path, text);
    return path;
}

/* Runs rt-export in `dir` with `args` (NULL-terminated), standard input
 * from `input` (or /dev/null). */
static rt_test_output export_in(const char *dir, const char *const *args,
                                const char *input)
{
    rt_test_setup setup = {input};
    return rt_test_run_with(dir, RT_EXPORT_PATH, args, &setup);
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
    rt_test_output r = export_in(dir, args, NULL);
    ck_assert_msg(r.code == 0, "rt-export failed: %s", r.err);
    ck_assert_str_eq(r.out, "reference.ppm\n");
    rt_test_output_free(&r);
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
    char *dir = rt_test_temp_dir();
    size_t expected_size;
    char *expected = reference_image(dir, &expected_size);
    const char *args[] = {cubes(), "-o", outputs[_i], "-q", NULL};
    rt_test_output r = export_in(dir, args, NULL);
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_uint_eq(r.out_size, expected_size);
    ck_assert(memcmp(r.out, expected, expected_size) == 0);
    rt_test_assert_dir_holds(dir, "reference.ppm");
    struct stat st;
    ck_assert_int_eq(lstat("/dev/stdout", &st), 0);
    ck_assert(S_ISLNK(st.st_mode));
    rt_test_output_free(&r);
    free(expected);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(scene_from_standard_input_renders_as_the_file_does)
{
    char *dir = rt_test_temp_dir();
    size_t expected_size;
    char *expected = reference_image(dir, &expected_size);
    const char *args[] = {"-", "-o", "piped.ppm", NULL};
    rt_test_output r = export_in(dir, args, cubes());
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_str_eq(r.out, "piped.ppm\n");
    char path[4096];
    snprintf(path, sizeof path, "%s/piped.ppm", dir);
    size_t size;
    char *bytes = rt_test_read_file(path, &size);
    ck_assert_uint_eq(size, expected_size);
    ck_assert(memcmp(bytes, expected, size) == 0);
    free(bytes);
    rt_test_output_free(&r);
    free(expected);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(errors_in_a_scene_from_standard_input_name_stdin)
{
    char *dir = rt_test_temp_dir();
    const char *path = write_text(dir, "bad.scn", "1,2\n");
    const char *args[] = {"-", "-o", "out.ppm", NULL};
    rt_test_output r = export_in(dir, args, path);
    ck_assert_int_eq(r.code, 1);
    ck_assert_msg(strncmp(r.err, "rt-export: <stdin>:1:", 21) == 0,
                  "message: %s", r.err);
    rt_test_output_free(&r);
    /* Without -o there is no name to derive: a usage error. */
    const char *no_output[] = {"-", NULL};
    r = export_in(dir, no_output, cubes());
    ck_assert_int_eq(r.code, 2);
    ck_assert_msg(strstr(r.err, "-o") != NULL, "message: %s", r.err);
    rt_test_output_free(&r);
    rt_test_assert_dir_holds(dir, "bad.scn");
    rt_test_remove_dir(dir);
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
    char *dir = rt_test_temp_dir();
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
        rt_test_output r = export_in(dir, args, NULL);
        ck_assert_msg(r.code == 0, "%s: exit %d: %s", cases[i].output,
                      r.code, r.err);
        char start[9];
        magic(dir, cases[i].output, start);
        ck_assert_msg(strncmp(start, cases[i].start, 3) == 0,
                      "%s starts with %.3s", cases[i].output, start);
        rt_test_output_free(&r);
    }
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(unknown_extension_is_a_usage_error_listing_the_formats)
{
    char *dir = rt_test_temp_dir();
    const char *args[] = {cubes(), "-o", "picture.jpg", NULL};
    rt_test_output r = export_in(dir, args, NULL);
    ck_assert_int_eq(r.code, 2);
    ck_assert_msg(strstr(r.err, ".png") && strstr(r.err, ".ppm") &&
                      strstr(r.err, "p3"),
                  "message: %s", r.err);
    rt_test_assert_dir_holds(dir, "");
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
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
    char *dir = rt_test_temp_dir();
    size_t size;
    free(reference_image(dir, &size));
    const char *args[] = {cubes(), "-o", "cubes.png", "-q", NULL};
    rt_test_output r = export_in(dir, args, NULL);
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
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

/* A scene whose render would take hours: only a refusal before rendering
 * lets these cases finish within the test's timeout. */
static const char endless_scene[] =
    "0,0,-5\n0,0,0, 1,0,0, 16384,16384\n3\n-1,-1,0\n1,-1,0\n0,1,0\n"
    "1\n1,2,3, 0.5, 200,100,50\n0,0,0\n0,0,-5, 255,255,255\n";

START_TEST(bad_output_fails_before_rendering)
{
    char *dir = rt_test_temp_dir();
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
        rt_test_output r = export_in(dir, args, NULL);
        ck_assert_msg(r.code == 1, "%s: exit %d", cases[i].output, r.code);
        ck_assert_msg(strstr(r.err, cases[i].output) &&
                          strstr(r.err, cases[i].reason),
                      "%s: message: %s", cases[i].output, r.err);
        rt_test_output_free(&r);
    }
    rt_test_assert_dir_holds(dir, "endless.scn folder.ppm");
    rt_test_remove_dir(dir);
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
    char *dir = rt_test_temp_dir();
    size_t expected_size;
    char *expected = reference_image(dir, &expected_size);
    char path[4096];
    snprintf(path, sizeof path, "%s/pipe", dir);
    ck_assert_int_eq(mkfifo(path, 0644), 0);
    fifo_reader reader = {path, NULL, 0};
    pthread_t thread;
    ck_assert_int_eq(pthread_create(&thread, NULL, read_fifo, &reader), 0);
    const char *args[] = {cubes(), "-o", "pipe", "-q", NULL};
    rt_test_output r = export_in(dir, args, NULL);
    pthread_join(thread, NULL);
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_ptr_nonnull(reader.bytes);
    ck_assert_uint_eq(reader.size, expected_size);
    ck_assert(memcmp(reader.bytes, expected, expected_size) == 0);
    struct stat st;
    ck_assert_int_eq(lstat(path, &st), 0);
    ck_assert(S_ISFIFO(st.st_mode));
    rt_test_assert_dir_holds(dir, "pipe reference.ppm");
    free(reader.bytes);
    rt_test_output_free(&r);
    free(expected);
    rt_test_remove_dir(dir);
}
END_TEST

/* Non-zero once dir holds a temporary file of the save with bytes in it
 * (the empty one of the check before rendering does not count). */
static int saving(const char *dir)
{
    char *names = rt_test_dir_names(dir);
    ck_assert_ptr_nonnull(names);
    const char *temp = strstr(names, ".rt-save-");
    char path[4096];
    if (temp != NULL)
        snprintf(path, sizeof path, "%s/%.15s", dir, temp);
    free(names);
    struct stat st;
    return temp != NULL && stat(path, &st) == 0 && st.st_size > 0;
}

/* A 3000 x 3000 P3 image takes long enough to write to be caught in the
 * middle of it by a signal. */
static void interrupt_the_save(int signal_number)
{
    char *dir = rt_test_temp_dir();
    write_text(dir, "big.scn",
               "0,0,-5\n0,0,0, 1,0,0, 3000,3000\n3\n-1,-1,0\n1,-1,0\n"
               "0,1,0\n1\n1,2,3, 0.5, 200,100,50\n0,0,0\n"
               "0,0,-5, 255,255,255\n");
    char path[4096];
    snprintf(path, sizeof path, "%s",
             write_text(dir, "out.ppm", rt_test_previous_ppm));

    const char *args[] = {"big.scn", "-o", "out.ppm", "--format", "p3", "-q",
                          NULL};
    rt_test_process export = rt_test_start(dir, RT_EXPORT_PATH, args, NULL);
    int seen = 0;
    for (int i = 0; i < 60000 && !seen; i++) {
        seen = saving(dir);
        if (!seen) {
            ck_assert_msg(rt_test_running(&export),
                          "rt-export ended before its save was seen");
            rt_test_sleep_ms(1);
        }
    }
    ck_assert_msg(seen, "no temporary file appeared within a minute");
    kill(export.pid, signal_number);
    rt_test_output r = rt_test_finish(&export);
    ck_assert_msg(r.code == 128 + signal_number,
                  "exit %d, expected %d (killed by the signal): %s", r.code,
                  128 + signal_number, r.err);
    rt_test_assert_previous_intact(path);
    rt_test_assert_dir_holds(dir, "big.scn out.ppm");
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
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
    char *dir = rt_test_temp_dir();
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        char source[4096];
        snprintf(source, sizeof source, "%s",
                 rt_test_source_path(scenes[i].path));
        const char *convert[] = {source, "converted.scn", "--extended",
                                 NULL};
        rt_test_output r = rt_test_run(dir, RT_CONVERT_PATH, convert);
        ck_assert_msg(r.code == 0, "%s: rt-convert exit %d: %s",
                      scenes[i].path, r.code, r.err);
        rt_test_output_free(&r);
        const char *direct[] = {source, "-o", "direct.ppm", "-q",
                                "--samples", scenes[i].samples, NULL};
        const char *again[] = {"converted.scn", "-o", "again.ppm", "-q",
                               "--samples", scenes[i].samples, NULL};
        r = export_in(dir, direct, NULL);
        ck_assert_msg(r.code == 0, "%s: %s", scenes[i].path, r.err);
        rt_test_output_free(&r);
        r = export_in(dir, again, NULL);
        ck_assert_msg(r.code == 0, "%s converted: %s", scenes[i].path, r.err);
        rt_test_output_free(&r);
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
    rt_test_output r = rt_test_run(dir, RT_CONVERT_PATH, plain);
    ck_assert_int_eq(r.code, 0);
    ck_assert_msg(strstr(r.err, "dropped the lights after the first") &&
                      strstr(r.err, "dropped the facets' transparency"),
                  "warnings: %s", r.err);
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
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
