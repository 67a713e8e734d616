/*
 * test_packets.c - the camera-ray packets of the fast kernel
 * (src/kernel/packet_impl.h: spans of up to 8 pixels of a row share a tile
 * cull and go through the filter several rays at a time; their shadow rays
 * go in packets with a plane cull) against the plain scalar loops: the
 * same image, byte for byte.
 *
 * The packets serve pinhole renders of opaque scenes of at most 64 live
 * facets, brute force, with the AVX2 kernel; their shadow packets scenes of
 * at most 8 lights.  Every case here is such a scene (or one just past a
 * limit), built in memory as .scn text, and rendered with RT_KERNEL_SCALAR
 * on one thread (the reference) and with RT_KERNEL_AUTO on one and two
 * threads, in double and in float, with 1 sample, 4 regular and 4
 * stratified samples a pixel.  A mismatch names the case, the render, the
 * first differing pixel and both colours; every mismatch of a test is
 * printed before the test fails, so one run shows all the cases a bug
 * breaks.
 *
 * Cases: random scenes (1..64 facets, random cameras - diagonal views,
 * wide angles whose spans straddle the frames and the sign of their axis,
 * eyes inside the scene - and 1..3 lights); facets across, behind, very
 * near and through the eye; lights on, near and inside facets and inside a
 * closed box; extreme scales; 1, 3, 8 and 9 lights; 0, 1, 64 and 65
 * facets; image sizes and regions whose spans start at odd columns;
 * tessellated grids whose shared edges and vertices the rays hit exactly;
 * telephoto views in which a pixel is a few units in the last place, where
 * the tile cull's margin is all that keeps it exact.
 *
 * RT_TEST_MEMCHECK (set under valgrind) shrinks the images and the number
 * of random cases about twenty times; every kind of case still runs.  On a
 * processor without AVX2 both kernels run the scalar loops: the suite then
 * says so and checks nothing about the packets.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* --- scenes as data, written as .scn text ---------------------------- */

#define MAX_VERTICES 256
#define MAX_FACETS 80
#define MAX_LIGHTS 12

typedef struct facet_spec {
    int v[3];               /* 0-based */
    double k;
    int color[3];
} facet_spec;

typedef struct light_spec {
    rt_vec3 p;
    int color[3];
} light_spec;

typedef struct spec {
    rt_vec3 eye, a, b;
    int width, height;
    int nv, nf, nl;
    rt_vec3 v[MAX_VERTICES];
    facet_spec f[MAX_FACETS];
    int background[3];
    light_spec l[MAX_LIGHTS];
} spec;

static spec *spec_new(void)
{
    spec *s = calloc(1, sizeof *s);
    ck_assert_ptr_nonnull(s);
    s->width = 24;
    s->height = 18;
    s->background[0] = 20;
    s->background[1] = 40;
    s->background[2] = 90;
    return s;
}

static rt_vec3 vec(double x, double y, double z) { return (rt_vec3){x, y, z}; }
static rt_vec3 add(rt_vec3 a, rt_vec3 b) { return vec(a.x + b.x, a.y + b.y, a.z + b.z); }
static rt_vec3 sub(rt_vec3 a, rt_vec3 b) { return vec(a.x - b.x, a.y - b.y, a.z - b.z); }
static rt_vec3 mul(rt_vec3 a, double s) { return vec(a.x * s, a.y * s, a.z * s); }
static rt_vec3 cross(rt_vec3 a, rt_vec3 b)
{
    return vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
               a.x * b.y - a.y * b.x);
}
static double length(rt_vec3 a) { return sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
static rt_vec3 unit(rt_vec3 a) { return mul(a, 1.0 / length(a)); }

static int vertex(spec *s, rt_vec3 p)
{
    ck_assert_int_lt(s->nv, MAX_VERTICES);
    s->v[s->nv] = p;
    return s->nv++;
}

static void facet(spec *s, int a, int b, int c, double k, int r, int g,
                  int bl)
{
    ck_assert_int_lt(s->nf, MAX_FACETS);
    s->f[s->nf++] = (facet_spec){{a, b, c}, k, {r, g, bl}};
}

static void triangle(spec *s, rt_vec3 a, rt_vec3 b, rt_vec3 c, double k,
                     int r, int g, int bl)
{
    int ia = vertex(s, a), ib = vertex(s, b), ic = vertex(s, c);
    facet(s, ia, ib, ic, k, r, g, bl);
}

/* The square a, b, c, d (in order round it) as two facets. */
static void quad(spec *s, rt_vec3 a, rt_vec3 b, rt_vec3 c, rt_vec3 d,
                 double k, int r, int g, int bl)
{
    int ia = vertex(s, a), ib = vertex(s, b), ic = vertex(s, c),
        id = vertex(s, d);
    facet(s, ia, ib, ic, k, r, g, bl);
    facet(s, ia, ic, id, k, r, g, bl);
}

static void light(spec *s, rt_vec3 p, int r, int g, int b)
{
    ck_assert_int_lt(s->nl, MAX_LIGHTS);
    s->l[s->nl++] = (light_spec){p, {r, g, b}};
}

/* The camera at `eye` looking along `direction` (A = eye + direction, as
 * given: an exact diagonal stays exact), the screen's half-width
 * `half_width` |direction|, right-handed with `up` roughly up. */
static void aim(spec *s, rt_vec3 eye, rt_vec3 direction, rt_vec3 up,
                double half_width)
{
    rt_vec3 right = cross(direction, up);
    if (length(right) < 1e-9 * length(direction) * length(up))
        right = cross(direction, vec(0.31, -0.83, 0.47));
    s->eye = eye;
    s->a = add(eye, direction);
    s->b = add(s->a, mul(unit(right), half_width * length(direction)));
}

/* A closed box [lo, hi] of 12 facets wound outwards. */
static void box(spec *s, rt_vec3 lo, rt_vec3 hi, double k, int r, int g,
                int b)
{
    int c[8];
    for (int i = 0; i < 8; i++)
        c[i] = vertex(s, vec(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y,
                             i & 4 ? hi.z : lo.z));
    static const int face[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; f++) {
        facet(s, c[face[f][0]], c[face[f][1]], c[face[f][2]], k, r, g, b);
        facet(s, c[face[f][0]], c[face[f][2]], c[face[f][3]], k, r, g, b);
    }
}

static void put_point(rt_test_text *t, rt_vec3 p, double scale)
{
    rt_test_text_add(t, "%.17g, %.17g, %.17g", p.x * scale, p.y * scale, p.z * scale);
}

/* The .scn text of *s with every coordinate (camera, vertices, lights)
 * multiplied by `scale`; malloc'd. */
static char *scn_text(const spec *s, double scale)
{
    rt_test_text t = {NULL, 0, 0};
    rt_test_text_add(&t, "# test_packets\n");
    put_point(&t, s->eye, scale);
    rt_test_text_add(&t, "\n");
    put_point(&t, s->a, scale);
    rt_test_text_add(&t, ",  ");
    put_point(&t, s->b, scale);
    rt_test_text_add(&t, ",  %d, %d\n%d\n", s->width, s->height, s->nv);
    for (int i = 0; i < s->nv; i++) {
        put_point(&t, s->v[i], scale);
        rt_test_text_add(&t, "\n");
    }
    rt_test_text_add(&t, "%d\n", s->nf);
    for (int i = 0; i < s->nf; i++) {
        const facet_spec *f = &s->f[i];
        rt_test_text_add(&t, "%d, %d, %d, %.17g, %d, %d, %d\n", f->v[0] + 1, f->v[1] + 1,
            f->v[2] + 1, f->k, f->color[0], f->color[1], f->color[2]);
    }
    rt_test_text_add(&t, "%d, %d, %d\n", s->background[0], s->background[1],
        s->background[2]);
    for (int i = 0; i < s->nl; i++) {
        put_point(&t, s->l[i].p, scale);
        rt_test_text_add(&t, ", %d, %d, %d\n", s->l[i].color[0], s->l[i].color[1],
            s->l[i].color[2]);
    }
    return t.data;
}

/* --- the comparison -------------------------------------------------- */

/* What a test found: cases compared, renders, mismatches (the first one's
 * message kept for the failure), cases or precisions skipped. */
static struct {
    int cases, renders, mismatches, skipped;
    char first[1024];
} tally;

static void tally_reset(void) { memset(&tally, 0, sizeof tally); }

static void mismatch(const char *format, ...)
{
    char message[1024];
    va_list ap;
    va_start(ap, format);
    vsnprintf(message, sizeof message, format, ap);
    va_end(ap);
    fprintf(stderr, "test_packets: MISMATCH: %s\n", message);
    if (tally.mismatches++ == 0)
        snprintf(tally.first, sizeof tally.first, "%s", message);
}

/* Fails the test when it found a mismatch; says what it checked. */
static void tally_finish(const char *test)
{
    printf("test_packets: %s: %d cases, %d renders compared, %d skipped, "
           "%d mismatches\n",
           test, tally.cases, tally.renders, tally.skipped,
           tally.mismatches);
    fflush(stdout);
    ck_assert_msg(tally.mismatches == 0,
                  "%s: %d mismatches between RT_KERNEL_AUTO and "
                  "RT_KERNEL_SCALAR; the first: %s",
                  test, tally.mismatches, tally.first);
}

#define DOUBLE_ONLY 1u
#define FLOAT_ONLY 2u
#define BOTH 3u

typedef struct sampling_case {
    int samples;
    rt_sampling sampling;
    const char *name;
} sampling_case;

static const sampling_case samplings[] = {
    {1, RT_SAMPLING_REGULAR, "1 sample"},
    {4, RT_SAMPLING_REGULAR, "4 regular"},
    {4, RT_SAMPLING_STRATIFIED, "4 stratified"},
};

static rt_image render_one(const rt_scene *scene,
                           const rt_render_options *options,
                           const char *what)
{
    int width, height;
    rt_error error;
    rt_image image = {0, 0, 0, NULL};
    ck_assert_msg(rt_render_image_size(scene, options, &width, &height,
                                       &error) == RT_OK,
                  "%s: %s", what, error.message);
    ck_assert_int_eq(rt_image_init(&image, width, height, NULL), RT_OK);
    rt_status status = rt_render(scene, options, &image, &error);
    ck_assert_msg(status == RT_OK, "%s: the render failed: %s", what,
                  error.message);
    tally.renders++;
    return image;
}

/* Compares `got` with the reference `ref`, byte for byte; a mismatch names
 * the first differing pixel (in the whole image's coordinates) and both
 * colours. */
static void compare(const rt_image *ref, const rt_image *got,
                    const rt_render_options *options, const char *what)
{
    ck_assert_int_eq(ref->width, got->width);
    ck_assert_int_eq(ref->height, got->height);
    long differ = 0;
    int fx = -1, fy = -1;
    for (int y = 0; y < ref->height; y++) {
        const unsigned char *a = rt_image_pixel(ref, 0, y);
        const unsigned char *b = rt_image_pixel(got, 0, y);
        if (memcmp(a, b, (size_t)ref->width * 3) == 0)
            continue;
        for (int x = 0; x < ref->width; x++)
            if (memcmp(a + 3 * x, b + 3 * x, 3) != 0) {
                if (differ++ == 0) {
                    fx = x;
                    fy = y;
                }
            }
    }
    if (differ == 0)
        return;
    const unsigned char *a = rt_image_pixel(ref, fx, fy);
    const unsigned char *b = rt_image_pixel(got, fx, fy);
    mismatch("%s: %ld pixels differ; the first at (%d, %d): scalar "
             "(%d, %d, %d), auto (%d, %d, %d)",
             what, differ, fx + options->region.x0, fy + options->region.y0,
             a[0], a[1], a[2], b[0], b[1], b[2]);
}

/*
 * Renders `scene` with `base` (precision, kernel, threads, samples and
 * sampling set here) in the precisions of `precisions` and the three
 * samplings: the scalar loops on one thread, the fast kernel on one and
 * two threads, which must give the same bytes and cast the same shadow and
 * reflected rays.  A precision the scene cannot be rendered in (float's
 * range) is skipped, and said so.
 */
static void check_scene(const char *name, const rt_scene *scene,
                        const rt_render_options *base, unsigned precisions)
{
    tally.cases++;
    for (int p = 0; p < 2; p++) {
        if (!(precisions & (1u << p)))
            continue;
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        const char *pname = p ? "float" : "double";
        rt_error error;
        if (rt_scene_check_precision(scene, precision, &error) != RT_OK) {
            printf("test_packets: SKIPPED: %s (%s): the scene cannot be "
                   "rendered in %s: %s\n",
                   name, pname, pname, error.message);
            tally.skipped++;
            continue;
        }
        for (size_t i = 0; i < sizeof samplings / sizeof samplings[0]; i++) {
            const sampling_case *c = &samplings[i];
            rt_render_options options = *base;
            options.precision = precision;
            options.samples = c->samples;
            options.sampling = c->sampling;
            char what[512];
            snprintf(what, sizeof what, "%s (%s, %s", name, pname, c->name);
            rt_render_stats s_ref, s_fast;
            options.kernel = RT_KERNEL_SCALAR;
            options.threads = 1;
            options.stats = &s_ref;
            rt_image ref = render_one(scene, &options, what);
            options.kernel = RT_KERNEL_AUTO;
            options.stats = &s_fast;
            rt_image fast1 = render_one(scene, &options, what);
            options.threads = 2;
            options.stats = NULL;
            rt_image fast2 = render_one(scene, &options, what);
            char label[600];
            snprintf(label, sizeof label, "%s, 1 thread)", what);
            compare(&ref, &fast1, &options, label);
            snprintf(label, sizeof label, "%s, 2 threads)", what);
            compare(&ref, &fast2, &options, label);
            if (s_ref.shadow_rays != s_fast.shadow_rays ||
                s_ref.reflection_rays != s_fast.reflection_rays)
                mismatch("%s): scalar cast %llu shadow and %llu reflected "
                         "rays, auto %llu and %llu",
                         what, (unsigned long long)s_ref.shadow_rays,
                         (unsigned long long)s_ref.reflection_rays,
                         (unsigned long long)s_fast.shadow_rays,
                         (unsigned long long)s_fast.reflection_rays);
            rt_image_release(&ref);
            rt_image_release(&fast1);
            rt_image_release(&fast2);
        }
    }
}

/* Loads *s at `scale` and checks it; when the loader refuses the scene,
 * fails the test unless `may_refuse`, in which case the case is skipped
 * and said so.  `base` NULL: the default options. */
static void check_spec(const char *name, const spec *s, double scale,
                       const rt_render_options *base, unsigned precisions,
                       int may_refuse)
{
    char *t = scn_text(s, scale);
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_parse(t, strlen(t), name, &scene, &error);
    free(t);
    if (status != RT_OK) {
        ck_assert_msg(may_refuse, "%s: the scene did not load: %s", name,
                      error.message);
        printf("test_packets: SKIPPED: %s: the loader refuses the scene: "
               "%s\n",
               name, error.message);
        tally.skipped++;
        return;
    }
    rt_render_options defaults;
    rt_render_options_init(&defaults);
    check_scene(name, scene, base != NULL ? base : &defaults, precisions);
    rt_scene_destroy(scene);
}

/* --- random scenes --------------------------------------------------- */

/* The generator of the random scenes, seeded by each test. */
static rt_test_rng rng;

static double uniform(double lo, double hi)
{
    return rt_test_rng_range(&rng, lo, hi);
}

static int below(int n) { return rt_test_rng_below(&rng, n); }

static rt_vec3 random_point(double r)
{
    return vec(uniform(-r, r), uniform(-r, r), uniform(-r, r));
}

static rt_vec3 random_direction(void)
{
    for (;;) {
        rt_vec3 d = random_point(1);
        double l = length(d);
        if (l > 0.1 && l <= 1)
            return mul(d, 1 / l);
    }
}

static const double reflections[] = {0, 0, 0, 0.25, 0.5, 1};

static void random_facets(spec *s, int count)
{
    int start = s->nf;
    if (count >= 6 && uniform(0, 1) < 0.5) {     /* a floor under them */
        double z = uniform(-2, -1);
        quad(s, vec(-4, -4, z), vec(4, -4, z), vec(4, 4, z), vec(-4, 4, z),
             uniform(0, 1) < 0.5 ? 0.0 : 0.4, 160, 160, 150);
    }
    while (s->nf - start < count) {
        double k = reflections[below(6)];
        int r = below(256), g = below(256), b = below(256);
        if (s->nf > start && uniform(0, 1) < 0.35) {
            /* a neighbour: shares an edge with the previous facet */
            const facet_spec *p = &s->f[s->nf - 1];
            int e = below(3);
            int i = p->v[e], j = p->v[(e + 1) % 3];
            rt_vec3 mid = mul(add(s->v[i], s->v[j]), 0.5);
            int c = vertex(s, add(mid, random_point(1.2)));
            facet(s, j, i, c, k, r, g, b);
            continue;
        }
        rt_vec3 centre = random_point(1.8);
        double size = uniform(0.15, 1.8);
        triangle(s, add(centre, mul(random_direction(), size)),
                 add(centre, mul(random_direction(), size)),
                 add(centre, mul(random_direction(), size)), k, r, g, b);
    }
}

static const rt_vec3 diagonals[] = {
    {1, 1, 1},  {1, 1, 0},  {-1, 1, 1}, {1, 0, -1}, {0, -1, 1},
    {-1, -1, -1}, {1, -1, 0}, {2, 1, 1}, {1, 1, 2}, {-1, 0, -1}};

/* A camera of kind `kind` on the scene near the origin. */
static void random_camera(spec *s, int kind)
{
    static const double fields[] = {0.3, 0.8, 1.5, 4, 40};
    double half_width = fields[below(5)];
    rt_vec3 up = random_direction();
    switch (kind) {
    case 0: {   /* from outside, at a point of the scene */
        rt_vec3 eye = mul(random_direction(), uniform(4, 8));
        aim(s, eye, sub(random_point(1), eye), up, half_width);
        break;
    }
    case 1: {   /* along a diagonal, exactly: spans straddle the frames */
        rt_vec3 d = diagonals[below(10)];
        rt_vec3 eye = sub(vec(below(3) - 1, below(3) - 1, below(3) - 1),
                          mul(d, 4));
        aim(s, eye, d, uniform(0, 1) < 0.5 ? vec(0, 0, 1) : up, half_width);
        break;
    }
    case 2: {   /* a wide angle: spans cross the axis planes, some straddle
                   the sign of their axis */
        rt_vec3 eye = mul(random_direction(), uniform(3, 6));
        aim(s, eye, sub(random_point(1), eye), up, uniform(5, 500));
        break;
    }
    default: {  /* inside the scene: facets all round and behind */
        rt_vec3 eye = random_point(1.5);
        aim(s, eye, random_direction(), up, half_width);
        break;
    }
    }
}

static void random_lights(spec *s, int count)
{
    for (int i = 0; i < count; i++)
        light(s, random_point(4), 80 + below(176), 80 + below(176),
              80 + below(176));
}

START_TEST(random_scenes_render_identically)
{
    tally_reset();
    int cases = rt_test_memcheck() ? 4 : 48;
    for (int i = 0; i < cases; i++) {
        rng.state = 0x5eed0000u + (uint64_t)i * 7919u;
        spec *s = spec_new();
        random_facets(s, 1 + below(64));
        random_camera(s, i % 4);
        random_lights(s, 1 + below(3));
        s->width = rt_test_memcheck() ? 6 + below(5) : 17 + below(24);
        s->height = rt_test_memcheck() ? 5 + below(4) : 9 + below(16);
        char name[128];
        snprintf(name, sizeof name, "random scene %d (%d facets, %d lights, "
                 "camera kind %d)", i, s->nf, s->nl, i % 4);
        check_spec(name, s, 1, NULL, BOTH, 0);
        free(s);
    }
    tally_finish("random scenes");
}
END_TEST

/* A camera on the origin looking along exact diagonals with a wide screen,
 * in a ring of facets: the screen crosses the axis planes and the planes
 * where the dominant axis changes. */
START_TEST(diagonal_views_render_identically)
{
    tally_reset();
    static const rt_vec3 views[] = {{1, 1, 1}, {1, 1, 0}, {-1, 1, -1},
                                    {0, 1, 1}, {1, 0, 0}};
    static const double widths[] = {1, 3, 1e3};
    for (int v = 0; v < 5; v++)
        for (int w = 0; w < 3; w++) {
            rng.state = 0xd1a90000u + (uint64_t)(v * 3 + w);
            spec *s = spec_new();
            /* facets all round the eye: a shell of 40 random ones */
            for (int i = 0; i < 40; i++) {
                rt_vec3 c = mul(random_direction(), uniform(2, 4));
                double size = uniform(0.3, 1.5);
                triangle(s, add(c, mul(random_direction(), size)),
                         add(c, mul(random_direction(), size)),
                         add(c, mul(random_direction(), size)),
                         reflections[below(6)], below(256), below(256),
                         below(256));
            }
            random_lights(s, 2);
            light(s, vec(0.5, 0.25, 0.125), 200, 200, 200);
            aim(s, vec(0, 0, 0), views[v], vec(0, 0, 1), widths[w]);
            s->width = rt_test_memcheck() ? 9 : 33;
            s->height = rt_test_memcheck() ? 7 : 25;
            char name[128];
            snprintf(name, sizeof name,
                     "diagonal view (%g, %g, %g), half-width %g", views[v].x,
                     views[v].y, views[v].z, widths[w]);
            check_spec(name, s, 1, NULL, BOTH, 0);
            free(s);
        }
    tally_finish("diagonal views");
}
END_TEST

/* --- the eye --------------------------------------------------------- */

START_TEST(facets_at_the_eye_render_identically)
{
    tally_reset();
    const rt_vec3 e = {0.25, -0.5, 0.125};     /* the eye, dyadic */
    const rt_vec3 d = {0.5, 1, 0.25};          /* the view */
    for (int variant = 0; variant < 8; variant++) {
        spec *s = spec_new();
        /* a backdrop: a wall ahead and a floor */
        quad(s, vec(-6, 8, -3), vec(6, 8, -3), vec(6, 8, 5), vec(-6, 8, 5), 0,
             200, 190, 170);
        quad(s, vec(-6, -6, -1), vec(6, -6, -1), vec(6, 8, -1), vec(-6, 8, -1),
             0.5, 120, 140, 160);
        const char *what = "";
        switch (variant) {
        case 0:     /* a large facet across the eye plane, beside the eye */
            what = "a facet across the eye plane";
            triangle(s, add(e, vec(-2, -3, -0.5)), add(e, vec(0.5, 4, -0.25)),
                     add(e, vec(-0.5, 2, 1.5)), 0.25, 250, 60, 60);
            break;
        case 1:     /* facets wholly behind the eye, and one across */
            what = "facets behind the eye";
            triangle(s, add(e, vec(-1, -2, -1)), add(e, vec(1, -2, -1)),
                     add(e, vec(0, -2, 1)), 0, 250, 60, 60);
            triangle(s, add(e, vec(-3, -0.5, -2)), add(e, vec(3, -0.5, -2)),
                     add(e, vec(0, 1.5, 2)), 0.5, 60, 250, 60);
            break;
        case 2:     /* tiny facets just in front of the eye */
            what = "facets very near the eye";
            triangle(s, add(e, vec(-1e-6, 2e-6, -1e-6)),
                     add(e, vec(1e-6, 2e-6, -1e-6)),
                     add(e, vec(0, 2e-6, 1e-6)), 0.25, 250, 60, 60);
            triangle(s, add(e, vec(1e-9, 1e-8, 1e-9)),
                     add(e, vec(3e-9, 1.1e-8, -2e-9)),
                     add(e, vec(-2e-9, 0.9e-8, 0)), 0, 60, 250, 60);
            break;
        case 3:     /* the eye inside a facet (its plane holds the eye) */
            what = "a facet through the eye";
            triangle(s, add(e, vec(-1, -1, -1)), add(e, vec(2, 0, -0.5)),
                     add(e, vec(-1, 1, 1.5)), 0.25, 250, 60, 60);
            break;
        case 4:     /* a vertex at the eye, an edge pointing at it */
            what = "a vertex at the eye and an edge pointing at it";
            triangle(s, e, add(e, vec(1, 3, 0.5)), add(e, vec(-0.5, 3, 1)), 0,
                     250, 60, 60);
            triangle(s, add(e, mul(d, 2)), add(e, mul(d, 4)),
                     add(e, vec(1, 2, -1)), 0.5, 60, 250, 60);
            break;
        case 5:     /* facets seen edge-on: their planes hold the eye */
            what = "facets seen edge-on";
            triangle(s, add(e, vec(-1, 2, 0)), add(e, vec(1, 2, 0)),
                     add(e, vec(0, 4, 0)), 0, 250, 60, 60);
            triangle(s, add(e, vec(0, 2, -1)), add(e, vec(0, 3, 1)),
                     add(e, vec(0, 5, 0)), 0.5, 60, 250, 60);
            break;
        case 6:     /* a facet a hair off the eye, almost edge-on */
            what = "a facet a hair from the eye";
            triangle(s, add(e, vec(-1, 1, 1e-13)), add(e, vec(1, 1, 1e-13)),
                     add(e, vec(0, 4, -1e-12)), 0.25, 250, 60, 60);
            triangle(s, add(e, vec(-2, -2, -2)), add(e, vec(2, -1, 2)),
                     add(e, vec(0, 1e-12, 0)), 0, 60, 250, 60);
            break;
        default:    /* the eye inside a closed box */
            what = "the eye inside a closed box";
            box(s, add(e, vec(-1, -1, -1)), add(e, vec(1.5, 2, 1)), 0.5, 200,
                200, 60);
            break;
        }
        light(s, vec(2, 1, 4), 255, 255, 255);
        light(s, add(e, vec(0.5, 0.5, 0.5)), 120, 120, 255);
        for (int camera = 0; camera < 2; camera++) {
            aim(s, e, d, vec(0, 0, 1), camera ? 6 : 0.7);
            s->width = rt_test_memcheck() ? 9 : 35;
            s->height = rt_test_memcheck() ? 7 : 27;
            char name[160];
            snprintf(name, sizeof name, "%s (%s)", what,
                     camera ? "wide" : "normal");
            check_spec(name, s, 1, NULL, BOTH, 0);
        }
        free(s);
    }
    tally_finish("facets at the eye");
}
END_TEST

/* --- lights on and in facets ----------------------------------------- */

/* A floor z = 0, a wall x = 2, posts that cast shadows on them. */
static spec *shadow_scene(void)
{
    spec *s = spec_new();
    quad(s, vec(-4, -4, 0), vec(4, -4, 0), vec(4, 4, 0), vec(-4, 4, 0), 0.25,
         200, 200, 200);
    quad(s, vec(2, -4, 0), vec(2, 4, 0), vec(2, 4, 3), vec(2, -4, 3), 0, 180,
         200, 220);
    box(s, vec(-1, -1, 0.5), vec(0, 0, 1.5), 0, 220, 80, 80);
    triangle(s, vec(0.5, 1, 0.25), vec(1.5, 1.5, 0.25), vec(1, 1, 2), 0.5,
             80, 220, 80);
    aim(s, vec(-6, -5, 4), vec(5.5, 5, -3.5), vec(0, 0, 1), 0.8);
    return s;
}

START_TEST(lights_on_and_in_facets_render_identically)
{
    tally_reset();
    static const struct {
        rt_vec3 p;
        const char *what;
    } lights[] = {
        {{-2, 1, 0}, "a light on the floor's plane"},
        {{-2, 1, 1e-14}, "a light 1e-14 above the floor's plane"},
        {{-2, 1, -1e-14}, "a light 1e-14 below the floor's plane"},
        {{-2, 1, 1e-9}, "a light 1e-9 above the floor's plane"},
        {{2, 0.5, 1.5}, "a light inside the wall (a facet through it)"},
        {{2, -4, 3}, "a light at a corner of the wall"},
        {{2, 0, 0}, "a light on the edge shared by wall and floor"},
        {{-0.5, -0.5, 1}, "a light inside the closed box"},
        {{-0.5, -0.5, 1.5}, "a light on the box's top face"},
        {{1, 1.25, 1.125}, "a light on the slanted facet's plane"},
    };
    for (size_t i = 0; i < sizeof lights / sizeof lights[0]; i++) {
        spec *s = shadow_scene();
        light(s, lights[i].p, 255, 240, 220);
        light(s, vec(-3, 2, 5), 90, 90, 140);
        s->width = rt_test_memcheck() ? 10 : 40;
        s->height = rt_test_memcheck() ? 8 : 30;
        check_spec(lights[i].what, s, 1, NULL, BOTH, 0);
        free(s);
    }
    /* the eye in the box with the light */
    spec *s = spec_new();
    box(s, vec(-1, -1, -1), vec(1, 1, 1), 0.25, 200, 200, 200);
    box(s, vec(-0.25, 0.25, -0.5), vec(0.25, 0.5, 0), 0, 220, 80, 80);
    light(s, vec(0.5, 0.5, 0.75), 255, 255, 255);
    light(s, vec(-0.75, 0.5, -0.9), 100, 100, 255);
    aim(s, vec(0, -0.75, 0.25), vec(0.25, 1, -0.5), vec(0, 0, 1), 1.5);
    s->width = rt_test_memcheck() ? 10 : 40;
    s->height = rt_test_memcheck() ? 8 : 30;
    check_spec("the eye and the lights inside a closed box", s, 1, NULL, BOTH,
               0);
    free(s);
    tally_finish("lights on and in facets");
}
END_TEST

/* --- scales ---------------------------------------------------------- */

START_TEST(extreme_scales_render_identically)
{
    tally_reset();
    static const struct {
        double scale;
        unsigned precisions;
    } scales[] = {
        {1e-100, DOUBLE_ONLY}, {1e100, DOUBLE_ONLY}, {1e-20, FLOAT_ONLY},
        {1e20, FLOAT_ONLY},    {1e-150, DOUBLE_ONLY}, {1e150, DOUBLE_ONLY},
        {1e-15, FLOAT_ONLY},   {1e15, FLOAT_ONLY},   {1e160, DOUBLE_ONLY},
        {1e-160, DOUBLE_ONLY}, {1e-22, FLOAT_ONLY}, /* products subnormal */
    };
    for (int scene = 0; scene < 2; scene++) {
        spec *s;
        if (scene == 0) {
            s = shadow_scene();
            light(s, vec(-2, 1, 3), 255, 240, 220);
            light(s, vec(1, -3, 2), 90, 90, 140);
        } else {
            rng.state = 0x5ca1e000u;
            s = spec_new();
            random_facets(s, 60);
            random_camera(s, 1);
            random_lights(s, 3);
        }
        s->width = rt_test_memcheck() ? 10 : 40;
        s->height = rt_test_memcheck() ? 8 : 30;
        for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
            char name[128];
            snprintf(name, sizeof name, "%s scaled by %g",
                     scene ? "a random scene" : "the shadow scene",
                     scales[i].scale);
            check_spec(name, s, scales[i].scale, NULL, scales[i].precisions,
                       1);
        }
        free(s);
    }
    tally_finish("extreme scales");
}
END_TEST

/* --- limits ---------------------------------------------------------- */

START_TEST(light_counts_render_identically)
{
    tally_reset();
    static const int counts[] = {1, 3, 8, 9};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++)
        for (int scene = 0; scene < 2; scene++) {
            spec *s;
            if (scene == 0) {
                s = shadow_scene();
            } else {
                rng.state = 0x119470u;
                s = spec_new();
                random_facets(s, 50);
                random_camera(s, 0);
            }
            rng.state = 0x1167u + i;
            for (int l = 0; l < counts[i]; l++)
                light(s, add(vec(0, 0, 2.5), random_point(3)), 30 + below(60),
                      30 + below(60), 30 + below(60));
            s->width = rt_test_memcheck() ? 10 : 36;
            s->height = rt_test_memcheck() ? 8 : 27;
            char name[128];
            snprintf(name, sizeof name, "%s with %d lights",
                     scene ? "a random scene" : "the shadow scene", counts[i]);
            check_spec(name, s, 1, NULL, BOTH, 0);
            free(s);
        }
    tally_finish("light counts");
}
END_TEST

START_TEST(facet_counts_render_identically)
{
    tally_reset();
    static const int counts[] = {0, 1, 2, 63, 64, 65};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        rng.state = 0xfac37u + i;
        spec *s = spec_new();
        random_facets(s, counts[i]);
        ck_assert_int_eq(s->nf, counts[i]);
        if (counts[i] == 0)
            vertex(s, vec(1, 2, 3));
        random_camera(s, 0);
        random_lights(s, 2);
        s->width = rt_test_memcheck() ? 10 : 36;
        s->height = rt_test_memcheck() ? 8 : 27;
        char name[64];
        snprintf(name, sizeof name, "%d facets", counts[i]);
        check_spec(name, s, 1, NULL, BOTH, 0);
        if (counts[i] == 65) {
            /* 65 in the file, 64 live: a zero-area facet is left out, so
             * the packets serve it */
            s->f[10].v[2] = s->f[10].v[0];
            char *t = scn_text(s, 1);
            rt_scene *scene = rt_test_scene_from_string(t);
            free(t);
            rt_scene_info info;
            rt_scene_get_info(scene, &info);
            ck_assert_int_eq(info.facet_count, 65);
            ck_assert_int_eq(info.live_facet_count, 64);
            rt_scene_destroy(scene);
            check_spec("65 facets, one of zero area", s, 1, NULL, BOTH, 0);
        }
        free(s);
    }
    tally_finish("facet counts");
}
END_TEST

/* Another image size than the scene's and regions: spans start at odd
 * columns and end short. */
START_TEST(sizes_and_regions_render_identically)
{
    tally_reset();
    static const struct {
        int width, height;
        rt_region region;
    } cases[] = {
        {37, 23, {0, 0, 0, 0}},     {37, 23, {3, 1, 36, 20}},
        {37, 23, {5, 7, 6, 9}},     {37, 23, {1, 0, 37, 23}},
        {0, 0, {7, 2, 31, 11}},     {61, 9, {13, 0, 56, 9}},
        {11, 40, {9, 3, 11, 38}},   {120, 90, {51, 40, 66, 47}},
    };
    for (int scene = 0; scene < 2; scene++) {
        spec *s;
        if (scene == 0) {
            s = shadow_scene();
            light(s, vec(-2, 1, 3), 255, 240, 220);
        } else {
            rng.state = 0x5123u;
            s = spec_new();
            random_facets(s, 64);
            random_camera(s, 1);
            random_lights(s, 2);
        }
        s->width = 32;
        s->height = 24;
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            if (rt_test_memcheck() && i % 3 != 0)
                continue;
            rt_render_options options;
            rt_render_options_init(&options);
            options.width = cases[i].width;
            options.height = cases[i].height;
            options.region = cases[i].region;
            char name[160];
            snprintf(name, sizeof name,
                     "%s at %d x %d, region (%d, %d)..(%d, %d)",
                     scene ? "a random scene" : "the shadow scene",
                     cases[i].width, cases[i].height, cases[i].region.x0,
                     cases[i].region.y0, cases[i].region.x1,
                     cases[i].region.y1);
            check_spec(name, s, 1, &options, BOTH, 0);
        }
        free(s);
    }
    tally_finish("sizes and regions");
}
END_TEST

/* --- shared edges ---------------------------------------------------- */

/* An nx x ny grid of squares of side `side` (two facets each, diagonals
 * alternating or not) in the plane z = 0 from (x0, y0), heights from
 * `height` (NULL: flat). */
static void grid(spec *s, int nx, int ny, double side, double x0, double y0,
                 const double *height, int alternate)
{
    int first = s->nv;
    for (int y = 0; y <= ny; y++)
        for (int x = 0; x <= nx; x++)
            vertex(s, vec(x0 + x * side, y0 + y * side,
                          height ? height[y * (nx + 1) + x] : 0.0));
    for (int y = 0; y < ny; y++)
        for (int x = 0; x < nx; x++) {
            int a = first + y * (nx + 1) + x, b = a + 1, c = a + nx + 1,
                d = c + 1;
            int r = 60 + 20 * x, g = 60 + 25 * y, bl = 140;
            double k = (x + y) % 3 == 0 ? 0.5 : 0;
            if (alternate && (x + y) % 2) {
                facet(s, a, b, c, k, r, g, bl);
                facet(s, b, d, c, k, r, g, bl);
            } else {
                facet(s, a, b, d, k, r, g, bl);
                facet(s, a, d, c, k, r, g, bl);
            }
        }
}

START_TEST(tessellated_grids_render_identically)
{
    tally_reset();
    const int w = rt_test_memcheck() ? 8 : 32, h = rt_test_memcheck() ? 8 : 16;
    /* 1. A flat 8 x 4 grid (64 facets) of side 2^-6 seen straight down from
     * the height that puts the pixel centres' rays on its vertices and the
     * 2 x 2 samples' on its diagonals, exactly. */
    for (int alternate = 0; alternate < 2; alternate++) {
        spec *s = spec_new();
        const double side = 0x1p-6;
        grid(s, 8, 4, side, -4 * side, -2 * side, NULL, alternate);
        s->width = w;
        s->height = h;
        /* centre ray of pixel i hits x = (2i + 1 - w) H / w: H = w side / 2
         * puts it on a vertex (x a multiple of side when w even) */
        double height = w * side / 2;
        s->eye = vec(0, 0, height);
        s->a = vec(0, 0, height - side);
        s->b = vec(side, 0, height - side);
        light(s, vec(3 * side, 1 * side, 2 * side), 255, 255, 255);
        light(s, vec(-2 * side, -1 * side, 0), 100, 100, 100);
        char name[96];
        snprintf(name, sizeof name, "a flat grid seen straight down%s",
                 alternate ? ", diagonals alternating" : "");
        check_spec(name, s, 1, NULL, BOTH, 0);
        /* the same grid at an angle, and from below */
        aim(s, vec(-3 * side, -5 * side, 4 * side), vec(3, 5, -4),
            vec(0, 0, 1), 0.5);
        snprintf(name, sizeof name, "a flat grid at an angle%s",
                 alternate ? ", diagonals alternating" : "");
        check_spec(name, s, 1, NULL, BOTH, 0);
        aim(s, vec(1 * side, 0.5 * side, -3 * side), vec(-1, -0.5, 3),
            vec(0, 1, 0), 1);
        snprintf(name, sizeof name, "a flat grid from below%s",
                 alternate ? ", diagonals alternating" : "");
        check_spec(name, s, 1, NULL, BOTH, 0);
        free(s);
    }
    /* 2. A bumpy 7 x 4 height field (56 facets) that shadows itself, with
     * posts, seen from several sides. */
    rng.state = 0x917du;
    double heights[8 * 5];
    for (int i = 0; i < 8 * 5; i++)
        heights[i] = uniform(0, 0.6);
    for (int view = 0; view < 4; view++) {
        spec *s = spec_new();
        grid(s, 7, 4, 0.5, -1.75, -1, heights, view % 2);
        triangle(s, vec(-0.5, 0, 0.3), vec(0.5, 0, 0.3), vec(0, 0.1, 1.5),
                 0.25, 240, 200, 60);
        light(s, vec(-2, -1, 2.5), 255, 255, 255);
        light(s, vec(3, 2, 1.2), 120, 140, 160);
        static const rt_vec3 eyes[] = {
            {-3, -3, 2.5}, {0.25, 0.0, 4}, {3, -0.5, 0.8}, {-1, 3, 1.5}};
        aim(s, eyes[view], sub(vec(0, 0, 0.3), eyes[view]), vec(0, 0, 1),
            0.7);
        s->width = rt_test_memcheck() ? 10 : 37;
        s->height = rt_test_memcheck() ? 8 : 25;
        char name[64];
        snprintf(name, sizeof name, "a bumpy height field, view %d", view);
        check_spec(name, s, 1, NULL, BOTH, 0);
        free(s);
    }
    tally_finish("tessellated grids");
}
END_TEST

/* --- telephoto: pixels a few ulps wide -------------------------------- */

/*
 * A fan of 6 facets round a vertex V, a wall behind it and an occluder
 * casting a shadow on the wall, seen through a screen so narrow that a
 * pixel of a 16384-pixel image spans about one unit in the last place of
 * the rays' shear: the rays of a span, normalised and divided in the
 * kernel's precision, then stray out of the box of the span's corners (by
 * a few ulps), past the edges of facets that cross near it.  The tile cull
 * must keep every facet such a ray may hit: only its margin (`slack`)
 * covers that.  targets[]: V, a point on each of the six edges from V
 * (each shared by two facets), a corner of the shadow.
 */
#define TARGETS 8

static spec *fan_scene(rt_vec3 targets[TARGETS])
{
    spec *s = spec_new();
    const rt_vec3 v = {0.3, 0.7, -0.2};
    int centre = vertex(s, v);
    int ring[6];
    for (int i = 0; i < 6; i++) {
        double angle = 2 * 3.14159265358979323846 * (i + 0.37) / 6;
        ring[i] = vertex(s, add(v, vec(cos(angle), 0.3 * sin(angle),
                                       sin(angle))));
    }
    for (int i = 0; i < 6; i++)
        facet(s, centre, ring[i], ring[(i + 1) % 6], i % 2 ? 0.25 : 0,
              40 * i + 30, 200 - 30 * i, 90 + 25 * i);
    /* a wall behind the fan, and an occluder between it and a light */
    quad(s, vec(-5, 5, -5), vec(5, 5, -5), vec(5, 5, 5), vec(-5, 5, 5), 0,
         180, 180, 180);
    const rt_vec3 corner = {3, 0.5, 1}, bright = {3.2, -2, 1.6};
    triangle(s, corner, vec(3.6, 0.5, 1.1), vec(3.3, 0.6, 0.4), 0, 250, 250,
             40);
    light(s, bright, 255, 255, 255);
    light(s, vec(-2, -3, -1), 80, 80, 120);
    targets[0] = v;
    for (int i = 0; i < 6; i++)
        targets[1 + i] = add(mul(v, 0.75), mul(s->v[ring[i]], 0.25));
    targets[7] = add(bright, mul(sub(corner, bright),
                                 (5 - bright.y) / (corner.y - bright.y)));
    return s;
}

START_TEST(telephoto_views_render_identically)
{
    tally_reset();
    /* the screen's half-width over |AO|: a pixel is 2 field / 16384 of
     * shear, a few ulps of the rays' shear (about 0.1 here) in double
     * (2^-52) and in float's kernel (2^-23) */
    static const struct {
        double field;
        unsigned precisions;
    } fields[] = {{3e-13, DOUBLE_ONLY}, {2e-13, DOUBLE_ONLY},
                  {1.5e-13, DOUBLE_ONLY}, {1e-13, DOUBLE_ONLY},
                  {7e-14, DOUBLE_ONLY}, {5e-14, DOUBLE_ONLY},
                  {1e-4, FLOAT_ONLY},   {7e-5, FLOAT_ONLY},
                  {5e-5, FLOAT_ONLY},   {3.5e-5, FLOAT_ONLY},
                  {2.5e-5, FLOAT_ONLY}, {1.8e-5, FLOAT_ONLY}};
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++)
        for (int t = 0; t < TARGETS; t++) {
            if (rt_test_memcheck() && (t + (int)i) % 4 != 0)
                continue;
            rt_vec3 targets[TARGETS];
            spec *s = fan_scene(targets);
            rt_vec3 eye = vec(0.1, -3.3, 0.35);
            aim(s, eye, sub(targets[t], eye), vec(0, 0, 1), fields[i].field);
            s->width = 16384;
            s->height = 16384;
            rt_render_options options;
            rt_render_options_init(&options);
            int rw = rt_test_memcheck() ? 16 : 64, rh = rt_test_memcheck() ? 4 : 16;
            options.region = (rt_region){8192 - rw / 2 + 1, 8192 - rh / 2,
                                         8192 + rw / 2 + 1, 8192 + rh / 2};
            char name[128];
            snprintf(name, sizeof name, "telephoto %g at %s %d",
                     fields[i].field,
                     t == 0 ? "the fan's vertex"
                     : t < 7 ? "a shared edge" : "a shadow's corner", t);
            check_spec(name, s, 1, &options, fields[i].precisions, 0);
            free(s);
        }
    tally_finish("telephoto views");
}
END_TEST

/* --- an eye far from the origin ---------------------------------------- */

/*
 * Found by a review: an eye a million units from the origin and a screen a
 * millionth of a unit wide.  The camera's rounding of the directions (of
 * the order of eps |O| over |AO|) put one stratified sample's shear outside
 * the box of the span's four corner rays, and the tile cull built from
 * that box left out the facet the sample hits: pixel (32, 0) came out as
 * background.  The cull now takes its box from the rays' own shears.
 */
static const char far_eye_scene[] =
    "700000, -500000, 300000\n"
    "700000.94072086841, -499999.7177837395, 300000.18814417365, "
    "700000.9407208655, -499999.7177837299, 300000.18814417365, 64, 4\n"
    "3\n"
    "1000700000, 299499999.94183695, -799700000.49500477\n"
    "1000700000, 299499999.94183695, 1200299999.5049953\n"
    "1000700000, -700500000.05816293, 200299999.50499529\n"
    "1\n"
    "1, 2, 3, 0, 200, 100, 50\n"
    "20, 40, 90\n"
    "229639.56580820138, -641108.13025753957, 205927.91316164029, 255, "
    "255, 255\n";

START_TEST(an_eye_far_from_the_origin_renders_identically)
{
    tally_reset();
    rt_scene *scene = NULL;
    rt_error error;
    ck_assert_msg(rt_scene_parse(far_eye_scene, strlen(far_eye_scene),
                                 "far-eye.scn", &scene, &error) == RT_OK,
                  "%s", error.message);
    static const int samples[] = {16, 9, 4, 1};
    for (int p = 0; p < 2; p++)
        for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++) {
            rt_render_options options;
            rt_render_options_init(&options);
            options.precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
            options.samples = samples[i];
            options.sampling = RT_SAMPLING_STRATIFIED;
            char what[128];
            snprintf(what, sizeof what, "far eye (%s, %d stratified)",
                     p ? "float" : "double", samples[i]);
            if (rt_scene_check_precision(scene, options.precision,
                                         &error) != RT_OK) {
                printf("test_packets: SKIPPED: %s: %s\n", what,
                       error.message);
                tally.skipped++;
                continue;
            }
            tally.cases++;
            options.kernel = RT_KERNEL_SCALAR;
            rt_image ref = render_one(scene, &options, what);
            options.kernel = RT_KERNEL_AUTO;
            rt_image fast = render_one(scene, &options, what);
            compare(&ref, &fast, &options, what);
            rt_image_release(&ref);
            rt_image_release(&fast);
        }
    rt_scene_destroy(scene);
    tally_finish("an eye far from the origin");
}
END_TEST

static Suite *packets_suite(void)
{
    Suite *s = suite_create("packets");
#if defined(__x86_64__) || defined(__i386__)
    int avx2 = __builtin_cpu_supports("avx2");
#else
    int avx2 = 0;
#endif
    if (!avx2)
        printf("test_packets: this processor has no AVX2: both kernels run "
               "the scalar loops, the packets are not checked\n");
    TCase *c = tcase_create("images");
    tcase_set_timeout(c, 600);
    tcase_add_test(c, random_scenes_render_identically);
    tcase_add_test(c, diagonal_views_render_identically);
    tcase_add_test(c, facets_at_the_eye_render_identically);
    tcase_add_test(c, lights_on_and_in_facets_render_identically);
    tcase_add_test(c, extreme_scales_render_identically);
    tcase_add_test(c, light_counts_render_identically);
    tcase_add_test(c, facet_counts_render_identically);
    tcase_add_test(c, sizes_and_regions_render_identically);
    tcase_add_test(c, tessellated_grids_render_identically);
    tcase_add_test(c, telephoto_views_render_identically);
    tcase_add_test(c, an_eye_far_from_the_origin_renders_identically);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(packets_suite)
