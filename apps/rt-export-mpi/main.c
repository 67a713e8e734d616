/*
 * rt-export-mpi - rt-export over MPI: the same image, byte for byte,
 * rendered by every rank of the job (docs/mpi.md).
 *
 *     mpirun -np N rt-export-mpi SCENE -o OUT [every rt-export render option]
 *
 * Every rank parses the same command line (only rank 0 speaks).  Rank 0
 * runs rt-export's export pipeline (apps/common/cli_export.h) with two
 * hooks of its own: the load reads the scene once, and every file it
 * names (an OBJ's material libraries), keeping their bytes; the bands go
 * to the ranks.  Once rank 0's checks have passed, those bytes go to
 * every rank, which parses the same scene from them without reading its
 * own disk and checks that it is rank 0's (apps/rt-export-mpi/share.h);
 * then the bands of the image are handed out from rank 0's queue
 * (apps/rt-export-mpi/farm.h), rendered with all the cores of each rank,
 * and received into rank 0's image, which the pipeline saves once every
 * band has arrived.  A bad scene or output (one the scene was read from
 * included): one message from rank 0, and every rank exits with its
 * status.  A save that fails after the render keeps the image under
 * another name.  A rank that dies: Open MPI ends the job, nothing is
 * saved.  Exit status as rt-export's: 0 success, 1 bad input or a failed
 * write, 2 bad usage.
 */
#define _GNU_SOURCE /* sched_getaffinity: the cores mpirun or srun gave */
#include <errno.h>
#include <fcntl.h>
#include <mpi.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_clock.h"
#include "cli_export.h"
#include "cli_text.h"
#include "farm.h"
#include "share.h"
#include "raytrace/raytrace.h"

#define EXIT_BAD_INPUT 1

static int band_rows_option; /* --band-rows, 0: farm_default_band_rows */

static const cli_option mpi_options[] = {
    {"band-rows", 0, "N", CLI_INT, 0, RT_MAX_IMAGE_SIDE, &band_rows_option,
     "rows of the image in each band handed out to a rank; 0 (the "
     "default): about 32 bands a rank, at most 32 rows each"},
    CLI_OPTIONS_END,
};

static const cli_program program = {
    "rt-export-mpi", "SCENE",
    "Renders SCENE as rt-export does, with every rank of an MPI job (run\n"
    "it with mpirun -np N or srun): rank 0 reads the scene and sends it to\n"
    "the others, the bands of rows go to whichever rank is free, each rank\n"
    "renders with all its cores (-j), and rank 0 saves the image - byte for\n"
    "byte the one rt-export writes - and prints its path.  SCENE `-' reads\n"
    "rank 0's standard input (then -o is needed); -o - is refused (mpirun\n"
    "passes standard output through a terminal).  --stats adds a line a\n"
    "rank: its bands, rows and busy time, and the imbalance.",
    "Exit status: 0 success, 1 bad scene or failed write, 2 bad usage; a\n"
    "rank that dies ends the job, and no image is written.",
    CLI_GROUP_RENDER | CLI_GROUP_LOAD | CLI_GROUP_OUTPUT | CLI_GROUP_REPORT |
        CLI_GROUP_QUIET,
    mpi_options, 1, 1, "expected a scene file"};

/* This rank's part of the job. */
typedef struct rank_state {
    int rank, count;
    share_input input;          /* what rank 0 read, for every rank */
    int shared;                 /* rank 0: its verdict went out */
    farm_job job;
    farm_rank_report *reports;  /* rank 0: a report a rank */
} rank_state;

/* Rank 0's load (a cli_export_load_func): the scene's bytes and those of
 * the files it names, kept for the other ranks, then parsed. */
static rt_status load_on_rank_0(void *user, const cli_export *ex,
                                rt_scene **scene, rt_error *error)
{
    rank_state *r = user;
    /* The format first, as rt_scene_load finds it: a file's extension that
     * names none is refused before it is read, a PLY is read binary. */
    rt_scene_format format = ex->settings->load.format;
    const char *base = strrchr(ex->operand, '/');
    base = base != NULL ? base + 1 : ex->operand;
    if (format == RT_SCENE_FORMAT_AUTO && !ex->from_stdin &&
        strrchr(base, '.') != NULL && strrchr(base, '.') != base &&
        rt_scene_format_from_path(ex->operand, &format, error) != RT_OK)
        return error->status;
    FILE *file = ex->from_stdin ? stdin : fopen(ex->operand, "rb");
    if (file == NULL) {
        char shown[RT_ERROR_MESSAGE_SIZE / 2];
        memset(error, 0, sizeof *error);
        error->status = RT_ERR_IO;
        snprintf(error->message, sizeof error->message,
                 "%s: cannot open: %s",
                 cli_printable(ex->operand, shown, sizeof shown),
                 strerror(errno));
        return RT_ERR_IO;
    }
    rt_status status =
        cli_read_scene_text(file, ex->name, format == RT_SCENE_FORMAT_PLY,
                            &r->input.text, &r->input.length, error);
    if (!ex->from_stdin)
        fclose(file);
    if (status != RT_OK)
        return status;
    rt_load_options load = ex->settings->load;
    load.resolve = share_record;
    load.resolve_user = &r->input.files;
    return rt_scene_parse(r->input.text, r->input.length, ex->name, &load,
                          scene, error);
}

/* The render every rank does. */
static farm_job make_job(const rt_scene *scene,
                         const rt_render_options *render, int ranks)
{
    farm_job job = {scene, *render, render->region, band_rows_option};
    rt_render_options whole = *render;
    whole.region = (rt_region){0, 0, 0, 0};
    int width = 0, height = 0;
    rt_render_image_size(scene, &whole, &width, &height, NULL);
    rt_region r = render->region;
    if (r.x0 == 0 && r.y0 == 0 && r.x1 == 0 && r.y1 == 0)
        job.area = (rt_region){0, 0, width, height};
    if (job.band_rows == 0)
        job.band_rows = farm_default_band_rows(job.area.y1 - job.area.y0,
                                               ranks);
    return job;
}

static void count_rows(void *user, int rows)
{
    for (int i = 0; i < rows; i++)
        cli_progress_row(user, 0);
}

/* Rank 0's bands (a cli_export_bands_func), once its checks passed: the
 * scene goes to every rank, then the farm hands the bands out. */
static int bands_on_ranks(void *user, const cli_export *ex,
                          cli_progress *progress, rt_image *image,
                          rt_render_stats *stats)
{
    rank_state *r = user;
    rt_scene *scene = ex->scene;
    r->shared = 1;
    int code = share_scene(&r->input, CLI_CONTINUE, ex->name,
                           &ex->settings->load, &scene, 0, MPI_COMM_WORLD);
    if (code != CLI_CONTINUE)
        return code;
    r->job = make_job(ex->scene, &ex->settings->render, r->count);
    r->reports = calloc((size_t)r->count, sizeof *r->reports);
    if (r->reports == NULL) {   /* the others are rendering: end the job */
        fprintf(stderr, "rt-export-mpi: out of memory\n");
        MPI_Abort(MPI_COMM_WORLD, EXIT_BAD_INPUT);
    }
    double start = cli_clock_seconds();
    rt_status status = farm_serve(&r->job, MPI_COMM_WORLD, image,
                                  progress ? count_rows : NULL, progress,
                                  r->reports);
    double seconds = cli_seconds_since(start);
    if (status != RT_OK) {
        fprintf(stderr, "rt-export-mpi: %s: rendering failed: %s\n",
                ex->name, rt_status_string(status));
        MPI_Abort(MPI_COMM_WORLD, EXIT_BAD_INPUT);
    }
    for (int rank = 0; rank < r->count; rank++)
        farm_stats_add(stats, &r->reports[rank].stats);
    stats->seconds = seconds;
    return CLI_CONTINUE;
}

/* --stats: a line a rank, and how even the ranks' work was. */
static void print_ranks(FILE *out, const farm_job *job,
                        const farm_rank_report *reports, int ranks)
{
    double most = 0, total = 0, first = -1, last = 0;
    for (int rank = 0; rank < ranks; rank++) {
        const farm_rank_report *r = &reports[rank];
        fprintf(out, "rt-export-mpi: rank %d: %d bands, %d rows, %.3f s "
                     "rendering (%.4f s a row, %.4f in its slowest band), "
                     "last band done at %.3f s\n", rank, r->bands, r->rows,
                r->busy_seconds, r->rows ? r->busy_seconds / r->rows : 0.0,
                r->slowest_row_seconds, r->finish_seconds);
        total += r->busy_seconds;
        most = r->busy_seconds > most ? r->busy_seconds : most;
        if (r->bands > 0) {
            first = first < 0 || r->finish_seconds < first ? r->finish_seconds
                                                           : first;
            last = r->finish_seconds > last ? r->finish_seconds : last;
        }
    }
    fprintf(out, "rt-export-mpi: %d ranks, bands of %d rows; imbalance "
                 "%.3f (the busiest rank's time over the mean); the last "
                 "rank finished %.3f s after the first\n", ranks,
            job->band_rows, total > 0 ? most * ranks / total : 1.0,
            first < 0 ? 0.0 : last - first);
}

/* print_ranks as a cli_export_report_func. */
static void report_ranks(void *user, FILE *out)
{
    const rank_state *r = user;
    print_ranks(out, &r->job, r->reports, r->count);
}

/* Rank 0: the pipeline, rt-export's but for the two hooks.  Returns the
 * exit status (the others have it too once r->shared). */
static int run_rank_0(cli_settings *s, rank_state *r)
{
    /* mpirun hands rank 0 a pseudo-terminal for its standard output,
     * whose line discipline may turn \n into \r\n: no image goes there */
    if (s->output != NULL && !strcmp(s->output, "-"))
        return cli_usage_error(&program, "-o -: the image cannot go to "
                               "standard output under MPI (mpirun passes it "
                               "through a terminal); name a file");
    const cli_export_config config = {
        .load = load_on_rank_0, .bands = bands_on_ranks,
        .report = report_ranks, .user = r, .no_stdout = 1};
    cli_export ex;
    cli_export_init(&ex, &program, s, &config);
    int code = cli_export_load(&ex, 1);
    if (code == CLI_CONTINUE) {
        cli_export_print_warnings(&ex);
        code = cli_export_render(&ex);
    }
    cli_export_release(&ex);
    return code;
}

/* Every other rank: rank 0's verdict, then the scene and the bands. */
static int run_worker(const cli_settings *s, rank_state *r)
{
    rt_scene *scene = NULL;
    const char *name = strcmp(s->operands[0], "-") ? s->operands[0]
                                                   : "<stdin>";
    int code = share_scene(&r->input, CLI_CONTINUE, name, &s->load, &scene,
                           r->rank, MPI_COMM_WORLD);
    if (code == CLI_CONTINUE) {
        farm_job job = make_job(scene, &s->render, r->count);
        farm_work(&job, MPI_COMM_WORLD);
        code = EXIT_SUCCESS;
    }
    rt_scene_destroy(scene);
    return code;
}

/* Parses the command line on every rank; only rank 0's messages and
 * --help are shown (the others parse with stdout and stderr closed). */
static int parse_everywhere(int argc, char **argv, cli_settings *s, int rank)
{
    int saved_out = -1, saved_err = -1;
    if (rank != 0) {
        int null = open("/dev/null", O_WRONLY);
        fflush(stdout);
        fflush(stderr);
        saved_out = dup(STDOUT_FILENO);
        saved_err = dup(STDERR_FILENO);
        if (null >= 0) {
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
            close(null);
        }
    }
    int code = cli_parse(&program, argc, argv, s);
    if (rank != 0) {
        fflush(stdout);
        fflush(stderr);
        if (saved_out >= 0) {
            dup2(saved_out, STDOUT_FILENO);
            close(saved_out);
        }
        if (saved_err >= 0) {
            dup2(saved_err, STDERR_FILENO);
            close(saved_err);
        }
    }
    /* the same argv everywhere; rank 0's verdict decides anyway */
    MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return code;
}

/*
 * -j 0 means the cores this rank may run on, not the machine's: mpirun
 * binds each rank to one core by default when it starts one or two, and
 * srun to --cpus-per-task, so the machine's count would put every thread
 * on one core.  A -j above them gets a warning from rank 0.
 */
static void fit_threads(cli_settings *s, int rank)
{
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) != 0)
        return;
    int cores = CPU_COUNT(&set);
    if (s->render.threads == 0)
        s->render.threads = cores;
    else if (s->render.threads > cores && rank == 0)
        fprintf(stderr, "rt-export-mpi: warning: -j %d, but rank 0 may run "
                        "on %d core%s (mpirun binds ranks to cores: see "
                        "--bind-to none in docs/mpi.md)\n", s->render.threads,
                cores, cores == 1 ? "" : "s");
}

/*
 * --help and --version are answered before MPI_Init, on a copy of argv
 * (cli_parse permutes it): Open MPI cannot start even one rank where its
 * launcher (openmpi-bin) is missing, and a question about the program
 * should not need it.  Returns the exit status, or CLI_CONTINUE when
 * neither was asked (or "--help" was an option's value, as in -o --help).
 */
static int answer_before_mpi(int argc, char **argv)
{
    int asked = 0;
    for (int i = 1; i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0 ||
            strcmp(argv[i], "--version") == 0)
            asked = 1;
    if (!asked)
        return CLI_CONTINUE;
    char **copy = malloc(((size_t)argc + 1) * sizeof *copy);
    if (!copy)
        return CLI_CONTINUE; /* MPI's own parse answers it then */
    memcpy(copy, argv, ((size_t)argc + 1) * sizeof *copy);
    cli_settings s;
    int code = cli_parse(&program, argc, copy, &s);
    free(copy);
    return code;
}

int main(int argc, char **argv)
{
    int provided;
    rank_state r;
    memset(&r, 0, sizeof r);
    int answered = answer_before_mpi(argc, argv);
    if (answered != CLI_CONTINUE)
        return answered;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &r.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &r.count);
    if (provided < MPI_THREAD_FUNNELED && r.rank == 0)
        fprintf(stderr, "rt-export-mpi: warning: this MPI gives no thread "
                        "support; rank 0 renders anyway on a thread that "
                        "makes no MPI call\n");
    cli_settings s;
    int code = parse_everywhere(argc, argv, &s, r.rank);
    if (code == CLI_CONTINUE) {
        fit_threads(&s, r.rank);
        if (r.rank != 0) {
            code = run_worker(&s, &r);
        } else {
            code = run_rank_0(&s, &r);
            /* a refusal before the render: the others wait for it */
            if (!r.shared)
                share_scene(&r.input, code, NULL, NULL, NULL, 0,
                            MPI_COMM_WORLD);
        }
    }
    share_input_free(&r.input);
    free(r.reports);
    MPI_Finalize();
    return code;
}
