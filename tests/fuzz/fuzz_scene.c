/*
 * fuzz_scene.c - libFuzzer harness for the scene loader from memory.
 *
 * Each input is handed to rt_scene_parse exactly as a program would hand it
 * an untrusted buffer (no terminating NUL: the copy is exactly `size` bytes,
 * so AddressSanitizer sees any read past the end).  A refusal must carry a
 * non-empty, NUL-terminated message and a status other than RT_OK; a scene
 * that loads is then asked every question the public API allows and a few
 * of its pixels are traced, so that whatever the loader accepts is also safe
 * to render (a scene that loads can be rendered).
 *
 * Built only with -DRAYTRACE_FUZZ=ON and clang (tests/fuzz/CMakeLists.txt).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "raytrace/raytrace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Aborts (a finding for libFuzzer) when a contract of the API is broken. */
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

/* Traces the four corner pixels and the centre: bounded work per input. */
static void trace_some_pixels(const rt_scene *scene, const rt_scene_info *info)
{
    const rt_camera *camera = &info->camera;
    int xs[3] = {0, camera->width / 2, camera->width - 1};
    int ys[3] = {0, camera->height / 2, camera->height - 1};
    for (int a = 0; a < 3; a++) {
        for (int b = 0; b < 3; b++) {
            rt_ray ray = rt_camera_ray(camera, xs[a], ys[b]);
            rt_color c = rt_trace(scene, ray, 2);
            (void)rt_channel_to_byte(c.r);
            (void)rt_channel_to_byte(c.g);
            (void)rt_channel_to_byte(c.b);
        }
    }
}

static void inspect(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    require(info.width >= 1 && info.width <= RT_MAX_IMAGE_SIDE);
    require(info.height >= 1 && info.height <= RT_MAX_IMAGE_SIDE);
    require(info.vertex_count >= 0 && info.facet_count >= 0);
    require(info.live_facet_count <= info.facet_count);
    for (int i = 0; i < info.vertex_count; i++)
        (void)rt_scene_vertex(scene, i);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info facet = {.size = sizeof facet};
        rt_scene_facet(scene, i, &facet);
        for (int j = 0; j < 3; j++)
            require(facet.vertex[j] >= 0 &&
                    facet.vertex[j] < info.vertex_count);
        require(facet.reflection >= 0.0 && facet.reflection <= 1.0);
    }
    for (int i = 0; i < info.warning_count; i++) {
        const rt_warning *w = rt_scene_warning(scene, i);
        require(memchr(w->message, '\0', sizeof w->message) != NULL);
    }
    trace_some_pixels(scene, &info);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* An exact-size heap copy: no NUL after it, red zone right behind. */
    char *text = malloc(size ? size : 1);
    if (text == NULL)
        return 0;
    if (size)
        memcpy(text, data, size);
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    memset(&error, 0x55, sizeof error);
    rt_status status =
        rt_scene_parse(text, size, "fuzz.scn", NULL, &scene, &error);
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
