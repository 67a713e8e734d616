/*
 * cli.c - the one command-line module (see cli.h).  The shared options are
 * one table of values: each entry says where its value goes in
 * cli_settings (an offset), what kind of value it is and its limits, so
 * that parsing, checking, the error message and the --help line of an
 * option all come from the same entry.  A program's own options
 * (cli_option) are turned into entries of the same form, with a pointer
 * instead of an offset.
 */
#include "cli.h"

#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli_text.h"
#include "cli_values.h"

#define MAX_SPECS 64
#define FIRST_ID 256            /* getopt_long values of the entries */
#define HELP_COLUMN 24          /* where help texts start */
#define HELP_WIDTH 79           /* where they wrap */
#define NO_OFFSET SIZE_MAX
#define SHOWN 512               /* a value in a message, escaped */

typedef enum value_kind {
    V_FLAG,         /* int = 1 */
    V_INT,          /* int in [min, max] */
    V_SQUARE,       /* square int in [min, max] */
    V_NUMBER,       /* double in the interval min..max (see bounds) */
    V_CHOICE,       /* int = values[i] for the i-th name of `choices` */
    V_STRING,       /* const char * */
    V_POINT,        /* rt_vec3 */
    V_LIGHT,        /* appended to lights[], load.light_count */
    V_SIZE,         /* WxH into render.width, render.height */
    V_REGION,       /* x0,y0,x1,y1 into render.region */
    V_PIXEL,        /* x,y into explain_x, explain_y */
    V_VIEW          /* name[=light] into view, view_light */
} value_kind;

/* One option: the table's entry, resolved to addresses at parse time. */
typedef struct spec {
    unsigned group;         /* 0: a program's own option */
    const char *name;
    int short_name;
    const char *argument;   /* NULL: none */
    int optional;           /* 1: `--name` or `--name=VALUE` */
    value_kind kind;
    double min, max;
    unsigned bounds;        /* V_NUMBER: CLI_BOUND_... (cli_values.h),
                               which ends are in the interval */
    const char *choices;    /* V_CHOICE: "a|b|c" */
    int values[12];         /* V_CHOICE: the value of each choice */
    size_t offset;          /* into cli_settings, or NO_OFFSET */
    size_t given;           /* int set to 1 when given, or NO_OFFSET */
    void *target;           /* a program's option: where its value goes */
    const char *help;
} spec;

#define AT(field) offsetof(cli_settings, field)
#define INF HUGE_VAL

/* The table.  Its order is the order of --help. */
static const spec table[] = {
    {CLI_GROUP_QUALITY, "depth", 0, "N", 0, V_INT, 0, CLI_MAX_DEPTH, 0,
     NULL, {0}, AT(render.max_depth), NO_OFFSET, NULL,
     "reflections followed after a primary ray (default 5)"},
    {CLI_GROUP_THREADS, "threads", 'j', "N", 0, V_INT, 0, CLI_MAX_THREADS,
     0, NULL, {0}, AT(render.threads), NO_OFFSET, NULL,
     "rendering threads; 0 = one per core (default 0)"},
    {CLI_GROUP_QUALITY, "precision", 0, "P", 0, V_CHOICE, 0, 0, 0,
     "double|float", {RT_PRECISION_DOUBLE, RT_PRECISION_FLOAT},
     AT(render.precision), NO_OFFSET, NULL,
     "arithmetic of the renderer: double (the reference, default) or "
     "float (faster, less accurate)"},
    {CLI_GROUP_QUALITY, "fast-sqrt", 0, NULL, 0, V_FLAG, 0, 0, 0, NULL,
     {0}, AT(render.fast_inv_sqrt), NO_OFFSET, NULL,
     "normalise vectors with the handout's fastInvSqrt"},
    {CLI_GROUP_QUALITY, "samples", 0, "N", 0, V_SQUARE, 1, CLI_MAX_SAMPLES,
     0, NULL, {0}, AT(render.samples), NO_OFFSET, NULL,
     "rays per pixel, a square (1, 4, 9, ...; default 1: one ray through "
     "the pixel's centre)"},
    {CLI_GROUP_QUALITY, "sampling", 0, "S", 0, V_CHOICE, 0, 0, 0,
     "regular|stratified", {RT_SAMPLING_REGULAR, RT_SAMPLING_STRATIFIED},
     AT(render.sampling), NO_OFFSET, NULL,
     "where a pixel's rays go: regular (grid centres, default) or "
     "stratified (one random point in each grid cell, the same every run)"},
    {CLI_GROUP_LENS, "aperture", 0, "A", 0, V_NUMBER, 0, INF, 0, NULL, {0},
     AT(render.aperture), NO_OFFSET, NULL,
     "lens radius >= 0 in scene units for depth of field (default: the "
     "scene's, else 0: a pinhole camera); smooth only with several "
     "samples per pixel"},
    {CLI_GROUP_LENS, "focus", 0, "F", 0, V_NUMBER, 0, INF,
     CLI_BOUND_OPEN_MIN, NULL, {0},
     AT(render.focal_distance), NO_OFFSET, NULL,
     "the distance in focus > 0, in scene units along the view axis "
     "(default: the scene's, else |AO|)"},
    {CLI_GROUP_QUALITY, "kernel", 0, "K", 0, V_CHOICE, 0, 0, 0,
     "auto|scalar", {RT_KERNEL_AUTO, RT_KERNEL_SCALAR}, AT(render.kernel),
     NO_OFFSET, NULL,
     "auto (default: the fastest loops this processor runs) or scalar "
     "(one facet at a time); the image is the same"},
    {CLI_GROUP_QUALITY, "accel", 0, "A", 0, V_CHOICE, 0, 0, 0,
     "auto|none|octree|kdtree",
     {RT_ACCEL_AUTO, RT_ACCEL_NONE, RT_ACCEL_OCTREE, RT_ACCEL_KDTREE},
     AT(render.accel), NO_OFFSET, NULL,
     "auto (default: an octree from 300 facets on), none (every ray tests "
     "every facet), octree or kdtree (built by the surface area "
     "heuristic); the image is the same"},
    {CLI_GROUP_SIZE, "size", 0, "WxH", 0, V_SIZE, 1, RT_MAX_IMAGE_SIDE, 0,
     NULL, {0}, NO_OFFSET, NO_OFFSET, NULL,
     "the image's size in pixels instead of the scene's; the screen keeps "
     "its width and pixels stay square, so another shape shows more or "
     "less of the scene above and below"},
    {CLI_GROUP_SIZE, "width", 0, "N", 0, V_INT, 1, RT_MAX_IMAGE_SIDE, 0,
     NULL, {0}, AT(render.width), NO_OFFSET, NULL,
     "the image's width; alone, it keeps the scene's height (as POV-Ray's "
     "+W)"},
    {CLI_GROUP_SIZE, "height", 0, "N", 0, V_INT, 1, RT_MAX_IMAGE_SIDE, 0,
     NULL, {0}, AT(render.height), NO_OFFSET, NULL,
     "the image's height; alone, it keeps the scene's width (as POV-Ray's "
     "+H)"},
    {CLI_GROUP_REGION, "region", 0, "X0,Y0,X1,Y1", 0, V_REGION, 0,
     RT_MAX_IMAGE_SIDE, 0, NULL, {0}, NO_OFFSET, NO_OFFSET, NULL,
     "render only columns X0 <= x < X1 and rows Y0 <= y < Y1 of the whole "
     "image (pixels, (0,0) top left); the output holds just that region, "
     "with exactly the pixels the whole image has there"},
    {CLI_GROUP_INPUT, "input-format", 0, "F", 0, V_CHOICE, 0, 0, 0,
     "scn|nff|obj|ply",
     {RT_SCENE_FORMAT_SCN, RT_SCENE_FORMAT_NFF, RT_SCENE_FORMAT_OBJ,
      RT_SCENE_FORMAT_PLY},
     AT(load.format), NO_OFFSET, NULL,
     "read the scene as scn, nff, obj or ply, whatever its extension says"},
    {CLI_GROUP_INPUT, "tessellate", 0, "T", 0, V_NUMBER, 0, 1,
     CLI_BOUND_OPEN_MIN, NULL, {0},
     AT(load.tessellation), NO_OFFSET, NULL,
     "NFF spheres and cones: the largest distance between the surface and "
     "its facets, relative to the radius; more than 0, less than 1"},
    {CLI_GROUP_CAMERA, "look-from", 0, "X,Y,Z", 0, V_POINT, 0,
     RT_MAX_COORDINATE, 0, NULL,
     {0}, AT(load.look_from), AT(load.look_from_given), NULL,
     "the observer (each view option on its own replaces that part of the "
     "scene's camera)"},
    {CLI_GROUP_CAMERA, "look-at", 0, "X,Y,Z", 0, V_POINT, 0,
     RT_MAX_COORDINATE, 0, NULL, {0},
     AT(load.look_at), AT(load.look_at_given), NULL,
     "the point the screen is centred on"},
    {CLI_GROUP_CAMERA, "up", 0, "X,Y,Z", 0, V_POINT, 0, INF, 0, NULL, {0},
     AT(load.up), AT(load.up_given), NULL, "up in the image"},
    {CLI_GROUP_INPUT, "up-axis", 0, "AXIS", 0, V_CHOICE, 0, 0, 0,
     "auto|x|y|z|-x|-y|-z|+x|+y|+z",
     {RT_UP_AUTO, RT_UP_X, RT_UP_Y, RT_UP_Z, RT_UP_NEG_X, RT_UP_NEG_Y,
      RT_UP_NEG_Z, RT_UP_X, RT_UP_Y, RT_UP_Z},
     AT(load.up_axis), NO_OFFSET, NULL,
     "OBJ and PLY: the model's up for the automatic camera (default auto: "
     "a comment's, else +y)"},
    {CLI_GROUP_CAMERA, "fov", 0, "DEGREES", 0, V_NUMBER, 0, 180,
     CLI_BOUND_OPEN_MIN, NULL, {0},
     AT(load.fov), AT(load.fov_given), NULL,
     "the horizontal field of view in degrees; more than 0, less than "
     "180"},
    {CLI_GROUP_CAMERA, "light", 0, "X,Y,Z[,R,G,B]", 0, V_LIGHT, 0, 0, 0, NULL,
     {0}, NO_OFFSET, NO_OFFSET, NULL,
     "a point light, white unless R,G,B (0..255) say otherwise; repeat "
     "for several (at most 16); they replace the scene's lights (an OBJ's "
     "default light included)"},
    {CLI_GROUP_OUTPUT, "output", 'o', "OUT", 0, V_STRING, 0, 0, 0, NULL,
     {0}, AT(output), NO_OFFSET, NULL,
     "where to write the image"},
    {CLI_GROUP_OUTPUT, "format", 0, "F", 0, V_CHOICE, 0, 0, 0, "p6|p3|png|pfm|exr",
     {RT_IMAGE_P6, RT_IMAGE_P3, RT_IMAGE_PNG, RT_IMAGE_PFM, RT_IMAGE_EXR},
     AT(format),
     AT(format_given), NULL,
     "p6 (binary PPM), p3 (ASCII PPM, the course's format), png, or "
     "pfm, exr (linear floats, 1.0 = 255); default: from the extension "
     "of OUT (.png, .pfm, .exr; .ppm and .pnm p6; another is an error), "
     "p6 when OUT has none"},
    {CLI_GROUP_REPORT, "stats", 0, "FORMAT", 1, V_CHOICE, 0, 0, 0,
     "text|json", {CLI_STATS_TEXT, CLI_STATS_JSON}, AT(stats), NO_OFFSET,
     NULL,
     "after the render, print the work done (rays, tests, time) on "
     "stderr: as text (the default) or as one JSON object"},
    {CLI_GROUP_REPORT, "progress", 0, NULL, 0, V_FLAG, 0, 0, 0, NULL, {0},
     AT(progress), NO_OFFSET, NULL,
     "show the progress line even when stderr is not a terminal"},
    {CLI_GROUP_QUIET, "quiet", 'q', NULL, 0, V_FLAG, 0, 0, 0, NULL, {0},
     AT(quiet), NO_OFFSET, NULL, "no progress line"},
    {CLI_GROUP_EXPLAIN, "explain", 0, "X,Y", 0, V_PIXEL, 0,
     RT_MAX_IMAGE_SIDE, 0, NULL, {0}, NO_OFFSET, AT(explain), NULL,
     "instead of the image, print on stdout the ray tree of pixel X,Y of "
     "the image (every ray, what it hits, N.S, E and the blocking facet "
     "with its line, each term of the formula and their sum, the byte it "
     "rounds to); docs/teaching.md"},
    {CLI_GROUP_EXPLAIN, "explain-json", 0, NULL, 0, V_FLAG, 0, 0, 0, NULL,
     {0}, AT(explain_json), NO_OFFSET, NULL,
     "with --explain: the tree as one JSON object"},
    {CLI_GROUP_VIEW, "view", 0, "V", 0, V_VIEW, 0, CLI_MAX_LIGHTS - 1, 0,
     NULL, {0}, NO_OFFSET, NO_OFFSET, NULL,
     "write a debug view instead of the image: normal, depth, facet, "
     "shadow[=L] (E of light L, default 0), bounces, ns[=L] (N.S) or "
     "shading-normal; "
     "docs/teaching.md says how to read each"},
};

static const struct {
    unsigned group;
    const char *title;
} headings[] = {
    {CLI_GROUP_QUALITY | CLI_GROUP_LENS | CLI_GROUP_THREADS, "Rendering:"},
    {CLI_GROUP_SIZE | CLI_GROUP_REGION, "Image size and region:"},
    {CLI_GROUP_LOAD, "Scene, view and lights:"},
    {CLI_GROUP_OUTPUT, "Output:"},
    {CLI_GROUP_REPORT | CLI_GROUP_QUIET, "Reports:"},
    {CLI_GROUP_EXPLAIN | CLI_GROUP_VIEW, "Teaching:"},
};

/* ------------------------------------------------------------------ */
/* Messages                                                            */

static int vusage_error(const cli_program *program, const char *format,
                        va_list args)
{
    fprintf(stderr, "%s: ", program->name);
    vfprintf(stderr, format, args);
    fprintf(stderr, "\nTry '%s --help'.\n", program->name);
    return CLI_EXIT_USAGE;
}

int cli_usage_error(const cli_program *program, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    int code = vusage_error(program, format, args);
    va_end(args);
    return code;
}

/* "--name: expected WHAT, found 'VALUE'" */
static int value_error(const cli_program *program, const spec *s,
                       const char *what, const char *value)
{
    char shown[SHOWN];
    return cli_usage_error(program, "--%s: expected %s, found '%s'", s->name,
                           what, cli_printable(value, shown, sizeof shown));
}

/* "a, b or c" from "a|b|c". */
static void choice_list(const char *choices, char *out, size_t size)
{
    int count = 1;
    for (const char *c = choices; *c; c++)
        count += *c == '|';
    size_t used = 0;
    int index = 0;
    for (const char *c = choices; *c && used + 5 < size; c++) {
        if (*c != '|') {
            out[used++] = *c;
            continue;
        }
        index++;
        const char *joint = index == count - 1 ? " or " : ", ";
        used += (size_t)snprintf(out + used, size - used, "%s", joint);
    }
    out[used < size ? used : size - 1] = '\0';
}

/* ------------------------------------------------------------------ */
/* Values                                                              */

/* The message for a value a cli_values reader refused: the text as typed
 * when it is not of the value's form; else the number found (and the text
 * it was read from, when that reads otherwise) and the limit it broke. */
static int problem_error(const cli_program *program, const spec *s,
                         const char *value, cli_read read,
                         const cli_problem *problem)
{
    if (read == CLI_READ_SYNTAX)
        return value_error(program, s, problem->expected, value);
    char number[64];
    cli_format_number(problem->value, number, sizeof number);
    if (strlen(number) == problem->piece_length &&
        memcmp(number, problem->piece, problem->piece_length) == 0)
        return cli_usage_error(program, "--%s: expected %s, found %s",
                               s->name, problem->expected, number);
    char piece[SHOWN], shown[SHOWN];
    snprintf(piece, sizeof piece, "%.*s", (int)problem->piece_length,
             problem->piece);
    return cli_usage_error(program, "--%s: expected %s, found %s ('%s')",
                           s->name, problem->expected, number,
                           cli_printable(piece, shown, sizeof shown));
}

/* Case-insensitive: --format P6 is --format p6. */
static int read_choice(const spec *s, const char *text, int *value)
{
    const char *name = s->choices;
    for (int i = 0; *name; i++) {
        size_t length = strcspn(name, "|");
        if (length == strlen(text) && strncasecmp(name, text, length) == 0) {
            *value = s->values[i];
            return 1;
        }
        name += length + (name[length] == '|');
    }
    return 0;
}

/* "name" or "name=L" of a debug view; the light only for shadow and ns. */
static int read_view(const char *text, int max_light, rt_debug_view *view,
                     int *light)
{
    static const struct {
        const char *name;
        rt_debug_view view;
    } views[] = {{"normal", RT_VIEW_NORMAL}, {"depth", RT_VIEW_DEPTH},
                 {"facet", RT_VIEW_FACET},   {"shadow", RT_VIEW_SHADOW},
                 {"bounces", RT_VIEW_BOUNCES}, {"ns", RT_VIEW_NS},
                 {"shading-normal", RT_VIEW_SHADING_NORMAL}};
    const char *equals = strchr(text, '=');
    size_t length = equals != NULL ? (size_t)(equals - text) : strlen(text);
    for (size_t i = 0; i < sizeof views / sizeof *views; i++) {
        if (strlen(views[i].name) != length ||
            strncmp(text, views[i].name, length) != 0)
            continue;
        *light = 0;
        cli_problem unused;
        if (equals != NULL &&
            ((views[i].view != RT_VIEW_SHADOW && views[i].view != RT_VIEW_NS)
             || cli_read_integer(equals + 1, 0, max_light, 0, light,
                                 &unused) != CLI_READ_OK))
            return 0;
        *view = views[i].view;
        return 1;
    }
    return 0;
}

static int store_light(const cli_program *program, const spec *s,
                       cli_settings *settings, const char *value)
{
    char shown[SHOWN];
    if (settings->load.light_count == CLI_MAX_LIGHTS)
        return cli_usage_error(program, "--light: expected at most %d "
                               "lights, found another: '%s'",
                               CLI_MAX_LIGHTS,
                               cli_printable(value, shown, sizeof shown));
    cli_problem problem;
    cli_read read = cli_read_light(
        value, &settings->lights[settings->load.light_count], &problem);
    if (read != CLI_READ_OK)
        return problem_error(program, s, value, read, &problem);
    settings->load.light_count++;
    settings->load.lights = settings->lights;
    return CLI_CONTINUE;
}

/* Checks `value` against the entry's limits and stores it. */
static int store(const cli_program *program, const spec *s,
                 cli_settings *settings, const char *value)
{
    char what[128];
    void *target = s->target;
    cli_problem problem;
    cli_read read = CLI_READ_OK;
    switch (s->kind) {
    case V_FLAG:
        *(int *)target = 1;
        return CLI_CONTINUE;
    case V_INT:
    case V_SQUARE:
        read = cli_read_integer(value, s->min, s->max, s->kind == V_SQUARE,
                                (int *)target, &problem);
        break;
    case V_NUMBER:
        read = cli_read_real(value, s->min, s->max, s->bounds,
                             (double *)target, &problem);
        break;
    case V_CHOICE:
        if (value == NULL) { /* an optional argument left out */
            *(int *)target = s->values[0];
            return CLI_CONTINUE;
        }
        if (read_choice(s, value, (int *)target))
            return CLI_CONTINUE;
        choice_list(s->choices, what, sizeof what);
        return value_error(program, s, what, value);
    case V_STRING:
        *(const char **)target = value;
        return CLI_CONTINUE;
    case V_POINT:
        read = cli_read_point(value, s->max, (rt_vec3 *)target, &problem);
        break;
    case V_LIGHT:
        return store_light(program, s, settings, value);
    case V_SIZE:
        read = cli_read_size(value, (int)s->max, &settings->render.width,
                             &settings->render.height, &problem);
        break;
    case V_REGION:
        read = cli_read_region(value, (int)s->max, &settings->render.region,
                               &problem);
        break;
    case V_PIXEL:
        read = cli_read_pixel(value, (int)s->max, &settings->explain_x,
                              &settings->explain_y, &problem);
        break;
    case V_VIEW:
        if (read_view(value, (int)s->max, &settings->view,
                      &settings->view_light))
            return CLI_CONTINUE;
        snprintf(what, sizeof what, "normal, depth, facet, shadow[=L], "
                 "bounces, ns[=L] (L in 0..%.0f) or shading-normal",
                 s->max);
        return value_error(program, s, what, value);
    }
    if (read != CLI_READ_OK)
        return problem_error(program, s, value, read, &problem);
    return CLI_CONTINUE;
}

/* ------------------------------------------------------------------ */
/* The program's table                                                 */

/* The entries `program` accepts, resolved to addresses in `settings`. */
static int collect(const cli_program *program, cli_settings *settings,
                   spec *specs)
{
    int count = 0;
    for (size_t i = 0; i < sizeof table / sizeof *table; i++) {
        if (!(table[i].group & program->groups))
            continue;
        spec *s = &specs[count++];
        *s = table[i];
        if (s->offset != NO_OFFSET)
            s->target = (char *)settings + s->offset;
    }
    for (const cli_option *o = program->extra; o && o->name; o++) {
        static const value_kind kinds[] = {V_FLAG, V_INT, V_SQUARE, V_NUMBER,
                                           V_STRING, V_NUMBER};
        if (count == MAX_SPECS)
            break;
        unsigned bounds = o->kind == CLI_NUMBER_CLOSED ? CLI_BOUND_CLOSED_MAX
                                                       : 0;
        specs[count++] = (spec){0, o->name, o->short_name, o->argument, 0,
                                kinds[o->kind], o->min, o->max, bounds, NULL,
                                {0}, NO_OFFSET, NO_OFFSET, o->target,
                                o->help};
    }
    return count;
}

static void set_defaults(cli_settings *settings)
{
    memset(settings, 0, sizeof *settings);
    rt_render_options_init(&settings->render);
    rt_load_options_init(&settings->load);
    settings->format = RT_IMAGE_P6;
}

/* Builds getopt_long's tables from the entries. */
static void getopt_tables(const spec *specs, int count,
                          struct option *longs, char *shorts)
{
    size_t used = 0;
    shorts[used++] = ':'; /* a missing argument returns ':' */
    for (int i = 0; i < count; i++) {
        int has_arg = specs[i].argument == NULL ? no_argument
                      : specs[i].optional       ? optional_argument
                                                : required_argument;
        longs[i] = (struct option){specs[i].name, has_arg, NULL,
                                   FIRST_ID + i};
        if (specs[i].short_name) {
            shorts[used++] = (char)specs[i].short_name;
            if (has_arg == required_argument)
                shorts[used++] = ':';
        }
    }
    longs[count] = (struct option){"help", no_argument, NULL, 'h'};
    longs[count + 1] = (struct option){"version", no_argument, NULL, 1};
    longs[count + 2] = (struct option){NULL, 0, NULL, 0};
    shorts[used++] = 'h';
    shorts[used] = '\0';
}

/* The entry getopt_long's answer `c` names, or NULL. */
static const spec *spec_of(const spec *specs, int count, int c)
{
    if (c >= FIRST_ID && c < FIRST_ID + count)
        return &specs[c - FIRST_ID];
    for (int i = 0; i < count; i++)
        if (specs[i].short_name == c)
            return &specs[i];
    return NULL;
}

/* The option getopt_long could not use, as the user wrote it. */
static int getopt_error(const cli_program *program, const spec *specs,
                        int count, int c, char **argv)
{
    const char *arg = argv[optind - 1];
    char shown[SHOWN];
    if (c == ':') {
        const spec *s = spec_of(specs, count, optopt);
        return cli_usage_error(program, "--%s: expected a value (%s)",
                               s ? s->name : "?", s ? s->argument : "?");
    }
    const spec *s = spec_of(specs, count, optopt);
    if (s != NULL && optopt >= FIRST_ID) /* --fast-sqrt=1 */
        return cli_usage_error(program, "--%s: takes no value, found '%s'",
                               s->name, cli_printable(arg, shown,
                                                      sizeof shown));
    if (optopt != 0)
        return cli_usage_error(program, "unknown option '-%c'", optopt);
    char name[SHOWN];
    snprintf(name, sizeof name, "%.*s", (int)strcspn(arg, "="), arg);
    return cli_usage_error(program, "unknown or ambiguous option '%s'",
                           cli_printable(name, shown, sizeof shown));
}

/* Checks made once every option is read. */
static int check_settings(const cli_program *program, cli_settings *settings)
{
    if (settings->operand_count < program->min_operands)
        return cli_usage_error(program, "%s", program->missing
                                                  ? program->missing
                                                  : "expected an operand");
    const char *out = settings->output;
    char shown[SHOWN];
    if (out != NULL && !settings->format_given) {
        const char *slash = strrchr(out, '/');
        const char *base = slash ? slash + 1 : out;
        const char *dot = strrchr(base, '.');
        if (dot != NULL && dot != base &&
            rt_image_format_from_path(out, &settings->format, NULL) != RT_OK)
            return cli_usage_error(program, "cannot tell the image format "
                                   "from the name '%s': expected .png, "
                                   ".ppm, .pnm, .pfm or .exr, or --format "
                                   "p3, p6, png, pfm or exr",
                                   cli_printable(out, shown, sizeof shown));
    }
    return CLI_CONTINUE;
}

static int add_operand(const cli_program *program, cli_settings *settings,
                       const char *operand)
{
    char shown[SHOWN];
    if (settings->operand_count >= program->max_operands ||
        settings->operand_count == CLI_MAX_OPERANDS)
        return cli_usage_error(program, "expected at most %d operand%s (%s),"
                               " found another: '%s'", program->max_operands,
                               program->max_operands == 1 ? "" : "s",
                               program->operands,
                               cli_printable(operand, shown, sizeof shown));
    settings->operands[settings->operand_count++] = operand;
    return CLI_CONTINUE;
}

int cli_parse(const cli_program *program, int argc, char **argv,
              cli_settings *settings)
{
    spec specs[MAX_SPECS];
    struct option longs[MAX_SPECS + 3];
    char shorts[2 * MAX_SPECS + 4];
    set_defaults(settings);
    int count = collect(program, settings, specs);
    getopt_tables(specs, count, longs, shorts);
    opterr = 0;
    optind = 0; /* glibc: start afresh, even after an earlier parse */
    for (;;) {
        int c = getopt_long(argc, argv, shorts, longs, NULL);
        if (c == -1)
            break;
        if (c == 'h' && spec_of(specs, count, 'h') == NULL) {
            cli_print_help(program, stdout);
            return EXIT_SUCCESS;
        }
        if (c == 1) {
            printf("%s (libraytrace) %s\n", program->name,
                   rt_version_string());
            return EXIT_SUCCESS;
        }
        const spec *s = c == '?' || c == ':' ? NULL
                                             : spec_of(specs, count, c);
        if (s == NULL)
            return getopt_error(program, specs, count, c, argv);
        int code = store(program, s, settings, optarg);
        if (code != CLI_CONTINUE)
            return code;
        if (s->given != NO_OFFSET)
            *(int *)((char *)settings + s->given) = 1;
    }
    for (int i = optind; i < argc; i++) {
        int code = add_operand(program, settings, argv[i]);
        if (code != CLI_CONTINUE)
            return code;
    }
    return check_settings(program, settings);
}

int cli_image_size(const cli_program *program, const cli_settings *settings,
                   const rt_scene *scene, int *width, int *height)
{
    rt_error error;
    if (rt_render_image_size(scene, &settings->render, width, height,
                             &error) == RT_OK)
        return CLI_CONTINUE;
    const rt_region *r = &settings->render.region;
    int region = r->x0 || r->y0 || r->x1 || r->y1;
    return cli_usage_error(program, "%s: %s",
                           region ? "--region" : "--size", error.message);
}

/* ------------------------------------------------------------------ */
/* Help                                                                */

/* Writes `text` wrapped between HELP_COLUMN and HELP_WIDTH; the first
 * line continues at `column`. */
static void print_wrapped(FILE *out, const char *text, int column)
{
    if (column > HELP_COLUMN - 2) {
        fputc('\n', out);
        column = 0;
    }
    fprintf(out, "%*s", HELP_COLUMN - column, "");
    column = HELP_COLUMN;
    while (*text) {
        size_t word = strcspn(text, " ");
        if (column > HELP_COLUMN && column + 1 + (int)word > HELP_WIDTH) {
            fprintf(out, "\n%*s", HELP_COLUMN, "");
            column = HELP_COLUMN;
        } else if (column > HELP_COLUMN) {
            fputc(' ', out);
            column++;
        }
        fwrite(text, 1, word, out);
        column += (int)word;
        text += word;
        text += strspn(text, " ");
    }
    fputc('\n', out);
}

static void print_option(FILE *out, const spec *s)
{
    char head[80];
    int n = s->short_name ? snprintf(head, sizeof head, "  -%c, --%s",
                                     s->short_name, s->name)
                          : snprintf(head, sizeof head, "      --%s", s->name);
    if (s->argument != NULL)
        snprintf(head + n, sizeof head - (size_t)n, s->optional ? "[=%s]"
                                                                : "=%s",
                 s->argument);
    fputs(head, out);
    print_wrapped(out, s->help, (int)strlen(head));
}

void cli_print_help(const cli_program *program, FILE *out)
{
    cli_settings unused;
    spec specs[MAX_SPECS];
    int count = collect(program, &unused, specs);
    fprintf(out, "usage: %s [OPTION]... %s\n\n%s\n", program->name,
            program->operands, program->description);
    for (size_t h = 0; h < sizeof headings / sizeof *headings; h++) {
        if (!(headings[h].group & program->groups))
            continue;
        /* rt-convert reads a scene but takes no view or light */
        int input_only = headings[h].group == CLI_GROUP_LOAD &&
                         !(program->groups & CLI_GROUP_CAMERA);
        fprintf(out, "\n%s\n", input_only ? "Scene:" : headings[h].title);
        for (int i = 0; i < count; i++)
            if (specs[i].group & headings[h].group)
                print_option(out, &specs[i]);
    }
    fprintf(out, "\n%s options:\n", program->name);
    for (int i = 0; i < count; i++)
        if (specs[i].group == 0)
            print_option(out, &specs[i]);
    spec help = {0, "help", 'h', NULL, 0, V_FLAG, 0, 0, 0, NULL, {0},
                 NO_OFFSET, NO_OFFSET, NULL, "this help"};
    spec version = {0, "version", 0, NULL, 0, V_FLAG, 0, 0, 0, NULL, {0},
                    NO_OFFSET, NO_OFFSET, NULL, "the version"};
    print_option(out, &help);
    print_option(out, &version);
    fprintf(out, "\nEvery option has the GNU forms --name=VALUE and --name "
                 "VALUE; short options\ntake -xVALUE or -x VALUE and bundle "
                 "(-qj2); `--' ends the options.\n");
    if (program->epilogue != NULL)
        fprintf(out, "%s\n", program->epilogue);
}
