/* parse.c - reads a .scn file (the handout's format) with util.h's
 * splitLine: one record a line, '#' starts a comment, numbers separated by
 * commas and spaces. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytracer.h"
#include "util.h"

#define MAX_WORDS 16

typedef struct sreader {
    FILE *file;
    const char *name;
    int line;
    double values[MAX_WORDS];
} reader;

/* Reads the next record of exactly `count` numbers into r->values; 0 on
 * success, else a message naming the file and the line. */
static int readRecord(reader *r, int count, const char *what)
{
    char buf[1024], *words[MAX_WORDS + 1];
    int n;

    for (;;) {
        if (NULL == fgets(buf, sizeof buf, r->file)) {
            fprintf(stderr, "%s: the file ends before the %s\n", r->name, what);
            return 1;
        }
        r->line++;
        splitLine(buf, words, MAX_WORDS + 1);
        for (n = 0; n <= MAX_WORDS && NULL != words[n] && '#' != words[n][0];)
            n++;
        if (n > 0)
            break;
    }
    if (n != count) {
        fprintf(stderr, "%s:%d: expected %d numbers for the %s, found %d\n",
                r->name, r->line, count, what, n);
        return 1;
    }
    for (n = 0; n < count; n++) {
        char *end;
        r->values[n] = strtod(words[n], &end);
        if (end == words[n] || '\0' != *end) {
            fprintf(stderr, "%s:%d: \"%s\" is not a number (%s)\n", r->name,
                    r->line, words[n], what);
            return 1;
        }
    }
    return 0;
}

static point toPoint(const double *v)
{
    point p = {v[0], v[1], v[2]};
    return p;
}

static int toComponent(double v)
{
    return v >= 0 && v <= 255 && (int)v == v;
}

static int toColor(const reader *r, const double *v, color *c)
{
    if (!toComponent(v[0]) || !toComponent(v[1]) || !toComponent(v[2])) {
        fprintf(stderr, "%s:%d: colours are whole numbers from 0 to 255\n",
                r->name, r->line);
        return 1;
    }
    c->r = (unsigned char)v[0];
    c->g = (unsigned char)v[1];
    c->b = (unsigned char)v[2];
    return 0;
}

static int readCount(reader *r, const char *what, int *count)
{
    if (readRecord(r, 1, what))
        return 1;
    if (r->values[0] < 0 || r->values[0] > 1000000 ||
        (int)r->values[0] != r->values[0]) {
        fprintf(stderr, "%s:%d: bad %s\n", r->name, r->line, what);
        return 1;
    }
    *count = (int)r->values[0];
    return 0;
}

static int readPoints(reader *r, scene *s)
{
    if (readCount(r, "number of vertices", &s->nbPoints))
        return 1;
    s->points = malloc((size_t)s->nbPoints * sizeof *s->points + 1);
    if (NULL == s->points)
        return 1;
    for (int i = 0; i < s->nbPoints; i++) {
        if (readRecord(r, 3, "vertex"))
            return 1;
        s->points[i] = toPoint(r->values);
    }
    return 0;
}

static int readFacets(reader *r, scene *s)
{
    if (readCount(r, "number of facets", &s->nbFacets))
        return 1;
    s->facets = malloc((size_t)s->nbFacets * sizeof *s->facets + 1);
    if (NULL == s->facets)
        return 1;
    for (int i = 0; i < s->nbFacets; i++) {
        int a, b, c;
        facet *f = &s->facets[i];
        if (readRecord(r, 7, "facet"))
            return 1;
        a = (int)r->values[0];
        b = (int)r->values[1];
        c = (int)r->values[2];
        if (a < 1 || b < 1 || c < 1 || a > s->nbPoints ||
            b > s->nbPoints || c > s->nbPoints) {
            fprintf(stderr, "%s:%d: vertices are numbered from 1 to %d\n",
                    r->name, r->line, s->nbPoints);
            return 1;
        }
        *f = createFacet(s->points[a - 1], s->points[b - 1], s->points[c - 1]);
        f->k = r->values[3];
        if (f->k < 0 || f->k > 1) {
            fprintf(stderr, "%s:%d: k is between 0 and 1\n", r->name, r->line);
            return 1;
        }
        if (toColor(r, r->values + 4, &f->cp))
            return 1;
    }
    return 0;
}

/* The handout's footnote: B is projected onto the plane through A
 * perpendicular to AO. */
static void projectB(scene *s)
{
    vector ao = vsub(s->obs, s->screenA);
    vector ab = vsub(s->screenB, s->screenA);
    double aoao = vdot(ao, ao);
    if (aoao > 0)
        s->screenB = vsub(s->screenB, vscale(ao, vdot(ab, ao) / aoao));
}

static int readScene(reader *r, scene *s)
{
    if (readRecord(r, 3, "observer"))
        return 1;
    s->obs = toPoint(r->values);
    if (readRecord(r, 8, "screen"))
        return 1;
    s->screenA = toPoint(r->values);
    s->screenB = toPoint(r->values + 3);
    s->width = (int)r->values[6];
    s->height = (int)r->values[7];
    if (s->width < 1 || s->height < 1 || s->width > 16384 ||
        s->height > 16384) {
        fprintf(stderr, "%s:%d: bad image size\n", r->name, r->line);
        return 1;
    }
    projectB(s);
    if (readPoints(r, s) || readFacets(r, s))
        return 1;
    if (readRecord(r, 3, "background") || toColor(r, r->values, &s->back))
        return 1;
    if (readRecord(r, 6, "light"))
        return 1;
    s->s.p = toPoint(r->values);
    return toColor(r, r->values + 3, &s->s.cp);
}

int parse(char *fname, scene *s)
{
    reader r;
    int failed;

    memset(s, 0, sizeof *s);
    r.file = fopen(fname, "r");
    r.name = fname;
    r.line = 0;
    if (NULL == r.file) {
        perror(fname);
        return 1;
    }
    failed = readScene(&r, s);
    fclose(r.file);
    if (failed)
        freeScene(s);
    return failed;
}

void freeScene(scene *s)
{
    free(s->points);
    free(s->facets);
    memset(s, 0, sizeof *s);
}
