/*
 * rt-export-mpi - rt-export over MPI: the same image, byte for byte,
 * rendered by every rank of the job (docs/mpi.md).
 *
 *     mpirun -np N rt-export-mpi SCENE -o OUT [every rt-export render option]
 *
 * Every rank parses the same command line (only rank 0 speaks).  Rank 0
 * reads the scene once and every file it names (an OBJ's material
 * libraries), checks it and the output, and broadcasts all those bytes,
 * from which every rank parses the same scene without reading its own disk
 * (apps/rt-export-mpi/share.h), and checks that it is rank 0's; then the bands of
 * the image are handed out from rank 0's queue (apps/rt-export-mpi/farm.h), rendered
 * with all the cores of each rank, and received into rank 0's image, which
 * rank 0 saves with the library's safe save once every band has arrived.
 * A bad scene or output (one the scene was read from included): one
 * message from rank 0, and every rank exits 1.  A save that fails after
 * the render keeps the image under another name (cli_keep_image).
 * A rank that dies: Open MPI ends the job, nothing is saved.  Exit status
 * as rt-export's: 0 success, 1 bad input or a failed write, 2 bad usage.
 */
#define _GNU_SOURCE /* sched_getaffinity: the cores mpirun or srun gave */
#include <errno.h>
#include <fcntl.h>
#include <mpi.h>
#include <sched.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "cli_output.h"
#include "cli_report.h"
#include "farm.h"
#include "share.h"
#include "raytrace/raytrace.h"

#define EXIT_BAD_INPUT 1

static int band_rows_option; /* --band-rows, 0: farm_default_band_rows */

static const cli_option mpi_options[] = {
    {"band-rows", 0, "N", CLI_INT, 0, RT_MAX_IMAGE_SIDE, &band_rows_option,
     "rows of the image in each band handed out to a rank; 0 (the "
     "default): about 32 bands a rank, at most 32 rows each"},
    {NULL, 0, NULL, CLI_FLAG, 0, 0, NULL, NULL},
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

/* The scene as rank 0 read it: the bytes every rank parses. */
typedef struct scene_text {
    char *bytes;
    size_t length;
    const char *name;           /* the path, or "<stdin>" */
} scene_text;

/* Reads all of `file` (at most RT_MAX_SCENE_BYTES + 1 bytes, so that the
 * parser names a larger one; up to a NUL byte, which no scene holds). */
static int read_all(FILE *file, scene_text *text)
{
    size_t capacity = 1 << 16, used = 0;
    char *bytes = malloc(capacity);
    while (bytes != NULL) {
        used += fread(bytes + used, 1, capacity - used, file);
        if (used < capacity || used > RT_MAX_SCENE_BYTES)
            break;
        char *bigger = realloc(bytes, capacity * 2);
        if (bigger == NULL)
            free(bytes);
        bytes = bigger;
        capacity *= 2;
    }
    if (bytes == NULL)
        return 0;
    char *nul = memchr(bytes, 0, used);
    text->bytes = bytes;
    text->length = nul ? (size_t)(nul - bytes) : used;
    return 1;
}

/* Rank 0: the scene's bytes, or a message and 0. */
static int read_scene(const char *path, scene_text *text)
{
    int from_stdin = !strcmp(path, "-");
    text->name = from_stdin ? "<stdin>" : path;
    FILE *file = from_stdin ? stdin : fopen(path, "rb");
    if (file == NULL) {
        fprintf(stderr, "rt-export-mpi: %s: cannot open: %s\n", path,
                strerror(errno));
        return 0;
    }
    int read = read_all(file, text);
    int failed = ferror(file);
    if (!from_stdin)
        fclose(file);
    if (!read || failed) {
        fprintf(stderr, "rt-export-mpi: %s: cannot read: %s\n", text->name,
                read ? strerror(errno) : "out of memory");
        if (read)
            free(text->bytes);
        text->bytes = NULL;
        return 0;
    }
    return 1;
}

/* "dir/name.scn" -> "name.ppm" (".png" for PNG), in the current folder. */
static char *default_output(const char *scene, rt_image_format format)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    const char *dot = strrchr(base, '.');
    size_t stem = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    char *out = malloc(stem + 5);
    if (out != NULL)
        snprintf(out, stem + 5, "%.*s%s", (int)stem, base,
                 format == RT_IMAGE_PNG ? ".png" : ".ppm");
    return out;
}

/* What rank 0 decided before the render. */
typedef struct plan {
    scene_text text;
    share_files files;          /* the files the scene names, as rank 0
                                   read them */
    rt_scene *scene;
    char *default_path;         /* allocated when -o was not given */
    const char *output;         /* where the image goes */
    double load_seconds;
} plan;

/* Rank 0: reads and parses the scene, checks the output and the options
 * against it.  Returns CLI_CONTINUE or the exit status (after one
 * message). */
static int prepare(cli_settings *s, plan *p)
{
    rt_error error;
    const char *path = s->operands[0];
    /* mpirun hands rank 0 a pseudo-terminal for its standard output,
     * whose line discipline may turn \n into \r\n: no image goes there */
    if (s->output != NULL && !strcmp(s->output, "-"))
        return cli_usage_error(&program, "-o -: the image cannot go to "
                               "standard output under MPI (mpirun passes it "
                               "through a terminal); name a file");
    if (!strcmp(path, "-") && s->output == NULL)
        return cli_usage_error(&program, "expected -o OUT with a scene "
                               "read from standard input");
    if (!rt_image_format_supported(s->format)) {
        fprintf(stderr, "rt-export-mpi: cannot write %s: this build has no "
                        "PNG support (it was built without libpng); use "
                        "--format p6 or p3\n", s->output ? s->output : "PNG");
        return EXIT_BAD_INPUT;
    }
    double start = cli_clock_seconds();
    if (!read_scene(path, &p->text))
        return EXIT_BAD_INPUT;
    rt_load_options load = s->load;
    load.resolve = share_record;
    load.resolve_user = &p->files;
    if (rt_scene_parse_with(p->text.bytes, p->text.length, p->text.name,
                            &load, &p->scene, &error) != RT_OK) {
        fprintf(stderr, "rt-export-mpi: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    p->load_seconds = cli_seconds_since(start);
    rt_scene_info info;
    rt_scene_get_info(p->scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "rt-export-mpi: %s\n",
                rt_scene_warning(p->scene, i)->message);
    if (s->output == NULL)
        p->default_path = default_output(path, s->format);
    p->output = s->output ? s->output : p->default_path;
    if (p->output == NULL) {
        fprintf(stderr, "rt-export-mpi: out of memory\n");
        return EXIT_BAD_INPUT;
    }
    if (cli_refuse_input_as_output("rt-export-mpi", p->output, p->scene,
                                   path, "the image"))
        return EXIT_BAD_INPUT;
    int width, height;
    int code = cli_image_size(&program, s, p->scene, &width, &height);
    if (code != CLI_CONTINUE)
        return code;
    if (rt_scene_check_precision(p->scene, s->render.precision, &error) !=
            RT_OK ||
        rt_image_save_check(p->output, &error) != RT_OK) {
        fprintf(stderr, "rt-export-mpi: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    return CLI_CONTINUE;
}

/* Every rank: rank 0's verdict, then the scene's bytes and those of the
 * files it names, parsed on the other ranks into the scene rank 0 built
 * (its digest compared).  Returns CLI_CONTINUE with p->scene set on every
 * rank, or the exit status every rank returns. */
static int share_scene(cli_settings *s, plan *p, int rank)
{
    long long header[2] = {CLI_CONTINUE, 0};
    if (rank == 0) {
        header[0] = prepare(s, p);
        header[1] = (long long)p->text.length;
    }
    MPI_Bcast(header, 2, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
    if (header[0] != CLI_CONTINUE)
        return (int)header[0];
    if (rank != 0) {
        p->text.length = (size_t)header[1];
        p->text.bytes = malloc(p->text.length + 1);
        p->text.name = strcmp(s->operands[0], "-") ? s->operands[0]
                                                   : "<stdin>";
        if (p->text.bytes == NULL) {
            fprintf(stderr, "rt-export-mpi: rank %d: out of memory\n", rank);
            MPI_Abort(MPI_COMM_WORLD, EXIT_BAD_INPUT);
        }
    }
    /* <= RT_MAX_SCENE_BYTES (1 GiB): one count fits an int */
    MPI_Bcast(p->text.bytes, (int)p->text.length, MPI_BYTE, 0,
              MPI_COMM_WORLD);
    share_broadcast(&p->files, rank, MPI_COMM_WORLD);
    int failed = 0;
    if (rank != 0) {
        rt_error error;
        rt_load_options load = s->load;
        load.resolve = share_serve;
        load.resolve_user = &p->files;
        if (rt_scene_parse_with(p->text.bytes, p->text.length, p->text.name,
                                &load, &p->scene, &error) != RT_OK) {
            fprintf(stderr, "rt-export-mpi: rank %d: %s\n", rank,
                    error.message);
            failed = 1;
        }
    }
    /* The same bytes, the same options: the same scene, unless the ranks
     * run different programs or were given different command lines. */
    unsigned long long digest = p->scene ? share_digest(p->scene) : 0;
    unsigned long long expected = digest;
    MPI_Bcast(&expected, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    if (rank != 0 && !failed && digest != expected) {
        fprintf(stderr, "rt-export-mpi: rank %d: %s: the scene this rank "
                        "built from rank 0's bytes is not rank 0's (digest "
                        "%016llx, rank 0's %016llx): the ranks run different "
                        "programs or command lines; nothing is rendered\n",
                rank, p->text.name, digest, expected);
        failed = 1;
    }
    MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX,
                  MPI_COMM_WORLD);
    return failed ? EXIT_BAD_INPUT : CLI_CONTINUE;
}

/* The render every rank does. */
static farm_job make_job(const plan *p, const cli_settings *s, int ranks)
{
    farm_job job = {p->scene, s->render, s->render.region, band_rows_option};
    rt_render_options whole = s->render;
    whole.region = (rt_region){0, 0, 0, 0};
    int width = 0, height = 0;
    rt_render_image_size(p->scene, &whole, &width, &height, NULL);
    rt_region r = s->render.region;
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

/* --stats: a line a rank, and how even the ranks' work was. */
static void print_ranks(const farm_job *job, const farm_rank_report *reports,
                        int ranks)
{
    double most = 0, total = 0, first = -1, last = 0;
    for (int rank = 0; rank < ranks; rank++) {
        const farm_rank_report *r = &reports[rank];
        fprintf(stderr, "rt-export-mpi: rank %d: %d bands, %d rows, %.3f s "
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
    fprintf(stderr, "rt-export-mpi: %d ranks, bands of %d rows; imbalance "
                    "%.3f (the busiest rank's time over the mean); the last "
                    "rank finished %.3f s after the first\n", ranks,
            job->band_rows, total > 0 ? most * ranks / total : 1.0,
            first < 0 ? 0.0 : last - first);
}

/* Rank 0: serves the bands, then saves the image.  Returns the exit
 * status; a failed render aborts the job. */
static int render_and_save(const farm_job *job, cli_settings *s,
                           const plan *p, int ranks)
{
    cli_render_report report = {
        .program = "rt-export-mpi", .scene = p->text.name,
        .output = p->output, .format = s->format, .settings = s,
        .load_seconds = p->load_seconds,
        .width = job->area.x1 - job->area.x0,
        .height = job->area.y1 - job->area.y0};
    rt_render_options whole = s->render;
    whole.region = (rt_region){0, 0, 0, 0};
    rt_render_image_size(p->scene, &whole, &report.full_width,
                         &report.full_height, NULL);
    rt_image image = {0};
    farm_rank_report *reports = calloc((size_t)ranks, sizeof *reports);
    if (reports == NULL ||
        rt_image_init(&image, report.width, report.height, NULL) != RT_OK) {
        fprintf(stderr, "rt-export-mpi: out of memory\n");
        MPI_Abort(MPI_COMM_WORLD, EXIT_BAD_INPUT);
    }
    int progress_on = !s->quiet && (s->progress || isatty(STDERR_FILENO));
    cli_progress progress;
    cli_progress_start(&progress, stderr, isatty(STDERR_FILENO), p->text.name,
                       report.height, report.width, s->render.samples);
    double start = cli_clock_seconds();
    rt_status status = farm_serve(job, MPI_COMM_WORLD, &image,
                                  progress_on ? count_rows : NULL, &progress,
                                  reports);
    double seconds = cli_seconds_since(start);
    cli_progress_end(&progress);
    if (status != RT_OK) {
        fprintf(stderr, "rt-export-mpi: %s: rendering failed: %s\n",
                p->text.name, rt_status_string(status));
        MPI_Abort(MPI_COMM_WORLD, EXIT_BAD_INPUT);
    }
    /* every band is in: only now is anything written */
    rt_render_stats stats;
    memset(&stats, 0, sizeof stats);
    for (int rank = 0; rank < ranks; rank++)
        farm_stats_add(&stats, &reports[rank].stats);
    stats.seconds = seconds;
    double write_start = cli_clock_seconds();
    rt_error error;
    /* hours of work may be in the image: a save that fails keeps it under
     * another name (a signal, the user's wish to stop, keeps nothing) */
    int code = EXIT_BAD_INPUT;
    if (cli_refuse_input_as_output("rt-export-mpi", p->output, p->scene,
                                   s->operands[0], "the image")) {
        cli_keep_image("rt-export-mpi", p->output, &image, s->format);
    } else if ((status = rt_image_save(p->output, &image, s->format,
                                       &error)) != RT_OK) {
        fprintf(stderr, "rt-export-mpi: %s\n", error.message);
        if (status != RT_ERR_INTERRUPTED)
            cli_keep_image("rt-export-mpi", p->output, &image, s->format);
    } else {
        report.write_seconds = cli_seconds_since(write_start);
        if (s->stats != CLI_STATS_NONE)
            print_ranks(job, reports, ranks);
        if (s->stats == CLI_STATS_TEXT)
            cli_print_stats_text(stderr, &stats, &report);
        else if (s->stats == CLI_STATS_JSON)
            cli_print_stats_json(stderr, &stats, &report);
        printf("%s\n", p->output);
        code = EXIT_SUCCESS;
    }
    rt_image_release(&image);
    free(reports);
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

int main(int argc, char **argv)
{
    int provided, rank, ranks;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (provided < MPI_THREAD_FUNNELED && rank == 0)
        fprintf(stderr, "rt-export-mpi: warning: this MPI gives no thread "
                        "support; rank 0 renders anyway on a thread that "
                        "makes no MPI call\n");
    cli_settings s;
    plan p;
    memset(&p, 0, sizeof p);
    int code = parse_everywhere(argc, argv, &s, rank);
    if (code == CLI_CONTINUE) {
        fit_threads(&s, rank);
        code = share_scene(&s, &p, rank);
    }
    if (code == CLI_CONTINUE) {
        farm_job job = make_job(&p, &s, ranks);
        if (rank == 0) {
            code = render_and_save(&job, &s, &p, ranks);
        } else {
            farm_work(&job, MPI_COMM_WORLD);
            code = EXIT_SUCCESS;
        }
    }
    rt_scene_destroy(p.scene);
    share_free(&p.files);
    free(p.text.bytes);
    free(p.default_path);
    MPI_Finalize();
    return code;
}
