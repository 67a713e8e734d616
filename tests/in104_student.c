/*
 * in104_student.c - a course program, written from docs/in104.md alone:
 * it uses only the handout's headers and functions (plus freeScene, to be
 * tidy) and standard C, and must build with
 *
 *   cc -Wall -Wextra -Werror -I<include/in104> in104_student.c \
 *      -lraytrace-in104 -lraytrace -lm -lpthread
 *
 * without a warning.  It checks the results the handout gives and prints a
 * line per failed check; the exit status is the number of failures.
 * Optional argument: a .scn file to parse (and report on) as well.
 */
#include "geometry.h"
#include "intersection.h"
#include "raytracer.h"

#include <math.h>
#include <stdio.h>

static int failures = 0;

static void checkNear(double got, double expected, const char *what)
{
    if (!(fabs(got - expected) <= 1e-9)) {
        printf("FAIL %s: got %.12g, expected %.12g\n", what, got, expected);
        ++failures;
    }
}

static void checkTrue(int condition, const char *what)
{
    if (0 == condition) {
        printf("FAIL %s\n", what);
        ++failures;
    }
}

static point makePoint(double x, double y, double z)
{
    point p;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
}

static void testCreateFacet(void)
{
    facet f = createFacet(makePoint(-1, -1, 1), makePoint(1, -1, -1),
                          makePoint(0, 1, 1));
    /* (b - a) x (c - a) = (4, -2, 4), of length 6 */
    checkNear(f.n.x, 2.0 / 3, "createFacet n.x");
    checkNear(f.n.y, -1.0 / 3, "createFacet n.y");
    checkNear(f.n.z, 2.0 / 3, "createFacet n.z");
    checkNear(f.k, 0.0, "createFacet k");
    checkTrue(0 == f.cp.r && 0 == f.cp.g && 0 == f.cp.b, "createFacet black");
    checkNear(f.b.x, 1.0, "createFacet keeps b");
}

static void testComputeIntersection(void)
{
    facet f = createFacet(makePoint(-1, -1, 1), makePoint(1, -1, -1),
                          makePoint(0, 1, 1));
    ray r;
    r.o = makePoint(0, 0, 0);
    r.v = makePoint(1, 3, 2);
    point p = computeIntersection(r, f);
    checkNear(p.x, 1.0 / 3, "computeIntersection x");
    checkNear(p.y, 1.0, "computeIntersection y");
    checkNear(p.z, 2.0 / 3, "computeIntersection z");

    vector v = r.v;          /* a point and a vector are interchangeable */
    r.v.x = 10 * v.x;        /* the direction need not be unit length */
    r.v.y = 10 * v.y;
    r.v.z = 10 * v.z;
    p = computeIntersection(r, f);
    checkNear(p.y, 1.0, "computeIntersection, long direction");
}

static void testChangeCoord(void)
{
    facet f = createFacet(makePoint(1, 0, 0), makePoint(3, 1, 0),
                          makePoint(1, 2, 1));
    double u = 0.25, v = 0.5, w = -0.75;
    point p;
    p.x = f.a.x + u * (f.b.x - f.a.x) + v * (f.c.x - f.a.x) + w * f.n.x;
    p.y = f.a.y + u * (f.b.y - f.a.y) + v * (f.c.y - f.a.y) + w * f.n.y;
    p.z = f.a.z + u * (f.b.z - f.a.z) + v * (f.c.z - f.a.z) + w * f.n.z;
    point q = changeCoord(p, f);
    checkNear(q.x, u, "changeCoord u");
    checkNear(q.y, v, "changeCoord v");
    checkNear(q.z, w, "changeCoord w");
}

static void testIsInFacet(void)
{
    facet f = createFacet(makePoint(0, 0, 0), makePoint(0, 1, 0),
                          makePoint(1, 0, 0));
    checkTrue(0 != isInFacet(makePoint(0.5, 0.5, 0), f),
              "(0.5, 0.5, 0) is in the facet");
    checkTrue(0 == isInFacet(makePoint(-0.5, -0.5, 0), f),
              "(-0.5, -0.5, 0) is out of the facet");
    checkTrue(0 != isInFacet(makePoint(0.2, 0.2, 0), f),
              "(0.2, 0.2, 0) is in the facet");
    checkTrue(0 == isInFacet(makePoint(0.6, 0.6, 0), f),
              "(0.6, 0.6, 0) is out of the facet");
    checkTrue(0 != isInFacet(makePoint(0, 0, 0), f), "a vertex is in");
    checkTrue(0 == isInFacet(makePoint(-3 * EPSILON, 0.5, 0), f),
              "3 EPSILON outside an edge is out");
}

static void testParse(void)
{
    const char *name = "in104_student.scn";
    FILE *file = fopen(name, "w");
    if (NULL == file) {
        printf("FAIL cannot write %s\n", name);
        ++failures;
        return;
    }
    fputs("# observer\n8,0,0\n"
          "3,0,0,3,4,0,20,10\n"
          "4\n-1,0,0\n-1,3,0\n-1,0,3\n-1,3,3\n"
          "2\n1,2,3,0.3,255,0,0\n2,3,4,0.5,0,255,0\n"
          "200,200,200\n"
          "0,1,1,255,255,128\n", file);
    fclose(file);

    scene s;
    int status = parse((char *)name, &s);
    checkTrue(0 == status, "parse returns 0");
    if (0 != status)
        return;
    checkTrue(20 == s.width && 10 == s.height, "parse: width, height");
    checkTrue(4 == s.nbPoints && 2 == s.nbFacets, "parse: counts");
    checkNear(s.obs.x, 8, "parse: obs");
    checkNear(s.screenA.x, 3, "parse: screenA");
    checkNear(s.screenB.y, 4, "parse: screenB");
    checkNear(s.points[3].z, 3, "parse: points");
    checkNear(s.facets[1].a.y, 3, "parse: facet vertices");
    checkNear(s.facets[1].k, 0.5, "parse: k");
    checkTrue(255 == s.facets[1].cp.g, "parse: facet colour");
    checkNear(fabs(s.facets[0].n.x), 1, "parse: normal");
    checkTrue(200 == s.back.r && 200 == s.back.b, "parse: background");
    checkNear(s.s.p.z, 1, "parse: light position");
    checkTrue(128 == s.s.cp.b, "parse: light colour");
    freeScene(&s);
    checkTrue(NULL == s.points && NULL == s.facets, "freeScene");
    remove(name);
}

int main(int argc, char **argv)
{
    testCreateFacet();
    testComputeIntersection();
    testChangeCoord();
    testIsInFacet();
    testParse();
    if (argc > 1) {
        scene s;
        if (0 != parse(argv[1], &s)) {
            ++failures;
        } else {
            printf("%s: %d x %d, %d points, %d facets\n", argv[1], s.width,
                   s.height, s.nbPoints, s.nbFacets);
            freeScene(&s);
        }
    }
    printf("%s: %d failure(s)\n", argv[0], failures);
    return failures;
}
