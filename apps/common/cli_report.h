/*
 * cli_report.h - what the programs tell about a render while and after it
 * runs: the progress line (percentage, elapsed and remaining time, camera
 * rays per second) and the statistics, as text or as one JSON object
 * (docs/command-line.md lists its fields).  Shared by the command-line
 * programs so that they report a render in the same words.
 */
#ifndef RAYTRACE_CLI_REPORT_H
#define RAYTRACE_CLI_REPORT_H

#include <stdint.h>
#include <stdio.h>

#include "cli.h"
#include "cli_clock.h"

/*
 * The progress of one render, on `out` (stderr).  On a terminal the line
 * is rewritten in place (carriage return) at most ten times a second, and
 * only once the render has taken half a second; elsewhere (--progress
 * into a file or a pipe) a whole line is written about once a second.
 * Rates count camera rays only (pixels done x samples): the library
 * counts the other rays only at the end of the render.
 */
typedef struct cli_progress {
    FILE *out;
    const char *name;           /* the scene, as the messages name it */
    int terminal;               /* 1: rewrite the line in place */
    int rows, done;
    double rays_per_row;        /* width x samples */
    double start, last;         /* cli_clock_seconds readings */
    int shown;                  /* a line was written */
} cli_progress;

/* Starts the clock of a render of `rows` rows of `width` pixels with
 * `samples` rays each. */
void cli_progress_start(cli_progress *progress, FILE *out, int terminal,
                        const char *name, int rows, int width, int samples);

/* An rt_row_callback (user: the cli_progress): counts the row and
 * redraws the line when it is time.  Always returns 1 (never cancels). */
int cli_progress_row(void *user, int row);

/* Ends the line, if one was shown. */
void cli_progress_end(cli_progress *progress);

/* What a render was asked to do and where its time went, besides what
 * rt_render_stats counts. */
typedef struct cli_render_report {
    const char *program;        /* "rt-export" */
    const char *scene;          /* as messages name it ("<stdin>") */
    const char *output;         /* the path written, "-" for stdout */
    rt_image_format format;
    int full_width, full_height;    /* the whole image */
    int width, height;          /* the image written (the region's size) */
    const cli_settings *settings;
    double load_seconds, write_seconds;
    /* The process's peak resident memory in bytes (getrusage's
     * ru_maxrss) when the load ended and when the report is printed,
     * and the scene's facets (as in the file), for bytes per facet; 0:
     * not known (the line is left out). */
    uint64_t load_peak_bytes, peak_bytes;
    int facet_count;
} cli_render_report;

/* The process's peak resident memory so far, in bytes; 0 when the system
 * does not say. */
uint64_t cli_peak_bytes(void);

/* The statistics as lines of text, on `out`. */
void cli_print_stats_text(FILE *out, const rt_render_stats *stats,
                          const cli_render_report *report);

/* The statistics as one JSON object on one line, on `out`. */
void cli_print_stats_json(FILE *out, const rt_render_stats *stats,
                          const cli_render_report *report);

#endif /* RAYTRACE_CLI_REPORT_H */
