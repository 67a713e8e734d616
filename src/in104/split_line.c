/*
 * split_line.c - splitLine() of the course's libutil (util.h): cuts a line
 * into words at commas and white space, in place.  The rules (runs of
 * separators, too many words, the NULL end mark) are util.h's.
 */
#include "util.h"

#include <assert.h>
#include <stddef.h>

static int is_separator(char c)
{
    return ',' == c || ' ' == c || '\t' == c || '\n' == c || '\r' == c ||
           '\v' == c || '\f' == c;
}

void splitLine(char *buf, char **out, int size)
{
    int count = 0;

    if (size <= 0)
        return;
    assert(buf != NULL && out != NULL);
    while (count < size) {
        while (*buf != '\0' && is_separator(*buf))
            buf++;
        if ('\0' == *buf)
            break;
        out[count++] = buf;
        while (*buf != '\0' && !is_separator(*buf))
            buf++;
        if (*buf != '\0')
            *buf++ = '\0';
    }
    for (int i = count; i < size; i++)
        out[i] = NULL;
}
