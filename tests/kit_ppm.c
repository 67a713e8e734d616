/*
 * kit_ppm.c - the image checks of the course-kit tests (tests/kit.cmake,
 * tests/in104.cmake): reads 8-bit PPM files, binary (P6) or ASCII (P3),
 * and compares their pixels, whatever the format and the layout of the
 * text.
 *
 *   kit_ppm compare EXPECTED ACTUAL [TOLERANCE MAX_PIXELS]
 *       same size, and at most MAX_PIXELS pixels (default 0) with a
 *       channel more than TOLERANCE (default 0) away from EXPECTED's;
 *       prints the count and the largest difference either way.
 *   kit_ppm gradient ACTUAL WIDTH HEIGHT
 *       ACTUAL is exactly the gradient the kit's tests_imgsdl-style
 *       programs draw: (255x/(w-1), 255y/(h-1), 255(x+y)/(w+h-2)).
 *
 * Exit status: 0 when the check holds, 1 when it does not, 2 on bad usage
 * or an unreadable file (with a message naming it).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct picture {
    int width, height;
    unsigned char *rgb; /* width * height * 3 bytes, rows from the top */
} picture;

/* The next decimal number of a PPM header or P3 body, skipping white
 * space and # comments; -1 at the end or on anything else. */
static long next_number(FILE *file)
{
    int c = fgetc(file);
    long value = 0;

    for (;;) {
        while (' ' == c || '\t' == c || '\n' == c || '\r' == c)
            c = fgetc(file);
        if ('#' != c)
            break;
        while (EOF != c && '\n' != c)
            c = fgetc(file);
    }
    if (c < '0' || c > '9')
        return -1;
    while (c >= '0' && c <= '9' && value < 1000000) {
        value = value * 10 + (c - '0');
        c = fgetc(file);
    }
    return value;
}

static int load(const char *path, picture *p)
{
    FILE *file = fopen(path, "rb");
    char magic[3] = "";
    long width, height, maxval;
    size_t count;
    int ok = 1;

    if (NULL == file) {
        perror(path);
        return 0;
    }
    if (2 != fread(magic, 1, 2, file) ||
        (strcmp(magic, "P6") != 0 && strcmp(magic, "P3") != 0)) {
        fprintf(stderr, "%s: not a P3 or P6 file\n", path);
        fclose(file);
        return 0;
    }
    width = next_number(file);
    height = next_number(file);
    maxval = next_number(file);
    if (width < 1 || height < 1 || width > 16384 || height > 16384 ||
        255 != maxval) {
        fprintf(stderr, "%s: expected a width, a height and 255\n", path);
        fclose(file);
        return 0;
    }
    p->width = (int)width;
    p->height = (int)height;
    count = (size_t)width * (size_t)height * 3;
    p->rgb = malloc(count);
    if (NULL == p->rgb) {
        fprintf(stderr, "%s: out of memory\n", path);
        fclose(file);
        return 0;
    }
    if ('6' == magic[1]) {
        ok = count == fread(p->rgb, 1, count, file);
    } else {
        for (size_t i = 0; ok && i < count; i++) {
            long v = next_number(file);
            ok = v >= 0 && v <= 255;
            p->rgb[i] = (unsigned char)v;
        }
    }
    fclose(file);
    if (!ok) {
        fprintf(stderr, "%s: fewer pixels than %ldx%ld\n", path, width,
                height);
        free(p->rgb);
    }
    return ok;
}

static int compare(const picture *expected, const picture *actual,
                   int tolerance, long max_pixels)
{
    long over = 0, total = (long)expected->width * expected->height;
    int largest = 0;

    if (expected->width != actual->width ||
        expected->height != actual->height) {
        printf("sizes differ: expected %dx%d, found %dx%d\n", expected->width,
               expected->height, actual->width, actual->height);
        return 1;
    }
    for (long i = 0; i < total; i++) {
        int worst = 0;
        for (int c = 0; c < 3; c++) {
            int d = abs(expected->rgb[3 * i + c] - actual->rgb[3 * i + c]);
            if (d > worst)
                worst = d;
        }
        if (worst > largest)
            largest = worst;
        if (worst > tolerance)
            over++;
    }
    printf("%ld of %ld pixels differ by more than %d (allowed: %ld); "
           "largest difference %d\n",
           over, total, tolerance, max_pixels, largest);
    return over <= max_pixels ? 0 : 1;
}

static void gradient(picture *p, int width, int height)
{
    p->width = width;
    p->height = height;
    p->rgb = malloc((size_t)width * (size_t)height * 3);
    if (NULL == p->rgb)
        exit(2);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            unsigned char *at = p->rgb + 3 * ((size_t)y * width + x);
            at[0] = (unsigned char)(255 * x / (width > 1 ? width - 1 : 1));
            at[1] = (unsigned char)(255 * y / (height > 1 ? height - 1 : 1));
            at[2] = (unsigned char)(255 * (x + y) /
                                    (width + height > 2 ? width + height - 2
                                                        : 1));
        }
}

int main(int argc, char **argv)
{
    picture expected, actual;
    int status;

    if (argc >= 4 && 0 == strcmp(argv[1], "compare") &&
        (4 == argc || 6 == argc)) {
        if (!load(argv[2], &expected))
            return 2;
        if (!load(argv[3], &actual)) {
            free(expected.rgb);
            return 2;
        }
        status = compare(&expected, &actual, 6 == argc ? atoi(argv[4]) : 0,
                         6 == argc ? atol(argv[5]) : 0);
    } else if (5 == argc && 0 == strcmp(argv[1], "gradient")) {
        int width = atoi(argv[3]), height = atoi(argv[4]);
        if (width < 1 || height < 1 || width > 16384 || height > 16384) {
            fprintf(stderr, "kit_ppm: bad size %sx%s\n", argv[3], argv[4]);
            return 2;
        }
        if (!load(argv[2], &actual))
            return 2;
        gradient(&expected, width, height);
        status = compare(&expected, &actual, 0, 0);
    } else {
        fprintf(stderr,
                "usage: kit_ppm compare EXPECTED ACTUAL [TOLERANCE MAX_PIXELS]\n"
                "       kit_ppm gradient ACTUAL WIDTH HEIGHT\n");
        return 2;
    }
    free(expected.rgb);
    free(actual.rgb);
    return status;
}
