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
 * is redrawn in place (a carriage return, the line, then ESC [ K to erase
 * what a longer line left) at most ten times a second, and only once the
 * render has taken half a second, fitted to the terminal's width
 * (cli_progress_fit, the width read again at each redraw); the final
 * state ends it with a newline.  Elsewhere (--progress into a file or a
 * pipe) nothing is written while the render runs, and one whole line at
 * its end.  Rates count camera rays only (pixels done x samples): the
 * library counts the other rays only at the end of the render.
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

/* Ends the progress: on a terminal, the final state of the line and a
 * newline when a line was shown; elsewhere the one final line, when any
 * row was counted. */
void cli_progress_end(cli_progress *progress);

/* The width assumed when the terminal does not give its own (0 columns,
 * or not a terminal the ioctl knows). */
#define CLI_PROGRESS_COLUMNS 80
/* The longest progress line, in bytes, NUL included. */
#define CLI_PROGRESS_LINE 1200

/*
 * The progress line "rendering NAME: F0, F1, ..." for a terminal of
 * `columns` columns (0 or less: CLI_PROGRESS_COLUMNS), into out[0..size)
 * (NUL-terminated).  It takes at most columns - 1 bytes, so that it never
 * reaches the last column and the terminal never wraps it (a byte is at
 * most one column: a UTF-8 name takes no more columns than bytes).  When
 * the whole line is wider, NAME is cut from the left, "..." then its end
 * ("...scenes/cubes.scn"), down to "..." and its file name; when even
 * that is too wide the fields go, the last one first (fields[0] always
 * stays), and then the file name is cut from the left too; a width below
 * even that cuts the line at the right edge.  A cut never splits a UTF-8
 * character.  `name` is shown as given (cli_printable it first).  Returns
 * the length written.  Thread-safe (no state).
 */
size_t cli_progress_fit(int columns, const char *name,
                        const char *const *fields, int count, char *out,
                        size_t size);

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
