/*
 * farm.h - the bands of one render handed out over MPI: rank 0 keeps the
 * queue of bands, a thread of its own renders from that queue too, and
 * every other rank asks for bands, renders each with all its cores and
 * sends the rows back, where rank 0 receives them straight into the image.
 *
 * A band is `band_rows` rows of the image being written (the region's
 * rows when there is one), rendered as the region of the whole image that
 * it covers, so its pixels are those of the whole image, byte for byte,
 * whichever rank renders it and with however many threads.  Rank 0 gives
 * each worker two bands ahead (one rendering, one waiting) so that a
 * worker never waits for the round trip; the queue is dynamic, so a slow
 * rank takes fewer bands.  Rank 0 saves nothing here: farm_serve returns
 * only when every band has arrived, and a rank that dies makes Open MPI end
 * the job before that.
 *
 * Every MPI call is made by the thread that called farm_serve or
 * farm_work (MPI_THREAD_FUNNELED is enough).  Waits poll with short sleeps
 * instead of spinning in a blocking call, so that an idle rank leaves its
 * cores to the ranks and threads that render (ranks may outnumber cores).
 */
#ifndef RAYTRACE_MPI_FARM_H
#define RAYTRACE_MPI_FARM_H

#include <mpi.h>

#include "raytrace/raytrace.h"

/* One render, the same on every rank. */
typedef struct farm_job {
    const rt_scene *scene;
    rt_render_options options;  /* the render's options; region, stats,
                                   on_row and user are set per band */
    rt_region area;             /* the part of the whole image written:
                                   the region, or all of it */
    int band_rows;              /* rows a band, >= 1 */
} farm_job;

/* What one rank did, for the statistics and the imbalance. */
typedef struct farm_rank_report {
    int bands, rows;
    double busy_seconds;        /* inside rt_render */
    double finish_seconds;      /* from the start to its last band done */
    double slowest_row_seconds; /* its slowest band's time over its rows */
    rt_render_stats stats;      /* the counters of its bands, summed */
} farm_rank_report;

/* Called on rank 0's calling thread as rows arrive (in bands, in any
 * order): `rows` more rows are done. */
typedef void (*farm_progress)(void *user, int rows);

/*
 * Rank 0: renders the job into `image` (the area's size) with the ranks
 * of `comm`, its own thread included; calls `progress` as bands arrive.
 * `reports` (the size of comm) receives each rank's report.  Returns
 * RT_OK, or the status of a band rank 0 itself failed to render (the
 * others then stop; a worker's failure aborts the job).
 */
rt_status farm_serve(const farm_job *job, MPI_Comm comm, rt_image *image,
                     farm_progress progress, void *user,
                     farm_rank_report *reports);

/* Every other rank: renders the bands rank 0 hands out until it says
 * stop, then sends its report.  Returns RT_OK, or after a failed band
 * aborts the job. */
rt_status farm_work(const farm_job *job, MPI_Comm comm);

/* The rows a band gets when none are asked for: about 32 bands a rank,
 * between 1 and 32 rows. */
int farm_default_band_rows(int rows, int ranks);

/* Adds the counters of `from` to `to` (the octree's figures, the same for
 * every band, are kept, not summed). */
void farm_stats_add(rt_render_stats *to, const rt_render_stats *from);

#endif /* RAYTRACE_MPI_FARM_H */
