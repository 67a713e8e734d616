/*
 * error.c - formatting error reports in the GNU "file:line:column: " form.
 */
#include "error.h"

#include <stdarg.h>
#include <stdio.h>

rt_status rt__error_set(rt_error *error, rt_status status, const char *name,
                        int line, int column, const char *fmt, ...)
{
    if (error == NULL)
        return status;
    error->status = status;
    error->line = line;
    error->column = column;
    size_t size = sizeof error->message;
    int used = 0;
    if (name != NULL && line > 0)
        used = snprintf(error->message, size, "%s:%d:%d: ", name, line, column);
    else if (name != NULL)
        used = snprintf(error->message, size, "%s: ", name);
    if (used < 0 || (size_t)used >= size)
        used = 0;
    va_list args;
    va_start(args, fmt);
    vsnprintf(error->message + used, size - (size_t)used, fmt, args);
    va_end(args);
    return status;
}
