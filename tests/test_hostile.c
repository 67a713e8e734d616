/*
 * test_hostile.c - bad input and faults (issue 8).
 *
 * A scene file or an image is untrusted: these tests feed the loaders what
 * the fuzzer found and what an attacker would try (counts that promise more
 * than the file holds, a megabyte of digits, a line of commas), check that
 * the work and memory stay proportional to the input, and that a refusal
 * says why.  The second half makes writes fail (a failing sink, a full
 * tmpfs, a file-size limit, a missing directory, SIGKILL mid-render) and
 * checks that the file at the destination is the old one or the complete
 * new one, never a partial one, and that no temporary file is left behind.
 *
 * Tests that need a child process fork one themselves, so that they also
 * hold under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif
#ifndef UNDER_ASAN
#define UNDER_ASAN 0
#endif

/* ------------------------------------------------------------------ */
/* Helpers                                                             */

static const char small_scene[] =
    "0 0 10\n"
    "0 0 5 4 0 5 40 30\n"
    "3\n"
    "-3 -3 0\n"
    "3 -3 0\n"
    "0 3 0\n"
    "1\n"
    "1 2 3 0.25 200 100 50\n"
    "10 20 30\n"
    "0 0 4 255 255 255\n";

/* Valgrind puts its preload libraries in LD_PRELOAD of the program it runs. */
static int under_valgrind(void)
{
    const char *preload = getenv("LD_PRELOAD");
    return preload != NULL && strstr(preload, "vgpreload") != NULL;
}

static char *make_temp_dir(void)
{
    const char *base = getenv("TMPDIR");
    char pattern[PATH_MAX];
    snprintf(pattern, sizeof pattern, "%s/rt-hostile-XXXXXX",
             base && *base ? base : "/tmp");
    char *dir = strdup(pattern);
    ck_assert_ptr_nonnull(dir);
    ck_assert_msg(mkdtemp(dir) != NULL, "mkdtemp: %s", strerror(errno));
    return dir;
}

static char *join(const char *dir, const char *name)
{
    size_t length = strlen(dir) + strlen(name) + 2;
    char *path = malloc(length);
    ck_assert_ptr_nonnull(path);
    snprintf(path, length, "%s/%s", dir, name);
    return path;
}

static void write_bytes(const char *path, const void *data, size_t size)
{
    FILE *file = fopen(path, "wb");
    ck_assert_msg(file != NULL, "%s: %s", path, strerror(errno));
    ck_assert_uint_eq(fwrite(data, 1, size, file), size);
    ck_assert_int_eq(fclose(file), 0);
}

/* The names in `dir` other than . and .., sorted, joined by spaces. */
static char *list_dir(const char *dir)
{
    DIR *d = opendir(dir);
    ck_assert_msg(d != NULL, "%s: %s", dir, strerror(errno));
    char *names[64];
    int count = 0;
    struct dirent *entry;
    while ((entry = readdir(d)) != NULL) {
        if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
            continue;
        ck_assert_int_lt(count, 64);
        names[count++] = strdup(entry->d_name);
    }
    closedir(d);
    for (int i = 1; i < count; i++)
        for (int j = i; j > 0 && strcmp(names[j - 1], names[j]) > 0; j--) {
            char *t = names[j];
            names[j] = names[j - 1];
            names[j - 1] = t;
        }
    char *out = calloc(1, 64 * 260);
    ck_assert_ptr_nonnull(out);
    for (int i = 0; i < count; i++) {
        if (i)
            strcat(out, " ");
        strcat(out, names[i]);
        free(names[i]);
    }
    return out;
}

static void assert_dir_holds(const char *dir, const char *expected)
{
    char *names = list_dir(dir);
    ck_assert_msg(strcmp(names, expected) == 0,
                  "%s holds `%s`, expected `%s` (a temporary file left "
                  "behind?)", dir, names, expected);
    free(names);
}

/* Removes the files of a flat directory, then the directory. */
static void remove_dir(char *dir)
{
    DIR *d = opendir(dir);
    if (d != NULL) {
        struct dirent *entry;
        while ((entry = readdir(d)) != NULL) {
            if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
                continue;
            char *path = join(dir, entry->d_name);
            if (unlink(path) != 0)
                rmdir(path);
            free(path);
        }
        closedir(d);
    }
    rmdir(dir);
    free(dir);
}

static rt_image make_image(int width, int height)
{
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, width, height, NULL), RT_OK);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            unsigned char *p = rt_image_pixel(&image, x, y);
            p[0] = (unsigned char)x;
            p[1] = (unsigned char)y;
            p[2] = (unsigned char)(x ^ y);
        }
    return image;
}

/* A PPM file that is recognisably "the previous one". */
static const char previous_ppm[] = "P3\n1 1\n255\n1 2 3\n";

static void assert_previous_intact(const char *path)
{
    size_t size;
    char *data = rt_test_read_file(path, &size);
    ck_assert_msg(data != NULL, "%s: the previous file is gone", path);
    ck_assert_msg(size == sizeof previous_ppm - 1 &&
                      memcmp(data, previous_ppm, size) == 0,
                  "%s: the previous file was changed (now %zu bytes)", path,
                  size);
    free(data);
}

/*
 * Runs `child(arg, message, size)` in a forked process and returns its exit
 * status (0: success; otherwise `message` says what went wrong).  What the
 * child reports travels through a pipe, so no Check call happens there.
 */
typedef int (*child_fn)(void *arg, char *message, size_t size);

static int run_in_child(child_fn child, void *arg, char *message,
                        size_t size)
{
    int fds[2];
    ck_assert_int_eq(pipe(fds), 0);
    fflush(NULL);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        close(fds[0]);
        char text[1024] = "";
        int code = child(arg, text, sizeof text);
        if (write(fds[1], text, strlen(text)) < 0)
            code = 99;
        close(fds[1]);
        _exit(code);
    }
    close(fds[1]);
    size_t used = 0;
    ssize_t n;
    while (used + 1 < size &&
           (n = read(fds[0], message + used, size - used - 1)) > 0)
        used += (size_t)n;
    message[used] = '\0';
    close(fds[0]);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    if (WIFSIGNALED(status)) {
        snprintf(message, size, "child killed by signal %d",
                 WTERMSIG(status));
        return 128 + WTERMSIG(status);
    }
    return WEXITSTATUS(status);
}

/* Parses `text` and checks the contract of a refusal; returns the status. */
static rt_status parse_refused(const char *text, size_t length,
                               rt_error *error)
{
    rt_scene *scene = (rt_scene *)1;
    memset(error, 0, sizeof *error);
    rt_status status = rt_scene_parse(text, length, "hostile.scn", &scene,
                                      error);
    ck_assert_msg(status != RT_OK, "a hostile scene loaded");
    ck_assert_ptr_null(scene);
    ck_assert_int_eq(error->status, status);
    ck_assert_msg(error->message[0] != '\0', "a refusal without a message");
    return status;
}

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* ------------------------------------------------------------------ */
/* Findings of the fuzzer and of reading the loaders, kept as tests     */

/* Every file of a corpus directory: a refusal has a status and a message;
 * an accepted scene answers the accessors and traces its corner pixels. */
START_TEST(scene_corpus_replays_without_fault)
{
    const char *dir_path = rt_test_source_path("tests/fuzz/corpus/scene");
    char *dir = strdup(dir_path);
    DIR *d = opendir(dir);
    ck_assert_msg(d != NULL, "%s: %s", dir, strerror(errno));
    int files = 0, loaded = 0;
    struct dirent *entry;
    while ((entry = readdir(d)) != NULL) {
        if (entry->d_name[0] == '.')
            continue;
        char *path = join(dir, entry->d_name);
        size_t size;
        char *data = rt_test_read_file(path, &size);
        ck_assert_ptr_nonnull(data);
        rt_scene *scene = (rt_scene *)1;
        rt_error error;
        memset(&error, 0, sizeof error);
        rt_status status = rt_scene_parse(data, size, entry->d_name, &scene,
                                          &error);
        int valid = strncmp(entry->d_name, "valid-", 6) == 0;
        int broken = strncmp(entry->d_name, "broken-", 7) == 0;
        ck_assert_msg(!valid || status == RT_OK, "%s: %s", entry->d_name,
                      error.message);
        ck_assert_msg(!broken || status != RT_OK, "%s loaded",
                      entry->d_name);
        if (status == RT_OK) {
            rt_scene_info info;
            rt_scene_get_info(scene, &info);
            rt_ray ray = rt_camera_ray(&info.camera, info.width - 1,
                                       info.height - 1);
            (void)rt_trace(scene, ray, 5);
            rt_scene_destroy(scene);
            loaded++;
        } else {
            ck_assert_ptr_null(scene);
            ck_assert_msg(error.message[0] != '\0', "%s: no message",
                          entry->d_name);
        }
        free(data);
        free(path);
        files++;
    }
    closedir(d);
    free(dir);
    ck_assert_int_ge(files, 10);
    ck_assert_int_ge(loaded, 3);
}
END_TEST

/* A count far beyond the lines of the file is refused with a message that
 * says how many lines there are, before anything is allocated for it. */
START_TEST(count_beyond_the_file_is_refused_with_the_lines_left)
{
    static const char text[] =
        "0 0 10\n0 0 5 4 0 5 8 8\n2147483647\n0 0 0\n1 0 0\n";
    rt_error error;
    ck_assert_int_eq(parse_refused(text, sizeof text - 1, &error),
                     RT_ERR_LIMIT);
    ck_assert_int_eq(error.line, 3);
    ck_assert_int_eq(error.column, 1);
    ck_assert_str_eq(error.message,
                     "hostile.scn:3:1: expected a vertex count of at most 2 "
                     "(the lines left in the file), found `2147483647`");
}
END_TEST

START_TEST(count_beyond_int_is_refused_as_out_of_range)
{
    static const char text[] =
        "0 0 10\n0 0 5 4 0 5 8 8\n0\n99999999999999999999\n";
    rt_error error;
    ck_assert_int_eq(parse_refused(text, sizeof text - 1, &error),
                     RT_ERR_RANGE);
    ck_assert_int_eq(error.line, 4);
    ck_assert_ptr_nonnull(strstr(error.message, "a facet count"));
}
END_TEST

START_TEST(image_side_beyond_the_limit_is_refused)
{
    static const char text[] = "0 0 10\n0 0 5 4 0 5 16385 1\n";
    rt_error error;
    ck_assert_int_eq(parse_refused(text, sizeof text - 1, &error),
                     RT_ERR_RANGE);
    ck_assert_str_eq(error.message,
                     "hostile.scn:2:13: expected an image width (a whole "
                     "number in 1..16384), found `16385`");
}
END_TEST

/* The input is read by length: no NUL after it, none needed, and a NUL
 * inside is a bad byte like any other. */
START_TEST(scene_without_terminating_nul_is_read_by_length)
{
    size_t length = strlen(small_scene);
    char *exact = malloc(length);
    ck_assert_ptr_nonnull(exact);
    memcpy(exact, small_scene, length);
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_parse(exact, length, NULL, &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
    /* every prefix is refused, with a message, until the last record
     * "0 0 4 255 255 255" has its sixth value; then every prefix loads */
    size_t complete = (size_t)(strstr(small_scene, "0 0 4 255 255 255") -
                               small_scene) + strlen("0 0 4 255 255 ");
    for (size_t n = 0; n < length; n++) {
        rt_status status = rt_scene_parse(exact, n, NULL, &scene, &error);
        if (n > complete) {
            ck_assert_msg(status == RT_OK, "prefix %zu: %s", n,
                          error.message);
            rt_scene_destroy(scene);
            continue;
        }
        ck_assert_msg(status != RT_OK, "a prefix of %zu bytes loaded", n);
        ck_assert_ptr_null(scene);
        ck_assert_msg(error.message[0] != '\0', "prefix %zu: no message", n);
    }
    free(exact);
    /* a NUL byte: no scene file holds one; the message says the file is
     * binary, at the byte's position */
    static const char nul_inside[] = "0 0 1\0" "0\n";
    ck_assert_int_eq(parse_refused(nul_inside, sizeof nul_inside - 1, &error),
                     RT_ERR_FORMAT);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:6: expected text, found a NUL byte: the "
                     "file is binary, not a scene");
}
END_TEST

/* A number token longer than any number needs is refused by its length,
 * without copying it. */
START_TEST(megabyte_number_is_refused_as_too_long)
{
    size_t length = 1 << 20;
    char *text = malloc(length);
    ck_assert_ptr_nonnull(text);
    memset(text, '7', length);
    memcpy(text, "0 0 ", 4);
    rt_error error;
    ck_assert_int_eq(parse_refused(text, length, &error), RT_ERR_LIMIT);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:5: expected a number of at most 256 "
                     "characters, found `7777777777777777777777777777777777777777"
                     "...`");
    free(text);
}
END_TEST

START_TEST(line_of_commas_is_refused_at_the_first_stray_comma)
{
    size_t length = 1000000;
    char *text = malloc(length);
    ck_assert_ptr_nonnull(text);
    memset(text, ',', length);
    rt_error error;
    ck_assert_int_eq(parse_refused(text, length, &error), RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:1: expected a number, found `,`");
    /* values then a million commas: the eleventh value (one more than the
     * longest record holds) is the error, found before the commas are
     * read */
    memcpy(text, "1,2,3,4,5,6,7,8,9,10,11", 23);
    ck_assert_int_eq(parse_refused(text, length, &error), RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:22: expected the end of the line, found "
                     "`11`");
    /* a complete observer, then a million commas on the next line */
    memset(text, ',', length);
    memcpy(text, "0,0,0\n1,", 8);
    ck_assert_int_eq(parse_refused(text, length, &error), RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "hostile.scn:2:3: expected a number, found `,`");
    free(text);
}
END_TEST

/*
 * A P3 header promising 16384 x 16384 pixels in a 20-byte file must be
 * refused before the 805 MB image is allocated: a P3 file needs at least
 * two bytes per value, so the header can be checked against what is left,
 * as the P6 reader already does.  Found by fuzz_ppm
 * (tests/fuzz/corpus/ppm/p3-huge-header.ppm); checked here under an
 * address-space limit, which does not work under AddressSanitizer or
 * valgrind (both reserve far more address space than they use).
 */
typedef struct bounded_parse {
    const char *data;
    size_t length;
    int is_image;
    size_t limit;           /* bytes of address space the parse may add */
} bounded_parse;

static size_t address_space_in_use(void)
{
    FILE *file = fopen("/proc/self/statm", "r");
    unsigned long pages = 0;
    if (file != NULL) {
        if (fscanf(file, "%lu", &pages) != 1)
            pages = 0;
        fclose(file);
    }
    return (size_t)pages * (size_t)sysconf(_SC_PAGESIZE);
}

static int parse_with_memory_limit(void *arg, char *message, size_t size)
{
    const bounded_parse *b = arg;
    size_t in_use = address_space_in_use();
    if (in_use == 0) {
        snprintf(message, size, "cannot read /proc/self/statm");
        return 2;
    }
    struct rlimit limit = {in_use + b->limit, in_use + b->limit};
    if (setrlimit(RLIMIT_AS, &limit) != 0) {
        snprintf(message, size, "setrlimit: %s", strerror(errno));
        return 2;
    }
    rt_error error;
    rt_status status;
    if (b->is_image) {
        rt_image image;
        status = rt_ppm_parse(b->data, b->length, "hostile.ppm", &image,
                              &error);
        rt_image_release(&image);
    } else {
        rt_scene *scene;
        status = rt_scene_parse(b->data, b->length, "hostile.scn", &scene,
                                &error);
        rt_scene_destroy(scene);
    }
    snprintf(message, size, "%s: %s", rt_status_string(status),
             status == RT_OK ? "loaded" : error.message);
    return status == RT_ERR_NOMEM ? 1 : 0;
}

static int memory_limit_unavailable(void)
{
    if (UNDER_ASAN || under_valgrind()) {
        fprintf(stderr, "test_hostile: address-space limits skipped under "
                        "a sanitizer or valgrind\n");
        return 1;
    }
    return 0;
}

START_TEST(ppm_header_promising_more_pixels_than_the_file_holds_is_refused_before_allocating)
{
    static const char text[] = "P3\n16384 16384\n255\n1";
    rt_image image;
    rt_error error;
    ck_assert_int_eq(rt_ppm_parse(text, sizeof text - 1, "hostile.ppm",
                                  &image, &error),
                     RT_ERR_SYNTAX);
    ck_assert_ptr_null(image.pixels);
    if (memory_limit_unavailable())
        return;
    bounded_parse b = {text, sizeof text - 1, 1, 64u << 20};
    char message[1024];
    int code = run_in_child(parse_with_memory_limit, &b, message,
                            sizeof message);
    ck_assert_msg(code == 0,
                  "a 20-byte P3 file made the reader allocate more than "
                  "64 MB: %s", message);
}
END_TEST

START_TEST(scene_counts_promising_more_than_the_file_holds_are_refused_before_allocating)
{
    static const char *const texts[] = {
        "0 0 10\n0 0 5 4 0 5 8 8\n2147483647\n",
        "0 0 10\n0 0 5 4 0 5 8 8\n0\n2147483647\n1 1 1 0 0 0 0\n",
    };
    if (memory_limit_unavailable())
        return;
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++) {
        bounded_parse b = {texts[i], strlen(texts[i]), 0, 16u << 20};
        char message[1024];
        int code = run_in_child(parse_with_memory_limit, &b, message,
                                sizeof message);
        ck_assert_msg(code == 0, "case %zu ran out of 16 MB: %s", i,
                      message);
        ck_assert_msg(strstr(message, "loaded") == NULL, "case %zu: %s", i,
                      message);
    }
}
END_TEST

/*
 * A refusal names the bad byte in printable form, as the scene loader does
 * (`?` for what cannot be shown): a NUL would cut the message short, and a
 * control byte from a hostile file would reach the user's terminal.
 */
START_TEST(ppm_refusal_shows_bad_bytes_as_printable_text)
{
    static const char *const inputs[] = {"P6\n1\0 1\n255\n",
                                         "P6\n1\x1b[2J 1\n255\n",
                                         "P6\n1 1\n255\xff"};
    static const size_t lengths[] = {12, 15, 11};
    for (int i = 0; i < 3; i++) {
        rt_image image;
        rt_error error;
        rt_status status = rt_ppm_parse(inputs[i], lengths[i], "in.ppm",
                                        &image, &error);
        ck_assert_int_eq(status, RT_ERR_SYNTAX);
        size_t length = strlen(error.message);
        for (size_t k = 0; k < length; k++)
            ck_assert_msg(error.message[k] >= 0x20 && error.message[k] < 0x7f,
                          "input %d: byte %zu of the message is 0x%02x", i,
                          k, (unsigned char)error.message[k]);
        int quotes = 0;
        for (size_t k = 0; k < length; k++)
            quotes += error.message[k] == '`';
        ck_assert_msg(quotes % 2 == 0, "input %d: the message is cut short: "
                      "%s", i, error.message);
    }
}
END_TEST

/* A zero width is refused where it stands, saying what was found. */
START_TEST(ppm_zero_width_is_refused_at_the_width)
{
    static const char text[] = "P6\n0 1\n255\n";
    rt_image image;
    rt_error error;
    ck_assert_int_eq(rt_ppm_parse(text, sizeof text - 1, "in.ppm", &image,
                                  &error),
                     RT_ERR_RANGE);
    ck_assert_msg(error.line == 2 && error.column == 1,
                  "the error is at %d:%d, not at the width (2:1): %s",
                  error.line, error.column, error.message);
    ck_assert_msg(strstr(error.message, "width") &&
                      strstr(error.message, "found 0"),
                  "the message does not say the width was 0: %s",
                  error.message);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Resource bounds: time proportional to the input                      */

/* A hostile input of about `size` bytes, of one of several shapes. */
typedef enum shape {
    SHAPE_DIGITS,           /* one huge number */
    SHAPE_COMMAS,           /* a valid start, then a line of commas */
    SHAPE_BLANK_LINES,      /* a valid start, then blank and comment lines */
    SHAPE_VERTICES,         /* a vertex count and that many vertices, then
                               a truncated file */
    SHAPE_FACETS,           /* a complete scene of many facets */
    SHAPE_DEGENERATE        /* a complete scene of zero-area facets */
} shape;

static const char *const shape_names[] = {
    "digits", "commas", "blank lines", "vertices", "facets",
    "zero-area facets"};

static char *make_input(shape s, size_t size, size_t *length)
{
    char *text = malloc(size + 256);
    ck_assert_ptr_nonnull(text);
    size_t n = 0;
    const char *head = "0 0 10\n0 0 5 4 0 5 8 8\n";
    switch (s) {
    case SHAPE_DIGITS:
        memset(text, '9', size);
        n = size;
        break;
    case SHAPE_COMMAS:
        n = (size_t)sprintf(text, "%s3\n1", head);
        memset(text + n, ',', size - n);
        n = size;
        break;
    case SHAPE_BLANK_LINES:
        n = (size_t)sprintf(text, "%s", head);
        while (n + 8 < size) {
            memcpy(text + n, "  \r\n# \n\n", 8);
            n += 8;
        }
        break;
    case SHAPE_VERTICES:
    case SHAPE_FACETS:
    case SHAPE_DEGENERATE: {
        /* vertices on a parabola, so consecutive triples are not
         * collinear (or all on a line for zero-area facets) */
        int count = (int)(size / 48);
        n = (size_t)sprintf(text, "%s%d\n", head, count);
        for (int i = 0; i < count; i++) {
            double x = (double)(i % 1000) * 0.001;
            double y = s == SHAPE_DEGENERATE ? 0.0 : x * x;
            n += (size_t)sprintf(text + n, "%.3f %.6f %d\n", x, y, -(i % 7));
        }
        if (s == SHAPE_VERTICES)
            break;
        n += (size_t)sprintf(text + n, "%d\n", count - 2);
        for (int i = 1; i + 2 <= count; i++)
            n += (size_t)sprintf(text + n, "%d %d %d 0 1 2 3\n", i, i + 1,
                                 i + 2);
        n += (size_t)sprintf(text + n, "0 0 0\n0 0 4 255 255 255\n");
        break;
    }
    }
    *length = n;
    return text;
}

/* The time of one parse, in seconds. */
/* CPU time of the calling thread: what the parse itself costs, whatever
 * else the machine is running (a parallel ctest, say). */
static double thread_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static double parse_time(const char *text, size_t length, shape s)
{
    rt_scene *scene;
    rt_error error;
    double start = thread_seconds();
    rt_status status = rt_scene_parse(text, length, "big.scn", &scene,
                                      &error);
    double elapsed = thread_seconds() - start;
    int should_load = s == SHAPE_FACETS || s == SHAPE_DEGENERATE;
    ck_assert_msg((status == RT_OK) == should_load, "%s: %s", shape_names[s],
                  error.message);
    rt_scene_destroy(scene);
    return elapsed;
}

/*
 * Parsing 8 times more input (1 MB, then 8 MB) takes about 8 times longer.
 * The bound, 4 x 8 = 32, leaves room for caches (8 MB no longer fits) and
 * for a loaded machine, and still catches a quadratic step (64).  Times
 * are the thread's CPU time, not the wall clock, so other processes do not
 * count.  Runs of
 * both sizes alternate, and the best of each counts, so that a change of
 * load during the test touches both.  A large parse under 20 ms is taken as
 * linear whatever the ratio: too short to tell.
 */
START_TEST(parse_time_grows_linearly_with_the_input)
{
    shape s = (shape)_i;
    size_t small = 1u << 20, large = 8 * small;
    if (under_valgrind())
        small /= 4, large /= 4;
    size_t small_length, large_length;
    char *a = make_input(s, small, &small_length);
    char *b = make_input(s, large, &large_length);
    double ta = HUGE_VAL, tb = HUGE_VAL;
    for (int run = 0; run < 3; run++) {
        ta = fmin(ta, parse_time(a, small_length, s));
        tb = fmin(tb, parse_time(b, large_length, s));
    }
    double ratio = tb / (ta > 1e-6 ? ta : 1e-6);
    double size_ratio = (double)large_length / (double)small_length;
    fprintf(stderr, "test_hostile: %s: %zu bytes %.2f ms, %zu bytes "
                    "%.2f ms (x%.1f for x%.1f)\n",
            shape_names[s], small_length, ta * 1e3, large_length, tb * 1e3,
            ratio, size_ratio);
    ck_assert_msg(ratio < 4 * size_ratio || tb < 0.02,
                  "%s: %.0f times the input took %.0f times as long",
                  shape_names[s], size_ratio, ratio);
    free(a);
    free(b);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Nothing lost: failing writes                                         */

/* A sink that fails on its n-th call and counts calls after a failure. */
typedef struct failing_sink {
    int calls, fail_at, calls_after_failure;
    size_t bytes;
} failing_sink;

static int failing_write(void *context, const void *data, size_t size)
{
    failing_sink *s = context;
    (void)data;
    if (s->calls > s->fail_at)
        s->calls_after_failure++;
    if (s->calls++ == s->fail_at)
        return 0;
    s->bytes += size;
    return 1;
}

START_TEST(failing_sink_stops_the_writer_with_an_io_error)
{
    rt_image image = make_image(37, 11);
    rt_ppm_format formats[2] = {RT_PPM_P3, RT_PPM_P6};
    for (int f = 0; f < 2; f++) {
        failing_sink count = {0, INT_MAX, 0, 0};
        ck_assert_int_eq(rt_ppm_write_to(failing_write, &count, &image,
                                         formats[f], NULL),
                         RT_OK);
        ck_assert_int_gt(count.calls, 2);
        for (int n = 0; n < count.calls; n++) {
            failing_sink s = {0, n, 0, 0};
            ck_assert_int_eq(rt_ppm_write_to(failing_write, &s, &image,
                                             formats[f], NULL),
                             RT_ERR_IO);
            ck_assert_msg(s.calls_after_failure == 0,
                          "P%d: the writer went on after the sink failed "
                          "on call %d", (int)formats[f], n);
        }
    }
    rt_image_release(&image);
}
END_TEST

/*
 * rt_ppm_write_file on a full device: the bytes sit in the FILE's buffer,
 * so success can only be known after a flush.  A writer that answers RT_OK
 * when nothing reached the device lets a caller believe an image was saved.
 */
START_TEST(ppm_write_file_reports_a_full_device)
{
    FILE *full = fopen("/dev/full", "wb");
    if (full == NULL) {
        fprintf(stderr, "test_hostile: no /dev/full; skipped\n");
        return;
    }
    rt_image image = make_image(4, 4);
    rt_status status = rt_ppm_write_file(full, &image, RT_PPM_P6, NULL);
    fclose(full);
    rt_image_release(&image);
    ck_assert_msg(status == RT_ERR_IO,
                  "writing to /dev/full returned %s, expected an "
                  "input/output error", rt_status_string(status));
}
END_TEST

START_TEST(save_into_a_missing_directory_leaves_nothing)
{
    char *dir = make_temp_dir();
    char *path = join(dir, "missing/out.ppm");
    rt_image image = make_image(8, 8);
    rt_error error;
    ck_assert_int_eq(rt_ppm_save(path, &image, RT_PPM_P6, &error), RT_ERR_IO);
    ck_assert_int_eq(error.status, RT_ERR_IO);
    char expected[PATH_MAX + 128];
    snprintf(expected, sizeof expected,
             "%s: cannot write the image: the folder %s/missing/ does not "
             "exist", path, dir);
    ck_assert_str_eq(error.message, expected);
    assert_dir_holds(dir, "");
    /* a path through a regular file, which no user (root included) can
     * write into */
    char *file = join(dir, "plain");
    write_bytes(file, "x", 1);
    char *through = join(dir, "plain/out.ppm");
    ck_assert_int_eq(rt_ppm_save(through, &image, RT_PPM_P6, &error),
                     RT_ERR_IO);
    ck_assert_ptr_nonnull(strstr(error.message, "plain/ is not a folder"));
    assert_dir_holds(dir, "plain");
    /* a read-only directory, when permissions apply to this user */
    ck_assert_int_eq(chmod(dir, 0555), 0);
    char *in_readonly = join(dir, "out.ppm");
    rt_status status = rt_ppm_save(in_readonly, &image, RT_PPM_P6, &error);
    ck_assert_int_eq(chmod(dir, 0755), 0);
    if (geteuid() != 0) {
        ck_assert_int_eq(status, RT_ERR_IO);
        ck_assert_ptr_nonnull(strstr(error.message, "Permission denied"));
        assert_dir_holds(dir, "plain");
    }
    free(in_readonly);
    free(through);
    free(file);
    free(path);
    rt_image_release(&image);
    remove_dir(dir);
}
END_TEST

/* Saving over a directory fails at the rename: the directory stays and the
 * temporary file is removed. */
START_TEST(save_over_a_directory_fails_and_removes_its_temporary_file)
{
    char *dir = make_temp_dir();
    char *target = join(dir, "image.ppm");
    ck_assert_int_eq(mkdir(target, 0755), 0);
    rt_image image = make_image(8, 8);
    rt_error error;
    ck_assert_int_eq(rt_ppm_save(target, &image, RT_PPM_P6, &error),
                     RT_ERR_IO);
    ck_assert_ptr_nonnull(strstr(error.message, "cannot write the image"));
    assert_dir_holds(dir, "image.ppm");
    struct stat st;
    ck_assert_int_eq(stat(target, &st), 0);
    ck_assert(S_ISDIR(st.st_mode));
    rt_image_release(&image);
    free(target);
    remove_dir(dir);
}
END_TEST

/* A destination name of NAME_MAX bytes is a valid file name; the temporary
 * name must fit too. */
START_TEST(save_to_the_longest_file_name_works)
{
    char *dir = make_temp_dir();
    char name[256];
    long name_max = pathconf(dir, _PC_NAME_MAX);
    size_t length = name_max > 0 && name_max < 255 ? (size_t)name_max : 255;
    memset(name, 'n', length);
    memcpy(name + length - 4, ".ppm", 4);
    name[length] = '\0';
    char *path = join(dir, name);
    rt_image image = make_image(3, 2);
    rt_error error;
    rt_status status = rt_ppm_save(path, &image, RT_PPM_P6, &error);
    char *names = list_dir(dir);
    rt_image_release(&image);
    free(path);
    remove_dir(dir);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    ck_assert_str_eq(names, name);
    free(names);
}
END_TEST

/* In a child: saves a 200 x 200 image over the previous file in `dir`,
 * which the caller has made too small to hold it; the save must fail. */
static int save_must_fail(const char *dir, char *message, size_t size)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/out.ppm", dir);
    rt_image image;
    if (rt_image_init(&image, 200, 200, NULL) != RT_OK) {
        snprintf(message, size, "no memory for the image");
        return 2;
    }
    rt_error error;
    rt_status status = rt_ppm_save(path, &image, RT_PPM_P6, &error);
    rt_image_release(&image);
    snprintf(message, size, "%s", status == RT_OK ? "saved" : error.message);
    return status == RT_ERR_IO ? 0 : 1;
}

/* A disk that fills up: a file-size limit makes the write fail (EFBIG)
 * half-way through, as a full disk would (ENOSPC). */
static int save_with_file_size_limit(void *arg, char *message, size_t size)
{
    signal(SIGXFSZ, SIG_IGN);
    struct rlimit limit = {16384, 16384};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) {
        snprintf(message, size, "setrlimit: %s", strerror(errno));
        return 2;
    }
    return save_must_fail(arg, message, size);
}

static void check_failed_save(const char *dir, int code, const char *message,
                              const char *reason)
{
    ck_assert_msg(code == 0, "the save did not fail as it should: %s",
                  message);
    ck_assert_msg(strstr(message, reason) != NULL,
                  "the message does not say `%s`: %s", reason, message);
    char *path = join(dir, "out.ppm");
    assert_previous_intact(path);
    free(path);
    assert_dir_holds(dir, "out.ppm");
}

START_TEST(save_that_exceeds_the_file_size_limit_keeps_the_previous_file)
{
    char *dir = make_temp_dir();
    char *path = join(dir, "out.ppm");
    write_bytes(path, previous_ppm, sizeof previous_ppm - 1);
    char message[1024];
    int code = run_in_child(save_with_file_size_limit, dir, message,
                            sizeof message);
    check_failed_save(dir, code, message, "File too large");
    free(path);
    remove_dir(dir);
}
END_TEST

/* A full disk for real: a 64 KB tmpfs mounted in a private mount namespace
 * of a child (needs root or CAP_SYS_ADMIN; skipped otherwise). */
static int save_on_a_full_tmpfs(void *arg, char *message, size_t size)
{
    const char *dir = arg;
    if (unshare(CLONE_NEWNS) != 0 ||
        /* the type is ignored here, but valgrind checks it is a string */
        mount("none", "/", "none", MS_REC | MS_PRIVATE, NULL) != 0 ||
        mount("rt-hostile", dir, "tmpfs", 0, "size=64k,mode=0755") != 0) {
        snprintf(message, size, "no tmpfs: %s", strerror(errno));
        return 3;
    }
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/out.ppm", dir);
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || write(fd, previous_ppm, sizeof previous_ppm - 1) !=
                      (ssize_t)(sizeof previous_ppm - 1)) {
        snprintf(message, size, "cannot write the previous file");
        return 2;
    }
    close(fd);
    int code = save_must_fail(dir, message, size);
    if (code != 0)
        return code;
    /* check the tmpfs from inside: the caller cannot see it */
    char text[600];
    snprintf(text, sizeof text, "%s", message);
    FILE *file = fopen(path, "rb");
    char data[64] = "";
    size_t n = file ? fread(data, 1, sizeof data, file) : 0;
    if (file)
        fclose(file);
    if (n != sizeof previous_ppm - 1 || memcmp(data, previous_ppm, n) != 0) {
        snprintf(message, size, "the previous file was changed: %s", text);
        return 1;
    }
    DIR *d = opendir(dir);
    struct dirent *entry;
    int others = 0;
    while (d && (entry = readdir(d)) != NULL)
        others += entry->d_name[0] != '.' && strcmp(entry->d_name, "out.ppm");
    if (d)
        closedir(d);
    if (others) {
        snprintf(message, size, "a temporary file was left: %s", text);
        return 1;
    }
    snprintf(message, size, "%s", text);
    return 0;
}

START_TEST(save_on_a_full_disk_keeps_the_previous_file)
{
    char *dir = make_temp_dir();
    char message[1024];
    int code = run_in_child(save_on_a_full_tmpfs, dir, message,
                            sizeof message);
    remove_dir(dir);
    if (code == 3) {
        fprintf(stderr, "test_hostile: full-disk test skipped (%s); the "
                        "file-size limit test covers it\n", message);
    } else {
        ck_assert_msg(code == 0, "%s", message);
        ck_assert_msg(strstr(message, "No space left on device") != NULL,
                      "the message does not say the disk is full: %s",
                      message);
    }
}
END_TEST

/* ------------------------------------------------------------------ */
/* rt-export: exit codes, refusals, interruptions                        */

/*
 * Runs rt-export with `args` (NULL-terminated) in `dir`, stdout and stderr
 * to files there (removed afterwards, their text in *out and *err).  A
 * non-negative `kill_after` sends SIGKILL once the process has used that
 * much CPU time.  Returns the exit status, or 128 + signal.
 */
static int run_program(const char *program, const char *dir,
                       const char *const *args, double kill_after,
                       rlim_t file_size_limit, char **out, char **err)
{
    char *out_path = join(dir, "..stdout"), *err_path = join(dir, "..stderr");
    fflush(NULL);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        if (chdir(dir) != 0)
            _exit(126);
        int o = open(out_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int e = open(err_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0)
            _exit(126);
        if (file_size_limit != RLIM_INFINITY) {
            signal(SIGXFSZ, SIG_IGN);
            struct rlimit limit = {file_size_limit, file_size_limit};
            if (setrlimit(RLIMIT_FSIZE, &limit) != 0)
                _exit(126);
        }
        char *argv[16];
        int argc = 0;
        argv[argc++] = (char *)program;
        for (int i = 0; args[i] && argc < 15; i++)
            argv[argc++] = (char *)args[i];
        argv[argc] = NULL;
        execv(program, argv);
        _exit(127);
    }
    int status;
    if (kill_after >= 0) {
        char stat_path[64];
        snprintf(stat_path, sizeof stat_path, "/proc/%d/stat", (int)pid);
        long ticks = sysconf(_SC_CLK_TCK);
        double start = now_seconds();
        for (;;) {
            if (waitpid(pid, &status, WNOHANG) == pid)
                goto finished;
            FILE *file = fopen(stat_path, "r");
            unsigned long user = 0, system = 0;
            if (file != NULL) {
                /* fields 14 and 15; the name (2) is in parentheses */
                char line[1024];
                if (fgets(line, sizeof line, file)) {
                    char *p = strrchr(line, ')');
                    if (p == NULL ||
                        sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u "
                                      "%*u %*u %lu %lu", &user, &system) != 2)
                        user = system = 0;
                }
                fclose(file);
            }
            double cpu = (double)(user + system) / (double)ticks;
            if (cpu >= kill_after || now_seconds() - start > 30)
                break;
            struct timespec pause = {0, 5000000};
            nanosleep(&pause, NULL);
        }
        kill(pid, SIGKILL);
    }
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
finished:
    *out = rt_test_read_file(out_path, NULL);
    *err = rt_test_read_file(err_path, NULL);
    ck_assert_ptr_nonnull(*out);
    ck_assert_ptr_nonnull(*err);
    unlink(out_path);
    unlink(err_path);
    free(out_path);
    free(err_path);
    return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
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
    char *dir = make_temp_dir();
    char *scene = join(dir, "scene.scn");
    write_bytes(scene, small_scene, strlen(small_scene));
    char *out, *err;
    /* the same file by its name, another spelling, and a symbolic link */
    const char *outputs[] = {"scene.scn", "./scene.scn", "link.scn"};
    char *link_path = join(dir, "link.scn");
    ck_assert_int_eq(symlink("scene.scn", link_path), 0);
    for (int i = 0; i < 3; i++) {
        const char *args[] = {"scene.scn", "-o", outputs[i], "--format",
                              "p6", "-q", NULL};
        int code = run_export(dir, args, -1, RLIM_INFINITY, &out, &err);
        ck_assert_int_eq(code, 1);
        char expected[256];
        snprintf(expected, sizeof expected,
                 "rt-export: %s: refusing to write the image over the scene "
                 "it was rendered from\n", outputs[i]);
        ck_assert_str_eq(err, expected);
        ck_assert_str_eq(out, "");
        free(out);
        free(err);
        size_t size;
        char *data = rt_test_read_file(scene, &size);
        ck_assert_str_eq(data, small_scene);
        free(data);
        assert_dir_holds(dir, "link.scn scene.scn");
    }
    free(link_path);
    free(scene);
    remove_dir(dir);
}
END_TEST

START_TEST(export_exit_codes_say_what_went_wrong)
{
    char *dir = make_temp_dir();
    char *scene = join(dir, "scene.scn");
    write_bytes(scene, small_scene, strlen(small_scene));
    char *bad = join(dir, "bad.scn");
    write_bytes(bad, "0 0 10\n0 0 5 4 0 5 8 8\n3\n", 25);
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
         "'-1'\n"
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
    assert_dir_holds(dir, "bad.scn scene.scn");
    free(bad);
    free(scene);
    remove_dir(dir);
}
END_TEST

START_TEST(export_that_cannot_write_keeps_the_previous_image)
{
    char *dir = make_temp_dir();
    char *scene = join(dir, "scene.scn");
    write_bytes(scene, small_scene, strlen(small_scene));
    char *image = join(dir, "out.ppm");
    write_bytes(image, previous_ppm, sizeof previous_ppm - 1);
    char *out, *err;
    /* the 40 x 30 P3 image is about 10 KB: a 2 KB limit stops it */
    const char *args[] = {"scene.scn", "-o", "out.ppm", "--format", "p3",
                          NULL};
    int code = run_export(dir, args, -1, 2048, &out, &err);
    ck_assert_int_eq(code, 1);
    ck_assert_str_eq(err, "rt-export: out.ppm: cannot write the image: File "
                          "too large\n");
    ck_assert_str_eq(out, "");
    free(out);
    free(err);
    assert_previous_intact(image);
    assert_dir_holds(dir, "out.ppm scene.scn");
    free(image);
    free(scene);
    remove_dir(dir);
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
    char *dir = make_temp_dir();
    char *scene = join(dir, "slow.scn");
    char *text = slow_scene();
    write_bytes(scene, text, strlen(text));
    free(text);
    char *image = join(dir, "out.ppm");
    write_bytes(image, previous_ppm, sizeof previous_ppm - 1);
    char *out, *err;
    const char *args[] = {"slow.scn", "-o", "out.ppm", "-q", NULL};
    int code = run_export(dir, args, 0.3, RLIM_INFINITY, &out, &err);
    ck_assert_msg(code == 128 + SIGKILL,
                  "rt-export finished (exit %d) before it was killed: the "
                  "scene is not slow enough; stderr: %s", code, err);
    free(out);
    free(err);
    assert_previous_intact(image);
    assert_dir_holds(dir, "out.ppm slow.scn");
    free(image);
    free(scene);
    remove_dir(dir);
}
END_TEST

/*
 * rt-bench's files (two CSV files and an SVG plot) follow the same rule as
 * images: a run that cannot write them leaves the previous ones whole.
 */
START_TEST(bench_that_cannot_write_keeps_the_previous_files)
{
#ifndef RT_BENCH_PATH
    fprintf(stderr, "test_hostile: rt-bench is not built; skipped\n");
#else
    char *dir = make_temp_dir();
    char *scene = join(dir, "scene.scn");
    write_bytes(scene, small_scene, strlen(small_scene));
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
        char *path = join(dir, files[i]);
        before[i] = rt_test_read_file(path, &sizes[i]);
        ck_assert_msg(before[i] != NULL, "rt-bench wrote no %s", files[i]);
        free(path);
    }
    char *listing = list_dir(dir);
    /* every file is larger than 100 bytes: a 100-byte limit fails each
     * write; then one that lets the small depth CSV through */
    rlim_t limits[2] = {100, 1024};
    for (int l = 0; l < 2; l++) {
        code = run_program(RT_BENCH_PATH, dir, args, -1, limits[l], &out,
                           &err);
        ck_assert_msg(code == 1, "rt-bench exit %d with a %d-byte file "
                      "limit, expected 1", code, (int)limits[l]);
        for (int i = 0; i < 3; i++) {
            char *path = join(dir, files[i]);
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
        char *names = list_dir(dir);
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
    remove_dir(dir);
#endif
}
END_TEST

static Suite *hostile_suite(void)
{
    Suite *s = suite_create("hostile");
    TCase *tc = tcase_create("fuzz findings and limits");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, scene_corpus_replays_without_fault);
    tcase_add_test(tc, count_beyond_the_file_is_refused_with_the_lines_left);
    tcase_add_test(tc, count_beyond_int_is_refused_as_out_of_range);
    tcase_add_test(tc, image_side_beyond_the_limit_is_refused);
    tcase_add_test(tc, scene_without_terminating_nul_is_read_by_length);
    tcase_add_test(tc, megabyte_number_is_refused_as_too_long);
    tcase_add_test(tc, line_of_commas_is_refused_at_the_first_stray_comma);
    tcase_add_test(tc, ppm_header_promising_more_pixels_than_the_file_holds_is_refused_before_allocating);
    tcase_add_test(tc, scene_counts_promising_more_than_the_file_holds_are_refused_before_allocating);
    tcase_add_test(tc, ppm_refusal_shows_bad_bytes_as_printable_text);
    tcase_add_test(tc, ppm_zero_width_is_refused_at_the_width);
    suite_add_tcase(s, tc);

    tc = tcase_create("time proportional to the input");
    tcase_set_timeout(tc, 300);
    tcase_add_loop_test(tc, parse_time_grows_linearly_with_the_input,
                        SHAPE_DIGITS, SHAPE_DEGENERATE + 1);
    suite_add_tcase(s, tc);

    tc = tcase_create("nothing lost");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, failing_sink_stops_the_writer_with_an_io_error);
    tcase_add_test(tc, ppm_write_file_reports_a_full_device);
    tcase_add_test(tc, save_into_a_missing_directory_leaves_nothing);
    tcase_add_test(tc, save_over_a_directory_fails_and_removes_its_temporary_file);
    tcase_add_test(tc, save_to_the_longest_file_name_works);
    tcase_add_test(tc, save_that_exceeds_the_file_size_limit_keeps_the_previous_file);
    tcase_add_test(tc, save_on_a_full_disk_keeps_the_previous_file);
    suite_add_tcase(s, tc);

    tc = tcase_create("rt-export");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, export_refuses_to_write_over_its_own_scene);
    tcase_add_test(tc, export_exit_codes_say_what_went_wrong);
    tcase_add_test(tc, export_that_cannot_write_keeps_the_previous_image);
    tcase_add_test(tc, export_killed_mid_render_keeps_the_previous_image);
    tcase_add_test(tc, bench_that_cannot_write_keeps_the_previous_files);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(hostile_suite)
