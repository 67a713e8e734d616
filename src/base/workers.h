/*
 * workers.h - a team of threads kept between jobs (internal).
 *
 * A render runs one function on several threads at once and waits for
 * them.  A program that renders an image band by band (rt-export-mpi,
 * one call per band) would otherwise start and end those threads for
 * every band; a team starts them once and hands them the next job.  Its
 * threads wait RT_WORKERS_LINGER seconds for a next job, then end: a
 * program idle after its renders holds no thread for them.  A scene keeps
 * one (scene/prepared.c), made by its first render on several threads,
 * and ends it when it is freed.
 *
 * One job holds the team at a time.  A job that finds it held (another
 * render of the same scene, or one started from a render's callback), or
 * that runs in a child process forked after the team was made (whose
 * threads the child does not have), starts threads of its own for the
 * call, as if there were no team; so does one given no team (NULL).  The
 * team's threads block every signal, so that a signal meant for the
 * program (SIGINT during a save) reaches one of its own threads.
 */
#ifndef RAYTRACE_WORKERS_H
#define RAYTRACE_WORKERS_H

/* How long a thread of a team waits for the next job before it ends:
 * far above the gap between two bands of a band-by-band render (a message
 * exchange, well under a millisecond), far below what a person notices
 * as a program holding threads after its work (rt-view's tests see a
 * cancelled render leave no thread within 0.2 s). */
#define RT_WORKERS_LINGER 0.05

typedef struct rt_workers rt_workers;

/* A team with no thread yet; NULL when out of memory. */
rt_workers *rt__workers_create(void);

/* Ends the team's threads (no job may be running) and frees it; NULL:
 * no-op. */
void rt__workers_destroy(rt_workers *workers);

/*
 * Runs task(argument) on `count` threads at once - the calling thread and
 * count - 1 others, the team's (started as needed) or the call's own -
 * and returns once every one has returned.  Fewer threads run it when the
 * system refuses to start more (the task must not depend on how many run
 * it); count <= 1: only the calling thread.  Thread-safe.
 */
void rt__workers_run(rt_workers *workers, int count, void (*task)(void *),
                     void *argument);

#endif /* RAYTRACE_WORKERS_H */
