/*
 * naive_impl.h - the naive reference renderer, written once for double and
 * float (included twice by engine.c with R the type and N(x) the name of a
 * symbol).  It is what a first ray tracer looks like: Moller-Trumbore or the
 * handout's plane-then-inside test, fixed 1e-5 epsilons, the hit point as
 * o + t d, secondary rays moved 1e-5 along the normal, and recursion for
 * reflections.  It exists to be measured against, never to be used.
 *
 * Transparency (docs/rendering-model.md) the way a first ray tracer adds it:
 * Snell-Descartes with the winding normal, the refracted ray started 1e-5
 * beyond the facet (on the far side of the hit point), the mirror ray 1e-5
 * in front of it, nothing skipped; every light's shadow ray tests every
 * facet, transparent or not (hard shadows).
 */

typedef struct N(vec) {
    R x, y, z;
} N(vec);

typedef struct N(tri) {
    N(vec) a, b, c, n;      /* n: unit (b - a) x (c - a), computed naively */
    R k, t, ior, d;         /* reflection, transparency, index, diffuse */
    R color[3];
} N(tri);

typedef struct N(scene) {
    N(tri) *tris;
    int count;
    N(vec) *lights;
    R (*light_colors)[3];
    int light_count;
    R background[3];
    int method;
} N(scene);

static N(vec) N(mk)(R x, R y, R z) { N(vec) v = {x, y, z}; return v; }
static N(vec) N(from)(rt_vec3 v) { return N(mk)((R)v.x, (R)v.y, (R)v.z); }
static N(vec) N(add)(N(vec) a, N(vec) b) { return N(mk)(a.x + b.x, a.y + b.y, a.z + b.z); }
static N(vec) N(sub)(N(vec) a, N(vec) b) { return N(mk)(a.x - b.x, a.y - b.y, a.z - b.z); }
static N(vec) N(mul)(N(vec) a, R s) { return N(mk)(a.x * s, a.y * s, a.z * s); }
static R N(dot)(N(vec) a, N(vec) b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static N(vec) N(cross)(N(vec) a, N(vec) b)
{
    return N(mk)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                 a.x * b.y - a.y * b.x);
}
/* What a contracting compiler makes of the same two functions. */
static R N(dot_fma)(N(vec) a, N(vec) b) { return fma(a.x, b.x, fma(a.y, b.y, a.z * b.z)); }
static N(vec) N(cross_fma)(N(vec) a, N(vec) b)
{
    return N(mk)(fma(a.y, b.z, -a.z * b.y), fma(a.z, b.x, -a.x * b.z),
                 fma(a.x, b.y, -a.y * b.x));
}
static N(vec) N(unit)(N(vec) a) { return N(mul)(a, 1 / sqrt(N(dot)(a, a))); }

/* Moller-Trumbore with the fixed epsilons of the textbooks. */
static R N(moller)(const N(tri) *f, N(vec) o, N(vec) d, int fused)
{
    const R eps = (R)RB_NAIVE_EPSILON;
    N(vec) e1 = N(sub)(f->b, f->a), e2 = N(sub)(f->c, f->a);
    N(vec) p = fused ? N(cross_fma)(d, e2) : N(cross)(d, e2);
    R det = fused ? N(dot_fma)(e1, p) : N(dot)(e1, p);
    if (det > -eps && det < eps)
        return -1;
    R inv = 1 / det;
    N(vec) s = N(sub)(o, f->a);
    R u = (fused ? N(dot_fma)(s, p) : N(dot)(s, p)) * inv;
    if (u < 0 || u > 1)
        return -1;
    N(vec) q = fused ? N(cross_fma)(s, e1) : N(cross)(s, e1);
    R v = (fused ? N(dot_fma)(d, q) : N(dot)(d, q)) * inv;
    if (v < 0 || u + v > 1)
        return -1;
    R t = (fused ? N(dot_fma)(e2, q) : N(dot)(e2, q)) * inv;
    return t > eps ? t : -1;
}

/* The handout: computeIntersection (line and plane), changeCoord through
 * the normal equations of the frame (b - a, c - a), isInFacet within
 * EPSILON. */
static R N(plane)(const N(tri) *f, N(vec) o, N(vec) d, int *nan_seen)
{
    const R eps = (R)RB_NAIVE_EPSILON;
    R t = N(dot)(f->n, N(sub)(f->a, o)) / N(dot)(f->n, d);
    if (t != t)
        *nan_seen = 1;
    if (t <= eps)
        return -1;
    N(vec) p = N(add)(o, N(mul)(d, t));
    N(vec) e1 = N(sub)(f->b, f->a), e2 = N(sub)(f->c, f->a),
           w = N(sub)(p, f->a);
    R d11 = N(dot)(e1, e1), d12 = N(dot)(e1, e2), d22 = N(dot)(e2, e2);
    R r1 = N(dot)(w, e1), r2 = N(dot)(w, e2);
    R den = d11 * d22 - d12 * d12;
    R u = (d22 * r1 - d12 * r2) / den, v = (d11 * r2 - d12 * r1) / den;
    if (u != u || v != v)
        *nan_seen = 1;
    return u >= -eps && v >= -eps && u + v <= 1 + eps ? t : -1;
}

static R N(intersect)(const N(scene) *s, const N(tri) *f, N(vec) o,
                      N(vec) d, int *nan_seen)
{
    if (s->method == RB_NAIVE_PLANE)
        return N(plane)(f, o, d, nan_seen);
    return N(moller)(f, o, d, s->method == RB_NAIVE_MT_FMA);
}

/* Nearest hit along the unit direction d; -1 when none. */
static int N(nearest)(const N(scene) *s, N(vec) o, N(vec) d, R *t_out,
                      int *nan_seen)
{
    int best = -1;
    R best_t = 0;
    for (int i = 0; i < s->count; i++) {
        R t = N(intersect)(s, &s->tris[i], o, d, nan_seen);
        if (t > 0 && (best < 0 || t < best_t))
            best = i, best_t = t;
    }
    *t_out = best_t;
    return best;
}

static int N(blocked)(const N(scene) *s, N(vec) o, N(vec) d, R distance,
                      int *nan_seen)
{
    for (int i = 0; i < s->count; i++) {
        R t = N(intersect)(s, &s->tris[i], o, d, nan_seen);
        if (t > 0 && t < distance)
            return 1;
    }
    return 0;
}

static void N(trace)(const N(scene) *s, N(vec) o, N(vec) d, int depth,
                     R out[3], int *nan_seen)
{
    const R eps = (R)RB_NAIVE_EPSILON;
    R t;
    int i = N(nearest)(s, o, d, &t, nan_seen);
    if (i < 0) {
        for (int c = 0; c < 3; c++)
            out[c] = s->background[c];
        return;
    }
    const N(tri) *f = &s->tris[i];
    N(vec) p = N(add)(o, N(mul)(d, t));
    N(vec) n = N(dot)(f->n, d) > 0 ? N(mul)(f->n, -1) : f->n;
    R direct[3] = {0, 0, 0};
    for (int l = 0; l < s->light_count; l++) {
        N(vec) to_light = N(sub)(s->lights[l], p);
        R ns = N(dot)(n, N(unit)(to_light));
        if (!(ns > 0))
            continue;
        N(vec) so = N(add)(p, N(mul)(n, eps));
        N(vec) sd = N(sub)(s->lights[l], so);
        R distance = sqrt(N(dot)(sd, sd));
        if (N(blocked)(s, so, N(mul)(sd, 1 / distance), distance, nan_seen))
            continue;
        for (int c = 0; c < 3; c++)
            direct[c] += ns * s->light_colors[l][c];
    }
    /* Snell-Descartes with the winding normal: entering when d.n_w < 0. */
    R mirror_weight = f->k;
    R refracted[3] = {0, 0, 0};
    if (f->t > 0 && depth > 0) {
        int entering = N(dot)(d, f->n) < 0;
        R eta = entering ? 1 / f->ior : f->ior;
        N(vec) nt = entering ? f->n : N(mul)(f->n, -1);
        R c = -N(dot)(d, nt);
        R q = 1 - eta * eta * (1 - c * c);
        if (q < 0) {
            mirror_weight += f->t;      /* total internal reflection */
        } else {
            N(vec) tr = N(add)(N(mul)(d, eta), N(mul)(nt, eta * c - sqrt(q)));
            N(trace)(s, N(sub)(p, N(mul)(n, eps)), N(unit)(tr), depth - 1,
                     refracted, nan_seen);
        }
    }
    R reflected[3] = {0, 0, 0};
    if (mirror_weight > 0 && depth > 0) {
        N(vec) r = N(sub)(d, N(mul)(n, 2 * N(dot)(d, n)));
        N(trace)(s, N(add)(p, N(mul)(n, eps)), N(unit)(r), depth - 1,
                 reflected, nan_seen);
    }
    for (int c = 0; c < 3; c++)
        out[c] = mirror_weight * reflected[c] + f->t * refracted[c] +
                 f->d * direct[c] * f->color[c] / 255;
}

static N(scene) *N(create)(const rt_scene *scene, int method)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    N(scene) *s = calloc(1, sizeof *s);
    s->tris = calloc((size_t)(info.facet_count + 1), sizeof *s->tris);
    s->method = method;
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info fi = {.size = sizeof fi};
        rt_scene_facet(scene, i, &fi);
        N(tri) *f = &s->tris[s->count++];
        f->a = N(from)(rt_scene_vertex(scene, fi.vertex[0]));
        f->b = N(from)(rt_scene_vertex(scene, fi.vertex[1]));
        f->c = N(from)(rt_scene_vertex(scene, fi.vertex[2]));
        f->n = N(unit)(N(cross)(N(sub)(f->b, f->a), N(sub)(f->c, f->a)));
        f->k = (R)fi.reflection;
        f->t = (R)fi.transparency;
        f->ior = (R)fi.refractive_index;
        f->d = (R)fi.diffuse;
        f->color[0] = fi.color.r, f->color[1] = fi.color.g,
        f->color[2] = fi.color.b;
    }
    s->light_count = info.light_count;
    s->lights = calloc((size_t)info.light_count + 1, sizeof *s->lights);
    s->light_colors = calloc((size_t)info.light_count + 1,
                             sizeof *s->light_colors);
    for (int l = 0; l < info.light_count; l++) {
        rt_light light;
        rt_scene_light(scene, l, &light);
        s->lights[l] = N(from)(light.position);
        s->light_colors[l][0] = light.color.r;
        s->light_colors[l][1] = light.color.g;
        s->light_colors[l][2] = light.color.b;
    }
    s->background[0] = info.background.r;
    s->background[1] = info.background.g;
    s->background[2] = info.background.b;
    return s;
}

static void N(free_scene)(N(scene) *s)
{
    if (s != NULL) {
        free(s->tris);
        free(s->lights);
        free(s->light_colors);
    }
    free(s);
}

static int N(hit)(const N(scene) *s, rt_ray ray, rb_hit *hit)
{
    int nan_seen = 0;
    N(vec) o = N(from)(ray.origin), d = N(unit)(N(from)(ray.direction));
    R t;
    int i = N(nearest)(s, o, d, &t, &nan_seen);
    if (i < 0)
        return 0;
    N(vec) p = N(add)(o, N(mul)(d, t));
    /* t along the caller's direction, as ours reports it. */
    hit->t = (double)t / rb_length(ray.direction);
    hit->facet = i;
    hit->point = (rt_vec3){p.x, p.y, p.z};
    return 1;
}

static rt_color N(color)(const N(scene) *s, rt_ray ray, int depth)
{
    int nan_seen = 0;
    R c[3];
    N(trace)(s, N(from)(ray.origin), N(unit)(N(from)(ray.direction)), depth,
             c, &nan_seen);
    return (rt_color){c[0], c[1], c[2]};
}
