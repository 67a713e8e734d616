/*
 * rt-convert - write any scene the library reads (.scn, NFF, OBJ, PLY) as a
 * course .scn file, for tools that read only that format.
 *
 * What the course's records cannot hold (lights beyond the first,
 * transparency, a lens, diffuse weights other than 1 - k - t, highlights,
 * vertex normals) is dropped with a warning, or kept in the optional
 * records with --extended.  The
 * numbers keep 17 digits: rt-export renders the converted file exactly as
 * the original.  The command line is the programs' one option table
 * (apps/common/cli.h): the same forms, limits and messages as rt-export.
 * The output is never a file the load read (the scene, an OBJ's material
 * library, standard input), and is named .scn unless --force-name says
 * otherwise.  Exit status: 0 success, 1 bad input or failed write, 2 bad
 * usage.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "cli_output.h"
#include "cli_text.h"
#include "raytrace/raytrace.h"

#define EXIT_BAD_INPUT 1

static int extended;    /* --extended */
static int force_name;  /* --force-name */

static const cli_option convert_options[] = {
    {"extended", 0, NULL, CLI_FLAG, 0, 0, &extended,
     "keep what the course's format cannot hold in the optional records "
     "(further lights, t and n, a lens, d, highlights, vertex normals); "
     "without it they are dropped, with a warning"},
    {"force-name", 0, NULL, CLI_FLAG, 0, 0, &force_name,
     "write the .scn text even to a name that does not end in .scn "
     "(without it, `out.png' is refused)"},
    CLI_OPTIONS_END,
};

static const cli_program program = {
    "rt-convert", "IN OUT.scn",
    "Reads the scene IN (a .scn scene, an NFF file, a Wavefront OBJ model\n"
    "or a PLY mesh, by its extension or --input-format) and writes it as a\n"
    ".scn scene at OUT.scn, then prints OUT.scn.  OUT `-' writes the scene to\n"
    "standard output and nothing else there.  A device or FIFO is written\n"
    "directly, a file is replaced atomically, keeping its mode, owner and\n"
    "links.  The output is never a file the scene was read from (IN, an\n"
    "OBJ's material library): that is refused, naming both.",
    "Exit status: 0 success, 1 bad scene or failed write, 2 bad usage.",
    CLI_GROUP_INPUT, convert_options, 2, 2, "expected IN and OUT.scn"};

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
        {RT_SCN_DROPPED_DIFFUSE, "diffuse weights other than 1 - k - t"},
        {RT_SCN_DROPPED_HIGHLIGHTS, "the facets' highlights (s and p)"},
        {RT_SCN_DROPPED_NORMALS,
         "the vertex normals (smooth facets become flat)"},
    };
    char shown[1024];
    cli_printable(strcmp(out, "-") ? out : "<stdout>", shown, sizeof shown);
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++)
        if (dropped & kinds[i].bit)
            fprintf(stderr,
                    "rt-convert: %s: warning: dropped %s (--extended keeps "
                    "them)\n",
                    shown, kinds[i].what);
}

/* Whether `out` may receive .scn text: "-", a name ending in .scn (any
 * case), or something that is not a file name of a type (a device, a
 * FIFO, a socket, reached through links); --force-name allows any. */
static int scene_name_allowed(const char *out)
{
    struct stat st;
    rt_scene_format format;
    return force_name || strcmp(out, "-") == 0 ||
           (rt_scene_format_from_path(out, &format, NULL) == RT_OK &&
            format == RT_SCENE_FORMAT_SCN) ||
           (stat(out, &st) == 0 && !S_ISREG(st.st_mode) &&
            !S_ISDIR(st.st_mode));
}

/* Writes `scene` at `out` ("-": standard output).  Returns an exit
 * status. */
static int write_scene(const rt_scene *scene, const char *out)
{
    rt_error error;
    unsigned dropped = 0;
    int to_stdout = strcmp(out, "-") == 0;
    rt_save_options save = cli_save_options();
    rt_status status =
        to_stdout ? rt_scene_write_scn(scene, extended, write_to_stdout, NULL,
                                       &dropped, &error)
                  : rt_scene_save_scn(scene, out, extended, &dropped, &save,
                                      &error);
    if (status == RT_OK && to_stdout && fflush(stdout) != 0)
        status = RT_ERR_IO, snprintf(error.message, sizeof error.message,
                                     "<stdout>: cannot write the scene");
    if (status != RT_OK) {
        fprintf(stderr, "rt-convert: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    report_dropped(dropped, out);
    return EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
    cli_settings s;
    int code = cli_parse(&program, argc, argv, &s);
    if (code != CLI_CONTINUE)
        return code;
    const char *in = s.operands[0], *out = s.operands[1];
    char shown[1024];
    if (!scene_name_allowed(out))
        return cli_usage_error(&program, "expected an output named .scn "
                               "(rt-convert writes .scn text), found '%s'; "
                               "--force-name writes it there anyway",
                               cli_printable(out, shown, sizeof shown));

    rt_scene *scene;
    rt_error error;
    if (rt_scene_load(in, &s.load, &scene, &error) != RT_OK) {
        fprintf(stderr, "rt-convert: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "rt-convert: %s\n", rt_scene_warning(scene, i)->message);
    cli_print_up_note(stderr, "rt-convert", in, scene);
    code = cli_refuse_input_as_output("rt-convert", out, scene, in,
                                      "the scene")
               ? EXIT_BAD_INPUT
               : write_scene(scene, out);
    rt_scene_destroy(scene);
    if (code == EXIT_SUCCESS && strcmp(out, "-") != 0)
        printf("%s\n", out);
    return code;
}
