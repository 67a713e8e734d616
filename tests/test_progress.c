/*
 * test_progress.c - the progress line (apps/common/cli_report.h).  The
 * fitting in process: at every width the line leaves the last column free,
 * a long name is cut from the left keeping its file name's end, then the
 * last fields go, and no cut splits a UTF-8 character.  Then rt-export as
 * a user sees it: under a pseudo-terminal of 70 columns, with a scene
 * named by a long absolute path, every drawing of the line is at most 69
 * columns and the updates are carriage returns on one line; with
 * --progress into a file, one final line and nothing else.
 */
#define _XOPEN_SOURCE 700       /* posix_openpt, grantpt, ptsname */
#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include "cli_report.h"
#include "testutil.h"

static const char *const fields[] = {" 42%", "2.0 s", "2.8 s left",
                                     "402k camera rays/s"};
#define LONG_NAME                                                            \
    "/home/someone/projects/a-rather-long-folder/renders/scenes/cubes.scn"

static size_t fit(int columns, const char *name, int count, char *out,
                  size_t size)
{
    size_t length = cli_progress_fit(columns, name, fields, count, out, size);
    ck_assert_uint_eq(length, strlen(out));
    return length;
}

/* Whether text is whole UTF-8 characters (no lead byte without its
 * continuation bytes, no continuation byte without its lead). */
static int whole_utf8(const char *text)
{
    const unsigned char *s = (const unsigned char *)text;
    while (*s) {
        int more = *s < 0x80 ? 0 : (*s & 0xE0) == 0xC0 ? 1
                                : (*s & 0xF0) == 0xE0 ? 2
                                : (*s & 0xF8) == 0xF0 ? 3 : -1;
        if (more < 0)
            return 0;
        s++;
        for (int i = 0; i < more; i++, s++)
            if ((*s & 0xC0) != 0x80)
                return 0;
    }
    return 1;
}

START_TEST(a_line_that_fits_is_left_whole)
{
    char line[CLI_PROGRESS_LINE];
    fit(200, "scenes/cubes.scn", 4, line, sizeof line);
    ck_assert_str_eq(line, "rendering scenes/cubes.scn:  42%, 2.0 s, "
                           "2.8 s left, 402k camera rays/s");
}
END_TEST

START_TEST(a_long_name_is_cut_from_the_left_keeping_its_end)
{
    char line[CLI_PROGRESS_LINE];
    size_t length = fit(70, LONG_NAME, 4, line, sizeof line);
    /* the name takes what the fields leave: the line is 69 exactly */
    ck_assert_uint_eq(length, 69);
    ck_assert_msg(strncmp(line, "rendering ...", 13) == 0, "%s", line);
    const char *colon = strstr(line, ": ");
    ck_assert_ptr_nonnull(colon);
    size_t tail = (size_t)(colon - (line + 13));
    ck_assert_uint_gt(tail, strlen("cubes.scn"));
    /* what is left of the name is the end of the name */
    ck_assert_mem_eq(line + 13, LONG_NAME + strlen(LONG_NAME) - tail, tail);
    for (int i = 0; i < 4; i++)
        ck_assert_ptr_nonnull(strstr(line, fields[i]));
}
END_TEST

START_TEST(the_last_fields_go_once_the_name_is_down_to_its_file_name)
{
    char line[CLI_PROGRESS_LINE];
    /* "rendering ...cubes.scn:  42%, 2.0 s, 2.8 s left" is 47 bytes: at
     * 50 columns the rate goes, and the name has 2 more bytes */
    fit(50, LONG_NAME, 4, line, sizeof line);
    ck_assert_str_eq(line,
                     "rendering ...s/cubes.scn:  42%, 2.0 s, 2.8 s left");
    /* "rendering ...cubes.scn:  42%" is 28 */
    fit(29, LONG_NAME, 4, line, sizeof line);
    ck_assert_str_eq(line, "rendering ...cubes.scn:  42%");
    /* narrower still: the file name is cut from the left too */
    fit(26, LONG_NAME, 4, line, sizeof line);
    ck_assert_str_eq(line, "rendering ...es.scn:  42%");
}
END_TEST

START_TEST(at_every_width_the_last_column_stays_free)
{
    char line[CLI_PROGRESS_LINE];
    for (int columns = 1; columns <= 300; columns++) {
        size_t length = fit(columns, LONG_NAME, 4, line, sizeof line);
        ck_assert_msg(length <= (size_t)columns - 1, "%d columns: %s",
                      columns, line);
        /* wide enough for "rendering ...cubes.scn:  42%": the file name
         * and the percentage are there */
        if (columns > 29) {
            ck_assert_msg(strstr(line, "cubes.scn:  42%") != NULL,
                          "%d columns: %s", columns, line);
        }
    }
}
END_TEST

START_TEST(no_width_means_80_columns)
{
    char at0[CLI_PROGRESS_LINE], at80[CLI_PROGRESS_LINE],
        below[CLI_PROGRESS_LINE];
    fit(0, LONG_NAME LONG_NAME, 4, at0, sizeof at0);
    fit(80, LONG_NAME LONG_NAME, 4, at80, sizeof at80);
    fit(-3, LONG_NAME LONG_NAME, 4, below, sizeof below);
    ck_assert_str_eq(at0, at80);
    ck_assert_str_eq(below, at80);
    ck_assert_uint_eq(strlen(at80), 79);
}
END_TEST

START_TEST(a_cut_never_splits_a_utf8_character)
{
    /* 2-, 3- and 4-byte characters in the folders and the file name */
    const char *name = "/données/プロジェクト/\xF0\x9F\x8E\xA8/été-仕上げ.scn";
    char line[CLI_PROGRESS_LINE];
    for (int columns = 1; columns <= 120; columns++) {
        size_t length = fit(columns, name, 4, line, sizeof line);
        ck_assert_uint_le(length, (size_t)columns - 1);
        ck_assert_msg(whole_utf8(line), "%d columns: %s", columns, line);
    }
}
END_TEST

START_TEST(a_small_buffer_is_filled_and_terminated)
{
    char line[12];
    size_t length = fit(200, LONG_NAME, 4, line, sizeof line);
    ck_assert_uint_eq(length, sizeof line - 1);
    ck_assert_str_eq(line, "rendering /");
}
END_TEST

/* ------------------------------------------------------------------ */
/* rt-export as a user sees it                                         */

/* A folder under `dir` deep enough that the scene's absolute path makes
 * the whole line wider than 70 columns; the teapot copied there.  Returns
 * the scene's path (malloc'd). */
static char *deep_scene(const char *dir)
{
    char *deep = rt_test_join(dir, "a-folder-with-a-rather-long-name");
    ck_assert_int_eq(mkdir(deep, 0700), 0);
    char *deeper = rt_test_join(deep, "and-another-one-below-it");
    ck_assert_int_eq(mkdir(deeper, 0700), 0);
    char *scene = rt_test_join(deeper, "teapot.scn");
    size_t size;
    char *text = rt_test_read_file(rt_test_source_path("scenes/teapot.scn"),
                                   &size);
    ck_assert_ptr_nonnull(text);
    rt_test_write_bytes(scene, text, size);
    free(text);
    free(deep);
    free(deeper);
    ck_assert_uint_gt(strlen(scene), 70);
    return scene;
}

/* Runs rt-export with `args` (NULL-terminated) with standard error on a
 * new pseudo-terminal of `columns` columns, without the newline
 * translation (a "\n" the program writes arrives as "\n"); standard output
 * to /dev/null.  Returns what the terminal received (malloc'd) and the
 * exit status through *code. */
static char *run_on_terminal(const char *dir, int columns,
                             const char *const *args, int *code)
{
    int master = posix_openpt(O_RDWR | O_NOCTTY);
    ck_assert_int_ge(master, 0);
    ck_assert_int_eq(grantpt(master), 0);
    ck_assert_int_eq(unlockpt(master), 0);
    int slave = open(ptsname(master), O_RDWR | O_NOCTTY);
    ck_assert_int_ge(slave, 0);
    struct winsize size = {.ws_row = 24, .ws_col = (unsigned short)columns};
    ck_assert_int_eq(ioctl(slave, TIOCSWINSZ, &size), 0);
    struct termios modes;
    ck_assert_int_eq(tcgetattr(slave, &modes), 0);
    modes.c_oflag &= ~(tcflag_t)OPOST;
    ck_assert_int_eq(tcsetattr(slave, TCSANOW, &modes), 0);

    const char *argv[32] = {RT_EXPORT_PATH};
    int n = 1;
    for (; args[n - 1] != NULL && n < 31; n++)
        argv[n] = args[n - 1];
    argv[n] = NULL;
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int null = open("/dev/null", O_RDWR);
        if (null < 0 || chdir(dir) != 0 || dup2(null, STDIN_FILENO) < 0 ||
            dup2(null, STDOUT_FILENO) < 0 || dup2(slave, STDERR_FILENO) < 0)
            _exit(126);
        close(master);
        execv(RT_EXPORT_PATH, (char *const *)argv);
        _exit(127);
    }
    close(slave);
    size_t length = 0, capacity = 1 << 16;
    char *text = malloc(capacity);
    ck_assert_ptr_nonnull(text);
    for (;;) {
        if (length + 4096 + 1 > capacity) {
            capacity *= 2;
            text = realloc(text, capacity);
            ck_assert_ptr_nonnull(text);
        }
        ssize_t got = read(master, text + length, 4096);
        if (got > 0)
            length += (size_t)got;
        else if (got < 0 && errno == EINTR)
            continue;
        else
            break;              /* EIO: the last writer closed the terminal */
    }
    text[length] = '\0';
    close(master);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    *code = rt_test_exit_code(status);
    return text;
}

START_TEST(on_a_70_column_terminal_the_line_stays_in_70_columns)
{
    char *dir = rt_test_temp_dir();
    char *scene = deep_scene(dir);
    /* a render of a few seconds on one thread, long past the half second
     * after which the line is drawn (AddressSanitizer's programs run some
     * 30 times slower: there a sixteenth of it does) */
    const char *args[] = {scene, "-o", "out.ppm", "--size",
                          RT_TEST_UNDER_ASAN ? "200x200" : "800x800",
                          "--samples", "16", "-j", "1", NULL};
    int code;
    char *text = run_on_terminal(dir, 70, args, &code);
    ck_assert_int_eq(code, 0);
    int lines_with_progress = 0, drawings = 0;
    char *line_end;
    for (char *line = text; *line != '\0'; line = line_end + 1) {
        line_end = strchr(line, '\n');
        ck_assert_msg(line_end != NULL, "a line without its newline: %s",
                      line);
        *line_end = '\0';
        if (strstr(line, "rendering ") != NULL)
            lines_with_progress++;
        /* each drawing: "\r", the line, ESC [ K; what a terminal shows */
        for (char *drawing = strtok(line, "\r"); drawing != NULL;
             drawing = strtok(NULL, "\r")) {
            char *erase = strstr(drawing, "\033[K");
            if (strncmp(drawing, "rendering ", 10) == 0) {
                drawings++;
                ck_assert_msg(erase != NULL && erase[3] == '\0', "%s",
                              drawing);
                *erase = '\0';
                ck_assert_msg(strstr(drawing, "...") != NULL &&
                                  strstr(drawing, "teapot.scn: ") != NULL,
                              "%s", drawing);
            }
            ck_assert_msg(strlen(drawing) <= 69, "%zu columns: %s",
                          strlen(drawing), drawing);
        }
    }
    /* the updates and the final state all on one line, redrawn in place */
    ck_assert_int_eq(lines_with_progress, 1);
    ck_assert_int_ge(drawings, 2);
    free(text);
    free(scene);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(off_a_terminal_progress_is_one_final_line)
{
    char *dir = rt_test_temp_dir();
    char *scene = deep_scene(dir);
    const char *args[] = {scene, "-o", "out.ppm", "--size", "200x200",
                          "--progress", NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_int_eq(r.code, 0);
    /* one line, whole (the name not cut), at 100%, and nothing else */
    ck_assert_msg(strncmp(r.err, "rendering ", 10) == 0, "%s", r.err);
    ck_assert_ptr_eq(strchr(r.err, '\n'), r.err + strlen(r.err) - 1);
    ck_assert_ptr_null(strchr(r.err, '\r'));
    ck_assert_ptr_null(strchr(r.err, '\033'));
    ck_assert_ptr_nonnull(strstr(r.err, scene));
    ck_assert_ptr_nonnull(strstr(r.err, ": 100%, "));
    rt_test_output_free(&r);

    /* without --progress: nothing */
    args[5] = NULL;
    r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_int_eq(r.code, 0);
    ck_assert_str_eq(r.err, "");
    rt_test_output_free(&r);
    free(scene);
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *progress_suite(void)
{
    Suite *s = suite_create("progress");
    TCase *c = tcase_create("fit");
    tcase_add_test(c, a_line_that_fits_is_left_whole);
    tcase_add_test(c, a_long_name_is_cut_from_the_left_keeping_its_end);
    tcase_add_test(c,
                   the_last_fields_go_once_the_name_is_down_to_its_file_name);
    tcase_add_test(c, at_every_width_the_last_column_stays_free);
    tcase_add_test(c, no_width_means_80_columns);
    tcase_add_test(c, a_cut_never_splits_a_utf8_character);
    tcase_add_test(c, a_small_buffer_is_filled_and_terminated);
    suite_add_tcase(s, c);
    TCase *runs = tcase_create("rt-export");
    tcase_set_timeout(runs, 120);
    tcase_add_test(runs, on_a_70_column_terminal_the_line_stays_in_70_columns);
    tcase_add_test(runs, off_a_terminal_progress_is_one_final_line);
    suite_add_tcase(s, runs);
    return s;
}

RT_CHECK_MAIN(progress_suite)
