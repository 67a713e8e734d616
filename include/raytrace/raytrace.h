/*
 * raytrace/raytrace.h - the whole public API of libraytrace in one include.
 *
 * libraytrace renders scenes of triangles lit by one point light, Whitted
 * style (hard shadows, mirror reflections), as docs/rendering-model.md
 * describes.
 *
 *     rt_scene *scene;
 *     rt_error error;
 *     if (rt_scene_load("cubes.scn", NULL, &scene, &error) != RT_OK) {
 *         fprintf(stderr, "%s\n", error.message);
 *         return 1;
 *     }
 *     rt_scene_info info = {.size = sizeof info};
 *     rt_scene_get_info(scene, &info);
 *     rt_image image;
 *     if (rt_image_init(&image, info.width, info.height, &error) != RT_OK ||
 *         rt_render(scene, NULL, &image, &error) != RT_OK ||  (NULL: defaults)
 *         rt_image_save("cubes.ppm", &image, RT_IMAGE_P6, NULL, &error) !=
 *             RT_OK)
 *         fprintf(stderr, "%s\n", error.message);
 *     rt_image_release(&image);
 *     rt_scene_destroy(scene);
 *
 * Rules that hold everywhere (docs/api.md): public names start with rt_ /
 * RT_; _create/_destroy for objects the library allocates, _init/_release
 * for storage the caller owns; fallible functions return rt_status and take
 * a last rt_error * (may be NULL) that they fill with a message saying what
 * was wrong; out-pointers are NULL after a failure and nothing leaks; option
 * structs carry their size (raytrace/render.h), and so do the structs the
 * library fills (raytrace/scene.h, above rt_facet_info); the library has
 * no global mutable state, never prints, never exits; each function states
 * its thread-safety.
 */
#ifndef RAYTRACE_RAYTRACE_H
#define RAYTRACE_RAYTRACE_H

#include "raytrace/explain.h"
#include "raytrace/image.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"
#include "raytrace/status.h"
#include "raytrace/vec3.h"
#include "raytrace/version.h"

#endif /* RAYTRACE_RAYTRACE_H */
