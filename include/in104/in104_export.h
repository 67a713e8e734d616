/*
 * in104_export.h - which declarations a shared libraytrace-in104 exports.
 *
 * The course layer is compiled with hidden visibility, so a shared build
 * exports only the handout's functions, marked IN104_API in geometry.h's
 * companions intersection.h and raytracer.h, and none of its own helpers
 * (as raytrace/export.h does for libraytrace).
 */
#ifndef IN104_EXPORT_H
#define IN104_EXPORT_H

#if defined(__GNUC__) || defined(__clang__)
#define IN104_API __attribute__((visibility("default")))
#else
#define IN104_API
#endif

#endif /* IN104_EXPORT_H */
