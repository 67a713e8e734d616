/*
 * my_tests.c - a student's unit tests in the IN 104 course's style, against
 * the handout's API (createFacet, computeIntersection, isInFacet, parse):
 * the handout's two worked examples, and a scene parsed when one is given.
 * Prints one line per failed check and the score; exit status 0 when all
 * pass.  Build (README, "For students of the IN 104 course"):
 *
 *   cc -Wall -Wextra -Iinclude/in104 examples/my_tests.c \
 *      -Lbuild/src/in104 -Lbuild/src -lraytrace-in104 -lraytrace -lm -lpthread
 */
#include "geometry.h"
#include "intersection.h"
#include "raytracer.h"

#include <math.h>
#include <stdio.h>

static int passed = 0, total = 0;

static void check(int condition, const char *what)
{
    ++total;
    if (condition)
        ++passed;
    else
        printf("FAIL %s\n", what);
}

static point pt(double x, double y, double z)
{
    point p;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
}

int main(int argc, char **argv)
{
    ray r;
    facet f = createFacet(pt(-1, -1, 1), pt(1, -1, -1), pt(0, 1, 1));
    facet t = createFacet(pt(0, 0, 0), pt(0, 1, 0), pt(1, 0, 0));
    point p;

    r.o = pt(0, 0, 0);
    r.v = pt(1, 3, 2);
    p = computeIntersection(r, f);
    check(fabs(p.x - 1.0 / 3) < 1e-9, "intersection x is 1/3");
    check(fabs(p.y - 1.0) < 1e-9, "intersection y is 1");
    check(fabs(p.z - 2.0 / 3) < 1e-9, "intersection z is 2/3");
    check(isInFacet(pt(0.5, 0.5, 0), t), "(0.5, 0.5, 0) is in");
    check(!isInFacet(pt(-0.5, -0.5, 0), t), "(-0.5, -0.5, 0) is out");

    if (argc > 1) {
        scene s;
        check(0 == parse(argv[1], &s), "parse succeeds");
        if (passed == total) {
            check(s.nbFacets > 0, "the scene has facets");
            printf("%s: %d facets, %d x %d\n", argv[1], s.nbFacets, s.width,
                   s.height);
            freeScene(&s);
        }
    }
    printf("%d/%d checks passed\n", passed, total);
    return passed == total ? 0 : 1;
}
