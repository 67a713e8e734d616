/*
 * raytrace/export.h - which declarations a shared libraytrace exports.
 *
 * The library is compiled with hidden visibility, so a shared build exports
 * only what its public headers mark RT_API: the rt_ functions of
 * raytrace/raytrace.h, never the library's internal functions.  In a static
 * build the mark is harmless (a program or library that links the archive
 * into a shared object of its own may hide it with -Wl,--exclude-libs).
 */
#ifndef RAYTRACE_EXPORT_H
#define RAYTRACE_EXPORT_H

#if defined(__GNUC__) || defined(__clang__)
#define RT_API __attribute__((visibility("default")))
#else
#define RT_API
#endif

#endif /* RAYTRACE_EXPORT_H */
