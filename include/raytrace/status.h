/*
 * raytrace/status.h - status codes and error reports.
 *
 * Every fallible function of libraytrace returns an rt_status and, when the
 * caller passes a non-NULL rt_error, fills it with the status, the position
 * in the input (for scene files and images) and a one-line message in the
 * GNU form "path:line:column: expected ..., found ...".  The library keeps no
 * "last error": the report travels with the call, so every function stays
 * reentrant.
 */
#ifndef RAYTRACE_STATUS_H
#define RAYTRACE_STATUS_H

#include "raytrace/export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* X(name, value, description): one table makes both the enum and the strings. */
#define RT_STATUS_MAP(X)                                                     \
    X(RT_OK, 0, "success")                                                   \
    X(RT_ERR_NOMEM, 1, "out of memory")                                      \
    X(RT_ERR_IO, 2, "input/output error")                                    \
    X(RT_ERR_SYNTAX, 3, "syntax error")                                      \
    X(RT_ERR_RANGE, 4, "value out of range")                                 \
    X(RT_ERR_CAMERA, 5, "degenerate camera")                                 \
    X(RT_ERR_LIMIT, 6, "input exceeds a limit")                              \
    X(RT_ERR_ARGUMENT, 7, "invalid argument")                                \
    X(RT_ERR_CANCELLED, 8, "cancelled")                                      \
    X(RT_ERR_FORMAT, 9, "unsupported image format")                          \
    X(RT_ERR_INTERRUPTED, 10, "interrupted by a signal")

typedef enum rt_status {
#define RT_STATUS_ENUM_(name, value, text) name = value,
    RT_STATUS_MAP(RT_STATUS_ENUM_)
#undef RT_STATUS_ENUM_
} rt_status;

/* Longest message an rt_error holds, including the terminating NUL. */
#define RT_ERROR_MESSAGE_SIZE 512

/*
 * What went wrong, and where.  line and column are 1-based positions in the
 * input (columns count bytes, a UTF-8 byte-order mark excluded); both are 0
 * when the error has no position (out of memory, a file that cannot be
 * opened).  message is always NUL-terminated and never empty on failure.
 */
typedef struct rt_error {
    rt_status status;
    int line;
    int column;
    char message[RT_ERROR_MESSAGE_SIZE];
} rt_error;

/* A short English description of status ("syntax error").  Never NULL; an
 * unknown value gives "unknown status".  Thread-safe. */
RT_API const char *rt_status_string(rt_status status);

#ifdef __cplusplus
}
#endif

#endif /* RAYTRACE_STATUS_H */
