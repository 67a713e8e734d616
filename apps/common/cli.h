/*
 * cli.h - the one command-line module of rt-export, rt-export-mpi,
 * rt-view, rt-bench and rt-convert.
 *
 * One table holds every shared option: its long name, its short letter,
 * the name of its argument, its limits and its one help text.  The parser
 * (getopt_long underneath, so every GNU form works: `--depth=2`,
 * `--depth 2`, `-oFILE`, `-o FILE`, bundled `-qj2`, unique prefixes such
 * as `--dep=2`, and `--` ending the options) and every program's `--help`
 * are both generated from it, so the programs accept, refuse and describe
 * an option in exactly the same words.  A program picks the groups of the
 * table it accepts (CLI_GROUP_...) and may add a table of its own options
 * (cli_option), parsed and described the same way.
 *
 * Usage errors are printed on stderr as
 *     PROG: --depth: expected an integer in 0..1000000, found 'x'
 *     Try 'PROG --help'.
 * (a value of the right form out of its limits: "found 2000000", the
 * number and the bound; cli_values.h reads every value with the scene
 * format's number grammar).
 * and cli_parse returns CLI_EXIT_USAGE (2).  Nothing here is thread-safe:
 * call it from main, once (getopt_long keeps global state).
 *
 * Typical use:
 *
 *     static const cli_program program = {
 *         "rt-export", "SCENE", "Renders SCENE to an image ...",
 *         "Exit status: 0 success, 1 ..., 2 bad usage.",
 *         CLI_GROUP_RENDER | CLI_GROUP_LOAD | CLI_GROUP_OUTPUT |
 *             CLI_GROUP_REPORT,
 *         extra_options, 1, 1, "expected a scene file"};
 *     cli_settings s;
 *     int code = cli_parse(&program, argc, argv, &s);
 *     if (code != CLI_CONTINUE)
 *         return code;          // 0 after --help or --version, 2 on misuse
 *     ... rt_scene_load(s.operands[0], &s.load, ...);
 *     ... s.render.on_row = ...; rt_render(scene, &s.render, &image, NULL);
 */
#ifndef RAYTRACE_CLI_H
#define RAYTRACE_CLI_H

#include <stdio.h>

#include "raytrace/raytrace.h"

#define CLI_CONTINUE (-1)       /* cli_parse: go on and do the work */
#define CLI_EXIT_USAGE 2        /* exit status of every usage error */

/* The one set of limits, the same in every program. */
#define CLI_MAX_DEPTH 1000000   /* --depth 0..CLI_MAX_DEPTH */
#define CLI_MAX_THREADS 1024    /* -j/--threads 0..CLI_MAX_THREADS */
#define CLI_MAX_SAMPLES 1024    /* --samples, a square in 1..CLI_MAX_SAMPLES */
#define CLI_MAX_LIGHTS 16       /* --light given at most this many times */
#define CLI_MAX_OPERANDS 8      /* arguments that are not options */

/* The groups of the table; a program accepts the union it passes. */
enum {
    CLI_GROUP_QUALITY = 1 << 0, /* --depth --precision --fast-sqrt
                                   --samples --sampling --kernel --accel */
    CLI_GROUP_LENS = 1 << 1,    /* --aperture --focus */
    CLI_GROUP_THREADS = 1 << 2, /* -j/--threads */
    CLI_GROUP_SIZE = 1 << 3,    /* --size --width --height */
    CLI_GROUP_REGION = 1 << 4,  /* --region */
    CLI_GROUP_INPUT = 1 << 5,   /* --input-format --tessellate */
    CLI_GROUP_CAMERA = 1 << 11, /* --look-from --look-at --up --fov
                                   --light */
    CLI_GROUP_OUTPUT = 1 << 6,  /* -o/--output --format */
    CLI_GROUP_REPORT = 1 << 7,  /* --stats[=text|json] --progress */
    CLI_GROUP_QUIET = 1 << 8,   /* -q/--quiet */
    CLI_GROUP_EXPLAIN = 1 << 9, /* --explain X,Y --explain-json */
    CLI_GROUP_VIEW = 1 << 10,   /* --view V[=L] (a debug view) */
    /* how the scene is read and viewed */
    CLI_GROUP_LOAD = CLI_GROUP_INPUT | CLI_GROUP_CAMERA,
    /* every render option: what rt-export and rt-view both take */
    CLI_GROUP_RENDER = CLI_GROUP_QUALITY | CLI_GROUP_LENS |
                       CLI_GROUP_THREADS | CLI_GROUP_SIZE | CLI_GROUP_REGION
};
/* -h/--help and --version are always accepted. */

/* What a program's own option holds (the value is checked against the
 * option's limits before it is stored). */
typedef enum cli_kind {
    CLI_FLAG,           /* no argument; *(int *)target = 1 */
    CLI_INT,            /* an integer in min..max into *(int *)target */
    CLI_SQUARE,         /* a square integer (1, 4, 9, ...) in min..max */
    CLI_NUMBER,         /* a finite number in [min, max) into *(double *)
                           (max itself allowed when it is infinite: no
                           upper limit) */
    CLI_STRING,         /* any text; *(const char **)target = the argv
                           string (not copied) */
    CLI_NUMBER_CLOSED   /* a finite number in [min, max], max included,
                           into *(double *) */
} cli_kind;

/* A program's own option.  A table of them ends with an entry whose
 * `name` is NULL: CLI_OPTIONS_END. */
typedef struct cli_option {
    const char *name;       /* long name without "--", e.g. "runs" */
    int short_name;         /* a letter, or 0 for none */
    const char *argument;   /* its name in the help, e.g. "N"; NULL for a
                               CLI_FLAG */
    cli_kind kind;
    double min, max;        /* limits of CLI_INT, CLI_SQUARE, CLI_NUMBER,
                               CLI_NUMBER_CLOSED */
    void *target;           /* where the value goes (see cli_kind) */
    const char *help;       /* one text, wrapped by cli_print_help */
} cli_option;

/* The entry that ends a table of a program's own options. */
#define CLI_OPTIONS_END {NULL, 0, NULL, CLI_FLAG, 0, 0, NULL, NULL}

/* A program: how it is described and what it accepts. */
typedef struct cli_program {
    const char *name;           /* "rt-export": the prefix of messages */
    const char *operands;       /* the usage line's operands, e.g. "SCENE" */
    const char *description;    /* paragraph(s) after the usage line */
    const char *epilogue;       /* after the options: exit status, ... */
    unsigned groups;            /* CLI_GROUP_... it accepts */
    const cli_option *extra;    /* its own options, or NULL */
    int min_operands, max_operands; /* how many operands it needs */
    const char *missing;        /* the message when operands are missing,
                                   e.g. "expected a scene file" */
} cli_program;

typedef enum cli_stats {
    CLI_STATS_NONE = 0,
    CLI_STATS_TEXT,         /* --stats or --stats=text */
    CLI_STATS_JSON          /* --stats=json */
} cli_stats;

/*
 * Everything the shared options set.  Fields of groups a program does not
 * accept keep their defaults.  `load.lights` points into `lights`: use
 * the struct where cli_parse filled it, do not copy it.
 */
typedef struct cli_settings {
    rt_render_options render;   /* rt_render_options_init, then --depth,
                                   -j, --precision, --fast-sqrt, --samples,
                                   --sampling, --kernel, --accel,
                                   --aperture, --focus, --size, --width,
                                   --height (0: the scene's), --region;
                                   on_row, user, stats, cancel stay NULL */
    rt_load_options load;       /* --input-format, --tessellate,
                                   --look-from, --look-at, --up, --fov,
                                   --light */
    rt_light lights[CLI_MAX_LIGHTS];
    const char *output;         /* -o/--output, NULL when not given */
    rt_image_format format;     /* --format, else from the extension of
                                   -o (checked), else RT_IMAGE_P6 */
    int format_given;           /* 1 when --format was given */
    cli_stats stats;            /* --stats[=text|json] */
    int progress;               /* 1: --progress (even off a terminal) */
    int quiet;                  /* 1: -q/--quiet (wins over --progress) */
    int explain;                /* 1: --explain X,Y was given */
    int explain_x, explain_y;   /* its pixel, in the output image */
    int explain_json;           /* 1: --explain-json */
    rt_debug_view view;         /* --view; 0 when not given */
    int view_light;             /* --view shadow=L or ns=L (default 0) */
    const char *operands[CLI_MAX_OPERANDS]; /* argv strings, in order */
    int operand_count;
} cli_settings;

/*
 * Parses argv (argv[0] is ignored; argv may be permuted, as getopt_long
 * does) into *settings, storing the program's own options through their
 * targets.  Returns CLI_CONTINUE, or an exit status: 0 after printing
 * --help or --version on stdout, CLI_EXIT_USAGE after printing the
 * message and "Try 'PROG --help'." on stderr.  Besides each option's own
 * limits it checks the number of operands, that --size/--width/--height
 * and --region fit RT_MAX_IMAGE_SIDE, and that -o's extension names a
 * format unless --format is given.
 */
int cli_parse(const cli_program *program, int argc, char **argv,
              cli_settings *settings);

/* The --help text of `program`, generated from the table (the groups it
 * accepts, then its own options), on `out`. */
void cli_print_help(const cli_program *program, FILE *out);

/*
 * Prints "PROG: MESSAGE\nTry 'PROG --help'.\n" on stderr (MESSAGE a
 * printf format) and returns CLI_EXIT_USAGE: for the checks a program
 * makes after cli_parse, e.g. "expected -o OUT with a scene read from
 * standard input".
 */
int cli_usage_error(const cli_program *program, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/*
 * The size of the image the render options give for `scene` (the region's
 * when one is set): rt_render_image_size, with a region or size that does
 * not fit the scene reported as a usage error ("PROG: --region: the region
 * 0,0,500,10 is not inside the 400 x 400 image ...").  Returns
 * CLI_CONTINUE with *width and *height set, or CLI_EXIT_USAGE.
 */
int cli_image_size(const cli_program *program, const cli_settings *settings,
                   const rt_scene *scene, int *width, int *height);

#endif /* RAYTRACE_CLI_H */
