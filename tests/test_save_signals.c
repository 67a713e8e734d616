/*
 * test_save_signals.c - rt_image_save under SIGTERM, SIGINT and SIGHUP
 * (raytrace/image.h, "Signals are the caller's").  With the option
 * hold_termination_signals, which the programs ask for: the signals are
 * blocked while the temporary file exists; a saving program killed by one
 * leaves the old file and no temporary; a handled SIGTERM makes the save
 * return RT_ERR_INTERRUPTED, as does one already pending; an ignored SIGINT
 * does not stop it.  By default: nothing is blocked, a handled SIGTERM runs
 * its handler during the save, which completes, and the mask, the handlers
 * and a pending signal are as the caller left them.  Each save runs in a
 * forked child (support/child.h), which the test signals once the save's
 * temporary file exists (reading the child's mask from /proc meanwhile), so
 * the suite also holds under CK_FORK=no (valgrind).  Under
 * RT_TEST_MEMCHECK the child saves a smaller image.
 */
#define _GNU_SOURCE 1

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stddef.h>
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
    int hold;               /* hold_termination_signals */
} signal_case;

static volatile sig_atomic_t caught, caught_while_saving, saving;

static void on_signal(int number)
{
    caught = number;
    caught_while_saving = saving;
}

/* Save options holding the termination signals, or the defaults. */
static rt_save_options save_options(int hold)
{
    rt_save_options options;
    rt_save_options_init(&options);
    options.hold_termination_signals = hold;
    return options;
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
    rt_save_options options = save_options(c->hold);
    saving = 1;
    rt_status status = rt_image_save(c->path, &image, RT_IMAGE_P3,
                                     c->hold ? &options : NULL, &error);
    saving = 0;
    rt_image_release(&image);
    snprintf(note, size, "caught=%d; during=%d; %s", (int)caught,
             (int)caught_while_saving,
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

/* Whether signal `number` is in the mask of process `pid` (its SigBlk line
 * in /proc: the mask of its one thread, in hexadecimal); -1 when it cannot
 * be read.  Under valgrind the kernel's mask is valgrind's own (it keeps
 * the program's to itself): the caller does not ask then. */
static int blocked_in(pid_t pid, int number)
{
    char path[64], line[256];
    snprintf(path, sizeof path, "/proc/%ld/status", (long)pid);
    FILE *file = fopen(path, "r");
    int blocked = -1;
    unsigned long long mask;
    while (file != NULL && blocked < 0 && fgets(line, sizeof line, file))
        if (sscanf(line, "SigBlk: %llx", &mask) == 1)
            blocked = (int)((mask >> (number - 1)) & 1);
    if (file != NULL)
        fclose(file);
    return blocked;
}

/* Starts a child saving over dir/out.ppm (which holds
 * rt_test_previous_ppm), with the termination signals held or not (`hold`),
 * checks once its temporary file exists that the child blocks `number`
 * exactly when held (and not ignored), sends it `number`, and waits for
 * it. */
static signal_run save_and_signal(int number, disposition d, int hold)
{
    signal_run run;
    run.dir = rt_test_temp_dir();
    run.out = rt_test_path_at(run.dir, "out.ppm");
    rt_test_write_bytes(run.out.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    signal_case c = {run.out.s, number, d, signal_side(), hold};
    rt_test_child saver = rt_test_child_start(save_while_signalled, &c);
    ck_assert_int_gt(saver.pid, 0);
    int seen = temporary_appears(run.dir, saver.pid);
    int read_mask = !rt_test_memcheck();
    int blocked = seen && read_mask ? blocked_in(saver.pid, number) : -1;
    kill(saver.pid, seen ? number : SIGKILL);
    run.wait_status = rt_test_child_finish(&saver, run.note, sizeof run.note);
    ck_assert_msg(seen, "no temporary file appeared while saving (wait "
                  "status %#x): %s", run.wait_status, run.note);
    /* an ignored signal cannot end the program: the save leaves it be */
    int expected = hold && d != IGNORE;
    static int told;
    if (!read_mask && !told++)
        fprintf(stderr, "test_save_signals: RT_TEST_MEMCHECK: the mask "
                        "under valgrind is valgrind's; not read from "
                        "/proc\n");
    ck_assert_msg(!read_mask || blocked == expected,
                  "signal %d %s during a save that %s "
                  "the termination signals", number,
                  blocked < 0 ? "(no mask read from /proc)"
                  : blocked   ? "was blocked"
                              : "was not blocked",
                  hold ? "holds" : "does not hold");
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
    signal_run run = save_and_signal(number, KEEP_DEFAULT, 1);
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
    signal_run run = save_and_signal(SIGTERM, CATCH, 1);
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

/* Checks that the save of `run` completed: out.ppm is the whole new image
 * and the folder holds nothing else. */
static void assert_saved(signal_run *run)
{
    ck_assert_msg(WIFEXITED(run->wait_status) &&
                      WEXITSTATUS(run->wait_status) == RT_OK,
                  "the save did not complete (wait status %#x): %s",
                  run->wait_status, run->note);
    rt_image image = rt_test_pattern(signal_side(), signal_side());
    size_t size = 0;
    ck_assert_int_eq(rt_image_write_to(count_bytes, &size, &image,
                                       RT_IMAGE_P3, NULL), RT_OK);
    rt_image_release(&image);
    struct stat st;
    ck_assert_int_eq(stat(run->out.s, &st), 0);
    ck_assert_msg((size_t)st.st_size == size,
                  "out.ppm has %ld bytes, the image %zu", (long)st.st_size,
                  size);
    char header[32];
    int side = signal_side();
    snprintf(header, sizeof header, "P3\n%d %d\n255\n", side, side);
    FILE *file = fopen(run->out.s, "rb");
    ck_assert_ptr_nonnull(file);
    char start[32] = "";
    size_t n = fread(start, 1, strlen(header), file);
    fclose(file);
    ck_assert_msg(n == strlen(header) && !memcmp(start, header, n),
                  "out.ppm does not start with the image's header");
    rt_test_assert_dir_holds(run->dir, "out.ppm");
    rt_test_remove_dir(run->dir);
}

START_TEST(an_ignored_sigint_does_not_stop_the_save)
{
    signal_run run = save_and_signal(SIGINT, IGNORE, 1);
    assert_saved(&run);
}
END_TEST

/* The default holds nothing: SIGTERM is not blocked while the temporary
 * file exists (save_and_signal reads the mask), its handler runs before
 * the save returns, and the save goes on to the end. */
START_TEST(a_default_save_lets_a_handled_sigterm_in_at_once_and_completes)
{
    signal_run run = save_and_signal(SIGTERM, CATCH, 0);
    ck_assert_msg(strstr(run.note, "caught=15; during=1;") != NULL,
                  "the handler did not run during the save: %s", run.note);
    assert_saved(&run);
}
END_TEST

/* ------------------------------------------------------------------ */
/* A signal already pending                                             */

/* What a job sees of the process's signals: the mask, SIGTERM's handler
 * and whether SIGTERM is pending. */
typedef struct signal_state {
    sigset_t mask;
    void (*handler)(int);
    int pending;
} signal_state;

static signal_state signal_state_now(void)
{
    signal_state s;
    sigset_t pending;
    struct sigaction action;
    sigprocmask(SIG_BLOCK, NULL, &s.mask);
    sigaction(SIGTERM, NULL, &action);
    s.handler = action.sa_handler;
    sigpending(&pending);
    s.pending = sigismember(&pending, SIGTERM) == 1;
    return s;
}

/* The first signal whose place in the two masks differs, or 0. */
static int mask_difference(const sigset_t *a, const sigset_t *b)
{
    for (int number = 1; number < 32; number++)
        if (sigismember(a, number) != sigismember(b, number))
            return number;
    return 0;
}

/* A save with SIGTERM pending: where, and with which options (1 holding
 * the signals, 0 NULL for the defaults, -1 options whose size ends before
 * hold_termination_signals, as a program built against an older header
 * passes). */
typedef struct pending_case {
    const char *path;
    int hold;
} pending_case;

/*
 * In a child: SIGTERM handled, blocked and pending (raised while blocked,
 * as a signal that came before the save), then a small save as `arg` (a
 * pending_case) says; the exit code is the save's status, or 90 + n when
 * the save changed the signals (the note says how).
 */
static int save_with_sigterm_pending(void *arg, char *note, size_t size)
{
    const pending_case *c = arg;
    int hold = c->hold;
    const char *path = c->path;
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGTERM, &action, NULL);
    sigset_t term;
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    sigprocmask(SIG_SETMASK, &term, NULL);
    raise(SIGTERM);
    rt_image image;
    if (rt_test_make_pattern(&image, 16, 8) != RT_OK)
        return rt_test_say(81, note, size, "no memory for the image");
    rt_save_options options = save_options(hold > 0);
    if (hold < 0)
        options.size = offsetof(rt_save_options, hold_termination_signals);
    signal_state before = signal_state_now();
    rt_error error = {0};
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6,
                                     hold == 0 ? NULL : &options, &error);
    signal_state after = signal_state_now();
    rt_image_release(&image);
    struct stat st;
    int exists = stat(path, &st) == 0;
    int changed = mask_difference(&before.mask, &after.mask);
    if (changed != 0)
        return rt_test_say(91, note, size, "signal %d changed its place in "
                           "the mask", changed);
    if (after.handler != before.handler)
        return rt_test_say(92, note, size, "SIGTERM's handler changed");
    if (!before.pending || !after.pending || caught != 0)
        return rt_test_say(93, note, size, "SIGTERM pending %d before, %d "
                           "after, caught=%d", before.pending, after.pending,
                           (int)caught);
    if (exists != (status == RT_OK))
        return rt_test_say(94, note, size, "the file %s after %s",
                           exists ? "exists" : "does not exist",
                           rt_status_string(status));
    return rt_test_say((int)status, note, size, "%s",
                       status == RT_OK ? "saved" : error.message);
}

/* Runs save_with_sigterm_pending in a fresh folder; returns its exit code
 * and checks what the folder holds after: out.ppm when saved, else
 * nothing. */
static int save_in_child_with_sigterm_pending(int hold, char *note,
                                              size_t size)
{
    char *dir = rt_test_temp_dir();
    rt_test_path out = rt_test_path_at(dir, "out.ppm");
    pending_case c = {out.s, hold};
    int code = rt_test_in_child(save_with_sigterm_pending, &c, note, size);
    rt_test_assert_dir_holds(dir, code == RT_OK ? "out.ppm" : "");
    rt_test_remove_dir(dir);
    return code;
}

START_TEST(a_default_save_leaves_the_mask_the_handler_and_a_pending_sigterm)
{
    char note[512];
    int code = save_in_child_with_sigterm_pending(0, note, sizeof note);
    ck_assert_msg(code == RT_OK, "exit code %d: %s", code, note);
    /* options from a header older than the field: its default too */
    code = save_in_child_with_sigterm_pending(-1, note, sizeof note);
    ck_assert_msg(code == RT_OK, "short options: exit code %d: %s", code,
                  note);
}
END_TEST

START_TEST(a_held_save_returns_interrupted_for_a_sigterm_already_pending)
{
    char note[512];
    int code = save_in_child_with_sigterm_pending(1, note, sizeof note);
    ck_assert_msg(code == RT_ERR_INTERRUPTED,
                  "exit code %d, expected RT_ERR_INTERRUPTED: %s", code, note);
    ck_assert_msg(strstr(note, "interrupted by signal 15") != NULL,
                  "the message does not name the signal: %s", note);
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
    tcase_add_test(tc, a_default_save_lets_a_handled_sigterm_in_at_once_and_completes);
    tcase_add_test(tc, a_default_save_leaves_the_mask_the_handler_and_a_pending_sigterm);
    tcase_add_test(tc, a_held_save_returns_interrupted_for_a_sigterm_already_pending);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(save_signals_suite)
