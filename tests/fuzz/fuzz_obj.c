/*
 * fuzz_obj.c - libFuzzer harness for the Wavefront OBJ reader and its
 * material libraries.
 *
 * An input is an OBJ, optionally followed by a line `#mtl` and the text of
 * a material library.  The library is written to m.mtl in a private
 * temporary folder (made once), and the OBJ is parsed from an exact-size
 * heap copy (no NUL after it: AddressSanitizer sees any read past the end)
 * with the name "<folder>/fuzz.obj" and a resolver that reads through
 * rt_resolve_in_folder, so `mtllib m.mtl` reads the library and every
 * other name meets the resolver's rules (`../x`, `/etc/passwd`, links),
 * except `fuzz.obj` itself, which it serves from the OBJ's own bytes (an
 * OBJ naming itself: the loader must know it).  As in
 * fuzz_scene.c, a refusal must carry a non-empty message and no scene; a
 * scene that loads is asked every question the public API allows and a few
 * of its pixels are traced.
 *
 * Built only with -DRAYTRACE_FUZZ=ON and clang (tests/fuzz/CMakeLists.txt).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "raytrace/raytrace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void require(int condition)
{
    if (!condition)
        abort();
}

static char folder[64];
static char obj_name[96], mtl_name[96];

static void remove_folder(void)
{
    unlink(mtl_name);
    rmdir(folder);
}

/* The folder of m.mtl, made on the first call. */
static int prepare(void)
{
    if (folder[0] != '\0')
        return 1;
    strcpy(folder, "/tmp/fuzz_obj.XXXXXX");
    if (mkdtemp(folder) == NULL)
        return 0;
    snprintf(obj_name, sizeof obj_name, "%s/fuzz.obj", folder);
    snprintf(mtl_name, sizeof mtl_name, "%s/m.mtl", folder);
    atexit(remove_folder);
    return 1;
}

static void write_library(const uint8_t *data, size_t size)
{
    FILE *file = fopen(mtl_name, "wb");
    if (file == NULL)
        return;
    if (size > 0)
        fwrite(data, 1, size, file);
    fclose(file);
}

/* The OBJ being parsed, which the resolver serves as "fuzz.obj". */
static const char *obj_text;
static size_t obj_length;

static rt_status resolve(void *user, const char *scene_name,
                         const char *reference, size_t limit,
                         rt_resolved_file *file, rt_error *error)
{
    const char *name = reference;
    while (name[0] == '.' && name[1] == '/')
        name += 2;
    if (strcmp(name, "fuzz.obj") != 0 || obj_length > limit)
        return rt_resolve_in_folder(user, scene_name, reference, limit, file,
                                    error);
    file->data = malloc(obj_length ? obj_length : 1);
    file->name = malloc(9);
    if (file->data == NULL || file->name == NULL) {
        free(file->data);
        free(file->name);
        return RT_ERR_NOMEM;
    }
    if (obj_length)
        memcpy(file->data, obj_text, obj_length);
    memcpy(file->name, "fuzz.obj", 9);
    file->length = obj_length;
    file->device = file->inode = 0;
    return RT_OK;
}

static void inspect(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    require(info.width >= 1 && info.width <= RT_MAX_IMAGE_SIDE);
    require(info.height >= 1 && info.height <= RT_MAX_IMAGE_SIDE);
    require(info.live_facet_count <= info.facet_count);
    require(rt_scene_source_count(scene) <= 1 + 1024);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info facet = {.size = sizeof facet};
        rt_scene_facet(scene, i, &facet);
        /* No facet without area is made (the triangulator drops them);
         * repeats of the facet before may be left out by the builder. */
        require(facet.degenerate != RT_FACET_ZERO_AREA);
        for (int j = 0; j < 3; j++)
            require(facet.vertex[j] >= 0 &&
                    facet.vertex[j] < info.vertex_count);
        require(facet.reflection >= 0.0 && facet.transparency >= 0.0 &&
                facet.reflection + facet.transparency <= 1.0);
        require(facet.refractive_index > 0.0 && facet.diffuse >= 0.0);
    }
    for (int i = 0; i < info.warning_count; i++) {
        const rt_warning *w = rt_scene_warning(scene, i);
        require(memchr(w->message, '\0', sizeof w->message) != NULL);
    }
    /* Every vertex of a facet lies in front of the automatic camera. */
    const rt_camera *c = &info.camera;
    rt_vec3 ao = {c->screen_center.x - c->observer.x,
                  c->screen_center.y - c->observer.y,
                  c->screen_center.z - c->observer.z};
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info facet = {.size = sizeof facet};
        rt_scene_facet(scene, i, &facet);
        rt_vec3 p = rt_scene_vertex(scene, facet.vertex[0]);
        double along = (p.x - c->observer.x) * ao.x +
                       (p.y - c->observer.y) * ao.y +
                       (p.z - c->observer.z) * ao.z;
        require(along > 0.0 || along != along);
    }
    int xs[3] = {0, c->width / 2, c->width - 1};
    int ys[3] = {0, c->height / 2, c->height - 1};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            rt_color color = rt_trace(scene, rt_camera_ray(c, xs[a], ys[b]),
                                      2);
            (void)rt_channel_to_byte(color.r);
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!prepare())
        return 0;
    static const char marker[] = "\n#mtl\n";
    size_t obj_size = size;
    for (size_t i = 0; i + sizeof marker - 1 <= size; i++)
        if (memcmp(data + i, marker, sizeof marker - 1) == 0) {
            obj_size = i + 1;
            break;
        }
    if (obj_size < size)
        write_library(data + obj_size + sizeof marker - 2,
                      size - obj_size - (sizeof marker - 2));
    else
        unlink(mtl_name);
    char *text = malloc(obj_size ? obj_size : 1);
    if (text == NULL)
        return 0;
    if (obj_size)
        memcpy(text, data, obj_size);
    rt_load_options options;
    rt_load_options_init(&options);
    options.width = options.height = 32;
    options.resolve = resolve;
    obj_text = text;
    obj_length = obj_size;
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    memset(&error, 0x55, sizeof error);
    rt_status status =
        rt_scene_parse(text, obj_size, obj_name, &options, &scene, &error);
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
    free(text);
    return 0;
}
