/*
 * test_viewer_load.c - rt-view's loads off its event loop
 * (apps/rt-view/view_load.c and view_app's use of it), on SDL's dummy video
 * driver: a scene is read on a worker thread while the window keeps its
 * picture and answers keys; a new load cancels the one under way; quitting,
 * closing the app and a termination signal never wait for a loader blocked
 * in read() (the tests' loader blocks on a pipe and ignores the flag, as a
 * read of a FIFO no one writes does); and a watched file replaced by a FIFO
 * leaves the window live, whether the library refuses the FIFO or blocks
 * on it.
 *
 * Nothing here asserts a time: "does not wait" is checked by the loader
 * still being blocked when quit and destroy have returned.  Waits for a
 * thread to come or go have a generous bound (WAIT_SECONDS) only so that a
 * broken build fails instead of hanging.
 */
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <semaphore.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "testutil.h"
#include "viewer.h"
#include "view_load.h"
#include "view_scene.h"

/* Safety bound for a thread to come or go (never reached when it works). */
#define WAIT_SECONDS 20.0

/* --- a loader the test holds ------------------------------------------- */

/* The tests' loader blocks in read() on `pipe` until the test writes one
 * byte: 'l' lets it load the file (view_scene_load), anything else (or the
 * pipe closed) makes it fail.  It records where and with what it ran. */
static struct gate {
    int pipe[2];
    sem_t entered;              /* posted when the loader starts */
    sem_t left;                 /* posted when it returns */
    atomic_int returned;
    pthread_t thread;           /* the loader's thread */
    const rt_cancel *cancel;    /* the flag its load was given */
} gate;

static void gate_open(void)
{
    ck_assert_int_eq(pipe(gate.pipe), 0);
    ck_assert_int_eq(sem_init(&gate.entered, 0, 0), 0);
    ck_assert_int_eq(sem_init(&gate.left, 0, 0), 0);
    atomic_store(&gate.returned, 0);
    gate.cancel = NULL;
}

static void gate_release(char byte)
{
    ck_assert_int_eq(write(gate.pipe[1], &byte, 1), 1);
}

static void gate_close(void)
{
    close(gate.pipe[0]);
    close(gate.pipe[1]);
    sem_destroy(&gate.entered);
    sem_destroy(&gate.left);
}

/* Waits (up to the safety bound) for `semaphore`; 0 if it never came. */
static int wait_for(sem_t *semaphore)
{
    struct timespec deadline;
    clock_gettime(CLOCK_REALTIME, &deadline);
    deadline.tv_sec += (time_t)WAIT_SECONDS;
    int status;
    while ((status = sem_timedwait(semaphore, &deadline)) != 0 &&
           errno == EINTR)
        ;
    return status == 0;
}

static rt_status held_load(const char *path, const rt_load_options *options,
                           rt_scene **scene, rt_error *error)
{
    gate.thread = pthread_self();
    gate.cancel = options->cancel;
    sem_post(&gate.entered);
    char byte = 0;
    ssize_t got = read(gate.pipe[0], &byte, 1);    /* deaf to the flag */
    rt_status status = RT_ERR_IO;
    if (got == 1 && byte == 'l') {
        status = view_scene_load(path, options, scene, error);
    } else {
        *scene = NULL;
        snprintf(error->message, sizeof error->message,
                 "%s: the test's loader was let go", path);
    }
    atomic_store(&gate.returned, 1);
    sem_post(&gate.left);
    return status;
}

/* A loader that waits for its cancellation flag for files named *slow*
 * (and says whether it saw it), and reads the others. */
static atomic_int saw_cancel;

static rt_status cancellable_load(const char *path,
                                  const rt_load_options *options,
                                  rt_scene **scene, rt_error *error)
{
    if (strstr(path, "slow") == NULL)
        return view_scene_load(path, options, scene, error);
    sem_post(&gate.entered);
    double deadline = rt_test_now() + WAIT_SECONDS;
    while (!rt_cancel_requested(options->cancel) &&
           rt_test_now() < deadline)
        rt_test_sleep_ms(1);
    atomic_store(&saw_cancel, rt_cancel_requested(options->cancel));
    *scene = NULL;
    snprintf(error->message, sizeof error->message, "%s: cancelled", path);
    sem_post(&gate.left);
    return RT_ERR_CANCELLED;
}

/* --- the app ----------------------------------------------------------- */

static view_app *open_app(view_load_func load, int watch)
{
    view_app_options options;
    rt_test_view_app_options(&options);
    options.watch = watch;
    options.load_scene = load;
    return rt_test_view_app_open(&options);
}
static void push_key(SDL_Keycode key)
{
    SDL_Event event;
    SDL_zero(event);
    event.type = SDL_KEYDOWN;
    event.key.keysym.sym = key;
    ck_assert_int_eq(SDL_PushEvent(&event), 1);
}

static void push_quit(void)
{
    SDL_Event event;
    SDL_zero(event);
    event.type = SDL_QUIT;
    ck_assert_int_eq(SDL_PushEvent(&event), 1);
}

/* The background colour of the image's top-left pixel. */
static int shows_background(const rt_image *image, int r, int g, int b)
{
    const unsigned char *pixel = rt_image_pixel(image, 0, 0);
    return pixel[0] == r && pixel[1] == g && pixel[2] == b;
}

/* Waits for the session's render to finish. */
static const rt_image *finished_image(view_app *app)
{
    view_session *session = view_app_session(app);
    ck_assert_ptr_nonnull(session);
    view_progress progress;
    double deadline = rt_test_now() + WAIT_SECONDS;
    do {
        view_session_get_progress(session, &progress);
        if (progress.state == VIEW_RENDERING)
            rt_test_sleep_ms(1);
    } while (progress.state == VIEW_RENDERING &&
             rt_test_now() < deadline);
    ck_assert_int_eq(progress.state, VIEW_DONE);
    return view_session_image(session);
}

/* --- the tests --------------------------------------------------------- */

START_TEST(a_load_runs_on_a_worker_while_the_window_keeps_its_picture)
{
    gate_open();
    rt_test_write_two_facet_scene("viewer-load-a.scn", "30, 30, 60");
    rt_test_write_two_facet_scene("viewer-load-b.scn", "200, 10, 10");
    view_app *app = open_app(held_load, 0);
    gate_release('l');              /* the first load goes through */
    ck_assert(view_app_open(app, "viewer-load-a.scn"));
    ck_assert(view_app_wait_load(app));
    ck_assert(wait_for(&gate.entered));     /* (posted by the first load) */
    ck_assert(wait_for(&gate.left));
    atomic_store(&gate.returned, 0);
    view_session *session = view_app_session(app);
    ck_assert(shows_background(finished_image(app), 30, 30, 60));

    ck_assert(view_app_open(app, "viewer-load-b.scn"));
    ck_assert(wait_for(&gate.entered));     /* the second load, held */
    ck_assert(!pthread_equal(gate.thread, pthread_self()));
    ck_assert(view_app_loading(app));
    /* The old picture stays, the title says what is loading, and the
     * loop answers keys meanwhile. */
    ck_assert_ptr_eq(view_app_session(app), session);
    ck_assert(shows_background(view_session_image(session), 30, 30, 60));
    ck_assert_msg(strstr(view_app_title(app), "loading viewer-load-b.scn"),
                  "%s", view_app_title(app));
    push_key(SDLK_n);
    push_quit();
    view_app_run(app);
    ck_assert_msg(strstr(view_app_title(app), "normal view") != NULL,
                  "%s", view_app_title(app));
    ck_assert(view_app_loading(app));
    ck_assert(!atomic_load(&gate.returned));

    gate_release('l');              /* now the new scene replaces it */
    ck_assert(view_app_wait_load(app));
    ck_assert(!view_app_loading(app));
    ck_assert_ptr_ne(view_app_session(app), session);
    /* The new scene in the view N asked for; V, its picture. */
    ck_assert_msg(strstr(view_app_title(app), "normal view") != NULL,
                  "%s", view_app_title(app));
    view_app_key(app, SDLK_v, 0);
    ck_assert(shows_background(finished_image(app), 200, 10, 10));
    ck_assert(strstr(view_app_title(app), "loading") == NULL);
    rt_test_view_app_close(app);
    gate_close();
    remove("viewer-load-a.scn");
    remove("viewer-load-b.scn");
}
END_TEST

START_TEST(a_quit_during_a_load_blocked_in_read_does_not_wait_for_it)
{
    int threads = rt_test_baseline_thread_count();
    gate_open();
    rt_test_write_two_facet_scene("viewer-load-q.scn", "30, 30, 60");
    view_app *app = open_app(held_load, 0);
    ck_assert(view_app_open(app, "viewer-load-q.scn"));
    ck_assert(wait_for(&gate.entered));
    push_quit();
    view_app_run(app);
    ck_assert_int_eq(view_app_exit_status(app), 1);    /* never loaded */
    rt_test_view_app_close(app);
    /* Quit and destroy have returned with the loader still in read():
     * neither waited for it; and its load was told to stop. */
    ck_assert(!atomic_load(&gate.returned));
    ck_assert(rt_cancel_requested(gate.cancel));

    gate_release('x');              /* it returns, and its thread ends */
    ck_assert(wait_for(&gate.left));
    ck_assert_int_eq(rt_test_settled_thread_count(threads, WAIT_SECONDS),
                     threads);
    gate_close();
    remove("viewer-load-q.scn");
}
END_TEST

START_TEST(a_new_load_cancels_the_one_under_way)
{
    gate_open();
    atomic_store(&saw_cancel, 0);
    rt_test_write_two_facet_scene("viewer-load-slow.scn", "30, 30, 60");
    rt_test_write_two_facet_scene("viewer-load-next.scn", "10, 200, 10");
    view_app *app = open_app(cancellable_load, 0);
    ck_assert(view_app_open(app, "viewer-load-slow.scn"));
    ck_assert(wait_for(&gate.entered));
    ck_assert(view_app_open(app, "viewer-load-next.scn"));
    ck_assert(wait_for(&gate.left));
    ck_assert(atomic_load(&saw_cancel));
    ck_assert(view_app_wait_load(app));
    ck_assert(shows_background(finished_image(app), 10, 200, 10));
    ck_assert_str_eq(view_app_message(app), "");
    rt_test_view_app_close(app);
    gate_close();
    remove("viewer-load-slow.scn");
    remove("viewer-load-next.scn");
}
END_TEST

START_TEST(a_termination_signal_during_a_blocked_load_ends_the_loop)
{
    /* As rt-view does: SIGTERM blocked before any thread starts, taken by
     * the event loop. */
    sigset_t term, before;
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    ck_assert_int_eq(pthread_sigmask(SIG_BLOCK, &term, &before), 0);
    int threads = rt_test_baseline_thread_count();
    gate_open();
    rt_test_write_two_facet_scene("viewer-load-t.scn", "30, 30, 60");
    view_app *app = open_app(held_load, 0);
    ck_assert(view_app_open(app, "viewer-load-t.scn"));
    ck_assert(wait_for(&gate.entered));
    ck_assert_int_eq(raise(SIGTERM), 0);   /* pending on this thread */
    view_app_run(app);
    ck_assert_int_eq(view_app_exit_status(app), 128 + SIGTERM);
    rt_test_view_app_close(app);
    ck_assert(!atomic_load(&gate.returned));
    gate_release('x');
    ck_assert(wait_for(&gate.left));
    ck_assert_int_eq(rt_test_settled_thread_count(threads, WAIT_SECONDS),
                     threads);
    gate_close();
    sigset_t pending;
    ck_assert_int_eq(sigpending(&pending), 0);
    ck_assert(!sigismember(&pending, SIGTERM));    /* the loop took it */
    pthread_sigmask(SIG_SETMASK, &before, NULL);
    remove("viewer-load-t.scn");
}
END_TEST

/* The real loader (rt_scene_load) on a FIFO: it either refuses it at
 * once or blocks opening it; either way the window stays live, keeps its
 * picture, and closing it does not wait. */
START_TEST(a_watched_file_replaced_by_a_fifo_leaves_the_window_live)
{
    int threads = rt_test_baseline_thread_count();
    const char *path = "viewer-load-fifo.scn";
    remove(path);
    rt_test_write_two_facet_scene(path, "30, 30, 60");
    view_app *app = open_app(NULL, 1);
    ck_assert(view_app_open(app, path));
    ck_assert(view_app_wait_load(app));
    view_session *session = view_app_session(app);
    finished_image(app);
    ck_assert_int_eq(remove(path), 0);
    ck_assert_int_eq(mkfifo(path, 0600), 0);
    ck_assert(view_app_check_watch(app));  /* returned: did not block */
    push_key(SDLK_n);
    push_quit();
    view_app_run(app);
    ck_assert_msg(strstr(view_app_title(app), "normal view") != NULL ||
                      view_app_message(app)[0] != '\0',
                  "%s", view_app_title(app));
    ck_assert_ptr_eq(view_app_session(app), session);
    /* The picture stays: N renders the view in the same session, and the
     * picture (finished before) comes back with V. */
    ck_assert(view_app_set_view(app, 0, 0));
    ck_assert(shows_background(finished_image(app), 30, 30, 60));
    rt_test_view_app_close(app);
    /* A worker blocked opening the FIFO is let through by a writer that
     * opens and closes it (the load then fails on an empty file); one that
     * refused it is gone already. */
    double deadline = rt_test_now() + WAIT_SECONDS;
    while (rt_test_thread_count() > threads &&
           rt_test_now() < deadline) {
        int fd = open(path, O_WRONLY | O_NONBLOCK);
        if (fd >= 0)
            close(fd);
        rt_test_sleep_ms(1);
    }
    ck_assert_int_eq(rt_test_settled_thread_count(threads, 0.2), threads);
    remove(path);
}
END_TEST

static Suite *viewer_load_suite(void)
{
    Suite *s = suite_create("viewer_load");
    TCase *tc = tcase_create("load");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc,
                   a_load_runs_on_a_worker_while_the_window_keeps_its_picture);
    tcase_add_test(tc, a_quit_during_a_load_blocked_in_read_does_not_wait_for_it);
    tcase_add_test(tc, a_new_load_cancels_the_one_under_way);
    tcase_add_test(tc, a_termination_signal_during_a_blocked_load_ends_the_loop);
    tcase_add_test(tc, a_watched_file_replaced_by_a_fifo_leaves_the_window_live);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(viewer_load_suite)
