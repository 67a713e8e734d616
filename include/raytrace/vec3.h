/*
 * raytrace/vec3.h - the plain value types shared by the whole API.
 *
 * Points, vectors, rays and colours are transparent structs passed by value;
 * they own nothing.  The arithmetic on them lives in the library (it is not
 * API): callers build them with compound literals, e.g. (rt_vec3){1, 2, 3}.
 */
#ifndef RAYTRACE_VEC3_H
#define RAYTRACE_VEC3_H

#ifdef __cplusplus
extern "C" {
#endif

/* A point or a vector in scene space. */
typedef struct rt_vec3 {
    double x, y, z;
} rt_vec3;

/* A half-line: origin + t * direction for t > 0.  direction need not be unit
 * length unless a function says so. */
typedef struct rt_ray {
    rt_vec3 origin;
    rt_vec3 direction;
} rt_ray;

/* An 8-bit RGB colour, as read from scene files and written to images. */
typedef struct rt_rgb8 {
    unsigned char r, g, b;
} rt_rgb8;

/* A real-valued RGB colour, nominally in [0, 255] per channel.  Rendering
 * keeps colours real through the recursion and rounds once per pixel. */
typedef struct rt_color {
    double r, g, b;
} rt_color;

#ifdef __cplusplus
}
#endif

#endif /* RAYTRACE_VEC3_H */
