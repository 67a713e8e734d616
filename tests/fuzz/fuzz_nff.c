/*
 * fuzz_nff.c - libFuzzer harness for the NFF reader (src/formats/nff.c)
 * and the tessellation of its spheres, cones and polygons.
 *
 * Each input is parsed as NFF from an exact-size heap copy (no NUL after
 * it: AddressSanitizer sees any read past the end).  As in fuzz_scene.c, a
 * refusal must carry a non-empty, NUL-terminated message and no scene; a
 * scene that loads is asked every question the public API allows and a few
 * of its pixels are traced.
 *
 * The default tolerance follows the file's view and may give a sphere
 * some 10^5 facets (a close sphere at 16384 pixels); so that one input
 * stays within the run's memory and time limits, inputs with more than
 * two bytes `s` or `c` (the sphere and cone entities) are read with a
 * coarse tolerance (0.3) instead.  Both paths are fuzzed.
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

static void check_refusal(rt_status status, const rt_scene *scene,
                          const rt_error *error)
{
    require(scene == NULL);
    require(error->status == status);
    require(memchr(error->message, '\0', sizeof error->message) != NULL);
    require(error->message[0] != '\0');
    require(error->line >= 0 && error->column >= 0);
}

static void inspect(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    require(info.width >= 1 && info.width <= RT_MAX_IMAGE_SIDE);
    require(info.height >= 1 && info.height <= RT_MAX_IMAGE_SIDE);
    require(info.vertex_count >= 0 && info.facet_count >= 0);
    require(info.live_facet_count <= info.facet_count);
    require(info.light_count >= 1);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info facet = {.size = sizeof facet};
        rt_scene_facet(scene, i, &facet);
        for (int j = 0; j < 3; j++)
            require(facet.vertex[j] >= 0 &&
                    facet.vertex[j] < info.vertex_count);
        require(facet.reflection >= 0.0 && facet.transparency >= 0.0 &&
                facet.reflection + facet.transparency <= 1.0);
        require(facet.diffuse >= 0.0 && facet.refractive_index > 0.0);
    }
    for (int i = 0; i < info.light_count; i++) {
        rt_light light;
        rt_scene_light(scene, i, &light);
    }
    for (int i = 0; i < info.warning_count; i++) {
        const rt_warning *w = rt_scene_warning(scene, i);
        require(memchr(w->message, '\0', sizeof w->message) != NULL);
    }
    const rt_camera *camera = &info.camera;
    int xs[3] = {0, camera->width / 2, camera->width - 1};
    int ys[3] = {0, camera->height / 2, camera->height - 1};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            rt_color c = rt_trace(scene, rt_camera_ray(camera, xs[a], ys[b]),
                                  2);
            (void)rt_channel_to_byte(c.r);
            (void)rt_channel_to_byte(c.g);
            (void)rt_channel_to_byte(c.b);
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size ? size : 1);
    if (text == NULL)
        return 0;
    if (size)
        memcpy(text, data, size);
    size_t curved = 0;
    for (size_t i = 0; i < size; i++)
        curved += data[i] == 's' || data[i] == 'c';
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_NFF;
    options.tessellation = curved > 2 ? 0.3 : 0.0;
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    memset(&error, 0x55, sizeof error);
    rt_status status =
        rt_scene_parse(text, size, "fuzz.nff", &options, &scene, &error);
    if (status == RT_OK) {
        require(scene != NULL);
        inspect(scene);
        rt_scene_destroy(scene);
    } else {
        check_refusal(status, scene, &error);
    }
    free(text);
    return 0;
}
