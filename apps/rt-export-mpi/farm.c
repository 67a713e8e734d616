/*
 * farm.c - the bands of one render over MPI: rank 0's queue, its own
 * rendering thread and its receiving loop, and the workers' loop
 * (farm.h says what each side promises).
 */
#include "farm.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli_clock.h"

enum {
    TAG_WORK = 1,       /* rank 0 -> worker: an int, the band, or -1: stop */
    TAG_ROWS = 2,       /* worker -> rank 0: the band's pixels */
    TAG_REPORT = 3,     /* worker -> rank 0: its farm_rank_report */
    AHEAD = 2           /* bands a worker holds: one rendering, one next */
};

#define POLL_MIN_NS 20000L      /* idle waits sleep 20 us, doubling ... */
#define POLL_MAX_NS 1000000L    /* ... up to 1 ms */

/* Sleeps *delay (then doubles it, up to POLL_MAX_NS). */
static void idle(long *delay)
{
    struct timespec pause = {0, *delay};
    nanosleep(&pause, NULL);
    if (*delay < POLL_MAX_NS)
        *delay *= 2;
}

/* Waits for `request` without spinning in MPI_Wait. */
static void wait_request(MPI_Request *request)
{
    long delay = POLL_MIN_NS;
    int done = 0;
    MPI_Test(request, &done, MPI_STATUS_IGNORE);
    while (!done) {
        idle(&delay);
        MPI_Test(request, &done, MPI_STATUS_IGNORE);
    }
}

static int band_count(const farm_job *job)
{
    int rows = job->area.y1 - job->area.y0;
    return (rows + job->band_rows - 1) / job->band_rows;
}

static int band_height(const farm_job *job, int band)
{
    int rows = job->area.y1 - job->area.y0;
    int left = rows - band * job->band_rows;
    return left < job->band_rows ? left : job->band_rows;
}

/* Renders `band` into `pixels` (its rows, stride 3 x the area's width)
 * as the region of the whole image it covers; adds to `report`. */
static rt_status render_band(const farm_job *job, int band,
                             unsigned char *pixels, farm_rank_report *report,
                             double start)
{
    int width = job->area.x1 - job->area.x0;
    int rows = band_height(job, band);
    int top = job->area.y0 + band * job->band_rows;
    rt_render_options options = job->options;
    rt_render_stats stats = {.size = sizeof stats};
    options.region = (rt_region){job->area.x0, top, job->area.x1,
                                 top + rows};
    options.stats = &stats;
    options.on_row = NULL;
    options.user = NULL;
    rt_image view = {width, rows, (size_t)width * 3, pixels};
    double begin = cli_clock_seconds();
    rt_status status = rt_render(job->scene, &options, &view, NULL);
    if (status != RT_OK)
        return status;
    double seconds = cli_seconds_since(begin);
    if (seconds / rows > report->slowest_row_seconds)
        report->slowest_row_seconds = seconds / rows;
    report->busy_seconds += seconds;
    report->finish_seconds = cli_seconds_since(start);
    report->bands++;
    report->rows += rows;
    farm_stats_add(&report->stats, &stats);
    return RT_OK;
}

/* ---- rank 0 ---------------------------------------------------------- */

/* The queue rank 0's thread and its receiving loop share. */
typedef struct queue {
    pthread_mutex_t lock;
    int next, total;            /* the next band to hand out, how many */
    int local_rows;             /* rows the thread finished, not yet
                                   counted by the loop */
    int local_bands;
    int local_running;          /* 0 once the thread has left */
    rt_status local_status;
    const farm_job *job;
    rt_image *image;
    farm_rank_report *report;   /* rank 0's */
    double start;               /* cli_clock_seconds at the start */
} queue;

/* The next band to render, or -1 when none is left. */
static int queue_take(queue *q)
{
    pthread_mutex_lock(&q->lock);
    int band = q->next < q->total ? q->next++ : -1;
    pthread_mutex_unlock(&q->lock);
    return band;
}

/* Rank 0's rendering thread: bands from the queue, straight into the
 * image. */
static void *render_locally(void *argument)
{
    queue *q = argument;
    rt_status status = RT_OK;
    int band;
    while (status == RT_OK && (band = queue_take(q)) >= 0) {
        unsigned char *rows = q->image->pixels +
                              (size_t)band * q->job->band_rows *
                                  q->image->stride;
        status = render_band(q->job, band, rows, q->report, q->start);
        pthread_mutex_lock(&q->lock);
        if (status == RT_OK) {
            q->local_rows += band_height(q->job, band);
            q->local_bands++;
        }
        pthread_mutex_unlock(&q->lock);
    }
    pthread_mutex_lock(&q->lock);
    q->local_status = status;
    q->local_running = 0;
    pthread_mutex_unlock(&q->lock);
    return NULL;
}

/* What rank 0 knows of one worker. */
typedef struct worker {
    int bands[AHEAD];           /* the bands it holds, oldest first */
    int held;
    int stopped;                /* it was told to stop */
    int reported;
} worker;

/* Tops up worker `rank`'s bands; tells it to stop when it holds none and
 * none is left. */
static void hand_out(queue *q, worker *w, int rank, MPI_Comm comm)
{
    while (!w->stopped && w->held < AHEAD) {
        int band = queue_take(q);
        if (band < 0) {
            if (w->held == 0) {
                MPI_Send(&band, 1, MPI_INT, rank, TAG_WORK, comm);
                w->stopped = 1;
            }
            return;
        }
        MPI_Send(&band, 1, MPI_INT, rank, TAG_WORK, comm);
        w->bands[w->held++] = band;
    }
}

/* Receives the next message of a worker, if one is waiting; returns the
 * rows it brought (0 for a report or nothing), -1 on a bad message. */
static int receive(queue *q, worker *workers, farm_rank_report *reports,
                   MPI_Comm comm, int *reports_done)
{
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &waiting, &status);
    if (!waiting)
        return 0;
    int rank = status.MPI_SOURCE, bytes = 0;
    worker *w = &workers[rank];
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    if (status.MPI_TAG == TAG_REPORT && !w->reported &&
        bytes == (int)sizeof reports[rank]) {
        MPI_Recv(&reports[rank], bytes, MPI_BYTE, rank, TAG_REPORT, comm,
                 MPI_STATUS_IGNORE);
        w->reported = 1;
        ++*reports_done;
        return 0;
    }
    int band = w->held > 0 ? w->bands[0] : -1;
    int rows = band >= 0 ? band_height(q->job, band) : 0;
    if (status.MPI_TAG != TAG_ROWS || band < 0 ||
        (size_t)bytes != (size_t)rows * q->image->stride) {
        fprintf(stderr, "rt-export-mpi: rank %d sent an unexpected message "
                        "(tag %d, %d bytes)\n", rank, status.MPI_TAG, bytes);
        return -1;
    }
    /* the band's rows are contiguous in the image: no copy */
    unsigned char *at = q->image->pixels +
                        (size_t)band * q->job->band_rows * q->image->stride;
    MPI_Recv(at, bytes, MPI_BYTE, rank, TAG_ROWS, comm, MPI_STATUS_IGNORE);
    memmove(w->bands, w->bands + 1, sizeof w->bands[0] * (AHEAD - 1));
    w->held--;
    hand_out(q, w, rank, comm);
    return rows;
}

rt_status farm_serve(const farm_job *job, MPI_Comm comm, rt_image *image,
                     farm_progress progress, void *user,
                     farm_rank_report *reports)
{
    int ranks;
    MPI_Comm_size(comm, &ranks);
    memset(reports, 0, sizeof *reports * (size_t)ranks);
    worker *workers = calloc((size_t)ranks, sizeof *workers);
    if (workers == NULL)
        return RT_ERR_NOMEM;
    queue q = {.next = 0, .total = band_count(job), .local_running = 1,
               .local_status = RT_OK, .job = job, .image = image,
               .report = &reports[0], .start = cli_clock_seconds()};
    pthread_mutex_init(&q.lock, NULL);
    pthread_t thread;
    int threaded = pthread_create(&thread, NULL, render_locally, &q) == 0;
    if (!threaded)
        q.local_running = 0;    /* the workers take every band */
    for (int rank = 1; rank < ranks; rank++)
        hand_out(&q, &workers[rank], rank, comm);

    rt_status status = RT_OK;
    int done = 0, reports_done = 0, running = 1;
    long delay = POLL_MIN_NS;
    while (done < q.total || reports_done < ranks - 1 || running) {
        int rows = receive(&q, workers, reports, comm, &reports_done);
        if (rows < 0) {
            status = RT_ERR_IO;
            break;
        }
        pthread_mutex_lock(&q.lock);
        int local = q.local_rows, local_bands = q.local_bands;
        q.local_rows = q.local_bands = 0;
        running = q.local_running;
        rt_status local_status = q.local_status;
        pthread_mutex_unlock(&q.lock);
        if (local_status != RT_OK) {
            status = local_status;
            break;
        }
        done += (rows > 0) + local_bands;
        if (rows + local > 0 && progress != NULL)
            progress(user, rows + local);
        if (rows + local > 0)
            delay = POLL_MIN_NS;
        else if (done < q.total || reports_done < ranks - 1)
            idle(&delay);
        else if (running)
            idle(&delay);       /* the thread is leaving: an empty queue */
    }
    if (threaded) {
        if (status != RT_OK) {  /* stop handing out bands */
            pthread_mutex_lock(&q.lock);
            q.next = q.total;
            pthread_mutex_unlock(&q.lock);
        }
        pthread_join(thread, NULL);
    }
    pthread_mutex_destroy(&q.lock);
    free(workers);
    reports[0].finish_seconds = reports[0].bands ? reports[0].finish_seconds
                                                 : 0.0;
    return status;
}

/* ---- the other ranks ------------------------------------------------- */

rt_status farm_work(const farm_job *job, MPI_Comm comm)
{
    int width = job->area.x1 - job->area.x0, rank;
    MPI_Comm_rank(comm, &rank);
    size_t band_bytes = (size_t)width * 3 * (size_t)job->band_rows;
    /* two buffers: one band is sent while the next renders */
    unsigned char *buffers[2] = {malloc(band_bytes), malloc(band_bytes)};
    MPI_Request sends[2] = {MPI_REQUEST_NULL, MPI_REQUEST_NULL};
    farm_rank_report report;
    memset(&report, 0, sizeof report);
    double start = cli_clock_seconds();
    rt_status status = buffers[0] && buffers[1] ? RT_OK : RT_ERR_NOMEM;
    for (int turn = 0; status == RT_OK; turn ^= 1) {
        int band = -1;
        MPI_Request request;
        MPI_Irecv(&band, 1, MPI_INT, 0, TAG_WORK, comm, &request);
        wait_request(&request);
        if (band < 0)
            break;
        wait_request(&sends[turn]);     /* the buffer is free again */
        status = render_band(job, band, buffers[turn], &report, start);
        if (status == RT_OK)
            MPI_Isend(buffers[turn], (int)((size_t)band_height(job, band) *
                                           (size_t)width * 3),
                      MPI_BYTE, 0, TAG_ROWS, comm, &sends[turn]);
    }
    if (status != RT_OK) {
        fprintf(stderr, "rt-export-mpi: rank %d: rendering failed: %s\n",
                rank, rt_status_string(status));
        MPI_Abort(comm, 1);
    }
    wait_request(&sends[0]);
    wait_request(&sends[1]);
    MPI_Request request;
    MPI_Isend(&report, (int)sizeof report, MPI_BYTE, 0, TAG_REPORT, comm,
              &request);
    wait_request(&request);
    free(buffers[0]);
    free(buffers[1]);
    return status;
}

int farm_default_band_rows(int rows, int ranks)
{
    int bands = 32 * (ranks > 0 ? ranks : 1);
    int band_rows = (rows + bands - 1) / bands;
    return band_rows < 1 ? 1 : band_rows > 32 ? 32 : band_rows;
}

void farm_stats_add(rt_render_stats *to, const rt_render_stats *from)
{
    /* Field by field as RT_STATS_MAP says: SUM adds, MAX keeps the
     * largest, SAME (the octree's figures: one octree per rank, built
     * once) is taken from any band that used it. */
#define MERGE_SUM_(name) to->name += from->name;
#define MERGE_MAX_(name)                                                     \
    if (from->name > to->name)                                               \
        to->name = from->name;
#define MERGE_SAME_(name)                                                    \
    if (from->accel_used)                                                    \
        to->name = from->name;
#define MERGE_(type, name, origin, merge, group, key, title)                 \
    MERGE_##merge##_(name)
    RT_STATS_MAP(MERGE_)
#undef MERGE_
#undef MERGE_SUM_
#undef MERGE_MAX_
#undef MERGE_SAME_
}
