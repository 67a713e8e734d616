/*
 * create_facet.c - createFacet() of the IN 104 handout (intersection.h).
 *
 * Each public function of the layer has its own file, so that a course
 * program that defines one of them itself still links with the others from
 * the static library without a duplicate symbol.
 */
#include "intersection.h"

#include "frame.h"

facet createFacet(point a, point b, point c)
{
    in104_frame frame;
    in104__frame_make(&frame, a, b, c);

    facet f;
    f.a = a;
    f.b = b;
    f.c = c;
    f.k = 0.0;
    f.cp.r = 0;
    f.cp.g = 0;
    f.cp.b = 0;
    f.n = in104_point(frame.unit);      /* zero for a zero-area facet */
    return f;
}
