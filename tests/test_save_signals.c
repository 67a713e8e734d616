/*
 * test_save_signals.c - rt_image_save under SIGTERM, SIGINT and SIGHUP
 * (raytrace/image.h): a saving program killed by one leaves the old file
 * and no temporary; a handled SIGTERM makes the save return
 * RT_ERR_INTERRUPTED; an ignored SIGINT does not stop it.  Each save runs in
 * a forked child (support/child.h), which the test signals once the save's
 * temporary file exists, so the suite also holds under CK_FORK=no
 * (valgrind).  Under RT_TEST_MEMCHECK the child saves a smaller image.
 */
#define _GNU_SOURCE 1

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Signals during a save                                                */

typedef enum disposition { KEEP_DEFAULT, CATCH, IGNORE } disposition;

typedef struct signal_case {
    const char *path;
    int number;
    disposition disposition;
    int side;
} signal_case;

static volatile sig_atomic_t caught;

static void on_signal(int number)
{
    caught = number;
}

/* In a child: default dispositions and an empty mask, then `disposition`
 * for the signal, then a large P3 save; exit code = the save's status. */
static int save_while_signalled(void *arg, char *note, size_t size)
{
    const signal_case *c = arg;
    static const int termination[] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++)
        signal(termination[i], SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    if (c->disposition == CATCH) {
        struct sigaction action;
        memset(&action, 0, sizeof action);
        action.sa_handler = on_signal;
        sigemptyset(&action.sa_mask);
        sigaction(c->number, &action, NULL);
    } else if (c->disposition == IGNORE) {
        signal(c->number, SIG_IGN);
    }
    rt_image image;
    if (rt_test_make_pattern(&image, c->side, c->side) != RT_OK)
        return rt_test_say(90, note, size, "no memory for the image");
    rt_error error = {0};
    rt_status status = rt_image_save(c->path, &image, RT_IMAGE_P3, &error);
    rt_image_release(&image);
    snprintf(note, size, "caught=%d; %s", (int)caught,
             status == RT_OK ? "saved" : error.message);
    return (int)status;
}

static int has_temporary(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    int found = 0;
    while (d != NULL && !found && (entry = readdir(d)) != NULL)
        found = strncmp(entry->d_name, ".rt-save-", 9) == 0;
    if (d != NULL)
        closedir(d);
    return found;
}

/* Waits until a temporary file shows in `dir` while `pid` runs. */
static int temporary_appears(const char *dir, pid_t pid)
{
    double deadline = rt_test_now() + (rt_test_memcheck() ? 600 : 60);
    const struct timespec pause = {0, 100000};
    while (rt_test_now() < deadline) {
        if (has_temporary(dir))
            return 1;
        siginfo_t info;
        memset(&info, 0, sizeof info);
        if (waitid(P_PID, (id_t)pid, &info, WEXITED | WNOHANG | WNOWAIT) ==
                0 && info.si_pid == pid)
            return 0;           /* it ended first */
        nanosleep(&pause, NULL);
    }
    return 0;
}

static int signal_side(void)
{
    if (!rt_test_memcheck())
        return 2000;
    static int told;
    if (!told++)
        fprintf(stderr, "test_save: RT_TEST_MEMCHECK: the signal tests save "
                        "a 300 x 300 image instead of 2000 x 2000\n");
    return 300;
}

typedef struct signal_run {
    char *dir;
    rt_test_path out;
    int wait_status;
    char note[1024];
} signal_run;

/* Starts a child saving over dir/out.ppm (which holds
 * rt_test_previous_ppm), sends it `number` once its temporary file exists,
 * and waits for it. */
static signal_run save_and_signal(int number, disposition d)
{
    signal_run run;
    run.dir = rt_test_temp_dir();
    run.out = rt_test_path_at(run.dir, "out.ppm");
    rt_test_write_bytes(run.out.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    signal_case c = {run.out.s, number, d, signal_side()};
    rt_test_child saver = rt_test_child_start(save_while_signalled, &c);
    ck_assert_int_gt(saver.pid, 0);
    int seen = temporary_appears(run.dir, saver.pid);
    kill(saver.pid, seen ? number : SIGKILL);
    run.wait_status = rt_test_child_finish(&saver, run.note, sizeof run.note);
    ck_assert_msg(seen, "no temporary file appeared while saving (wait "
                  "status %#x): %s", run.wait_status, run.note);
    return run;
}

static void assert_left_as_it_was(signal_run *run)
{
    ck_assert_msg(rt_test_file_holds(run->out.s, rt_test_previous_ppm,
                                     sizeof rt_test_previous_ppm - 1),
                  "the previous file was changed");
    rt_test_assert_dir_holds(run->dir, "out.ppm");
    rt_test_remove_dir(run->dir);
}

static void killed_by(int number)
{
    signal_run run = save_and_signal(number, KEEP_DEFAULT);
    ck_assert_msg(WIFSIGNALED(run.wait_status) &&
                      WTERMSIG(run.wait_status) == number,
                  "the saving program was not killed by signal %d (wait "
                  "status %#x): %s", number, run.wait_status, run.note);
    assert_left_as_it_was(&run);
}

START_TEST(sigterm_kills_the_saving_program_and_leaves_the_old_file)
{
    killed_by(SIGTERM);
}
END_TEST

START_TEST(sigint_kills_the_saving_program_and_leaves_the_old_file)
{
    killed_by(SIGINT);
}
END_TEST

START_TEST(sighup_kills_the_saving_program_and_leaves_the_old_file)
{
    killed_by(SIGHUP);
}
END_TEST

START_TEST(a_handled_sigterm_makes_the_save_return_interrupted)
{
    signal_run run = save_and_signal(SIGTERM, CATCH);
    ck_assert_msg(WIFEXITED(run.wait_status) &&
                      WEXITSTATUS(run.wait_status) == RT_ERR_INTERRUPTED,
                  "the save did not return RT_ERR_INTERRUPTED (wait status "
                  "%#x): %s", run.wait_status, run.note);
    ck_assert_msg(strstr(run.note, "caught=15;") != NULL,
                  "the handler did not run after the save: %s", run.note);
    ck_assert_msg(strstr(run.note, run.out.s) != NULL,
                  "the message does not name the path: %s", run.note);
    assert_left_as_it_was(&run);
}
END_TEST

/* A sink that only counts the bytes (`user`: a size_t). */
static int count_bytes(void *user, const void *data, size_t size)
{
    (void)data;
    *(size_t *)user += size;
    return 1;
}

START_TEST(an_ignored_sigint_does_not_stop_the_save)
{
    signal_run run = save_and_signal(SIGINT, IGNORE);
    ck_assert_msg(WIFEXITED(run.wait_status) &&
                      WEXITSTATUS(run.wait_status) == RT_OK,
                  "the save did not complete (wait status %#x): %s",
                  run.wait_status, run.note);
    rt_image image = rt_test_pattern(signal_side(), signal_side());
    size_t size = 0;
    ck_assert_int_eq(rt_image_write_to(count_bytes, &size, &image,
                                       RT_IMAGE_P3, NULL), RT_OK);
    rt_image_release(&image);
    struct stat st;
    ck_assert_int_eq(stat(run.out.s, &st), 0);
    ck_assert_msg((size_t)st.st_size == size,
                  "out.ppm has %ld bytes, the image %zu", (long)st.st_size,
                  size);
    char header[32];
    int side = signal_side();
    snprintf(header, sizeof header, "P3\n%d %d\n255\n", side, side);
    FILE *file = fopen(run.out.s, "rb");
    ck_assert_ptr_nonnull(file);
    char start[32] = "";
    size_t n = fread(start, 1, strlen(header), file);
    fclose(file);
    ck_assert_msg(n == strlen(header) && !memcmp(start, header, n),
                  "out.ppm does not start with the image's header");
    rt_test_assert_dir_holds(run.dir, "out.ppm");
    rt_test_remove_dir(run.dir);
}
END_TEST

/* ------------------------------------------------------------------ */

static Suite *save_signals_suite(void)
{
    Suite *s = suite_create("save_signals");
    TCase *tc = tcase_create("signals during a save");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, sigterm_kills_the_saving_program_and_leaves_the_old_file);
    tcase_add_test(tc, sigint_kills_the_saving_program_and_leaves_the_old_file);
    tcase_add_test(tc, sighup_kills_the_saving_program_and_leaves_the_old_file);
    tcase_add_test(tc, a_handled_sigterm_makes_the_save_return_interrupted);
    tcase_add_test(tc, an_ignored_sigint_does_not_stop_the_save);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(save_signals_suite)
