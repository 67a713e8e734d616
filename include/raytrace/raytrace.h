/*
 * raytrace/raytrace.h - the whole public API of libraytrace in one include.
 *
 * libraytrace renders scenes of triangles Whitted style, as
 * docs/rendering-model.md describes: point lights (up to RT_MAX_LIGHTS)
 * casting hard shadows, mirror reflection and refraction through glass up
 * to a bounded depth, a pinhole or thin-lens camera, one or several rays a
 * pixel.  A scene is read from a .scn, NFF or OBJ file (its MTL libraries
 * through a resolver the caller may replace) or built from a description
 * in memory (raytrace/scene.h); it is immutable once built, and any number
 * of threads may render it.  A render (raytrace/render.h) is exact in
 * double precision and faster in float, by brute force or through an
 * octree that gives the same bytes, on as many threads as asked, and can
 * be cancelled; images are saved as PPM (or PNG, in a build with libpng)
 * without ever leaving a half-written file (raytrace/image.h);
 * rt_explain_pixel tells how a pixel got its colour (raytrace/explain.h).
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
