/*
 * rt-convert - write any scene the library reads (.scn, NFF, OBJ) as a
 * course .scn file, for tools that read only that format.
 *
 * What the course's records cannot hold (lights beyond the first,
 * transparency, a lens, diffuse weights other than 1 - k - t) is dropped
 * with a warning, or kept in the optional records with --extended.  The
 * numbers keep 17 digits: rt-export renders the converted file exactly as
 * the original.  Exit status: 0 success, 1 bad input or failed write, 2 bad
 * usage.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_values.h"
#include "raytrace/raytrace.h"

static const char usage[] =
    "usage: rt-convert IN OUT.scn [--extended] [--input-format scn|nff|obj]\n"
    "                  [--tessellate T]\n"
    "\n"
    "Reads the scene IN (its format from its extension, or --input-format)\n"
    "and writes it as a .scn file at OUT.scn (`-' for standard output).\n"
    "\n"
    "  --extended        keep what the course's format cannot hold in the\n"
    "                    optional records (further lights, t and n, a lens);\n"
    "                    without it they are dropped, with a warning\n"
    "  --input-format F  scn, nff or obj, whatever IN's extension says\n"
    "  --tessellate T    NFF spheres and cones: the largest distance between\n"
    "                    the surface and its facets, relative to the radius\n"
    "  -h, --help        this help\n"
    "\n"
    "Exit status: 0 success, 1 bad scene or failed write, 2 bad usage.\n";

static int usage_error(const char *message, const char *value)
{
    fprintf(stderr, "rt-convert: %s%s%s%s\nTry 'rt-convert --help'.\n",
            message, value ? " '" : "", value ? value : "",
            value ? "'" : "");
    return 2;
}

static int write_to_stdout(void *user, const void *data, size_t size)
{
    (void)user;
    return fwrite(data, 1, size, stdout) == size;
}

/* Warnings for what the conversion dropped. */
static void report_dropped(unsigned dropped, const char *out)
{
    static const struct {
        unsigned bit;
        const char *what;
    } kinds[] = {
        {RT_SCN_DROPPED_LIGHTS, "the lights after the first"},
        {RT_SCN_DROPPED_TRANSPARENCY,
         "the facets' transparency and refractive index"},
        {RT_SCN_DROPPED_LENS, "the lens (aperture and focal distance)"},
        {RT_SCN_DROPPED_DIFFUSE,
         "diffuse weights other than 1 - k - t (no .scn record holds them)"},
    };
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++)
        if (dropped & kinds[i].bit)
            fprintf(stderr, "rt-convert: %s: warning: dropped %s%s\n", out,
                    kinds[i].what,
                    kinds[i].bit == RT_SCN_DROPPED_DIFFUSE
                        ? ""
                        : " (--extended keeps them)");
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    int extended = 0;
    rt_load_options options;
    rt_load_options_init(&options);
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(arg, "-h") || !strcmp(arg, "--help")) {
            fputs(usage, stdout);
            return 0;
        } else if (!strcmp(arg, "--extended")) {
            extended = 1;
        } else if (!strcmp(arg, "--input-format")) {
            if (value == NULL || !cli_parse_scene_format(value, &options.format))
                return usage_error("expected scn, nff or obj after "
                                   "--input-format, found", value);
            i++;
        } else if (!strcmp(arg, "--tessellate")) {
            if (value == NULL ||
                !cli_parse_length(value, 1, &options.tessellation) ||
                !(options.tessellation < 1))
                return usage_error("expected a tolerance in (0, 1) after "
                                   "--tessellate, found", value);
            i++;
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return usage_error("unknown option", arg);
        } else if (in == NULL) {
            in = arg;
        } else if (out == NULL) {
            out = arg;
        } else {
            return usage_error("expected two files, found a third:", arg);
        }
    }
    if (in == NULL || out == NULL)
        return usage_error("expected IN and OUT.scn", NULL);

    rt_scene *scene;
    rt_error error;
    if (rt_scene_load_with(in, &options, &scene, &error) != RT_OK) {
        fprintf(stderr, "rt-convert: %s\n", error.message);
        return 1;
    }
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "rt-convert: %s\n", rt_scene_warning(scene, i)->message);
    unsigned dropped = 0;
    rt_status status =
        strcmp(out, "-") == 0
            ? rt_scene_write_scn(scene, extended, write_to_stdout, NULL,
                                 &dropped, &error)
            : rt_scene_save_scn(scene, out, extended, &dropped, &error);
    if (status == RT_OK && strcmp(out, "-") == 0 && fflush(stdout) != 0)
        status = RT_ERR_IO, snprintf(error.message, sizeof error.message,
                                     "<stdout>: cannot write the scene");
    rt_scene_destroy(scene);
    if (status != RT_OK) {
        fprintf(stderr, "rt-convert: %s\n", error.message);
        return 1;
    }
    report_dropped(dropped, out);
    if (strcmp(out, "-") != 0)
        printf("%s\n", out);
    return 0;
}
