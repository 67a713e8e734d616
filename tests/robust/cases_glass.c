/*
 * cases_glass.c - the robustness cases (docs/robustness.md) of glass slabs,
 * prisms and cubes against the analytic paths of Snell's law and total
 * internal reflection (G: transparency).  Their table is in cases.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robust/cases.h"

/* ================================================================== */
/* Transparency                                                        */

/*
 * What a ray through glass must give is computed here from the geometry
 * alone, in double, in the body's own frame at unit scale: a convex glass
 * body is a set of planes (n.p < c inside, n unit and outward), a ray meets
 * it by clipping, Snell-Descartes (docs/rendering-model.md) gives each new
 * direction in closed form, and every exit ray ends on a lit floor (a
 * white, opaque quad under the glass, lit by one light between the glass
 * and the floor, so that no glass shadows it) or in the background.  The
 * glass has k = 0, t = 0.9, d = 0 and n = 1.5: the colour of a ray is
 * 0.9^m times what it finally meets, m the number of facets it crossed or
 * was totally reflected by, so the colour counts the hits as well as
 * placing the end point.  The scene the renderer gets is this one rotated
 * (no axis stays aligned) and scaled.
 */
#define GLASS_T 0.9
#define GLASS_N 1.5
#define GLASS_PLANES 8

typedef struct glass {
    rt_vec3 n[GLASS_PLANES];
    double c[GLASS_PLANES];
    int planes;
    double extent;      /* > 0: a slab, unusable beyond |x|, |y| of this */
} glass;

typedef struct floor_det {
    double z, cx, cy, half;     /* z = z, |x - cx| and |y - cy| <= half */
    rt_vec3 light;              /* white, above the floor, under the glass */
} floor_det;

typedef struct glass_expect {
    double color[3];
    double tolerance;           /* per channel */
} glass_expect;

/* A ray of a case, in the local frame: from o along unit d; aimed at
 * lerp(vertex va, vertex vb, u) when va >= 0 (the same point is then
 * taken on the placed mesh, so that it stays on the shared edge);
 * entering through plane force[0] or force[1] when it is aimed at the
 * edge between them (either is right). */
typedef struct glass_aim {
    rt_vec3 o, d;
    int va, vb;
    double u, dist;
    int force[2];
} glass_aim;

static double max2(double a, double b) { return a > b ? a : b; }
static double min2(double a, double b) { return a < b ? a : b; }
static rt_vec3 unit_of(rt_vec3 a) { return rb_scale(a, 1 / rb_length(a)); }

/* The parameter interval of the line o + s d inside g; 0 when empty.
 * *entry: the plane it enters through (the last one crossed inwards). */
static int glass_clip(const glass *g, rt_vec3 o, rt_vec3 d, double *s0,
                      double *s1, int *entry)
{
    double lo = -INFINITY, hi = INFINITY;
    int arg = -1;
    for (int i = 0; i < g->planes; i++) {
        double dn = rb_dot(g->n[i], d), on = g->c[i] - rb_dot(g->n[i], o);
        if (dn == 0) {
            if (on < 0)
                return 0;
            continue;
        }
        double s = on / dn;
        if (dn < 0 && s > lo)
            lo = s, arg = i;
        else if (dn > 0 && s < hi)
            hi = s;
    }
    *s0 = lo, *s1 = hi, *entry = arg;
    return lo < hi;
}

/* How far p lies inside every plane but skip1 and skip2 (and inside a
 * slab's extent). */
static double glass_depth(const glass *g, rt_vec3 p, int skip1, int skip2)
{
    double m = INFINITY;
    for (int i = 0; i < g->planes; i++)
        if (i != skip1 && i != skip2)
            m = min2(m, g->c[i] - rb_dot(g->n[i], p));
    if (g->extent > 0)
        m = min2(m, min2(g->extent - fabs(p.x), g->extent - fabs(p.y)));
    return m;
}

/* Where the precision's rounding may move things: the tolerances below
 * are GLASS_ULPS rounding units of the path's coordinates, amplified by
 * the path's conditioning. */
#define GLASS_ULPS 64

/*
 * The colour of the ray (o, d) of the local frame, and its tolerance.
 * `force` (or -1): the plane the ray enters through (aimed at an edge;
 * `other` is the edge's second plane).  Returns 0 when the ray cannot be
 * judged: a hit within `margin` of an edge it was not aimed at, an
 * incidence within `crit` radians of the critical angle asin(1/n), more
 * than `depth` levels, an end point within `margin` of the floor's border.
 */
static int glass_expected(const glass *g, const floor_det *fl, rt_vec3 o,
                          rt_vec3 d, int force, int other, double margin,
                          double crit, int depth, double eps,
                          glass_expect *e)
{
    const double background[3] = {SKY.r, SKY.g, SKY.b};
    double w = 1, travel = 0, reach = rb_length(o), tan_max = 0, q_min = 1;
    double critical = asin(1 / GLASS_N);
    int levels = 0;
    rt_vec3 p = o;
    double s0, s1;
    if (o.z <= fl->z)
        return 0;                   /* under the floor: not generated */
    int entry;
    if (glass_clip(g, o, d, &s0, &s1, &entry) && s1 > 0) {
        if (s0 <= 0)
            return 0;               /* starts inside: not generated */
        if (force >= 0)
            entry = force;
        p = rb_add(o, rb_scale(d, s0));
        travel += s0;
        reach = max2(reach, rb_length(p));
        if (glass_depth(g, p, entry, force >= 0 ? other : -1) < margin)
            return 0;
        /* Entering: eta = 1/n, N_t = n_w. */
        rt_vec3 nt = g->n[entry];
        double c = -rb_dot(d, nt);
        if (!(c > 0))
            return 0;
        tan_max = max2(tan_max, sqrt(1 - c * c) / c);
        double eta = 1 / GLASS_N, q = 1 - eta * eta * (1 - c * c);
        d = unit_of(rb_add(rb_scale(d, eta), rb_scale(nt, eta * c - sqrt(q))));
        w *= GLASS_T;
        levels++;
        for (;;) {
            double best = INFINITY;
            int j = -1;
            for (int i = 0; i < g->planes; i++) {
                double dn = rb_dot(g->n[i], d);
                if (dn <= 0)
                    continue;
                double s = (g->c[i] - rb_dot(g->n[i], p)) / dn;
                if (s < best)
                    best = s, j = i;
            }
            if (j < 0 || levels >= depth)
                return 0;
            p = rb_add(p, rb_scale(d, best));
            travel += best;
            reach = max2(reach, rb_length(p));
            if (glass_depth(g, p, j, -1) < margin)
                return 0;
            /* Leaving: eta = n, N_t = -n_w, c = -d.N_t. */
            double cl = rb_dot(d, g->n[j]);
            double alpha = acos(min2(cl, 1));
            if (fabs(alpha - critical) < crit)
                return 0;
            tan_max = max2(tan_max, sqrt(max2(1 - cl * cl, 0)) / cl);
            w *= GLASS_T;
            levels++;
            double ql = 1 - GLASS_N * GLASS_N * (1 - cl * cl);
            if (ql < 0) {           /* total internal reflection */
                d = unit_of(rb_sub(d, rb_scale(g->n[j], 2 * cl)));
                continue;
            }
            q_min = min2(q_min, ql);
            rt_vec3 out = rb_scale(g->n[j], -1);
            d = unit_of(rb_add(rb_scale(d, GLASS_N),
                               rb_scale(out, GLASS_N * cl - sqrt(ql))));
            break;
        }
    }
    /* Out of a convex body for good: the floor or the background. */
    double grad = 0;
    for (int c = 0; c < 3; c++)
        e->color[c] = w * background[c];
    if (d.z < 0) {
        double s = (fl->z - p.z) / d.z;
        rt_vec3 f = rb_add(p, rb_scale(d, s));
        double u = max2(fabs(f.x - fl->cx), fabs(f.y - fl->cy));
        if (fabs(u - fl->half) < margin * (1 + fl->half))
            return 0;
        if (u < fl->half) {
            travel += s;
            reach = max2(reach, rb_length(f));
            double cf = -d.z;
            tan_max = max2(tan_max, sqrt(max2(1 - cf * cf, 0)) / cf);
            rt_vec3 to_light = rb_sub(fl->light, f);
            double distance = rb_length(to_light);
            double ns = to_light.z / distance;
            double a0, a1;
            int plane;
            if (glass_clip(g, f, to_light, &a0, &a1, &plane) && a0 < 1 &&
                a1 > 0)
                ns = 0;             /* never in these scenes */
            for (int c = 0; c < 3; c++)
                e->color[c] = w * ns * 255;
            grad = w * 255 / distance;
        }
    }
    double delta = GLASS_ULPS * eps * (reach + travel) * (1 + tan_max) *
                   (1 + 1 / sqrt(q_min));
    e->tolerance = grad * delta + GLASS_ULPS * eps * 255;
    return 1;
}

static const double glass_scales[5] = {1e-6, 1e-3, 1, 1e3, 1e6};

static rt_vec3 glass_place(rt_vec3 p, int rotate, double scale)
{
    return rb_scale(rotate ? rb_rotate(p) : p, scale);
}

/* The local scene of a case: the glass as a mesh and as planes, and the
 * floor. */
typedef void (*glass_build)(rb_mesh *m, glass *g, floor_det *fl);
/* The i-th ray of a case (resampled while glass_expected refuses it). */
typedef void (*glass_aim_fn)(const rb_mesh *m, rt_test_rng *rng, int i,
                             double crit, glass_aim *aim);

/* How far a colour is from what was expected, in tolerances. */
static double glass_error(rt_color c, const glass_expect *e)
{
    double worst = max2(fabs(c.r - e->color[0]),
                        max2(fabs(c.g - e->color[1]), fabs(c.b - e->color[2])));
    return worst / e->tolerance;
}

static void glass_note(rb_result *r, const long per_scale[5], rb_method method,
                       double worst)
{
    int n = snprintf(r->note, sizeof r->note,
                     "failures at scale 1e-6 %ld, 1e-3 %ld, 1 %ld, 1e3 %ld, "
                     "1e6 %ld", per_scale[0], per_scale[1], per_scale[2],
                     per_scale[3], per_scale[4]);
    if (method == RB_OURS && n > 0 && (size_t)n < sizeof r->note)
        snprintf(r->note + n, sizeof r->note - (size_t)n,
                 "; largest error %.2g of the tolerance", worst);
}

/* Runs a case: at each scale, `rays` rays (fewer under memcheck) against
 * their analytic colours. */
static void glass_run(rb_method method, rt_precision precision, rb_result *r,
                      glass_build build, glass_aim_fn aim_fn, int rotate,
                      int depth, int rays, uint64_t seed)
{
    double eps = rb_is_double(precision) ? 0x1p-52 : 0x1p-23;
    double margin = rb_is_double(precision) ? 1e-6 : 1e-3;
    double crit = rb_is_double(precision) ? 1e-6 : 1e-3;
    long per_scale[5] = {0};
    double worst = 0;
    for (int k = 0; k < 5; k++) {
        double scale = glass_scales[k];
        rb_mesh local = {0}, m = {0};
        glass g = {0};
        floor_det fl = {0};
        build(&local, &g, &fl);
        m = local;
        m.vertices = malloc(sizeof *m.vertices * (size_t)(local.vertex_count + 1));
        m.facets = malloc(sizeof *m.facets * (size_t)(local.facet_count + 1));
        m.vertex_capacity = local.vertex_count + 1;
        m.facet_capacity = local.facet_count + 1;
        memcpy(m.facets, local.facets, sizeof *m.facets * (size_t)local.facet_count);
        for (int i = 0; i < local.vertex_count; i++)
            m.vertices[i] = glass_place(local.vertices[i], rotate, scale);
        rb_view view = rb_ray_view(scale, glass_place(fl.light, rotate, scale),
                                   SKY);
        rt_scene *scene = rb_scene(&m, &view);
        rb_engine *e = scene ? rb_engine_create(scene, method, precision) : NULL;
        rt_test_rng rng = {seed + (uint64_t)k};
        for (int i = 0; e != NULL && i < rb_scaled(rays); i++) {
            glass_aim aim;
            glass_expect x[2];
            int candidates = 0;
            for (int attempt = 0; attempt < 1000 && candidates == 0; attempt++) {
                aim_fn(&local, &rng, i, crit, &aim);
                if (aim.force[0] < 0) {
                    candidates = glass_expected(&g, &fl, aim.o, aim.d, -1, -1,
                                                margin, crit, depth, eps, &x[0]);
                } else if (glass_expected(&g, &fl, aim.o, aim.d, aim.force[0],
                                          aim.force[1], margin, crit, depth,
                                          eps, &x[0]) &&
                           glass_expected(&g, &fl, aim.o, aim.d, aim.force[1],
                                          aim.force[0], margin, crit, depth,
                                          eps, &x[1])) {
                    candidates = 2;
                }
            }
            if (candidates == 0)
                continue;
            rt_ray ray;
            ray.direction = glass_place(aim.d, rotate, 1);
            if (aim.va >= 0) {
                rt_vec3 target = rb_lerp(m.vertices[aim.va], m.vertices[aim.vb],
                                         aim.u);
                ray.origin = rb_sub(target, rb_scale(ray.direction,
                                                     aim.dist * scale));
            } else {
                ray.origin = glass_place(aim.o, rotate, scale);
            }
            rt_color c = rb_engine_trace(e, ray, depth);
            r->total++;
            if (rb_color_has_nan(c)) {
                r->nans++;
                continue;
            }
            double err = glass_error(c, &x[0]);
            if (candidates == 2)
                err = min2(err, glass_error(c, &x[1]));
            if (err > 1) {
                r->failures++;
                per_scale[k]++;
            }
            worst = max2(worst, err);
        }
        rb_engine_free(e);
        rt_scene_destroy(scene);
        rb_mesh_free(&m);
        rb_mesh_free(&local);
    }
    glass_note(r, per_scale, method, worst);
}

/* The floor under the glass and its light, white, opaque. */
static void glass_floor(rb_mesh *m, floor_det *fl, double z, double cx,
                        double cy, double half, rt_vec3 light)
{
    *fl = (floor_det){z, cx, cy, half, light};
    rb_mesh_quad(m, rb_v(cx - half, cy - half, z), rb_v(cx + half, cy - half, z),
                 rb_v(cx + half, cy + half, z), rb_v(cx - half, cy + half, z),
                 0, WHITE);
}

/* G1: a slab between z = 0 and z = -1, 2000 units wide (its sides are
 * never reached), horizontal; the floor at z = -2, the light at
 * (0, 0, -1.5). */
static void slab_build(rb_mesh *m, glass *g, floor_det *fl)
{
    const double w = 1000;
    rb_mesh_quad(m, rb_v(-w, -w, 0), rb_v(w, -w, 0), rb_v(w, w, 0),
                 rb_v(-w, w, 0), 0, WHITE);
    rb_mesh_quad(m, rb_v(-w, -w, -1), rb_v(w, -w, -1), rb_v(w, w, -1),
                 rb_v(-w, w, -1), 0, WHITE);
    rb_mesh_orient_outward(m, 0, rb_v(0, 0, -0.5));
    rb_mesh_glass(m, 0, GLASS_T, GLASS_N);
    g->planes = 2;
    g->n[0] = rb_v(0, 0, 1), g->c[0] = 0;
    g->n[1] = rb_v(0, 0, -1), g->c[1] = 1;
    g->extent = 0.99 * w;
    glass_floor(m, fl, -2, 0, 0, 10, rb_v(0, 0, -1.5));
}

/*
 * Rays built backwards from where they must end: a floor point F within 2
 * of the light's foot, an incidence theta (half of the rays uniform in
 * [0, 80] degrees, half grazing: 90 - theta from 10 down to 0.1 degree)
 * and an azimuth; the exit ray is parallel to the incoming one, so it
 * leaves the slab at X = F - I / cos(theta), travelled inside along
 * T (sin theta_t = sin theta / n) from E = X - T / cos(theta_t): the ray
 * is displaced sideways by sin(theta - theta_t) / cos(theta_t), the slab's
 * lateral shift.
 */
static void slab_aim(const rb_mesh *m, rt_test_rng *rng, int i, double crit,
                     glass_aim *aim)
{
    (void)m, (void)crit;
    double theta = i % 2 ? rt_test_rng_range(rng, 0, 80)
                         : 90 - pow(10, rt_test_rng_range(rng, -1, 1));
    theta *= RB_PI / 180;
    double phi = rt_test_rng_range(rng, 0, 2 * RB_PI);
    double radius = 2 * sqrt(rt_test_rng_uniform(rng)),
           around = rt_test_rng_range(rng, 0, 2 * RB_PI);
    rt_vec3 f = rb_v(radius * cos(around), radius * sin(around), -2);
    rt_vec3 in = rb_v(sin(theta) * cos(phi), sin(theta) * sin(phi), -cos(theta));
    rt_vec3 x = rb_sub(f, rb_scale(in, 1 / cos(theta)));
    double st = sin(theta) / GLASS_N, ct = sqrt(1 - st * st);
    rt_vec3 t = rb_v(st * cos(phi), st * sin(phi), -ct);
    rt_vec3 entry = rb_sub(x, rb_scale(t, 1 / ct));
    *aim = (glass_aim){rb_sub(entry, rb_scale(in, rt_test_rng_range(rng, 0.5, 2.5))),
                       in, -1, -1, 0, 0, {-1, -1}};
}

void rb_case_g1(rb_method m, rt_precision p, rb_result *r)
{
    glass_run(m, p, r, slab_build, slab_aim, 0, 4, 2000, 141);
}

/* G2: a right-angle prism, 45-degree faces, 6 long: its section has the
 * vertices (0, 0), (1, 0) and (0, -1) in (x, z): the top face z = 0, the
 * side x = 0, the hypotenuse x - z = 1; the floor at z = -3 and the light
 * at (0.5, 0, -2). */
static void prism_build(rb_mesh *m, glass *g, floor_det *fl)
{
    const double l = 3;
    rt_vec3 p0[2], p1[2], p2[2];
    for (int s = 0; s < 2; s++) {
        double y = s ? l : -l;
        p0[s] = rb_v(0, y, 0), p1[s] = rb_v(1, y, 0), p2[s] = rb_v(0, y, -1);
    }
    rb_mesh_quad(m, p0[0], p1[0], p1[1], p0[1], 0, WHITE);
    rb_mesh_quad(m, p0[0], p0[1], p2[1], p2[0], 0, WHITE);
    rb_mesh_quad(m, p1[0], p2[0], p2[1], p1[1], 0, WHITE);
    for (int s = 0; s < 2; s++)         /* the end caps */
        rb_mesh_facet(m, rb_mesh_vertex_shared(m, p0[s]),
                      rb_mesh_vertex_shared(m, p1[s]),
                      rb_mesh_vertex_shared(m, p2[s]), 0, WHITE);
    rb_mesh_orient_outward(m, 0, rb_v(0.3, 0, -0.3));
    rb_mesh_glass(m, 0, GLASS_T, GLASS_N);
    g->planes = 5;
    g->n[0] = rb_v(0, 0, 1), g->c[0] = 0;
    g->n[1] = rb_v(-1, 0, 0), g->c[1] = 0;
    g->n[2] = rb_v(sqrt(0.5), 0, -sqrt(0.5)), g->c[2] = sqrt(0.5);
    g->n[3] = rb_v(0, 1, 0), g->c[3] = l;
    g->n[4] = rb_v(0, -1, 0), g->c[4] = l;
    glass_floor(m, fl, -3, 0.5, 0, 60, rb_v(0.5, 0, -2));
}

/*
 * Rays entering the top face at incidence beta in the plane of the section
 * (half of them) or off it by up to 0.4 rad.  In the section, the ray
 * inside meets the hypotenuse at alpha = 45 degrees - beta_t (sin beta_t =
 * sin beta / n), so alpha = asin(1/n) at beta_c = asin(n sin(45 degrees -
 * asin(1/n))) = 4.79 degrees: half of the rays come within 10^-0.5 rad of
 * beta_c, down to the margin, on both sides.  Beyond the critical angle
 * the ray is reflected towards the side x = 0 and leaves it upwards (the
 * background); below it, it leaves the hypotenuse downwards, grazing it
 * near beta_c, to the floor.  Far from beta_c it may be reflected by the
 * side first: every path is followed.
 */
static void prism_aim(const rb_mesh *m, rt_test_rng *rng, int i, double crit,
                      glass_aim *aim)
{
    (void)m;
    double critical = asin(1 / GLASS_N);
    double beta_c = asin(GLASS_N * sin(RB_PI / 4 - critical));
    double beta;
    if (i % 2) {
        beta = rt_test_rng_range(rng, -RB_PI / 3, RB_PI / 3);
    } else {
        double off = pow(10, rt_test_rng_range(rng, log10(crit), -0.5));
        beta = beta_c + (rt_test_rng_uniform(rng) < 0.5 ? -off : off);
    }
    double phi = i % 4 < 2 ? 0 : rt_test_rng_range(rng, -0.4, 0.4);
    rt_vec3 in = rb_v(sin(beta) * cos(phi), sin(beta) * sin(phi), -cos(beta));
    rt_vec3 entry = rb_v(rt_test_rng_range(rng, 0.02, 0.98),
                         rt_test_rng_range(rng, -1, 1), 0);
    *aim = (glass_aim){rb_sub(entry, rb_scale(in, rt_test_rng_range(rng, 0.5, 1.5))),
                       in, -1, -1, 0, 0, {-1, -1}};
}

void rb_case_g2(rb_method m, rt_precision p, rb_result *r)
{
    glass_run(m, p, r, prism_build, prism_aim, 1, 10, 2000, 142);
}

static rt_vec3 axis_vec(int a, double s)
{
    return rb_v(a == 0 ? s : 0, a == 1 ? s : 0, a == 2 ? s : 0);
}

/* The cube [-1, 1]^3 of glass, 12 facets on 8 shared vertices, wound
 * outwards; each face is split along the diagonal from (-u, -v) to
 * (+u, +v) of its two other axes, so that opposite faces' diagonals face
 * each other.  Plane 2a + (s < 0) is the face of axis a and side s. */
static void box_glass(rb_mesh *m, glass *g)
{
    int first = m->facet_count;
    for (int a = 0; a < 3; a++)
        for (int side = 0; side < 2; side++) {
            double s = side ? -1 : 1;
            int u = (a + 1) % 3, v = (a + 2) % 3;
            rt_vec3 c = axis_vec(a, s), eu = axis_vec(u, 1), ev = axis_vec(v, 1);
            rb_mesh_quad(m, rb_sub(rb_sub(c, eu), ev), rb_sub(rb_add(c, eu), ev),
                         rb_add(rb_add(c, eu), ev), rb_add(rb_sub(c, eu), ev),
                         0, WHITE);
            g->n[2 * a + side] = c;
            g->c[2 * a + side] = 1;
        }
    g->planes = 6;
    rb_mesh_orient_outward(m, first, rb_v(0, 0, 0));
    rb_mesh_glass(m, first, GLASS_T, GLASS_N);
}

/* G3: the glass cube over a floor at z = -3, the light at (0.3, -0.2, -2). */
static void cube_build(rb_mesh *m, glass *g, floor_det *fl)
{
    box_glass(m, g);
    glass_floor(m, fl, -3, 0, 0, 60, rb_v(0.3, -0.2, -2));
}

static int find_vertex(const rb_mesh *m, rt_vec3 p)
{
    for (int v = 0; v < m->vertex_count; v++)
        if (m->vertices[v].x == p.x && m->vertices[v].y == p.y &&
            m->vertices[v].z == p.z)
            return v;
    return -1;
}

/*
 * Rays aimed exactly at shared edges of the closed cube: 40% at a face's
 * diagonal (the edge its two facets share) from any direction that enters
 * the face; 30% at an edge of the cube (shared by facets of two faces),
 * entering both faces (either may take it: two expected colours); 30% at
 * a face's diagonal at normal incidence, so that they leave exactly
 * through the opposite face's diagonal.
 */
static void cube_aim(const rb_mesh *m, rt_test_rng *rng, int i, double crit,
                     glass_aim *aim)
{
    (void)crit;
    int kind = i % 10 < 4 ? 0 : i % 10 < 7 ? 1 : 2;
    int a = (int)(rt_test_rng_uniform(rng) * 3);
    double s = rt_test_rng_uniform(rng) < 0.5 ? 1 : -1;
    int u = (a + 1) % 3, v = (a + 2) % 3;
    rt_vec3 na = axis_vec(a, s), nb = rb_v(0, 0, 0);
    rt_vec3 pa, pb;
    int fa = 2 * a + (s < 0), fb = -1;
    if (kind == 1) {
        int b = rt_test_rng_uniform(rng) < 0.5 ? u : v, c = 3 - a - b;
        double sb = rt_test_rng_uniform(rng) < 0.5 ? 1 : -1;
        nb = axis_vec(b, sb);
        fb = 2 * b + (sb < 0);
        pa = rb_sub(rb_add(na, nb), axis_vec(c, 1));
        pb = rb_add(rb_add(na, nb), axis_vec(c, 1));
    } else {
        pa = rb_sub(rb_sub(na, axis_vec(u, 1)), axis_vec(v, 1));
        pb = rb_add(rb_add(na, axis_vec(u, 1)), axis_vec(v, 1));
    }
    double t = rt_test_rng_range(rng, 0.01, 0.99);
    rt_vec3 target = rb_lerp(pa, pb, t), d;
    if (kind == 2) {
        d = rb_scale(na, -1);
    } else {
        do
            d = rb_random_unit(rng);
        while (!(rb_dot(d, na) < -0.1 && (fb < 0 || rb_dot(d, nb) < -0.1)));
    }
    double dist = rt_test_rng_range(rng, 0.5, 2.5);
    *aim = (glass_aim){rb_sub(target, rb_scale(d, dist)), d,
                       find_vertex(m, pa), find_vertex(m, pb), t, dist,
                       {kind == 1 ? fa : -1, kind == 1 ? fb : -1}};
}

void rb_case_g3(rb_method m, rt_precision p, rb_result *r)
{
    glass_run(m, p, r, cube_build, cube_aim, 1, 32, 3000, 143);
}

/*
 * G4: a light inside the closed glass cube (orange, (0.3, 0.1, 0.2)), a
 * second light outside (blue, (3, -2, 4)); an opaque white plate inside
 * the cube (z = -0.5, x in [-0.8, -0.2]) and a white floor outside
 * (z = -1.5, 16 wide).  Shadow rays are blocked by transparent facets
 * too (hard shadows): a point inside is lit by the inside light only, a
 * point outside by the outside light only, where the cube does not stand
 * between them.  Rays start inside the cube and end on the plate, or
 * start outside and end on the floor without crossing the cube.
 */
void rb_case_g4(rb_method method, rt_precision precision, rb_result *r)
{
    static const double in_color[3] = {255, 128, 0};
    static const double out_color[3] = {0, 128, 255};
    double eps = rb_is_double(precision) ? 0x1p-52 : 0x1p-23;
    double margin = rb_is_double(precision) ? 1e-6 : 1e-3;
    rt_vec3 light_in = rb_v(0.3, 0.1, 0.2), light_out = rb_v(3, -2, 4);
    long per_scale[5] = {0}, leaks = 0;
    double worst = 0;
    for (int k = 0; k < 5; k++) {
        double scale = glass_scales[k];
        rb_mesh m = {0};
        glass g = {0}, big, small;
        box_glass(&m, &g);
        big = small = g;
        for (int i = 0; i < g.planes; i++)
            big.c[i] = 1 + margin, small.c[i] = 1 - margin;
        rb_mesh_quad(&m, rb_v(-0.8, -0.8, -0.5), rb_v(-0.2, -0.8, -0.5),
                     rb_v(-0.2, 0.8, -0.5), rb_v(-0.8, 0.8, -0.5), 0, WHITE);
        rb_mesh_quad(&m, rb_v(-8, -8, -1.5), rb_v(8, -8, -1.5),
                     rb_v(8, 8, -1.5), rb_v(-8, 8, -1.5), 0, WHITE);
        for (int i = 0; i < m.vertex_count; i++)
            m.vertices[i] = glass_place(m.vertices[i], 1, scale);
        rb_view view = rb_ray_view(scale, glass_place(light_in, 1, scale), SKY);
        view.light_color = (rt_rgb8){255, 128, 0};
        rt_light more = {glass_place(light_out, 1, scale), {0, 128, 255}};
        rt_scene *scene = rb_scene_lights(&m, &view, &more, 1);
        rb_engine *e = scene ? rb_engine_create(scene, method, precision) : NULL;
        rt_test_rng rng = {144 + (uint64_t)k};
        for (int i = 0; e != NULL && i < rb_scaled(2000); i++) {
            rt_vec3 o, p, light;
            const double *color;
            int lit = 1;
            if (i % 2 == 0) {       /* inside, on the plate */
                p = rb_v(rt_test_rng_range(&rng, -0.79, -0.21),
                         rt_test_rng_range(&rng, -0.79, 0.79), -0.5);
                o = rb_v(rt_test_rng_range(&rng, -0.95, 0.95),
                         rt_test_rng_range(&rng, -0.95, 0.95),
                         rt_test_rng_range(&rng, -0.45, 0.95));
                light = light_in, color = in_color;
            } else {                /* outside, on the floor */
                light = light_out, color = out_color;
                for (;;) {
                    p = rb_v(rt_test_rng_range(&rng, -7.9, 7.9),
                             rt_test_rng_range(&rng, -7.9, 7.9), -1.5);
                    rt_vec3 up = rb_random_unit(&rng);
                    if (up.z < 0.05)
                        continue;
                    o = rb_add(p,
                               rb_scale(up, rt_test_rng_range(&rng, 0.3, 3)));
                    double s0, s1;
                    int plane;
                    if (glass_clip(&big, o, rb_sub(p, o), &s0, &s1, &plane) &&
                        s0 < 1 && s1 > 0)
                        continue;   /* would cross the cube */
                    rt_vec3 to = rb_sub(light, p);
                    int near = glass_clip(&big, p, to, &s0, &s1, &plane) &&
                               s0 < 1 && s1 > 0;
                    int far = glass_clip(&small, p, to, &s0, &s1, &plane) &&
                              s0 < 1 && s1 > 0;
                    if (near != far)
                        continue;   /* on the edge of the cube's shadow */
                    lit = !near;
                    break;
                }
            }
            rt_vec3 to_light = rb_sub(light, p), view_dir = rb_sub(p, o);
            double distance = rb_length(to_light);
            double ns = lit ? to_light.z / distance : 0;
            double tan_in = sqrt(view_dir.x * view_dir.x + view_dir.y * view_dir.y) /
                            fabs(view_dir.z);
            double delta = GLASS_ULPS * eps *
                           (rb_length(o) + rb_length(view_dir) + distance) *
                           (1 + tan_in);
            double tol = 255 * delta / distance + GLASS_ULPS * eps * 255;
            rt_ray ray = {glass_place(o, 1, scale), glass_place(view_dir, 1, 1)};
            rt_color c = rb_engine_trace(e, ray, 8);
            r->total++;
            if (rb_color_has_nan(c)) {
                r->nans++;
                continue;
            }
            double got[3] = {c.r, c.g, c.b}, err = 0;
            for (int ch = 0; ch < 3; ch++)
                err = max2(err, fabs(got[ch] - ns * color[ch]) / tol);
            worst = max2(worst, err);
            if (err > 1) {
                r->failures++;
                per_scale[k]++;
                leaks += i % 2 == 1 && c.r > tol;
            }
        }
        rb_engine_free(e);
        rt_scene_destroy(scene);
        rb_mesh_free(&m);
    }
    glass_note(r, per_scale, method, worst);
    size_t n = strlen(r->note);
    snprintf(r->note + n, sizeof r->note - n,
             "; outside points lit by the inside light %ld", leaks);
}

