/*
 * report.h - the rows of rt-bench's report: one measured
 * configuration each, printed as a table, written to and read back from a
 * CSV file, and compared with the rows of an earlier run.
 *
 * The CSV has a header line and one line per row, comma-separated, no
 * quoting (labels never hold commas); numbers are written with %.6g, so a
 * value read back and written again gives the same text.  Thread-safe on
 * distinct files.
 */
#ifndef RT_BENCH_REPORT_H
#define RT_BENCH_REPORT_H

#include <stdio.h>

#include "metrics.h"
#include "raytrace/render.h"

typedef struct bench_row {
    char label[48];         /* "float+fast d2 16s" (see rt-bench --help) */
    char varies[16];        /* default, precision, sqrt, samples, depth,
                               combination: the knobs that differ from the
                               default render */
    rt_precision precision;
    int fast_sqrt;
    int samples;            /* rays per pixel */
    rt_sampling sampling;
    int depth;
    int runs;
    double median, minimum, maximum;    /* render time, seconds */
    bench_error total;      /* against the converged reference */
    bench_error numerical;  /* against the same settings in double with
                               the exact square root */
    int on_front;           /* on the Pareto front of (median, total RMSE) */
} bench_row;

/* The table of the report, one line per row, in the given order. */
void bench_print_table(FILE *file, const bench_row *rows, int count);

/* Writes the CSV (header and rows); `scene`, width and height go in every
 * line.  Returns 1 on success, 0 if writing failed. */
int bench_write_csv(FILE *file, const char *scene, int width, int height,
                    const bench_row *rows, int count);

/* Reads a CSV that bench_write_csv wrote into a new array (free() it).
 * Returns the number of rows, or -1 when the file cannot be read or is not
 * such a CSV (a message naming the file and line goes to `message`). */
int bench_read_csv(const char *path, bench_row **rows, char *message,
                   size_t message_size);

/*
 * Compares this run's rows with an earlier run's, matched by label, and
 * prints the outcome: errors must be equal (renders are deterministic); a
 * median time agrees when it lies within the other run's min-max spread.
 * Returns 1 when every error matched and every label was found in both.
 */
int bench_compare_runs(FILE *file, const bench_row *now, int now_count,
                       const bench_row *before, int before_count);

#endif /* RT_BENCH_REPORT_H */
