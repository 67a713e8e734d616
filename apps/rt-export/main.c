/*
 * rt-export - render a scene (.scn, NFF, OBJ) to a PPM or PNG image,
 * headless.
 *
 * A thin command-line client of libraytrace: the options come from the
 * one table (apps/common/cli.h), and the load, the checks, the render of
 * every band on this process's threads, the save (keeping the image when
 * it fails late) and the reports are the export pipeline it shares with
 * rt-export-mpi (apps/common/cli_export.h).  What is rt-export's own:
 * --check, which lists what the scene holds, and --explain, which prints
 * a pixel's ray tree instead of the image (apps/common/cli_explain.h).
 * Exit status: 0 success, 1 bad input or a failed write, 2 bad usage; a
 * signal during the save ends it killed by that signal, the previous file
 * intact.
 */
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "cli_explain.h"
#include "cli_export.h"
#include "cli_text.h"
#include "raytrace/raytrace.h"

#define EXIT_BAD_INPUT 1

static int check_only; /* --check */

static const cli_option export_options[] = {
    {"check", 0, NULL, CLI_FLAG, 0, 0, &check_only,
     "validate the scene and print what it holds; do not render"},
    CLI_OPTIONS_END,
};

static const cli_program program = {
    "rt-export", "SCENE",
    "Renders SCENE (a .scn scene, an NFF file, a Wavefront OBJ model or a\n"
    "PLY mesh, by its extension) to an image and prints the path it wrote.\n"
    "SCENE `-' reads the scene from standard input (then -o is needed).  The\n"
    "image goes to OUT (default: the scene's name with .ppm, or .png with\n"
    "--format png, in the current directory; `-o -' writes it to standard\n"
    "output and nothing else there); a device, FIFO or socket is\n"
    "written directly, a file is replaced atomically, keeping its mode,\n"
    "owner and links.  The progress line (stderr, on a terminal) shows the\n"
    "time left and the camera rays per second; --stats=json prints one\n"
    "JSON object on one line, the last line on stderr.  --explain X,Y\n"
    "prints why pixel X,Y has its colour instead of writing the image;\n"
    "--view writes a debug view in its place (docs/teaching.md).",
    "Exit status: 0 success, 1 bad scene or failed write, 2 bad usage.\n"
    "A signal during the save leaves the previous file intact.",
    CLI_GROUP_RENDER | CLI_GROUP_LOAD | CLI_GROUP_OUTPUT | CLI_GROUP_REPORT |
        CLI_GROUP_QUIET | CLI_GROUP_EXPLAIN | CLI_GROUP_VIEW,
    export_options, 1, 1, "expected a scene file"};

static void print_check(const char *path, const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    printf("%s: valid scene\n", path);
    printf("  image      %d x %d\n", info.width, info.height);
    printf("  vertices   %d\n", info.vertex_count);
    printf("  facets     %d (%d can be hit, %d reflective, %d "
           "transparent, %d smooth, %d with highlights)\n",
           info.facet_count, info.live_facet_count,
           info.reflective_facet_count, info.transparent_facet_count,
           info.smooth_facet_count, info.highlight_facet_count);
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
    char up[160];
    int said = cli_up_axis_text(scene, up, sizeof up);
    if (said)
        printf("  up axis    %s%s\n", up,
               said == 1 ? "; --up-axis picks another" : "");
    printf("  warnings   %d\n", info.warning_count);
    for (int i = 0; i < info.warning_count; i++)
        printf("  %s\n", rt_scene_warning(scene, i)->message);
}

/* --explain X,Y: the ray tree of that pixel, as text or JSON.  Returns an
 * exit status. */
static int explain(const rt_scene *scene, const cli_settings *s,
                   const char *scene_name)
{
    rt_ray_tree *tree;
    rt_error error;
    if (rt_explain_pixel(scene, &s->render, s->explain_x, s->explain_y, -1,
                         &tree, &error) != RT_OK) {
        fprintf(stderr, "rt-export: %s: cannot explain: %s\n", scene_name,
                error.message);
        return EXIT_BAD_INPUT;
    }
    if (s->explain_json)
        cli_explain_print_json(stdout, tree, scene_name, s->explain_x,
                               s->explain_y);
    else
        cli_explain_print_text(stdout, tree, scene_name, s->explain_x,
                               s->explain_y, s->render.samples);
    rt_ray_tree_destroy(tree);
    return EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
    cli_settings s;
    int code = cli_parse(&program, argc, argv, &s);
    if (code != CLI_CONTINUE)
        return code;
    cli_export ex;
    cli_export_init(&ex, &program, &s, NULL);
    /* --check writes nothing: no output to refuse */
    code = cli_export_load(&ex, !check_only);
    if (code == CLI_CONTINUE && check_only) {
        print_check(ex.name, ex.scene);
        code = EXIT_SUCCESS;
    } else if (code == CLI_CONTINUE) {
        cli_export_print_warnings(&ex);
        code = s.explain ? explain(ex.scene, &s, ex.name)
                         : cli_export_render(&ex);
    }
    cli_export_release(&ex);
    return code;
}
