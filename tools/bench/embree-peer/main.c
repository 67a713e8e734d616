/*
 * rt-embree-peer - the same rays as rt-export, traced by Intel Embree 3, to
 * measure our renderer against it (docs/performance.md, "Peers: POV-Ray and
 * Embree on the same rays").
 *
 *   rt-embree-peer [--size WxH] [--depth N] [--threads N] [-o OUT] SCENE
 *
 * The scene is read by libraytrace's public API (any file rt-export reads:
 * .scn, .nff, .obj), its live facets (zero-area and repeated ones left out,
 * as the renderer leaves them) go into one Embree scene built with
 * RTC_BUILD_QUALITY_HIGH and RTC_SCENE_FLAG_ROBUST, and the picture is
 * rendered on one thread by the rendering model of
 * docs/rendering-model.md, casting the rays our renderer casts
 * (src/kernel/trace_impl.h, shade_impl.h): a camera ray per pixel (one
 * sample, through the pixel's centre, rt_camera_ray), a shadow ray per
 * light at every hit but where d = 0 or N.S <= 0 (rtcOccluded1), a mirror
 * ray where k > 0 (or at a total internal reflection) and a refracted ray
 * where t > 0, up to the depth.  Embree works in float and has no exact
 * hits, so the counts agree with rt-export --stats to a fraction of a
 * percent, not exactly; secondary rays start a small relative distance off
 * the surface (OFFSET_RELATIVE) instead of our error bounds.
 *
 * It prints one line on standard output,
 *   embree: facets N build S s render S s camera_rays A shadow_rays B
 *   reflection_rays C refraction_rays D load S s
 * (one line; build: rtcCommitScene alone; render: the pixels alone, not the
 * load, the build or the write; load: rt_scene_load, the read rt-export
 * does, alone), and writes the image to OUT when -o is
 * given.  --threads sets the threads of Embree's build (0: all cores, the
 * default); the render is always one thread.  A benchmark peer, never a
 * dependency of the library: built only where CMake finds Embree 3.
 */
#include <embree3/rtcore.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_clock.h"
#include "raytrace/raytrace.h"

/* Secondary rays leave the hit point this far along the normal, relative
 * to its largest coordinate (and at least to the scene's extent times
 * OFFSET_FLOOR): about 80 float ulps, well beyond the rounding of the
 * vertices to float and of Embree's hit, small beside any facet of the
 * SPD scenes. */
#define OFFSET_RELATIVE 1e-5
#define OFFSET_FLOOR 1e-3

typedef struct vec {
    double x, y, z;
} vec;

static vec mk(double x, double y, double z) { return (vec){x, y, z}; }
static vec add(vec a, vec b) { return mk(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec sub(vec a, vec b) { return mk(a.x - b.x, a.y - b.y, a.z - b.z); }
static vec scale(vec a, double s) { return mk(a.x * s, a.y * s, a.z * s); }
static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec unit(vec a) { return scale(a, 1.0 / sqrt(dot(a, a))); }
static vec of_rt(rt_vec3 v) { return mk(v.x, v.y, v.z); }
static double max_abs(vec a)
{
    return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
}

/* What shading needs of a live facet. */
typedef struct facet {
    vec a, b, c;            /* its vertices */
    vec normal;             /* unit, of the winding (b - a) x (c - a) */
    double k, t, n, d;      /* reflection, transparency, index, diffuse */
    double color[3];        /* C_F / 255 */
} facet;

/* The scene as the render reads it. */
typedef struct peer {
    RTCScene scene;
    const facet *facets;    /* by Embree's primitive id */
    int light_count;
    vec lights[RT_MAX_LIGHTS];
    double light_color[RT_MAX_LIGHTS][3];   /* C_S,l */
    double background[3];
    double offset_floor;    /* OFFSET_FLOOR times the scene's extent */
    int max_depth;
} peer;

/* Rays cast, by kind. */
typedef struct counts {
    unsigned long long camera, shadow, reflection, refraction;
} counts;

/* A ray to follow: unit direction, the weight its colour carries. */
typedef struct task {
    vec origin, direction;
    double weight;
    int level;
} task;

/* The nearest hit of the ray, as Embree finds it: its primitive id (or
 * -1), its barycentric u, v. */
static int intersect(const peer *p, vec origin, vec direction, double *u,
                     double *v)
{
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    struct RTCRayHit rh;
    rh.ray.org_x = (float)origin.x;
    rh.ray.org_y = (float)origin.y;
    rh.ray.org_z = (float)origin.z;
    rh.ray.tnear = 0.0f;
    rh.ray.dir_x = (float)direction.x;
    rh.ray.dir_y = (float)direction.y;
    rh.ray.dir_z = (float)direction.z;
    rh.ray.time = 0.0f;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = UINT_MAX;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(p->scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return -1;
    *u = rh.hit.u;
    *v = rh.hit.v;
    return (int)rh.hit.primID;
}

/* Non-zero when a facet lies between `origin` and `to` (t in (0, 1)). */
static int occluded(const peer *p, vec origin, vec to)
{
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    vec d = sub(to, origin);
    struct RTCRay ray;
    ray.org_x = (float)origin.x;
    ray.org_y = (float)origin.y;
    ray.org_z = (float)origin.z;
    ray.tnear = 0.0f;
    ray.dir_x = (float)d.x;
    ray.dir_y = (float)d.y;
    ray.dir_z = (float)d.z;
    ray.time = 0.0f;
    ray.tfar = 1.0f;
    ray.mask = UINT_MAX;
    ray.id = 0;
    ray.flags = 0;
    rtcOccluded1(p->scene, &context, &ray);
    return ray.tfar < 0.0f;     /* -inf when blocked */
}

/* `point` moved off its facet (normal `normal`) to the side `towards`
 * points to. */
static vec leave(const peer *p, vec point, vec normal, vec towards)
{
    double e = OFFSET_RELATIVE * fmax(max_abs(point), p->offset_floor);
    return add(point, scale(normal, dot(towards, normal) < 0 ? -e : e));
}

/* The refracted direction at a facet of winding normal n_w and index n
 * (the rendering model's Snell-Descartes), 0 for a total internal
 * reflection.  `in` is unit. */
static int refract(vec in, vec n_w, double n, vec *out)
{
    int entering = dot(in, n_w) < 0;
    double eta = entering ? 1.0 / n : n;
    vec normal = entering ? n_w : scale(n_w, -1.0);
    double c = -dot(in, normal);
    double q = 1.0 - eta * eta * (1.0 - c * c);
    if (q < 0)
        return 0;
    *out = add(scale(in, eta), scale(normal, eta * c - sqrt(q)));
    return 1;
}

/* Adds the direct light at `point` of facet f (normal facing the ray) to
 * color, weighted, casting the shadow rays the renderer casts. */
static void direct_light(const peer *p, const facet *f, vec point, vec normal,
                         double weight, double color[3], counts *n)
{
    for (int l = 0; l < p->light_count; l++) {
        vec to_light = sub(p->lights[l], point);
        if (f->d == 0 || !(dot(normal, to_light) > 0))
            continue;
        n->shadow++;
        if (occluded(p, leave(p, point, normal, to_light), p->lights[l]))
            continue;
        double w = weight * f->d * dot(normal, unit(to_light));
        for (int ch = 0; ch < 3; ch++)
            color[ch] += w * p->light_color[l][ch] * f->color[ch];
    }
}

/* The colour a camera ray carries: the ray tree walked depth first
 * (`stack` has room for max_depth + 2 tasks: each task pushes at most two
 * of the level below it). */
static void trace(const peer *p, vec origin, vec direction, task *stack,
                  double color[3], counts *n)
{
    int used = 0;
    stack[used++] = (task){origin, direction, 1.0, 0};
    while (used > 0) {
        task r = stack[--used];
        double u, v;
        int id = intersect(p, r.origin, r.direction, &u, &v);
        if (id < 0) {
            for (int ch = 0; ch < 3; ch++)
                color[ch] += r.weight * p->background[ch];
            continue;
        }
        const facet *f = &p->facets[id];
        vec point = add(scale(f->a, 1.0 - u - v),
                        add(scale(f->b, u), scale(f->c, v)));
        vec normal = dot(f->normal, r.direction) > 0 ? scale(f->normal, -1.0)
                                                     : f->normal;
        direct_light(p, f, point, normal, r.weight, color, n);
        if (r.level >= p->max_depth)
            continue;           /* past the limit: black */
        double mirror_weight = f->k;
        vec refracted = mk(0, 0, 0);
        int refracts = f->t > 0 && refract(r.direction, f->normal, f->n,
                                           &refracted);
        if (f->t > 0 && !refracts)
            mirror_weight += f->t;      /* total internal reflection */
        if (refracts) {
            stack[used++] = (task){leave(p, point, normal, refracted),
                                   unit(refracted), r.weight * f->t,
                                   r.level + 1};
            n->refraction++;
        }
        if (mirror_weight > 0) {
            vec mirror = sub(r.direction,
                             scale(normal, 2 * dot(r.direction, normal)));
            stack[used++] = (task){leave(p, point, normal, mirror),
                                   unit(mirror), r.weight * mirror_weight,
                                   r.level + 1};
            n->reflection++;
        }
    }
}

/* Renders the picture (the camera's size) on this thread into `image`
 * (of that size; NULL: the pixels are computed and dropped); 0 when out of
 * memory. */
static int render(const peer *p, const rt_camera *camera, rt_image *image,
                  counts *n)
{
    task *stack = malloc(((size_t)p->max_depth + 2) * sizeof *stack);
    if (stack == NULL)
        return 0;
    for (int j = 0; j < camera->height; j++) {
        for (int i = 0; i < camera->width; i++) {
            rt_ray ray = rt_camera_ray(camera, i, j);
            double color[3] = {0, 0, 0};
            n->camera++;
            trace(p, of_rt(ray.origin), unit(of_rt(ray.direction)), stack,
                  color, n);
            if (image != NULL) {
                unsigned char *out = rt_image_pixel(image, i, j);
                for (int ch = 0; ch < 3; ch++)
                    out[ch] = rt_channel_to_byte(color[ch]);
            }
        }
    }
    free(stack);
    return 1;
}

static void on_embree_error(void *user, enum RTCError code, const char *str)
{
    (void)user;
    fprintf(stderr, "rt-embree-peer: embree error %d: %s\n", (int)code,
            str != NULL ? str : "");
}

/* The scene's live facets as Embree geometry and shading records; 0 when
 * out of memory.  *facets is the table by primitive id. */
static int fill(const rt_scene *scene, const rt_scene_info *info,
                RTCDevice device, RTCScene rtc, facet **facets, int *live)
{
    facet *table = malloc((size_t)(info->live_facet_count > 0
                                       ? info->live_facet_count
                                       : 1) *
                          sizeof *table);
    if (table == NULL)
        return 0;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *vertices = rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
        3 * sizeof(float), (size_t)info->vertex_count);
    unsigned *indices = rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
        3 * sizeof(unsigned), (size_t)info->live_facet_count);
    if (vertices == NULL || indices == NULL) {
        rtcReleaseGeometry(geometry);
        free(table);
        return 0;
    }
    for (int i = 0; i < info->vertex_count; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        vertices[3 * i] = (float)v.x;
        vertices[3 * i + 1] = (float)v.y;
        vertices[3 * i + 2] = (float)v.z;
    }
    int m = 0;
    for (int i = 0; i < info->facet_count; i++) {
        rt_facet_info fi = {.size = sizeof fi};
        rt_scene_facet(scene, i, &fi);
        if (fi.degenerate != 0 || m >= info->live_facet_count)
            continue;
        for (int c = 0; c < 3; c++)
            indices[3 * m + c] = (unsigned)fi.vertex[c];
        facet *f = &table[m++];
        f->a = of_rt(rt_scene_vertex(scene, fi.vertex[0]));
        f->b = of_rt(rt_scene_vertex(scene, fi.vertex[1]));
        f->c = of_rt(rt_scene_vertex(scene, fi.vertex[2]));
        f->normal = of_rt(fi.normal);
        f->k = fi.reflection;
        f->t = fi.transparency;
        f->n = fi.refractive_index;
        f->d = fi.diffuse;
        f->color[0] = fi.color.r / 255.0;
        f->color[1] = fi.color.g / 255.0;
        f->color[2] = fi.color.b / 255.0;
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(rtc, geometry);
    rtcReleaseGeometry(geometry);
    *facets = table;
    *live = m;
    return 1;
}

/* The extent of the vertices: the largest side of their bounding box. */
static double extent(const rt_scene *scene, int vertex_count)
{
    vec lo = mk(INFINITY, INFINITY, INFINITY), hi = scale(lo, -1.0);
    for (int i = 0; i < vertex_count; i++) {
        vec v = of_rt(rt_scene_vertex(scene, i));
        lo = mk(fmin(lo.x, v.x), fmin(lo.y, v.y), fmin(lo.z, v.z));
        hi = mk(fmax(hi.x, v.x), fmax(hi.y, v.y), fmax(hi.z, v.z));
    }
    return vertex_count > 0 ? max_abs(sub(hi, lo)) : 1.0;
}

static int usage(void)
{
    fprintf(stderr, "usage: rt-embree-peer [--size WxH] [--depth N] "
                    "[--threads N] [-o OUT] SCENE\n");
    return 2;
}

/* A decimal integer in [lo, hi] at the start of `text`, followed by the
 * character `stop` (*rest, when given, is set past it); 0 when there is
 * none. */
static int read_int(const char *text, long lo, long hi, char stop,
                    const char **rest, int *value)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || errno != 0 || v < lo || v > hi || *end != stop)
        return 0;
    if (rest != NULL)
        *rest = end + 1;
    *value = (int)v;
    return 1;
}

int main(int argc, char **argv)
{
    const char *path = NULL, *out = NULL;
    int width = 0, height = 0, depth = RT_DEFAULT_DEPTH, threads = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        const char *rest;
        if (strcmp(a, "--size") == 0 && value != NULL) {
            if (!read_int(value, 1, RT_MAX_IMAGE_SIDE, 'x', &rest, &width) ||
                !read_int(rest, 1, RT_MAX_IMAGE_SIDE, '\0', NULL, &height))
                return usage();
        } else if (strcmp(a, "--depth") == 0 && value != NULL) {
            if (!read_int(value, 0, 1000000, '\0', NULL, &depth))
                return usage();
        } else if (strcmp(a, "--threads") == 0 && value != NULL) {
            if (!read_int(value, 0, 1024, '\0', NULL, &threads))
                return usage();
        } else if (strcmp(a, "-o") == 0 && value != NULL) {
            out = value;
        } else if (a[0] == '-' || path != NULL) {
            return usage();
        } else {
            path = a;
            continue;
        }
        i++;
    }
    if (path == NULL)
        return usage();

    rt_error error = {0};
    rt_scene *scene = NULL;
    double start = cli_clock_seconds();
    if (rt_scene_load(path, NULL, &scene, &error) != RT_OK) {
        fprintf(stderr, "rt-embree-peer: %s\n", error.message);
        return 1;
    }
    double load = cli_seconds_since(start);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_camera camera = info.camera;
    if (width > 0) {    /* the renderer's rule: the screen keeps its width */
        camera.width = width;
        camera.height = height;
    }

    peer p = {0};
    p.max_depth = depth;
    p.light_count = info.light_count;
    for (int l = 0; l < info.light_count; l++) {
        rt_light light;
        rt_scene_light(scene, l, &light);
        p.lights[l] = of_rt(light.position);
        p.light_color[l][0] = light.color.r;
        p.light_color[l][1] = light.color.g;
        p.light_color[l][2] = light.color.b;
    }
    p.background[0] = info.background.r;
    p.background[1] = info.background.g;
    p.background[2] = info.background.b;
    p.offset_floor = OFFSET_FLOOR * extent(scene, info.vertex_count);

    char config[32];
    snprintf(config, sizeof config, "threads=%d", threads);
    RTCDevice device = rtcNewDevice(config);
    if (device == NULL) {
        fprintf(stderr, "rt-embree-peer: no Embree device (error %d)\n",
                (int)rtcGetDeviceError(NULL));
        rt_scene_destroy(scene);
        return 1;
    }
    rtcSetDeviceErrorFunction(device, on_embree_error, NULL);
    p.scene = rtcNewScene(device);
    rtcSetSceneFlags(p.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(p.scene, RTC_BUILD_QUALITY_HIGH);
    facet *facets = NULL;
    int live = 0, status = 1;
    if (fill(scene, &info, device, p.scene, &facets, &live)) {
        p.facets = facets;
        start = cli_clock_seconds();
        rtcCommitScene(p.scene);
        double build = cli_seconds_since(start);

        rt_image image = {0};
        int ok = out == NULL ||
                 rt_image_init(&image, camera.width, camera.height,
                               &error) == RT_OK;
        counts n = {0};
        start = cli_clock_seconds();
        ok = ok && render(&p, &camera, out != NULL ? &image : NULL, &n);
        double seconds = cli_seconds_since(start);
        if (ok) {
            printf("embree: facets %d build %.6f s render %.6f s "
                   "camera_rays %llu shadow_rays %llu reflection_rays %llu "
                   "refraction_rays %llu load %.6f s\n",
                   live, build, seconds, n.camera, n.shadow, n.reflection,
                   n.refraction, load);
            status = 0;
        } else if (error.message[0] == '\0') {
            snprintf(error.message, sizeof error.message, "out of memory");
        }
        rt_image_format format = RT_IMAGE_P6;
        if (ok && out != NULL &&
            (rt_image_format_from_path(out, &format, &error) != RT_OK ||
             rt_image_save(out, &image, format, NULL, &error) != RT_OK))
            status = 1;
        if (status != 0)
            fprintf(stderr, "rt-embree-peer: %s\n", error.message);
        rt_image_release(&image);
    } else {
        fprintf(stderr, "rt-embree-peer: out of memory\n");
    }
    free(facets);
    rtcReleaseScene(p.scene);
    rtcReleaseDevice(device);
    rt_scene_destroy(scene);
    return status;
}
