/*
 * test_cli.c - the one command-line module (apps/common/cli.h) and the
 * programs built on it, as a user sees them: every GNU form of an option,
 * the same limits and messages in every program (exit status 2), --size
 * equal byte for byte to a scene edited to that size, --region equal to
 * the crop of the whole image, and --stats=json read by a real JSON parser
 * (python3's json module; without python3 that case is a visible CTest
 * skip, exit 77).  The parser is tested in process; the rest runs the real
 * programs on small images so that the suite stays fast.
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Files and programs (support/programs.h)                              */

static const char *cubes(void)
{
    static char path[4096];
    snprintf(path, sizeof path, "%s", rt_test_source_path("scenes/cubes.scn"));
    return path;
}

/* Runs rt-export with `args`, expects success and returns the bytes of
 * the image it wrote to dir/out.ppm (it is given `-o out.ppm -q`). */
static char *export_image(const char *dir, const char *const *args,
                          size_t *size)
{
    const char *all[32];
    int n = 0;
    for (int i = 0; args[i] != NULL && n < 28; i++)
        all[n++] = args[i];
    all[n++] = "-o";
    all[n++] = "out.ppm";
    all[n++] = "-q";
    all[n] = NULL;
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, all);
    ck_assert_msg(r.code == 0, "rt-export failed (%d): %s", r.code, r.err);
    rt_test_output_free(&r);
    char *image = rt_test_read_file(rt_test_in_dir(dir, "out.ppm"), size);
    ck_assert_ptr_nonnull(image);
    return image;
}

/* ------------------------------------------------------------------ */
/* The parser, in process                                              */

static int scale;
static const cli_option test_options[] = {
    {"scale", 's', "N", CLI_INT, 1, 8, &scale, "a program's own option"},
    {NULL, 0, NULL, CLI_FLAG, 0, 0, NULL, NULL},
};

static const cli_program test_program = {
    "rt-test", "SCENE", "A program that takes every group.", NULL,
    CLI_GROUP_RENDER | CLI_GROUP_LOAD | CLI_GROUP_OUTPUT | CLI_GROUP_REPORT |
        CLI_GROUP_QUIET,
    test_options, 1, 1, "expected a scene file"};

/* cli_parse on a NULL-terminated list of arguments. */
static int parse(cli_settings *s, const char *const *args)
{
    static char *argv[32];
    int argc = 0;
    argv[argc++] = "rt-test";
    for (int i = 0; args[i] != NULL && argc < 31; i++)
        argv[argc++] = (char *)args[i];
    argv[argc] = NULL;
    scale = 1;
    return cli_parse(&test_program, argc, argv, s);
}

START_TEST(every_gnu_form_of_an_option_gives_the_same_value)
{
    static const char *const forms[][5] = {
        {"--depth=2", "s.scn", NULL},
        {"--depth", "2", "s.scn", NULL},
        {"s.scn", "--depth", "2", NULL}, /* options after the operand */
        {"--dep=2", "s.scn", NULL},      /* a unique prefix */
    };
    for (size_t i = 0; i < sizeof forms / sizeof *forms; i++) {
        cli_settings s;
        ck_assert_int_eq(parse(&s, forms[i]), CLI_CONTINUE);
        ck_assert_int_eq(s.render.max_depth, 2);
        ck_assert_int_eq(s.operand_count, 1);
        ck_assert_str_eq(s.operands[0], "s.scn");
    }
    static const char *const outputs[][5] = {
        {"-oq.ppm", "s.scn", NULL},
        {"-o", "q.ppm", "s.scn", NULL},
        {"--output=q.ppm", "s.scn", NULL},
        {"--output", "q.ppm", "s.scn", NULL},
    };
    for (size_t i = 0; i < sizeof outputs / sizeof *outputs; i++) {
        cli_settings s;
        ck_assert_int_eq(parse(&s, outputs[i]), CLI_CONTINUE);
        ck_assert_str_eq(s.output, "q.ppm");
        ck_assert_int_eq(s.format, RT_IMAGE_P6);
    }
}
END_TEST

START_TEST(short_options_bundle_and_double_dash_ends_the_options)
{
    static const char *const bundles[][5] = {
        {"-qj2", "s.scn", NULL},
        {"-q", "-j", "2", "s.scn", NULL},
        {"-j2", "-q", "s.scn", NULL},
        {"--quiet", "--threads=2", "s.scn", NULL},
    };
    for (size_t i = 0; i < sizeof bundles / sizeof *bundles; i++) {
        cli_settings s;
        ck_assert_int_eq(parse(&s, bundles[i]), CLI_CONTINUE);
        ck_assert_int_eq(s.quiet, 1);
        ck_assert_int_eq(s.render.threads, 2);
    }
    cli_settings s;
    const char *const weird[] = {"-q", "--", "-weird.scn", NULL};
    ck_assert_int_eq(parse(&s, weird), CLI_CONTINUE);
    ck_assert_int_eq(s.operand_count, 1);
    ck_assert_str_eq(s.operands[0], "-weird.scn");
    const char *const own[] = {"-s3", "s.scn", NULL};
    ck_assert_int_eq(parse(&s, own), CLI_CONTINUE);
    ck_assert_int_eq(scale, 3);
}
END_TEST

START_TEST(render_and_load_options_reach_the_library_options)
{
    const char *const args[] = {
        "s.scn", "--size=300x200", "--region", "1,2,30,40", "--samples=4",
        "--sampling=stratified", "--precision", "float", "--fast-sqrt",
        "--aperture=0.5", "--focus=7", "--kernel=scalar", "--accel=octree",
        "--light=1,2,3", "--light", "4,5,6,10,20,30", "--fov=50",
        "--look-at=0,0,1", "--stats=json", "--format=P3", "-o", "x.png",
        NULL};
    cli_settings s;
    ck_assert_int_eq(parse(&s, args), CLI_CONTINUE);
    ck_assert_int_eq(s.render.width, 300);
    ck_assert_int_eq(s.render.height, 200);
    ck_assert_int_eq(s.render.region.x0, 1);
    ck_assert_int_eq(s.render.region.y1, 40);
    ck_assert_int_eq(s.render.samples, 4);
    ck_assert_int_eq(s.render.sampling, RT_SAMPLING_STRATIFIED);
    ck_assert_int_eq(s.render.precision, RT_PRECISION_FLOAT);
    ck_assert_int_eq(s.render.fast_inv_sqrt, 1);
    ck_assert_double_eq(s.render.aperture, 0.5);
    ck_assert_double_eq(s.render.focal_distance, 7.0);
    ck_assert_int_eq(s.render.kernel, RT_KERNEL_SCALAR);
    ck_assert_int_eq(s.render.accel, RT_ACCEL_OCTREE);
    ck_assert_int_eq(s.load.light_count, 2);
    ck_assert_ptr_eq(s.load.lights, s.lights);
    ck_assert_int_eq(s.lights[1].color.b, 30);
    ck_assert_int_eq(s.load.fov_given, 1);
    ck_assert_double_eq(s.load.fov, 50.0);
    ck_assert_int_eq(s.load.look_at_given, 1);
    ck_assert_int_eq(s.load.look_from_given, 0);
    ck_assert_int_eq(s.stats, CLI_STATS_JSON);
    ck_assert_int_eq(s.format, RT_IMAGE_P3); /* --format wins over -o */
    const char *const width_only[] = {"s.scn", "--width", "64", "--stats",
                                      NULL};
    ck_assert_int_eq(parse(&s, width_only), CLI_CONTINUE);
    ck_assert_int_eq(s.render.width, 64);
    ck_assert_int_eq(s.render.height, 0); /* the scene's */
    ck_assert_int_eq(s.stats, CLI_STATS_TEXT);
    ck_assert_int_eq(s.render.max_depth, RT_DEFAULT_DEPTH);
}
END_TEST

START_TEST(bad_values_are_usage_errors)
{
    static const char *const bad[][4] = {
        {"--depth=x", "s.scn", NULL},
        {"--depth=-1", "s.scn", NULL},
        {"--depth=1000001", "s.scn", NULL},
        {"-j", "1025", "s.scn", NULL},
        {"--samples=3", "s.scn", NULL},
        {"--size=0x10", "s.scn", NULL},
        {"--size=10x", "s.scn", NULL},
        {"--size=16385x1", "s.scn", NULL},
        {"--region=5,5,5,9", "s.scn", NULL},
        {"--region=1,2,3", "s.scn", NULL},
        {"--fov=180", "s.scn", NULL},
        {"--tessellate=0", "s.scn", NULL},
        {"--aperture=-1", "s.scn", NULL},
        {"--focus=0", "s.scn", NULL},
        {"--precision=half", "s.scn", NULL},
        {"--stats=xml", "s.scn", NULL},
        {"--fast-sqrt=1", "s.scn", NULL},
        {"--unknown", "s.scn", NULL},
        {"-z", "s.scn", NULL},
        {"-o", "x.jpg", "s.scn", NULL},
        {"--scale=9", "s.scn", NULL},
        {"a.scn", "b.scn", NULL},
        {"--depth", NULL},
        {NULL},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        cli_settings s;
        ck_assert_msg(parse(&s, bad[i]) == CLI_EXIT_USAGE,
                      "case %zu (%s) was accepted", i,
                      bad[i][0] ? bad[i][0] : "no argument");
    }
}
END_TEST

/* ------------------------------------------------------------------ */
/* The programs: messages, limits, help                                */

START_TEST(bad_values_print_the_option_the_limits_and_the_value)
{
    char *dir = rt_test_temp_dir();
    static const struct {
        const char *args[5];
        const char *message;
    } cases[] = {
        {{"--depth=x", "s.scn", NULL},
         "--depth: expected an integer in 0..1000000, found 'x'"},
        {{"-jx", "s.scn", NULL},
         "--threads: expected an integer in 0..1024, found 'x'"},
        {{"--samples", "3", "s.scn", NULL},
         "--samples: expected a square (1, 4, 9, 16, ...) in 1..1024, "
         "found '3'"},
        {{"--size=10x", "s.scn", NULL},
         "--size: expected WIDTHxHEIGHT, each in 1..16384, found '10x'"},
        {{"--region=4,4,2,8", "s.scn", NULL},
         "--region: expected X0,Y0,X1,Y1, whole numbers with X0 < X1 and "
         "Y0 < Y1, found '4,4,2,8'"},
        {{"--fov=0", "s.scn", NULL},
         "--fov: expected a number in (0, 180), found 0"},
        {{"--stats=xml", "s.scn", NULL},
         "--stats: expected text or json, found 'xml'"},
        {{"--nope", "s.scn", NULL}, "unknown or ambiguous option '--nope'"},
        {{"s.scn", "--depth", NULL}, "--depth: expected a value (N)"},
        {{NULL}, "expected a scene file"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, cases[i].args);
        char expected[512];
        snprintf(expected, sizeof expected,
                 "rt-export: %s\nTry 'rt-export --help'.\n",
                 cases[i].message);
        ck_assert_msg(r.code == 2, "case %zu: exit %d", i, r.code);
        ck_assert_str_eq(r.err, expected);
        ck_assert_str_eq(r.out, "");
        rt_test_output_free(&r);
    }
    rt_test_remove_dir(dir);
}
END_TEST

/* The programs built with the module, and the options all of them take. */
static const char *const programs[] = {
    RT_EXPORT_PATH,
#ifdef RT_BENCH_PATH
    RT_BENCH_PATH,
#endif
#ifdef RT_VIEW_PATH
    RT_VIEW_PATH,
#endif
};

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

START_TEST(every_program_has_the_same_limits_and_words)
{
    char *dir = rt_test_temp_dir();
    static const struct {
        const char *args[4];
        const char *message;
    } cases[] = {
        {{"-j", "x", "s.scn", NULL},
         "--threads: expected an integer in 0..1024, found 'x'"},
        {{"--size", "10x0", "s.scn", NULL},
         "--size: expected a height in 1..16384, found 0"},
        {{"--aperture=-2", "s.scn", NULL},
         "--aperture: expected a number >= 0, found -2"},
    };
    for (size_t p = 0; p < sizeof programs / sizeof *programs; p++) {
        const char *name = base_name(programs[p]);
        for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
            rt_test_output r = rt_test_run(dir, programs[p], cases[i].args);
            char expected[512];
            snprintf(expected, sizeof expected, "%s: %s\nTry '%s --help'.\n",
                     name, cases[i].message, name);
            ck_assert_msg(r.code == 2, "%s case %zu: exit %d", name, i,
                          r.code);
            ck_assert_str_eq(r.err, expected);
            rt_test_output_free(&r);
        }
    }
    rt_test_remove_dir(dir);
}
END_TEST

/* The line of `text` that starts with `start`, up to its end. */
static char *line_starting(const char *text, const char *start)
{
    for (const char *at = text; at != NULL && *at;) {
        if (strncmp(at, start, strlen(start)) == 0)
            return strndup(at, strcspn(at, "\n"));
        at = strchr(at, '\n');
        at = at ? at + 1 : NULL;
    }
    return NULL;
}

START_TEST(every_help_comes_from_the_one_table)
{
    char *dir = rt_test_temp_dir();
    const char *const help[] = {"--help", NULL};
    char *first_line = NULL;
    for (size_t p = 0; p < sizeof programs / sizeof *programs; p++) {
        rt_test_output r = rt_test_run(dir, programs[p], help);
        ck_assert_int_eq(r.code, 0);
        ck_assert_str_eq(r.err, "");
        char usage[256];
        snprintf(usage, sizeof usage, "usage: %s [OPTION]...",
                 base_name(programs[p]));
        ck_assert_msg(strncmp(r.out, usage, strlen(usage)) == 0, "%s",
                      r.out);
        char *line = line_starting(r.out, "  -j, --threads=N");
        ck_assert_ptr_nonnull(line);
        if (first_line == NULL)
            first_line = line;
        else {
            ck_assert_str_eq(line, first_line);
            free(line);
        }
        ck_assert_ptr_nonnull(strstr(r.out, "--size=WxH"));
        rt_test_output_free(&r);
    }
    free(first_line);
    rt_test_remove_dir(dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* --size and --region against the scene and the whole image           */

/* cubes.scn with the screen line's (the second record's) width and
 * height replaced, written to dir/name. */
static void write_cubes_at(const char *dir, const char *name, int width,
                           int height)
{
    char *text = rt_test_read_file(cubes(), NULL);
    ck_assert_ptr_nonnull(text);
    char *out = malloc(strlen(text) + 64);
    ck_assert_ptr_nonnull(out);
    size_t used = 0;
    int record = 0;
    for (char *line = text; *line;) {
        size_t length = strcspn(line, "\n");
        char *content = line + strspn(line, " \t");
        int is_record = *content != '#' && *content != '\n' && *content;
        if (is_record && ++record == 2) {
            /* six numbers for A and B, then w, h (and perhaps a lens) */
            char *at = line;
            for (int commas = 0; commas < 6; at++)
                commas += *at == ',';
            char *after = at;
            for (int commas = 0; commas < 2 && *after != '\n'; after++)
                commas += *after == ',';
            memcpy(out + used, line, (size_t)(at - line));
            used += (size_t)(at - line);
            used += (size_t)sprintf(out + used, " %d, %d%s", width, height,
                                    after[-1] == ',' ? "," : "");
            memcpy(out + used, after, (size_t)(line + length - after));
            used += (size_t)(line + length - after);
        } else {
            memcpy(out + used, line, length);
            used += length;
        }
        line += length;
        if (*line == '\n')
            out[used++] = *line++;
    }
    out[used] = '\0';
    rt_test_write_file(rt_test_in_dir(dir, name), out);
    free(out);
    free(text);
}

START_TEST(size_equals_a_scene_edited_to_that_size)
{
    char *dir = rt_test_temp_dir();
    static const struct {
        const char *option, *value;
        int width, height;
    } sizes[] = {
        {"--size", "40x40", 40, 40},
        {"--size", "48x20", 48, 20},     /* wider than the scene */
        {"--size", "17x33", 17, 33},     /* taller, odd sides */
        {"--width", "30", 30, 400},      /* alone: the scene's height */
        {"--height", "12", 400, 12},     /* alone: the scene's width */
    };
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++) {
        write_cubes_at(dir, "edited.scn", sizes[i].width, sizes[i].height);
        const char *sized[] = {cubes(), sizes[i].option, sizes[i].value,
                               NULL};
        const char *edited[] = {"edited.scn", NULL};
        size_t a_size, b_size;
        char *a = export_image(dir, sized, &a_size);
        char *b = export_image(dir, edited, &b_size);
        char header[64];
        snprintf(header, sizeof header, "P6\n%d %d\n255\n", sizes[i].width,
                 sizes[i].height);
        ck_assert_msg(strncmp(b, header, strlen(header)) == 0,
                      "case %zu: the edited scene has another size", i);
        ck_assert_msg(a_size == b_size && memcmp(a, b, a_size) == 0,
                      "case %zu: %s %s differs from the edited scene", i,
                      sizes[i].option, sizes[i].value);
        free(a);
        free(b);
    }
    rt_test_remove_dir(dir);
}
END_TEST

/* The pixels of region r of a P6 image of the given width, as a P6. */
static char *crop(const char *ppm, int width, rt_region r, size_t *size)
{
    const char *pixels = ppm;
    for (int newlines = 0; newlines < 3; pixels++)
        newlines += *pixels == '\n';
    int w = r.x1 - r.x0, h = r.y1 - r.y0;
    char *out = malloc(64 + (size_t)w * h * 3);
    ck_assert_ptr_nonnull(out);
    size_t used = (size_t)sprintf(out, "P6\n%d %d\n255\n", w, h);
    for (int y = r.y0; y < r.y1; y++) {
        memcpy(out + used, pixels + ((size_t)y * width + r.x0) * 3,
               (size_t)w * 3);
        used += (size_t)w * 3;
    }
    *size = used;
    return out;
}

static void check_regions(const char *dir, const char *samples,
                          const char *sampling)
{
    static const rt_region regions[] = {
        {0, 0, 40, 30},     /* the whole image */
        {0, 0, 1, 1},       /* the top-left pixel */
        {39, 29, 40, 30},   /* the bottom-right pixel */
        {0, 29, 40, 30},    /* the last row */
        {39, 0, 40, 30},    /* the last column */
        {7, 3, 31, 22},     /* inside */
    };
    const char *whole[] = {cubes(), "--size=40x30", "--samples", samples,
                           "--sampling", sampling, NULL};
    size_t whole_size;
    char *full = export_image(dir, whole, &whole_size);
    for (size_t i = 0; i < sizeof regions / sizeof *regions; i++) {
        rt_region r = regions[i];
        char value[64];
        snprintf(value, sizeof value, "%d,%d,%d,%d", r.x0, r.y0, r.x1, r.y1);
        const char *args[] = {cubes(), "--size=40x30", "--region", value,
                              "--samples", samples, "--sampling", sampling,
                              NULL};
        size_t got_size, want_size;
        char *got = export_image(dir, args, &got_size);
        char *want = crop(full, 40, r, &want_size);
        ck_assert_msg(got_size == want_size && memcmp(got, want, got_size) ==
                                                   0,
                      "--region %s (%s samples, %s) is not the crop of the "
                      "whole image", value, samples, sampling);
        free(got);
        free(want);
    }
    free(full);
}

START_TEST(region_equals_the_crop_of_the_whole_image)
{
    char *dir = rt_test_temp_dir();
    check_regions(dir, "1", "regular");
    check_regions(dir, "4", "stratified");
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(region_outside_the_image_is_a_usage_error_before_rendering)
{
    char *dir = rt_test_temp_dir();
    const char *args[] = {cubes(), "--size=40x30", "--region=0,0,41,30",
                          "-o", "out.ppm", NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_int_eq(r.code, 2);
    ck_assert_msg(strncmp(r.err, "rt-export: --region: ", 21) == 0, "%s",
                  r.err);
    ck_assert_ptr_nonnull(strstr(r.err, "40 x 30"));
    ck_assert_ptr_nonnull(strstr(r.err, "Try 'rt-export --help'."));
    ck_assert_int_eq(access(rt_test_in_dir(dir, "out.ppm"), F_OK), -1);
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(no_progress_line_off_a_terminal_unless_asked)
{
    char *dir = rt_test_temp_dir();
    const char *args[] = {cubes(), "--size=16x12", "-o", "out.ppm", NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_int_eq(r.code, 0);
    ck_assert_str_eq(r.err, "");
    ck_assert_str_eq(r.out, "out.ppm\n");
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* --stats=json, read by python3's json module                         */

/* Checks the object on standard input; argv: width height full_width
 * full_height samples region ("null" or "x0,y0,x1,y1") scene. */
static const char json_check[] =
    "import json, sys\n"
    "lines = sys.stdin.read().splitlines()\n"
    "o = json.loads(lines[-1])\n"
    "w, h, fw, fh, n = (int(a) for a in sys.argv[1:6])\n"
    "region = None if sys.argv[6] == 'null' else "
    "[int(v) for v in sys.argv[6].split(',')]\n"
    "def want(name, value):\n"
    "    assert o[name] == value, '%s: %r, expected %r' % (name, o[name], "
    "value)\n"
    "want('program', 'rt-export'); want('scene', sys.argv[7])\n"
    "want('width', w); want('height', h); want('pixels', w * h)\n"
    "want('full_width', fw); want('full_height', fh); want('region', region)\n"
    "want('samples', n); want('depth', 5); want('precision', 'double')\n"
    "want('output', 'out.ppm'); want('format', 'p6')\n"
    "assert o['rays']['camera'] == w * h * n, o['rays']\n"
    "r = o['rays']\n"
    "assert r['total'] == r['camera'] + r['shadow'] + r['reflection'] + "
    "r['refraction']\n"
    "assert o['ray_facet_tests'] > 0 and o['seconds']['render'] >= 0\n"
    "for k in ('load', 'render', 'write'): "
    "assert isinstance(o['seconds'][k], float)\n"
    "assert o['octree'] is None or o['octree']['leaves'] > 0\n"
    "for a in ('octree', 'kdtree'):\n"
    "    t = o[a]\n"
    "    if t is None: continue\n"
    "    for ratio, top, bottom in (('references_per_facet', 'references', "
    "'facets'), ('bytes_per_facet', 'bytes', 'facets'), "
    "('steps_per_query', 'steps', 'queries')):\n"
    "        want_r = t[top] / t[bottom]\n"
    "        assert abs(t[ratio] - want_r) <= 1e-5 * want_r, (ratio, t)\n"
    "    assert t['steps'] >= t['leaves_visited'] > 0, t\n";

static void check_json(const char *dir, const char *err, const char *w,
                       const char *h, const char *samples,
                       const char *region, const char *scene)
{
    rt_test_write_file(rt_test_in_dir(dir, "check.py"), json_check);
    rt_test_write_file(rt_test_in_dir(dir, "stats.txt"), err);
    char command[8192];
    snprintf(command, sizeof command,
             "cd '%s' && python3 check.py %s %s 40 30 %s '%s' '%s' "
             "< stats.txt", dir, w, h, samples, region, scene);
    ck_assert_msg(system(command) == 0, "the JSON failed its check: %s",
                  err);
}

START_TEST(stats_json_is_one_object_a_json_parser_reads)
{
    char *dir = rt_test_temp_dir();
    /* a name that needs escaping: a quote and a backslash */
    char *text = rt_test_read_file(cubes(), NULL);
    rt_test_write_file(rt_test_in_dir(dir, "cu\"b\\es.scn"), text);
    free(text);
    const char *whole[] = {"cu\"b\\es.scn", "--size=40x30", "--stats=json",
                           "-q", "-o", "out.ppm", NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, whole);
    ck_assert_msg(r.code == 0, "%s", r.err);
    ck_assert_int_eq(strchr(r.err, '\n') - r.err + 1, (long)strlen(r.err));
    check_json(dir, r.err, "40", "30", "1", "null", "cu\"b\\es.scn");
    rt_test_output_free(&r);
    const char *region[] = {cubes(), "--size=40x30", "--region=2,3,12,9",
                            "--samples=4", "--stats=json", "-o", "out.ppm",
                            NULL};
    r = rt_test_run(dir, RT_EXPORT_PATH, region);
    ck_assert_msg(r.code == 0, "%s", r.err);
    check_json(dir, r.err, "10", "6", "4", "2,3,12,9", cubes());
    rt_test_output_free(&r);
    for (int a = 0; a < 2; a++) {   /* the structures' figures and ratios */
        const char *accel[] = {cubes(), "--size=40x30",
                               a ? "--accel=kdtree" : "--accel=octree",
                               "--stats=json", "-o", "out.ppm", NULL};
        r = rt_test_run(dir, RT_EXPORT_PATH, accel);
        ck_assert_msg(r.code == 0, "%s", r.err);
        ck_assert_msg(strstr(r.err, a ? "\"kdtree\":{" : "\"octree\":{"),
                      "%s", r.err);
        check_json(dir, r.err, "40", "30", "1", "null", cubes());
        rt_test_output_free(&r);
    }
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *cli_suite(void)
{
    Suite *s = suite_create("cli");
    TCase *c = tcase_create("parser");
    tcase_add_test(c, every_gnu_form_of_an_option_gives_the_same_value);
    tcase_add_test(c, short_options_bundle_and_double_dash_ends_the_options);
    tcase_add_test(c, render_and_load_options_reach_the_library_options);
    tcase_add_test(c, bad_values_are_usage_errors);
    suite_add_tcase(s, c);
    c = tcase_create("programs");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, bad_values_print_the_option_the_limits_and_the_value);
    tcase_add_test(c, every_program_has_the_same_limits_and_words);
    tcase_add_test(c, every_help_comes_from_the_one_table);
    tcase_add_test(c, no_progress_line_off_a_terminal_unless_asked);
    suite_add_tcase(s, c);
    c = tcase_create("size_and_region");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, size_equals_a_scene_edited_to_that_size);
    tcase_add_test(c, region_equals_the_crop_of_the_whole_image);
    tcase_add_test(c, region_outside_the_image_is_a_usage_error_before_rendering);
    suite_add_tcase(s, c);
    return s;
}

static Suite *cli_json_suite(void)
{
    Suite *s = suite_create("cli_json");
    TCase *c = tcase_create("json");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, stats_json_is_one_object_a_json_parser_reads);
    suite_add_tcase(s, c);
    return s;
}

/* `test_cli` runs the suite; `test_cli json` the JSON case, which exits
 * 77 (a skip CTest shows) when python3 and its json module are absent. */
int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "json") == 0) {
        if (!rt_test_have_python_json()) {
            fprintf(stderr, "test_cli: python3 with its json module is "
                            "not installed; --stats=json not checked\n");
            return RT_TEST_SKIPPED;
        }
        return rt_test_run_suite(cli_json_suite());
    }
    return rt_test_run_suite(cli_suite());
}
