/*
 * util.h - the IN 104 course's libutil, rebuilt (library raytrace-util,
 * companion of raytrace-in104): fastInvSqrt and splitLine, with the
 * handout's signatures, so a course project that used the course's
 * libutil.a links unchanged against this one.
 *
 * The library has no dependency (not even libraytrace or libm) and no
 * state; both functions may run in several threads at once on different
 * arguments.
 *
 * Build:   cc -Iinclude -I<prefix>/include/in104 prog.c <prefix>/lib/libraytrace-util.a
 *     or   cc prog.c -L<prefix>/lib -lraytrace-util
 *     or   cc prog.c $(pkg-config --cflags --libs raytrace-util)
 *     or   find_package(raytrace) and the target raytrace::util
 * (the library is not called libutil: glibc already has a libutil.)
 */
#ifndef IN104_UTIL_H
#define IN104_UTIL_H

#ifdef __cplusplus
extern "C" {
#endif

/*
 * An approximation of 1 / sqrt(x), the handout's: the bit-level first guess
 * 0x5f3759df - (bits(x) >> 1) refined by one Newton step,
 * y * (1.5f - 0.5f * x * y * y).  The same function, bit for bit, as the one
 * rt-export --fast-sqrt --precision float normalises with.
 *
 * For a positive, finite, normal x the relative error is below 0.18 %
 * (about 1.75e-3 at worst): fastInvSqrt(4.0f) is about 0.49915, not 0.5.
 * Other arguments give no error and no trap, but nothing meaningful:
 * x = 0 gives about 1.98e19 instead of infinity, a negative x or a NaN a
 * negative number or a NaN.  Thread-safe.
 */
float fastInvSqrt(float x);

/*
 * Splits the line `buf` into words, in place, and stores a pointer to each
 * word in out[0], out[1], ..., as the handout's parser uses it:
 *
 *     char line[256], *words[8];
 *     fgets(line, sizeof line, file);            "3,-3,-1, 3,-9,0, 400,400\n"
 *     splitLine(line, words, 8);                  words: "3" "-3" "-1" "3"
 *     double x = atof(words[0]);                         "-9" "0" "400" "400"
 *
 * - Separators are commas and white space: ' ', '\t', '\n', '\r', '\v' and
 *   '\f' (so the '\n' that fgets keeps never ends a word).  Every other
 *   byte, '#' included, belongs to a word.
 * - A run of separators counts as one: "1, 2,,3" gives "1" "2" "3" (there
 *   are no empty words); separators before the first word and after the
 *   last are ignored.
 * - At most `size` words are stored.  When the line has fewer, every slot
 *   after the last word is set to NULL, so the first NULL ends the list and
 *   an empty line (or one of separators only) gives out[0] == NULL.  When
 *   it has `size` words or more, out is full and the words beyond the
 *   size-th are ignored: pass one slot more than the words you expect and
 *   check that out[expected] is NULL to detect a line that is too long.
 * - buf is modified: the separator that follows each stored word is
 *   replaced by '\0'; nothing after the size-th word is touched.  The words
 *   point into buf and live as long as it does.
 * - size <= 0 stores nothing.  buf must be a NUL-terminated string and out
 *   an array of at least size pointers (neither may be NULL when size > 0).
 *
 * Thread-safe on distinct buffers.
 */
void splitLine(char *buf, char **out, int size);

#ifdef __cplusplus
}
#endif

#endif /* IN104_UTIL_H */
