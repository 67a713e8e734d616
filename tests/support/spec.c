/*
 * spec.c - scenes as data and the fast kernel against the scalar loops
 * (see spec.h).
 */
#define _GNU_SOURCE 1       /* program_invocation_short_name */

#include "spec.h"

#include <check.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenes.h"

rt_test_spec *rt_test_spec_new(void)
{
    rt_test_spec *s = calloc(1, sizeof *s);
    ck_assert_ptr_nonnull(s);
    s->width = 24;
    s->height = 18;
    s->background[0] = 20;
    s->background[1] = 40;
    s->background[2] = 90;
    return s;
}

int rt_test_spec_vertex(rt_test_spec *s, rt_vec3 p)
{
    ck_assert_int_lt(s->nv, RT_TEST_SPEC_MAX_VERTICES);
    s->v[s->nv] = p;
    return s->nv++;
}

void rt_test_spec_facet(rt_test_spec *s, int a, int b, int c, double k, int r,
                        int g,
                  int bl)
{
    ck_assert_int_lt(s->nf, RT_TEST_SPEC_MAX_FACETS);
    s->f[s->nf++] = (rt_test_spec_facet_t){{a, b, c}, k, {r, g, bl}};
}

void rt_test_spec_triangle(rt_test_spec *s, rt_vec3 a, rt_vec3 b, rt_vec3 c,
                           double k,
                     int r, int g, int bl)
{
    int ia = rt_test_spec_vertex(s, a), ib = rt_test_spec_vertex(s, b),
        ic = rt_test_spec_vertex(s, c);
    rt_test_spec_facet(s, ia, ib, ic, k, r, g, bl);
}

/* The square a, b, c, d (in order round it) as two facets. */
void rt_test_spec_quad(rt_test_spec *s, rt_vec3 a, rt_vec3 b, rt_vec3 c,
                       rt_vec3 d,
                 double k, int r, int g, int bl)
{
    int ia = rt_test_spec_vertex(s, a), ib = rt_test_spec_vertex(s, b),
        ic = rt_test_spec_vertex(s, c), id = rt_test_spec_vertex(s, d);
    rt_test_spec_facet(s, ia, ib, ic, k, r, g, bl);
    rt_test_spec_facet(s, ia, ic, id, k, r, g, bl);
}

void rt_test_spec_light(rt_test_spec *s, rt_vec3 p, int r, int g, int b)
{
    ck_assert_int_lt(s->nl, RT_TEST_SPEC_MAX_LIGHTS);
    s->l[s->nl++] = (rt_test_spec_light_t){p, {r, g, b}};
}

/* The camera at `eye` looking along `direction` (A = eye + direction, as
 * given: an exact diagonal stays exact), the screen's half-width
 * `half_width` |direction|, right-handed with `up` roughly up. */
void rt_test_spec_aim(rt_test_spec *s, rt_vec3 eye, rt_vec3 direction,
                      rt_vec3 up,
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
void rt_test_spec_box(rt_test_spec *s, rt_vec3 lo, rt_vec3 hi, double k, int r,
                      int g,
                int b)
{
    int c[8];
    for (int i = 0; i < 8; i++)
        c[i] = rt_test_spec_vertex(s,
                                   vec(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y,
                             i & 4 ? hi.z : lo.z));
    static const int face[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; f++) {
        rt_test_spec_facet(s, c[face[f][0]], c[face[f][1]], c[face[f][2]], k,
                           r, g, b);
        rt_test_spec_facet(s, c[face[f][0]], c[face[f][2]], c[face[f][3]], k,
                           r, g, b);
    }
}

static void put_point(rt_test_text *t, rt_vec3 p, double scale)
{
    rt_test_text_add(t, "%.17g, %.17g, %.17g", p.x * scale, p.y * scale,
                     p.z * scale);
}

/* The .scn text of *s with every coordinate (camera, vertices, lights)
 * multiplied by `scale`; malloc'd. */
char *rt_test_spec_text(const rt_test_spec *s, double scale)
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
        const rt_test_spec_facet_t *f = &s->f[i];
        rt_test_text_add(&t, "%d, %d, %d, %.17g, %d, %d, %d\n", f->v[0] + 1,
                         f->v[1] + 1,
            f->v[2] + 1, f->k, f->color[0], f->color[1], f->color[2]);
    }
    rt_test_text_add(&t, "%d, %d, %d\n", s->background[0], s->background[1],
        s->background[2]);
    for (int i = 0; i < s->nl; i++) {
        put_point(&t, s->l[i].p, scale);
        rt_test_text_add(&t, ", %d, %d, %d\n", s->l[i].color[0],
                         s->l[i].color[1],
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

void rt_test_kernels_reset(void) { memset(&tally, 0, sizeof tally); }

static void mismatch(const char *format, ...)
{
    char message[1024];
    va_list ap;
    va_start(ap, format);
    vsnprintf(message, sizeof message, format, ap);
    va_end(ap);
    fprintf(stderr, "%s: MISMATCH: %s\n", program_invocation_short_name,
            message);
    if (tally.mismatches++ == 0)
        snprintf(tally.first, sizeof tally.first, "%s", message);
}

/* Fails the test when it found a mismatch; says what it checked. */
void rt_test_kernels_finish(const char *test)
{
    printf("%s: %s: %d cases, %d renders compared, %d skipped, "
           "%d mismatches\n",
           program_invocation_short_name, test, tally.cases, tally.renders,
               tally.skipped,
           tally.mismatches);
    fflush(stdout);
    ck_assert_msg(tally.mismatches == 0,
                  "%s: %d mismatches between RT_KERNEL_AUTO and "
                  "RT_KERNEL_SCALAR; the first: %s",
                  test, tally.mismatches, tally.first);
}

#define RT_TEST_DOUBLE_ONLY 1u
#define RT_TEST_FLOAT_ONLY 2u
#define RT_TEST_BOTH_PRECISIONS 3u

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

rt_image rt_test_kernels_render(const rt_scene *scene,
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
void rt_test_kernels_compare(const rt_image *ref, const rt_image *got,
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
void rt_test_kernels_check(const char *name, const rt_scene *scene,
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
            char what[512], why[1024];
            snprintf(what, sizeof what, "%s (%s)", name, pname);
            snprintf(why, sizeof why, "the scene cannot be rendered in %s: %s",
                     pname, error.message);
            rt_test_kernels_skip(what, why);
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
            rt_render_stats s_ref = {.size = sizeof s_ref};
            rt_render_stats s_fast = {.size = sizeof s_fast};
            options.kernel = RT_KERNEL_SCALAR;
            options.threads = 1;
            options.stats = &s_ref;
            rt_image ref = rt_test_kernels_render(scene, &options, what);
            options.kernel = RT_KERNEL_AUTO;
            options.stats = &s_fast;
            rt_image fast1 = rt_test_kernels_render(scene, &options, what);
            options.threads = 2;
            options.stats = NULL;
            rt_image fast2 = rt_test_kernels_render(scene, &options, what);
            char label[600];
            snprintf(label, sizeof label, "%s, 1 thread)", what);
            rt_test_kernels_compare(&ref, &fast1, &options, label);
            snprintf(label, sizeof label, "%s, 2 threads)", what);
            rt_test_kernels_compare(&ref, &fast2, &options, label);
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
void rt_test_spec_check(const char *name, const rt_test_spec *s, double scale,
                       const rt_render_options *base, unsigned precisions,
                       int may_refuse)
{
    char *t = rt_test_spec_text(s, scale);
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status =
        rt_scene_parse(t, strlen(t), name, NULL, &scene, &error);
    free(t);
    if (status != RT_OK) {
        ck_assert_msg(may_refuse, "%s: the scene did not load: %s", name,
                      error.message);
        char why[1024];
        snprintf(why, sizeof why, "the loader refuses the scene: %s",
                 error.message);
        rt_test_kernels_skip(name, why);
        return;
    }
    rt_render_options defaults;
    rt_render_options_init(&defaults);
    rt_test_kernels_check(name, scene, base != NULL ? base : &defaults,
                          precisions);
    rt_scene_destroy(scene);
}

void rt_test_kernels_count_case(void)
{
    tally.cases++;
}

void rt_test_kernels_skip(const char *what, const char *why)
{
    printf("%s: SKIPPED: %s: %s\n", program_invocation_short_name, what,
           why);
    tally.skipped++;
}
