/*
 * raytrace/raytrace.h - the whole public API of libraytrace in one include.
 *
 * libraytrace renders scenes of triangles lit by one point light, Whitted
 * style (hard shadows, mirror reflections), as docs/rendering-model.md
 * describes.
 *
 *     rt_scene *scene;
 *     rt_error error;
 *     if (rt_scene_load("cubes.scn", &scene, &error) != RT_OK) {
 *         fprintf(stderr, "%s\n", error.message);
 *         return 1;
 *     }
 *     rt_scene_info info;
 *     rt_scene_get_info(scene, &info);
 *     rt_image image;
 *     rt_image_init(&image, info.width, info.height);
 *     rt_render(scene, NULL, &image);            (NULL: default options)
 *     rt_ppm_save("cubes.ppm", &image, RT_PPM_P6, &error);
 *     rt_image_release(&image);
 *     rt_scene_destroy(scene);
 *
 * Rules that hold everywhere: public names start with rt_ / RT_; fallible
 * functions return rt_status and fill an optional rt_error; out-pointers are
 * NULL after a failure and nothing leaks; the library has no global mutable
 * state, never prints, never exits; each function states its thread-safety.
 */
#ifndef RAYTRACE_RAYTRACE_H
#define RAYTRACE_RAYTRACE_H

#include "raytrace/image.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"
#include "raytrace/status.h"
#include "raytrace/vec3.h"
#include "raytrace/version.h"

#endif /* RAYTRACE_RAYTRACE_H */
