/*
 * workers.c - a team of threads kept between jobs (workers.h).
 *
 * A job is posted under the team's lock as a generation number, the task
 * and how many of the team's threads it wants (at most as many as are
 * alive); each waiting thread that has not run this generation takes one
 * of those places, runs the task and counts itself done; the caller runs
 * the task too, then waits until every place is done.  A thread never runs
 * a generation twice, and ends only when its wait for a place times out
 * with none free, so every place of a job is taken.  The threads are
 * detached: the last to end tells a waiting rt__workers_destroy.
 */
#include "workers.h"

#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

struct rt_workers {
    pthread_mutex_t lock;
    pthread_cond_t wake;        /* a job is posted, or the end */
    pthread_cond_t done;        /* a place is done, or a thread ended */
    int alive;                  /* threads started and not ended */
    pid_t owner;                /* the process whose threads they are */
    int busy;                   /* a job holds the team */
    int quit;
    unsigned long generation;   /* of the job posted last (0: none) */
    int wanted, taken, finished;    /* places of that job */
    void (*task)(void *);
    void *argument;
};

rt_workers *rt__workers_create(void)
{
    rt_workers *w = calloc(1, sizeof *w);
    if (w == NULL)
        return NULL;
    pthread_condattr_t monotonic;
    pthread_condattr_init(&monotonic);
    pthread_condattr_setclock(&monotonic, CLOCK_MONOTONIC);
    pthread_mutex_init(&w->lock, NULL);
    pthread_cond_init(&w->wake, &monotonic);
    pthread_cond_init(&w->done, NULL);
    pthread_condattr_destroy(&monotonic);
    w->owner = getpid();
    return w;
}

/* Non-zero when w's current job has a place for a thread that last ran
 * generation `last`. */
static int place_for(const rt_workers *w, unsigned long last)
{
    return w->generation != last && w->taken < w->wanted;
}

/* The time RT_WORKERS_LINGER seconds from now, on CLOCK_MONOTONIC. */
static struct timespec linger_deadline(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    long nanoseconds = (long)(RT_WORKERS_LINGER * 1e9);
    t.tv_nsec += nanoseconds % 1000000000L;
    t.tv_sec += nanoseconds / 1000000000L + t.tv_nsec / 1000000000L;
    t.tv_nsec %= 1000000000L;
    return t;
}

static void *member(void *argument)
{
    rt_workers *w = argument;
    unsigned long last = 0;     /* the last generation this thread ran */
    pthread_mutex_lock(&w->lock);
    for (;;) {
        struct timespec deadline = linger_deadline();
        int timed_out = 0;
        while (!w->quit && !place_for(w, last) && !timed_out)
            timed_out = pthread_cond_timedwait(&w->wake, &w->lock,
                                               &deadline) == ETIMEDOUT;
        if (w->quit || !place_for(w, last))
            break;
        last = w->generation;
        w->taken++;
        void (*task)(void *) = w->task;
        void *task_argument = w->argument;
        pthread_mutex_unlock(&w->lock);
        task(task_argument);
        pthread_mutex_lock(&w->lock);
        w->finished++;
        pthread_cond_broadcast(&w->done);
    }
    w->alive--;
    pthread_cond_broadcast(&w->done);
    pthread_mutex_unlock(&w->lock);
    return NULL;
}

void rt__workers_destroy(rt_workers *w)
{
    if (w == NULL)
        return;
    if (getpid() != w->owner) {
        /* A forked child has none of these threads, and its copies of the
         * lock and conditions may show their waiters: it only frees. */
        free(w);
        return;
    }
    pthread_mutex_lock(&w->lock);
    w->quit = 1;
    pthread_cond_broadcast(&w->wake);
    while (w->alive > 0)
        pthread_cond_wait(&w->done, &w->lock);
    pthread_mutex_unlock(&w->lock);
    pthread_cond_destroy(&w->done);
    pthread_cond_destroy(&w->wake);
    pthread_mutex_destroy(&w->lock);
    free(w);
}

/* A job for threads started for it alone. */
typedef struct call {
    void (*task)(void *);
    void *argument;
} call;

static void *run_call(void *argument)
{
    const call *c = argument;
    c->task(c->argument);
    return NULL;
}

/* Runs the job on the caller and count - 1 threads started for it, each
 * with every signal blocked as the team's are. */
static void run_alone(int count, void (*task)(void *), void *argument)
{
    call job = {task, argument};
    pthread_t *threads = malloc((size_t)(count - 1) * sizeof *threads);
    int started = 0;
    sigset_t all, before;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &before);  /* inherited by them */
    for (int t = 0; threads != NULL && t < count - 1; t++) {
        if (pthread_create(&threads[t], NULL, run_call, &job) != 0)
            break;          /* fewer threads: still correct */
        started++;
    }
    pthread_sigmask(SIG_SETMASK, &before, NULL);
    task(argument);
    for (int t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    free(threads);
}

/* Starts threads until the team has `count` alive (or the system refuses
 * more), each with every signal blocked and detached. */
static void grow(rt_workers *w, int count)
{
    if (w->alive >= count)
        return;
    pthread_attr_t detached;
    if (pthread_attr_init(&detached) != 0)
        return;
    pthread_attr_setdetachstate(&detached, PTHREAD_CREATE_DETACHED);
    sigset_t all, before;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &before);  /* inherited by them */
    pthread_t thread;
    while (w->alive < count &&
           pthread_create(&thread, &detached, member, w) == 0)
        w->alive++;
    pthread_sigmask(SIG_SETMASK, &before, NULL);
    pthread_attr_destroy(&detached);
}

void rt__workers_run(rt_workers *w, int count, void (*task)(void *),
                     void *argument)
{
    if (count <= 1) {
        task(argument);
        return;
    }
    /* A forked child has none of the team's threads and may have
     * inherited the lock held: it does not touch the lock. */
    if (w == NULL || getpid() != w->owner) {
        run_alone(count, task, argument);
        return;
    }
    pthread_mutex_lock(&w->lock);
    if (w->busy) {              /* a job inside a job */
        pthread_mutex_unlock(&w->lock);
        run_alone(count, task, argument);
        return;
    }
    w->busy = 1;
    grow(w, count - 1);
    w->wanted = w->alive < count - 1 ? w->alive : count - 1;
    w->taken = 0;
    w->finished = 0;
    w->task = task;
    w->argument = argument;
    w->generation++;
    pthread_cond_broadcast(&w->wake);
    pthread_mutex_unlock(&w->lock);
    task(argument);             /* the calling thread works too */
    pthread_mutex_lock(&w->lock);
    while (w->finished < w->wanted)
        pthread_cond_wait(&w->done, &w->lock);
    w->busy = 0;
    pthread_mutex_unlock(&w->lock);
}
