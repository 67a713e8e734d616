/*
 * nff_cut.c - NFF's spheres and cones cut into facets once the whole file
 * is read (nff.h), when the view that sizes their facets is known: each as
 * finely as it looks from the eye (nothing finer than a pixel, the
 * coarsest behind the eye), all of them within a budget of facets
 * proportional to the file's size (docs/formats.md, "Tessellation").
 */
#include <math.h>
#include <stdio.h>

#include "base/vecmath.h"
#include "formats/framing.h"
#include "formats/nff.h"

/* The default tolerance keeps a silhouette within DEFAULT_PIXELS of the
 * true one at the file's resolution and facets about DEFAULT_FACET_PIXELS
 * across, within these bounds (docs/formats.md, "Tessellation"). */
#define DEFAULT_PIXELS 0.25
#define DEFAULT_FACET_PIXELS 5.0
#define DEFAULT_TOLERANCE_MIN 5e-5
#define DEFAULT_TOLERANCE_MAX 0.05
/* The coarsest cuts: an octahedron, a three-sided prism (or pyramid). */
#define COARSEST_BANDS 2
#define COARSEST_SEGMENTS 3

/* The tolerance that keeps a silhouette of radius rho pixels within
 * DEFAULT_PIXELS of the true one and facets about DEFAULT_FACET_PIXELS
 * across where they face the eye, within the default bounds. */
static double smooth_tolerance(double rho)
{
    double tol = DEFAULT_PIXELS / rho;
    /* facets about DEFAULT_FACET_PIXELS across where they face the eye
     * (a band of angle pi / bands ~ sqrt(2) acos(1 - tol)): flat shading
     * then changes in steps too small to be seen as bands */
    double across = 1.0 - cos(DEFAULT_FACET_PIXELS / (sqrt(2.0) * rho));
    if (across < tol)
        tol = across;
    if (!(tol >= DEFAULT_TOLERANCE_MIN))
        tol = DEFAULT_TOLERANCE_MIN;
    if (tol > DEFAULT_TOLERANCE_MAX)
        tol = DEFAULT_TOLERANCE_MAX;
    return tol;
}

/* How a primitive is cut: a tolerance, or 0 for the coarsest cut; and at
 * most `most_facets` facets (0: no cap but the budget). */
typedef struct cut {
    double tolerance;
    double most_facets;
} cut;

/*
 * The default cut of a primitive from the file's view (docs/formats.md,
 * "Tessellation"), with r its radius (a cone's larger one) and `center`
 * its centre (a cone's midpoint):
 * - in front of the eye (its nearest depth along the view, at least a
 *   tenth of r, is positive): sized by its radius in pixels there, rho; the
 *   coarsest when it is smaller than a pixel (2 rho < 1);
 * - entirely behind the eye (its bounding sphere behind the plane of the
 *   eye): the coarsest, as only reflections can show it;
 * - otherwise (around or beside the eye): as if seen from the distance of
 *   its farthest point, so rho is at most the focal length in pixels, and
 *   at most as many facets as the image has pixels.
 */
static cut default_cut(const parser *p, const primitive *prim)
{
    cut c = {0.0, 0.0};
    double r = prim->r0 > prim->r1 ? prim->r0 : prim->r1;
    rt_vec3 center = prim->cone ? v3_scale(v3_add(prim->base, prim->apex), 0.5)
                                : prim->base;
    rt_vec3 w = v3_normalize(v3_sub(p->at_point, p->from));
    double along = v3_dot(v3_sub(center, p->from), w);
    double depth = along - r;
    if (depth > 0) {
        if (!(depth > 0.1 * r))
            depth = 0.1 * r;
        double half_width = depth * rt__frame_tan_half(p->angle);
        double pixels_per_unit = 0.5 * p->width / half_width;
        double rho = pixels_per_unit * r;  /* the radius in pixels */
        if (2.0 * rho >= 1.0)
            c.tolerance = smooth_tolerance(rho);
        return c;
    }
    double reach = r;       /* the radius of a sphere holding the primitive */
    if (prim->cone) {
        double half = 0.5 * v3_length(v3_sub(prim->apex, prim->base));
        reach = sqrt(half * half + r * r);
    }
    if (!(along + reach > 0))
        return c;
    double farthest = v3_length(v3_sub(center, p->from)) + reach;
    double focal = 0.5 * p->width / rt__frame_tan_half(p->angle);
    c.tolerance = smooth_tolerance(focal * r / farthest);
    c.most_facets = (double)p->width * (double)p->height;
    return c;
}

/* The bands of a sphere cut by `c` (tol_bands: the bands its tolerance
 * gives, 0 when it needs too many). */
static int sphere_bands(const cut *c, int tol_bands)
{
    if (c->tolerance == 0)
        return COARSEST_BANDS;
    if (tol_bands == 0 || c->most_facets == 0 ||
        rt__tess_sphere_facet_count(tol_bands) <= c->most_facets)
        return tol_bands;
    /* the most bands b with 4 b (b - 1) <= most_facets */
    int most = (int)floor(0.5 * (1.0 + sqrt(1.0 + c->most_facets)));
    while (most > COARSEST_BANDS && rt__tess_sphere_facet_count(most) >
                                        c->most_facets)
        most--;
    return most > COARSEST_BANDS ? most : COARSEST_BANDS;
}

static int cone_segments(const cut *c, int tol_segments, const primitive *p)
{
    if (c->tolerance == 0)
        return COARSEST_SEGMENTS;
    if (tol_segments == 0 || c->most_facets == 0 ||
        rt__tess_cone_facet_count(tol_segments, p->r0, p->r1) <=
            c->most_facets)
        return tol_segments;
    double per_segment = rt__tess_cone_facet_count(1, p->r0, p->r1);
    double most = floor(c->most_facets / per_segment);
    return most > COARSEST_SEGMENTS ? (int)most : COARSEST_SEGMENTS;
}

static rt_status too_many(parser *p, const primitive *prim, double facets,
                          double budget, double tolerance)
{
    char tol[48] = "", total[48];
    if (tolerance > 0)
        snprintf(tol, sizeof tol, " (now %g for this %s)", tolerance,
                 prim->cone ? "cone" : "sphere");
    if (p->mesh.facet_count + facets > RT_TESS_MAX_FACETS)
        snprintf(total, sizeof total, "more than %d", RT_TESS_MAX_FACETS);
    else
        snprintf(total, sizeof total, "%.0f", p->mesh.facet_count + facets);
    return rt__error_set(p->error, RT_ERR_LIMIT, p->name, prim->line,
                         prim->column,
                         "expected at most %.0f facets in all for a file of "
                         "%zu bytes (%d + %d a byte, at most %d), found that "
                         "this %s brings them to %s: give a larger "
                         "tessellation tolerance (--tessellate)%s",
                         budget, rt__nff_file_bytes(p), RT_TESS_BUDGET_BASE,
                         RT_TESS_BUDGET_PER_BYTE, RT_TESS_MAX_FACETS,
                         prim->cone ? "cone" : "sphere", total, tol);
}

/* Cuts primitive `prim` into the mesh: 0, -1 (out of memory) or
 * RT_TESS_CANCELLED, after checking its facets against `budget`. */
static rt_status cut_primitive(parser *p, const primitive *prim,
                               const cut *c, int bands, int segments,
                               double budget)
{
    const rt_facet_desc *m = &p->materials[prim->material];
    double facets;
    if (prim->cone)
        facets = segments == 0 ? 1e300
                               : rt__tess_cone_facet_count(segments, prim->r0,
                                                           prim->r1);
    else
        facets = bands == 0 ? 1e300 : rt__tess_sphere_facet_count(bands);
    if (p->mesh.facet_count + facets > budget)
        return too_many(p, prim, facets, budget, c->tolerance);
    int done = prim->cone
                   ? rt__tess_cone(&p->mesh, prim->base, prim->r0, prim->apex,
                                   prim->r1, prim->inward, segments, m,
                                   prim->line)
                   : rt__tess_sphere(&p->mesh, prim->base, prim->r0,
                                     prim->inward, bands, m, prim->line);
    if (done == RT_TESS_CANCELLED)
        return rt__load_cancel(p->error, p->name);
    return done == 0 ? RT_OK : rt__nff_out_of_memory(p);
}

rt_status rt__nff_tessellate(parser *p, double option)
{
    double budget = rt__tess_budget(rt__nff_file_bytes(p));
    double last_tol = -1;
    int last_bands = 0, last_segments = 0;
    const primitive *first_dropped = NULL;
    p->mesh.cancel = p->options->cancel;
    for (int i = 0; i < p->primitive_count; i++) {
        const primitive *prim = &p->primitives[i];
        if (rt__nff_poll_cancel(p))
            return rt__load_cancel(p->error, p->name);
        cut c = {option, 0.0};
        if (!(option > 0))
            c = default_cut(p, prim);
        if (c.tolerance > 0 && c.tolerance != last_tol) {
            last_tol = c.tolerance;
            last_bands = rt__tess_sphere_bands(c.tolerance);
            last_segments = rt__tess_circle_segments(c.tolerance);
        }
        int dropped = p->mesh.dropped;
        rt_status status =
            cut_primitive(p, prim, &c, sphere_bands(&c, last_bands),
                          cone_segments(&c, last_segments, prim), budget);
        if (status != RT_OK)
            return status;
        if (dropped == 0 && p->mesh.dropped > 0)
            first_dropped = prim;
    }
    if (first_dropped != NULL)
        rt__notes_add(&p->notes, p->name, first_dropped->line,
                      first_dropped->column,
                      "%d facets of zero area left out of spheres and cones "
                      "(their vertices round together: the radius is small "
                      "for the coordinates of the centre; the first such "
                      "%s is here)", p->mesh.dropped,
                      first_dropped->cone ? "cone" : "sphere");
    return RT_OK;
}
