/*
 * fuzz_ply.c - libFuzzer harness for the PLY reader, ASCII and binary.
 *
 * An input is a PLY file, parsed from an exact-size heap copy (no NUL
 * after it: AddressSanitizer sees any read past the end) with the name
 * "fuzz.ply", so that the loader picks the PLY reader from the extension.
 * As in fuzz_obj.c, a refusal must carry a non-empty message and no
 * scene; a scene that loads is asked what the public API allows about
 * its facets, warnings and camera, and a few of its pixels are traced.
 *
 * Built only with -DRAYTRACE_FUZZ=ON and clang (tests/fuzz/CMakeLists.txt).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "raytrace/raytrace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void require(int condition)
{
    if (!condition)
        abort();
}

static void inspect(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    require(info.width == 32 && info.height == 32);
    require(info.live_facet_count <= info.facet_count);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info facet = {.size = sizeof facet};
        rt_scene_facet(scene, i, &facet);
        /* no facet without area is made (the cut drops them) */
        require(facet.degenerate != RT_FACET_ZERO_AREA);
        for (int j = 0; j < 3; j++)
            require(facet.vertex[j] >= 0 &&
                    facet.vertex[j] < info.vertex_count);
        require(facet.reflection == 0.0 && facet.transparency == 0.0);
    }
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 p = rt_scene_vertex(scene, i);
        require(p.x == p.x && p.y == p.y && p.z == p.z);
    }
    for (int i = 0; i < info.warning_count; i++) {
        const rt_warning *w = rt_scene_warning(scene, i);
        require(memchr(w->message, '\0', sizeof w->message) != NULL);
    }
    const rt_camera *c = &info.camera;
    int xs[3] = {0, c->width / 2, c->width - 1};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            rt_color color =
                rt_trace(scene, rt_camera_ray(c, xs[a], xs[b]), 2);
            (void)rt_channel_to_byte(color.r);
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *copy = malloc(size ? size : 1);
    if (copy == NULL)
        return 0;
    if (size)
        memcpy(copy, data, size);
    rt_load_options options;
    rt_load_options_init(&options);
    options.width = options.height = 32;
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    memset(&error, 0x55, sizeof error);
    rt_status status =
        rt_scene_parse(copy, size, "fuzz.ply", &options, &scene, &error);
    if (status == RT_OK) {
        require(scene != NULL);
        inspect(scene);
        rt_scene_destroy(scene);
    } else {
        require(scene == NULL);
        require(error.status == status);
        require(memchr(error.message, '\0', sizeof error.message) != NULL);
        require(error.message[0] != '\0');
        require(error.line >= 0 && error.column >= 0);
    }
    free(copy);
    return 0;
}
