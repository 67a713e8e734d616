/* tests_notes.c - the graded test, in the course's style: 20 checks of
 * computeIntersection and isInFacet, a tenth of a point each; prints the
 * score out of 2. */
#include <stdio.h>

#include "geometry.h"
#include "intersection.h"

static int score = 0;

static void check(double got, double expected, const char *what)
{
    if ((got - expected) * (got - expected) < 1e-6)
        score++;
    else
        printf("got %f, expected %f (%s)\n", got, expected, what);
}

static void checkPoint(point p, double x, double y, double z, const char *what)
{
    check(p.x, x, what);
    check(p.y, y, what);
    check(p.z, z, what);
}

static point pt(double x, double y, double z)
{
    point p;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
}

static ray mkRay(point o, vector v)
{
    ray r;
    r.o = o;
    r.v = v;
    return r;
}

static void checkIn(int got, int expected, const char *what)
{
    if ((0 != got) == expected)
        score++;
    else
        printf("isInFacet is %d, expected %s (%s)\n", got,
               expected ? "non-zero" : "0", what);
}

int main(void)
{
    facet flat = createFacet(pt(0, 0, 1), pt(1, 0, 1), pt(0, 1, 1));
    facet slant = createFacet(pt(3, 0, 0), pt(0, 3, 0), pt(0, 0, 3));
    facet wall = createFacet(pt(0, 2, 0), pt(1, 2, 0), pt(0, 2, 1));
    facet tilted = createFacet(pt(0, 0, 0), pt(1, 0, 1), pt(0, 1, 0));
    facet unit = createFacet(pt(0, 0, 0), pt(0, 1, 0), pt(1, 0, 0));

    printf("Intersections\n");
    checkPoint(computeIntersection(mkRay(pt(0, 0, 0), pt(1, 2, 4)), flat),
               0.25, 0.5, 1, "z = 1");
    checkPoint(computeIntersection(mkRay(pt(0, 0, 0), pt(1, 1, 1)), slant),
               1, 1, 1, "x + y + z = 3");
    checkPoint(computeIntersection(mkRay(pt(1, 0, 1), pt(0, -1, 0)), wall),
               1, 2, 1, "y = 2, behind the origin");
    checkPoint(computeIntersection(mkRay(pt(0, 0, 5), pt(1, 0, 0)), tilted),
               5, 0, 5, "z = x");

    printf("Points in a facet\n");
    checkIn(isInFacet(pt(0.25, 0.25, 0), unit), 1, "inside");
    checkIn(isInFacet(pt(0, 0, 0), unit), 1, "a vertex");
    checkIn(isInFacet(pt(0.5, 0.5, 0), unit), 1, "on the long edge");
    checkIn(isInFacet(pt(0.5, 0, 0), unit), 1, "on a short edge");
    checkIn(isInFacet(pt(-0.5, -0.5, 0), unit), 0, "beyond a vertex");
    checkIn(isInFacet(pt(0.6, 0.6, 0), unit), 0, "beyond the long edge");
    checkIn(isInFacet(pt(2, -1, 0), unit), 0, "far away");
    checkIn(isInFacet(pt(0.5, -0.001, 0), unit), 0, "just below a side");

    printf("Note finale (sur 2) : %.2f\n", score / 10.);
    return 0;
}
