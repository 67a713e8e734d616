/*
 * rt-export - render a `.scn` scene to a PPM or PNG image, headless.
 *
 * A thin command-line client of libraytrace: parse the arguments, load the
 * scene (from a file or standard input), check that the output can be
 * written, render on all cores with a progress line on a terminal, save the
 * image with the library's safe save (or stream it to standard output),
 * print the path.  Exit status: 0 success, 1 bad input or a failed write,
 * 2 bad usage; a signal during the save ends it killed by that signal, the
 * previous file intact.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli_values.h"
#include "raytrace/raytrace.h"

#define EXIT_BAD_INPUT 1
#define EXIT_USAGE 2

static const char usage[] =
    "usage: rt-export SCENE.scn [-o OUT] [--format p3|p6|png] [--depth N]\n"
    "                 [--threads N] [--precision double|float] [--fast-sqrt]\n"
    "                 [--samples N] [--sampling regular|stratified]\n"
    "                 [--aperture A] [--focus F] [--input-format F]\n"
    "                 [--tessellate T] [--look-from X,Y,Z] [--look-at X,Y,Z]\n"
    "                 [--up X,Y,Z] [--fov DEGREES] [--light X,Y,Z[,R,G,B]]...\n"
    "                 [--kernel auto|scalar] [--accel auto|none|octree]\n"
    "                 [--check] [--stats] [--quiet]\n"
    "\n"
    "Renders SCENE (a .scn scene, an NFF file or a Wavefront OBJ model, by\n"
    "its extension) to an image and prints the path it wrote.  SCENE `-'\n"
    "reads the scene from standard input (then -o is needed).\n"
    "\n"
    "  -o, --output OUT  where to write the image (default: the scene's name\n"
    "                    with .ppm, or .png with --format png, in the\n"
    "                    current directory); `-' writes the image to\n"
    "                    standard output.  A device, FIFO or socket is\n"
    "                    written directly; a file is replaced atomically,\n"
    "                    keeping its mode, owner and links\n"
    "  --format F        p6 (binary PPM), p3 (ASCII PPM, the course's\n"
    "                    format) or png; default: from the extension of OUT\n"
    "                    (.png png, .ppm and .pnm p6; another extension is\n"
    "                    an error), p6 when OUT has none\n"
    "  --depth N         reflections followed after a primary ray (default 5)\n"
    "  --threads N       rendering threads; 0 = one per core (default 0)\n"
    "  --precision P     arithmetic of the renderer: double (the reference,\n"
    "                    default) or float (faster, less accurate)\n"
    "  --fast-sqrt       normalise vectors with the handout's fastInvSqrt\n"
    "  --samples N       rays per pixel, a square (1, 4, 9, ...; default 1:\n"
    "                    one ray through the pixel's centre)\n"
    "  --sampling S      regular (grid centres, default) or stratified\n"
    "  --aperture A      lens radius in scene units for depth of field\n"
    "                    (default: the scene's, else 0: a pinhole camera);\n"
    "                    smooth only with several samples per pixel\n"
    "  --focus F         the distance in focus, in scene units along the\n"
    "                    view axis (default: the scene's, else |AO|)\n"
    "  --kernel K        auto (default: the fastest loops this processor\n"
    "                    runs) or scalar (one facet at a time); the image\n"
    "                    is the same\n"
    "  --accel A         auto (default: an octree from 300 facets on), none\n"
    "                    (every ray tests every facet) or octree; the\n"
    "                    image is the same\n"
    "  --input-format F  scn, nff or obj, whatever the scene's extension says\n"
    "  --tessellate T    NFF spheres and cones: the largest distance between\n"
    "                    the surface and its facets, relative to the radius\n"
    "  --look-from P     the observer, X,Y,Z (each view option on its own\n"
    "                    replaces that part of the scene's camera)\n"
    "  --look-at P       the point the screen is centred on, X,Y,Z\n"
    "  --up V            up in the image, X,Y,Z\n"
    "  --fov D           the horizontal field of view in degrees\n"
    "  --light L         a point light X,Y,Z or X,Y,Z,R,G,B (0..255; white\n"
    "                    by default); repeat for several; they replace the\n"
    "                    scene's lights (an OBJ's default light included)\n"
    "  --check           validate the scene and print what it holds; do not\n"
    "                    render\n"
    "  --stats           print the work done (rays, tests, time) on stderr\n"
    "  -q, --quiet       no progress line\n"
    "  -h, --help        this help\n"
    "  --version         the version\n"
    "\n"
    "Exit status: 0 success, 1 bad scene or failed write, 2 bad usage.\n"
    "A signal during the save leaves the previous file intact.\n";

typedef struct arguments {
    const char *scene;
    const char *output;
    rt_image_format format;
    int format_given;
    int depth;
    int threads;
    rt_precision precision;
    int fast_sqrt;
    int samples;
    rt_sampling sampling;
    rt_kernel_choice kernel;
    rt_accel accel;
    double aperture;        /* negative: the scene's */
    double focal_distance;  /* 0: the scene's */
    int check;
    int stats;
    int quiet;
    rt_load_options load;   /* format, tessellation, view, lights */
    rt_light lights[16];    /* --light, in order */
} arguments;

#define MAX_LIGHTS 16

static int usage_error(const char *fmt, const char *value)
{
    fprintf(stderr, "rt-export: ");
    fprintf(stderr, fmt, value);
    fprintf(stderr, "\nTry 'rt-export --help'.\n");
    return EXIT_USAGE;
}

static int parse_int(const char *text, int min, int max, int *value)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (errno != 0 || end == text || *end != '\0' || v < min || v > max)
        return 0;
    *value = (int)v;
    return 1;
}

/* Non-zero when the file name at the end of `path` has an extension (a
 * name without one, such as /dev/null or `-', is written as P6). */
static int has_extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    return dot != NULL && dot != base;
}

/* Returns -1 to go on, or an exit status. */
static int parse_arguments(int argc, char **argv, arguments *a)
{
    *a = (arguments){.format = RT_IMAGE_P6, .depth = RT_DEFAULT_DEPTH,
                     .aperture = -1.0,
                     .samples = 1};
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        int takes_value = !strcmp(arg, "-o") || !strcmp(arg, "--output") ||
                          !strcmp(arg, "--format") ||
                          !strcmp(arg, "--depth") ||
                          !strcmp(arg, "--threads") ||
                          !strcmp(arg, "--precision") ||
                          !strcmp(arg, "--samples") ||
                          !strcmp(arg, "--sampling") ||
                          !strcmp(arg, "--kernel") ||
                          !strcmp(arg, "--accel") ||
                          !strcmp(arg, "--aperture") ||
                          !strcmp(arg, "--focus") ||
                          !strcmp(arg, "--input-format") ||
                          !strcmp(arg, "--tessellate") ||
                          !strcmp(arg, "--look-from") ||
                          !strcmp(arg, "--look-at") ||
                          !strcmp(arg, "--up") || !strcmp(arg, "--fov") ||
                          !strcmp(arg, "--light");
        if (takes_value && value == NULL)
            return usage_error("option '%s' needs a value", arg);
        if (!strcmp(arg, "-h") || !strcmp(arg, "--help")) {
            fputs(usage, stdout);
            return EXIT_SUCCESS;
        } else if (!strcmp(arg, "--version")) {
            printf("rt-export (libraytrace) %s\n", rt_version_string());
            return EXIT_SUCCESS;
        } else if (!strcmp(arg, "-o") || !strcmp(arg, "--output")) {
            a->output = value;
        } else if (!strcmp(arg, "--format")) {
            if (!strcmp(value, "p3") || !strcmp(value, "P3"))
                a->format = RT_IMAGE_P3;
            else if (!strcmp(value, "p6") || !strcmp(value, "P6"))
                a->format = RT_IMAGE_P6;
            else if (!strcmp(value, "png") || !strcmp(value, "PNG"))
                a->format = RT_IMAGE_PNG;
            else
                return usage_error("expected p3, p6 or png after --format, "
                                   "found '%s'", value);
            a->format_given = 1;
        } else if (!strcmp(arg, "--depth")) {
            if (!parse_int(value, 0, 1000000, &a->depth))
                return usage_error("expected a depth in 0..1000000, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--threads")) {
            if (!parse_int(value, 0, 1024, &a->threads))
                return usage_error("expected a thread count in 0..1024, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--precision")) {
            if (!strcmp(value, "double"))
                a->precision = RT_PRECISION_DOUBLE;
            else if (!strcmp(value, "float"))
                a->precision = RT_PRECISION_FLOAT;
            else
                return usage_error("expected double or float after "
                                   "--precision, found '%s'", value);
        } else if (!strcmp(arg, "--fast-sqrt")) {
            a->fast_sqrt = 1;
        } else if (!strcmp(arg, "--samples")) {
            int root = 1;
            if (!parse_int(value, 1, 1024, &a->samples))
                return usage_error("expected a sample count in 1..1024, "
                                   "found '%s'", value);
            while (root * root < a->samples)
                root++;
            if (root * root != a->samples)
                return usage_error("expected a square sample count (1, 4, "
                                   "9, 16, ...), found '%s'", value);
        } else if (!strcmp(arg, "--sampling")) {
            if (!strcmp(value, "regular"))
                a->sampling = RT_SAMPLING_REGULAR;
            else if (!strcmp(value, "stratified"))
                a->sampling = RT_SAMPLING_STRATIFIED;
            else
                return usage_error("expected regular or stratified after "
                                   "--sampling, found '%s'", value);
        } else if (!strcmp(arg, "--kernel")) {
            if (!strcmp(value, "auto"))
                a->kernel = RT_KERNEL_AUTO;
            else if (!strcmp(value, "scalar"))
                a->kernel = RT_KERNEL_SCALAR;
            else
                return usage_error("expected auto or scalar after --kernel, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--input-format")) {
            if (!cli_parse_scene_format(value, &a->load.format))
                return usage_error("expected scn, nff or obj after "
                                   "--input-format, found '%s'", value);
        } else if (!strcmp(arg, "--tessellate")) {
            if (!cli_parse_length(value, 1, &a->load.tessellation) ||
                !(a->load.tessellation < 1))
                return usage_error("expected a tolerance in (0, 1) after "
                                   "--tessellate, found '%s'", value);
        } else if (!strcmp(arg, "--look-from")) {
            if (!cli_parse_point(value, &a->load.look_from))
                return usage_error("expected x,y,z after --look-from, "
                                   "found '%s'", value);
            a->load.look_from_given = 1;
        } else if (!strcmp(arg, "--look-at")) {
            if (!cli_parse_point(value, &a->load.look_at))
                return usage_error("expected x,y,z after --look-at, found "
                                   "'%s'", value);
            a->load.look_at_given = 1;
        } else if (!strcmp(arg, "--up")) {
            if (!cli_parse_point(value, &a->load.up))
                return usage_error("expected x,y,z after --up, found '%s'",
                                   value);
            a->load.up_given = 1;
        } else if (!strcmp(arg, "--fov")) {
            if (!cli_parse_length(value, 1, &a->load.fov) ||
                !(a->load.fov < 180))
                return usage_error("expected a field of view in (0, 180) "
                                   "degrees after --fov, found '%s'", value);
            a->load.fov_given = 1;
        } else if (!strcmp(arg, "--light")) {
            if (a->load.light_count == MAX_LIGHTS)
                return usage_error("expected at most 16 --light options, "
                                   "found another: '%s'", value);
            if (!cli_parse_light(value, &a->lights[a->load.light_count]))
                return usage_error("expected x,y,z or x,y,z,r,g,b (colour "
                                   "0..255) after --light, found '%s'",
                                   value);
            a->load.light_count++;
            a->load.lights = a->lights;
        } else if (!strcmp(arg, "--aperture")) {
            if (!cli_parse_length(value, 0, &a->aperture))
                return usage_error("expected a lens radius >= 0 after "
                                   "--aperture, found '%s'", value);
        } else if (!strcmp(arg, "--focus")) {
            if (!cli_parse_length(value, 1, &a->focal_distance))
                return usage_error("expected a distance > 0 after --focus, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--accel")) {
            if (!strcmp(value, "auto"))
                a->accel = RT_ACCEL_AUTO;
            else if (!strcmp(value, "none"))
                a->accel = RT_ACCEL_NONE;
            else if (!strcmp(value, "octree"))
                a->accel = RT_ACCEL_OCTREE;
            else
                return usage_error("expected auto, none or octree after "
                                   "--accel, found '%s'", value);
        } else if (!strcmp(arg, "--check")) {
            a->check = 1;
        } else if (!strcmp(arg, "--stats")) {
            a->stats = 1;
        } else if (!strcmp(arg, "-q") || !strcmp(arg, "--quiet")) {
            a->quiet = 1;
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return usage_error("unknown option '%s'", arg);
        } else if (a->scene == NULL) {
            a->scene = arg;
        } else {
            return usage_error("expected one scene, found a second: '%s'",
                               arg);
        }
        i += takes_value;
    }
    if (a->scene == NULL)
        return usage_error("%s", "expected a scene file");
    if (!strcmp(a->scene, "-") && a->output == NULL)
        return usage_error("%s", "expected -o OUT (or -o - for standard "
                           "output) with a scene read from standard input");
    if (!a->format_given && a->output != NULL && has_extension(a->output) &&
        rt_image_format_from_path(a->output, &a->format) != RT_OK)
        return usage_error("cannot tell the image format from the name "
                           "'%s': expected .png, .ppm or .pnm, or --format "
                           "p3, p6 or png", a->output);
    return -1;
}

/* "dir/name.scn" -> "name.ppm", or "name.png" for PNG (in the current
 * directory). */
static char *default_output(const char *scene, rt_image_format format)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    const char *dot = strrchr(base, '.');
    size_t length = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    const char *extension = format == RT_IMAGE_PNG ? ".png" : ".ppm";
    char *out = malloc(length + 5);
    if (out != NULL) {
        memcpy(out, base, length);
        memcpy(out + length, extension, 5);
    }
    return out;
}

/* Reads the whole scene from standard input and parses it as "<stdin>". */
static rt_status load_standard_input(const rt_load_options *options,
                                     rt_scene **scene, rt_error *error)
{
    size_t capacity = 1 << 16, used = 0;
    char *text = malloc(capacity);
    while (text != NULL) {
        size_t got = fread(text + used, 1, capacity - used, stdin);
        used += got;
        if (used < capacity)
            break;
        /* /dev/zero or a huge binary: the loader's check names it */
        if (used > RT_MAX_SCENE_BYTES || memchr(text + used - got, 0, got))
            break;
        char *bigger = capacity <= SIZE_MAX / 2 ? realloc(text, capacity * 2)
                                                : NULL;
        if (bigger == NULL)
            free(text);
        text = bigger;
        capacity *= 2;
    }
    if (text == NULL) {
        *scene = NULL;
        snprintf(error->message, sizeof error->message,
                 "<stdin>: out of memory reading the scene");
        return RT_ERR_NOMEM;
    }
    if (ferror(stdin)) {
        free(text);
        *scene = NULL;
        snprintf(error->message, sizeof error->message,
                 "<stdin>: cannot read: %s", strerror(errno));
        return RT_ERR_IO;
    }
    rt_status status = rt_scene_parse_with(text, used, "<stdin>", options,
                                           scene, error);
    free(text);
    return status;
}

static void print_check(const char *path, const rt_scene *scene)
{
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    printf("%s: valid scene\n", path);
    printf("  image      %d x %d\n", info.width, info.height);
    printf("  vertices   %d\n", info.vertex_count);
    printf("  facets     %d (%d can be hit, %d reflective, %d "
           "transparent)\n",
           info.facet_count, info.live_facet_count,
           info.reflective_facet_count, info.transparent_facet_count);
    printf("  camera     O (%g, %g, %g), A (%g, %g, %g)%s\n",
           info.camera.observer.x, info.camera.observer.y,
           info.camera.observer.z, info.camera.screen_center.x,
           info.camera.screen_center.y, info.camera.screen_center.z,
           info.camera.b_was_projected
               ? ", B projected onto the screen plane"
               : "");
    if (info.camera.aperture > 0.0)
        printf("  lens       aperture %g, focal distance %g\n",
               info.camera.aperture, info.camera.focal_distance);
    for (int i = 0; i < info.light_count; i++) {
        rt_light light;
        rt_scene_light(scene, i, &light);
        printf("  light      (%g, %g, %g), colour %d %d %d\n",
               light.position.x, light.position.y, light.position.z,
               light.color.r, light.color.g, light.color.b);
    }
    printf("  background %d %d %d\n", info.background.r, info.background.g,
           info.background.b);
    printf("  warnings   %d\n", info.warning_count);
    for (int i = 0; i < info.warning_count; i++)
        printf("  %s\n", rt_scene_warning(scene, i)->message);
}

/* Progress on a terminal: a line rewritten in place, shown only once a
 * render has taken more than half a second. */
typedef struct progress {
    const char *name;
    int rows, done;
    struct timespec start, last;
    int shown;
} progress;

static double seconds_since(const struct timespec *t)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - t->tv_sec) + (now.tv_nsec - t->tv_nsec) * 1e-9;
}

static int on_row(void *user, int row)
{
    (void)row;
    progress *p = user;
    p->done++;
    double elapsed = seconds_since(&p->start);
    if (elapsed < 0.5 || (p->shown && seconds_since(&p->last) < 0.1 &&
                          p->done < p->rows))
        return 1;
    clock_gettime(CLOCK_MONOTONIC, &p->last);
    fprintf(stderr, "\rrendering %s: %3d%% (%.1f s)", p->name,
            (int)(100.0 * p->done / p->rows), elapsed);
    fflush(stderr);
    p->shown = 1;
    return 1;
}

/* The work of a render and where the time went, on stderr. */
static void print_stats(const rt_render_stats *s, double load_seconds,
                        double write_seconds, const arguments *a)
{
    double tests_per_second = s->seconds > 0 ? s->ray_facet_tests / s->seconds
                                             : 0.0;
    unsigned long long cast = s->camera_rays + s->shadow_rays +
                              s->reflection_rays + s->refraction_rays;
    fprintf(stderr,
            "rays: %llu camera, %llu shadow, %llu reflection, %llu refraction "
            "(%llu in all)\n"
            "skipped by the scene analysis: %llu shadow rays "
            "(N.S <= 0 or d = 0), %llu reflection rays (k = 0), %llu "
            "refraction rays (depth limit or total internal reflection; "
            "none where t = 0)\n"
            "ray-facet tests: %llu (%.3g per second); %llu more without the "
            "analysis and early exits\n"
            "time: load %.3f s, render %.3f s (%s threads, %s kernel, %s), "
            "write %.3f s\n",
            (unsigned long long)s->camera_rays,
            (unsigned long long)s->shadow_rays,
            (unsigned long long)s->reflection_rays,
            (unsigned long long)s->refraction_rays, cast,
            (unsigned long long)s->shadow_rays_skipped,
            (unsigned long long)s->reflection_rays_skipped,
            (unsigned long long)s->refraction_rays_skipped,
            (unsigned long long)s->ray_facet_tests, tests_per_second,
            (unsigned long long)s->ray_facet_tests_skipped, load_seconds,
            s->seconds, a->threads == 0 ? "all" : "the given",
            a->kernel == RT_KERNEL_SCALAR ? "scalar" : "fast",
            a->precision == RT_PRECISION_FLOAT ? "float" : "double",
            write_seconds);
    if (!s->accel_used)
        return;
    uint64_t queries = s->accel_queries ? s->accel_queries : 1;
    fprintf(stderr,
            "octree: built in %.3f s; %llu leaves, depth %d, %.2f references "
            "per facet (+%llu slivers in every ray's list), %.1f MB\n"
            "octree per query: %.2f leaves visited, %.2f facets tested "
            "(brute force: %llu); %llu queries left to brute force\n",
            s->accel_build_seconds, (unsigned long long)s->accel_leaves,
            s->accel_depth,
            s->accel_facets > 0
                ? (double)s->accel_references / (double)s->accel_facets
                : 0.0,
            (unsigned long long)s->accel_always, s->accel_bytes / 1e6,
            (double)s->accel_leaves_visited / queries,
            (double)s->accel_facet_tests / queries,
            (unsigned long long)s->accel_facets,
            (unsigned long long)s->accel_fallbacks);
}

static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

/* Non-zero when `path` names the file open as descriptor `fd`
 * (-o /dev/stdout). */
static int same_file_as(const char *path, int fd)
{
    struct stat sp, sf;
    return stat(path, &sp) == 0 && fstat(fd, &sf) == 0 &&
           sp.st_dev == sf.st_dev && sp.st_ino == sf.st_ino;
}

int main(int argc, char **argv)
{
    arguments a;
    int code = parse_arguments(argc, argv, &a);
    if (code >= 0)
        return code;
    int to_stdout = a.output != NULL && !strcmp(a.output, "-");
    int from_stdin = !strcmp(a.scene, "-");
    const char *scene_name = from_stdin ? "<stdin>" : a.scene;
    if (!a.check && !rt_image_format_supported(a.format)) {
        fprintf(stderr, "rt-export: cannot write %s: this build has no PNG "
                        "support (it was built without libpng); use --format "
                        "p6 or p3\n", a.output ? a.output : "PNG");
        return EXIT_BAD_INPUT;
    }
    if (!a.check && to_stdout && a.format != RT_IMAGE_P3 &&
        isatty(STDOUT_FILENO)) {
        fprintf(stderr, "rt-export: refusing to write a binary image to a "
                        "terminal; redirect standard output, or use "
                        "--format p3\n");
        return EXIT_USAGE;
    }

    rt_scene *scene;
    rt_error error;
    struct timespec load_start;
    clock_gettime(CLOCK_MONOTONIC, &load_start);
    rt_status loaded = from_stdin
                           ? load_standard_input(&a.load, &scene, &error)
                           : rt_scene_load_with(a.scene, &a.load, &scene,
                                                &error);
    if (loaded != RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    if (a.check) {
        print_check(scene_name, scene);
        rt_scene_free(scene);
        return EXIT_SUCCESS;
    }
    double load_seconds = seconds_since(&load_start);
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "rt-export: %s\n", rt_scene_warning(scene, i)->message);

    char *output = a.output ? NULL : default_output(a.scene, a.format);
    const char *path = a.output ? a.output : output;
    rt_image image = {0};
    code = EXIT_BAD_INPUT;
    if (path == NULL) {
        fprintf(stderr, "rt-export: out of memory\n");
        goto done;
    }
    if (!from_stdin && !to_stdout && same_file(path, a.scene)) {
        fprintf(stderr, "rt-export: %s: refusing to write the image over "
                        "the scene it was rendered from\n", path);
        goto done;
    }
    if (rt_scene_check_precision(scene, a.precision, &error) != RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        goto done;
    }
    /* A bad output fails now, not after the render. */
    if (!to_stdout && rt_image_save_check(path, &error) != RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        goto done;
    }
    if (rt_image_create(&image, info.width, info.height) != RT_OK) {
        fprintf(stderr, "rt-export: out of memory\n");
        goto done;
    }

    progress p = {.name = scene_name, .rows = info.height};
    clock_gettime(CLOCK_MONOTONIC, &p.start);
    rt_render_stats stats;
    rt_render_options options;
    rt_render_options_init(&options);
    options.max_depth = a.depth;
    options.threads = a.threads;
    options.precision = a.precision;
    options.fast_inv_sqrt = a.fast_sqrt;
    options.samples = a.samples;
    options.sampling = a.sampling;
    options.kernel = a.kernel;
    options.aperture = a.aperture;
    options.focal_distance = a.focal_distance;
    options.accel = a.accel;
    options.stats = &stats;
    if (!a.quiet && isatty(STDERR_FILENO)) {
        options.on_row = on_row;
        options.user = &p;
    }
    rt_status status = rt_render(scene, &options, &image);
    if (p.shown)
        fprintf(stderr, "\n");
    if (status != RT_OK) {
        fprintf(stderr, "rt-export: %s: rendering failed: %s\n", scene_name,
                rt_status_string(status));
        goto done;
    }
    struct timespec write_start;
    clock_gettime(CLOCK_MONOTONIC, &write_start);
    status = to_stdout ? rt_image_write_file(stdout, &image, a.format, &error)
                       : rt_image_save(path, &image, a.format, &error);
    if (status != RT_OK) {
        fprintf(stderr, "rt-export: %s%s\n",
                to_stdout ? "<stdout>: " : "", error.message);
        goto done;
    }
    if (a.stats)
        print_stats(&stats, load_seconds, seconds_since(&write_start), &a);
    /* The path goes to standard output unless the image went there. */
    if (!to_stdout && !same_file_as(path, STDOUT_FILENO))
        printf("%s\n", path);
    code = EXIT_SUCCESS;
done:
    rt_image_destroy(&image);
    free(output);
    rt_scene_free(scene);
    return code;
}
