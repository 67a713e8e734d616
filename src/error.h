/*
 * error.h - filling an rt_error (internal).
 */
#ifndef RAYTRACE_ERROR_H
#define RAYTRACE_ERROR_H

#include "raytrace/status.h"

#if defined(__GNUC__)
#define RT_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define RT_PRINTF_LIKE(f, a)
#endif

/*
 * Sets *error (when not NULL) to status at (line, column) with a message
 * formatted by fmt; the message is prefixed with "name:line:column: " when
 * line > 0, with "name: " when line == 0 and name != NULL.  Returns status.
 */
rt_status rt__error_set(rt_error *error, rt_status status, const char *name,
                        int line, int column, const char *fmt, ...)
    RT_PRINTF_LIKE(6, 7);

#endif /* RAYTRACE_ERROR_H */
