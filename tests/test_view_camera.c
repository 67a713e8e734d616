/*
 * test_view_camera.c - rt-view's camera moves (apps/rt-view/view_camera.c,
 * view_move.c): an orbit keeps the target at the image centre and its
 * distance, a pan keeps the distance and the direction of view and moves
 * what lies at the target's depth by the pan's pixels, a dolly keeps the
 * direction and scales the distance, flying moves both points alike, the
 * field of view is clamped, a picked point becomes the centre; C's text
 * reads back, through rt-export's options and as a .scn file's camera
 * records, to the viewer's camera bit for bit; and in the app (SDL's
 * dummy driver) a drag renders the library's image of the moved camera,
 * once a turn, without explaining, a click still explains, and Home gives
 * the file's camera back.  Scenes: scenes/cubes.scn, an NFF
 * (tests/fuzz/corpus/nff/sphere-cone.nff, small enough for the sanitizer
 * pass), tests/data/obj/cube.obj, scenes/focus.scn (a lens) and a PLY.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "cli.h"
#include "testutil.h"
#include "view_app_internal.h"
#include "view_camera.h"
#include "view_overlay.h"
#include "viewer.h"

#define PI 3.14159265358979323846

/* The three formats: a .scn with its camera, an NFF with its view, an OBJ
 * with the automatic camera; and a .scn with a lens. */
static const char *const scene_files[] = {
    "scenes/cubes.scn", "tests/fuzz/corpus/nff/sphere-cone.nff",
    "tests/data/obj/cube.obj",
    "scenes/focus.scn",         /* a lens: a, f in the screen record */
    "tests/fuzz/corpus/ply/terrain-ascii.ply", /* PLY: the automatic camera */
};
#define SCENE_FILES (int)(sizeof scene_files / sizeof *scene_files)

static rt_vec3 sub(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.x - b.x, a.y - b.y, a.z - b.z};
}

static double dot(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static double length(rt_vec3 a)
{
    return sqrt(dot(a, a));
}

static rt_vec3 unit(rt_vec3 a)
{
    double l = length(a);
    return (rt_vec3){a.x / l, a.y / l, a.z / l};
}

static double distance_of(const rt_look *look)
{
    return length(sub(look->look_from, look->look_at));
}

static rt_vec3 view_direction(const rt_look *look)
{
    return unit(sub(look->look_at, look->look_from));
}

static void assert_vec_near(rt_vec3 a, rt_vec3 b, double tolerance,
                            const char *what)
{
    ck_assert_msg(fabs(a.x - b.x) <= tolerance &&
                      fabs(a.y - b.y) <= tolerance &&
                      fabs(a.z - b.z) <= tolerance,
                  "%s: (%.17g, %.17g, %.17g) is not (%.17g, %.17g, %.17g) "
                  "within %g", what, a.x, a.y, a.z, b.x, b.y, b.z, tolerance);
}

/* The camera of `look` for `scene`; fails the test when refused. */
static rt_camera camera_of(const rt_scene *scene, const rt_look *look)
{
    rt_camera camera;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_scene_look(scene, look, &camera, NULL, &error);
    ck_assert_msg(status == RT_OK, "rt_scene_look: %s", error.message);
    return camera;
}

/* Image coordinates of `point` through `camera` at width x height. */
static void project(const rt_camera *camera, int width, int height,
                    rt_vec3 point, double *x, double *y)
{
    view_projection projection;
    memset(&projection, 0, sizeof projection);
    projection.camera = *camera;
    projection.width = width;
    projection.height = height;
    ck_assert(view_project_point(&projection, point, x, y));
}

static int same_double(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

static int same_vec(rt_vec3 a, rt_vec3 b)
{
    return same_double(a.x, b.x) && same_double(a.y, b.y) &&
           same_double(a.z, b.z);
}

/* Field by field (memcmp of the structs would read their padding). */
static void assert_same_camera(const rt_camera *a, const rt_camera *b,
                               const char *what)
{
    ck_assert_msg(same_vec(a->observer, b->observer), "%s: observer", what);
    ck_assert_msg(same_vec(a->screen_center, b->screen_center),
                  "%s: screen centre", what);
    ck_assert_msg(same_vec(a->right, b->right), "%s: right", what);
    ck_assert_msg(same_vec(a->up, b->up), "%s: up", what);
    ck_assert_msg(a->width == b->width && a->height == b->height,
                  "%s: size", what);
    ck_assert_msg(a->b_was_projected == b->b_was_projected,
                  "%s: projected", what);
    ck_assert_msg(same_double(a->aperture, b->aperture), "%s: aperture",
                  what);
    ck_assert_msg(same_double(a->focal_distance, b->focal_distance),
                  "%s: focal distance", what);
}

/* A view moved away from the file's: every kind of move once. */
static rt_look moved_look(const rt_scene *scene)
{
    rt_vec3 up = view_camera_world_up(scene);
    rt_look look = view_camera_file_look(scene);
    view_camera_orbit(&look, up, 0.37, -0.21);
    rt_camera camera = camera_of(scene, &look);
    view_camera_pan(&look, &camera, camera.width, 13.25, -7.5);
    view_camera_dolly(&look, 0.83, 1e-6, 1e6);
    look.fov = view_camera_clamp_fov(look.fov * 1.1);
    view_camera_fly(&look, &camera, up, 0.1, -0.05, 0.02);
    return look;
}

/* ---- the moves ---- */

/* The first target is what the axis of view meets: the file's direction
 * and field of view, look_at on the nearest hit of the ray O -> A (every
 * scene here is hit in the middle of its picture). */
START_TEST(the_first_target_is_what_the_axis_of_view_meets)
{
    for (int s = 0; s < SCENE_FILES; s++) {
        rt_scene *scene = rt_test_load_source_scene(scene_files[s]);
        rt_scene_info info = rt_test_scene_info(scene);
        rt_look file;
        rt_camera_get_look(&info.camera, &file);
        rt_look look = view_camera_file_look(scene);
        ck_assert(same_vec(look.look_from, file.look_from));
        ck_assert(same_vec(look.up, file.up));
        ck_assert(same_double(look.fov, file.fov));
        rt_vec3 a = {file.look_at.x - file.look_from.x,
                     file.look_at.y - file.look_from.y,
                     file.look_at.z - file.look_from.z};
        rt_vec3 b = {look.look_at.x - look.look_from.x,
                     look.look_at.y - look.look_from.y,
                     look.look_at.z - look.look_from.z};
        double la = sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
        double lb = sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
        ck_assert_msg(fabs((a.x * b.x + a.y * b.y + a.z * b.z) / (la * lb) -
                           1) < 1e-12,
                      "%s: the direction of view changed", scene_files[s]);
        rt_hit hit;
        rt_vec3 unit = {a.x / la, a.y / la, a.z / la};
        ck_assert_msg(rt_scene_nearest_hit(scene,
                                           (rt_ray){file.look_from, unit},
                                           INFINITY, &hit),
                      "%s: the axis meets nothing", scene_files[s]);
        ck_assert_msg(fabs(lb - hit.t) <= 1e-9 * hit.t,
                      "%s: the target is %g away, the hit %g",
                      scene_files[s], lb, hit.t);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(orbit_keeps_the_target_at_the_centre_and_its_distance)
{
    const double turns[][2] = {{0.3, 0}, {-1.2, 0.4}, {2.5, -0.9},
                               {0, 0.05}};
    for (int s = 0; s < SCENE_FILES; s++) {
        rt_scene *scene = rt_test_load_source_scene(scene_files[s]);
        rt_vec3 up = view_camera_world_up(scene);
        rt_look look = view_camera_file_look(scene);
        for (size_t k = 0; k < sizeof turns / sizeof *turns; k++) {
            rt_look before = look;
            view_camera_orbit(&look, up, turns[k][0], turns[k][1]);
            ck_assert_msg(length(sub(look.look_from, before.look_from)) >
                              1e-3 * distance_of(&before),
                          "%s: orbit %zu did not move", scene_files[s], k);
            assert_vec_near(look.look_at, before.look_at, 0, "target");
            ck_assert_double_eq_tol(distance_of(&look), distance_of(&before),
                                    1e-12 * distance_of(&before));
            assert_vec_near(look.up, up, 0, "the look's up");
            rt_camera camera = camera_of(scene, &look);
            double x, y;
            project(&camera, camera.width, camera.height, look.look_at, &x,
                    &y);
            ck_assert_double_eq_tol(x, camera.width / 2.0,
                                    1e-9 * camera.width);
            ck_assert_double_eq_tol(y, camera.height / 2.0,
                                    1e-9 * camera.width);
        }
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(orbit_yaw_turns_about_the_world_up_and_pitch_stops_short_of_it)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_vec3 up = view_camera_world_up(scene);
    rt_look look = view_camera_file_look(scene);
    /* A yaw keeps the height above the target; a quarter turn moves the
     * observer towards the image's right (AB). */
    rt_look turned = look;
    view_camera_orbit(&turned, up, PI / 2, 0);
    double height = dot(sub(look.look_from, look.look_at), up);
    ck_assert_double_eq_tol(dot(sub(turned.look_from, turned.look_at), up),
                            height, 1e-12 * distance_of(&look));
    rt_camera camera = camera_of(scene, &look);
    ck_assert(dot(sub(turned.look_from, look.look_from), camera.right) > 0);
    /* Pitching far past the pole stops VIEW_CAMERA_POLE_DEGREES short. */
    for (int sign = -1; sign <= 1; sign += 2) {
        rt_look tilted = look;
        view_camera_orbit(&tilted, up, 0, sign * 10.0);
        double angle = acos(dot(unit(sub(tilted.look_from, tilted.look_at)),
                                (rt_vec3){sign * up.x, sign * up.y,
                                          sign * up.z})) * 180 / PI;
        ck_assert_double_eq_tol(angle, VIEW_CAMERA_POLE_DEGREES, 1e-9);
        camera_of(scene, &tilted);  /* still a camera */
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(pan_moves_what_lies_at_the_targets_depth_with_the_cursor)
{
    for (int s = 0; s < SCENE_FILES; s++) {
        rt_scene *scene = rt_test_load_source_scene(scene_files[s]);
        rt_look look = moved_look(scene);
        rt_camera camera = camera_of(scene, &look);
        /* At the scene's width and at another render width. */
        const int widths[] = {camera.width, 2 * camera.width + 3};
        for (int w = 0; w < 2; w++) {
            int width = widths[w];
            int height = camera.height * width / camera.width;
            /* A point of the screen plane, which holds the target. */
            rt_vec3 point = {look.look_at.x + 0.3 * camera.right.x -
                                 0.2 * camera.up.x,
                             look.look_at.y + 0.3 * camera.right.y -
                                 0.2 * camera.up.y,
                             look.look_at.z + 0.3 * camera.right.z -
                                 0.2 * camera.up.z};
            double x0, y0, x1, y1;
            project(&camera, width, height, point, &x0, &y0);
            rt_look panned = look;
            const double dx = 17.5, dy = -9.25;
            view_camera_pan(&panned, &camera, width, dx, dy);
            ck_assert_double_eq_tol(distance_of(&panned), distance_of(&look),
                                    1e-12 * distance_of(&look));
            assert_vec_near(view_direction(&panned), view_direction(&look),
                            1e-12, "direction of view");
            rt_camera moved = camera_of(scene, &panned);
            project(&moved, width, height, point, &x1, &y1);
            ck_assert_double_eq_tol(x1 - x0, dx, 1e-9 * width);
            ck_assert_double_eq_tol(y1 - y0, dy, 1e-9 * width);
        }
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(dolly_keeps_the_direction_and_scales_the_distance)
{
    for (int s = 0; s < SCENE_FILES; s++) {
        rt_scene *scene = rt_test_load_source_scene(scene_files[s]);
        rt_look look = moved_look(scene);
        double distance = distance_of(&look);
        const double factors[] = {0.5, 1 / 1.2, 3.0};
        for (int f = 0; f < 3; f++) {
            rt_look dollied = look;
            view_camera_dolly(&dollied, factors[f], 1e-9 * distance,
                              1e9 * distance);
            assert_vec_near(view_direction(&dollied), view_direction(&look),
                            1e-12, "direction of view");
            assert_vec_near(dollied.look_at, look.look_at, 0, "target");
            ck_assert_double_eq_tol(distance_of(&dollied),
                                    distance * factors[f],
                                    1e-12 * distance * factors[f]);
        }
        /* Never onto the target: the nearest is min_distance. */
        rt_look near = look;
        for (int k = 0; k < 2000; k++)
            view_camera_dolly(&near, 1 / 1.2, 1e-4 * distance, 1e4 * distance);
        ck_assert_double_eq_tol(distance_of(&near), 1e-4 * distance,
                                1e-12 * distance);
        assert_vec_near(view_direction(&near), view_direction(&look), 1e-9,
                        "direction of view, close up");
        camera_of(scene, &near);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(fly_moves_both_points_by_the_same_vector)
{
    for (int s = 0; s < SCENE_FILES; s++) {
        rt_scene *scene = rt_test_load_source_scene(scene_files[s]);
        rt_vec3 up = view_camera_world_up(scene);
        rt_look look = moved_look(scene);
        rt_camera camera = camera_of(scene, &look);
        double scale = distance_of(&look) + length(look.look_at);
        rt_look flown = look;
        view_camera_fly(&flown, &camera, up, 0.7, -0.4, 0.25);
        rt_vec3 from_shift = sub(flown.look_from, look.look_from);
        rt_vec3 at_shift = sub(flown.look_at, look.look_at);
        assert_vec_near(from_shift, at_shift, 1e-12 * scale, "shifts");
        /* Its parts: ahead along the view, right along AB, up along the
         * world up. */
        rt_vec3 ahead = view_direction(&look), right = unit(camera.right);
        rt_vec3 expected = {0.7 * ahead.x - 0.4 * right.x + 0.25 * up.x,
                            0.7 * ahead.y - 0.4 * right.y + 0.25 * up.y,
                            0.7 * ahead.z - 0.4 * right.z + 0.25 * up.z};
        assert_vec_near(from_shift, expected, 1e-12 * scale, "shift");
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(field_of_view_is_clamped)
{
    ck_assert_double_eq(view_camera_clamp_fov(60), 60);
    ck_assert_double_eq(view_camera_clamp_fov(0.5), VIEW_CAMERA_MIN_FOV);
    ck_assert_double_eq(view_camera_clamp_fov(-3), VIEW_CAMERA_MIN_FOV);
    ck_assert_double_eq(view_camera_clamp_fov(179.9), VIEW_CAMERA_MAX_FOV);
    ck_assert_double_eq(view_camera_clamp_fov(NAN), VIEW_CAMERA_MIN_FOV);
    ck_assert(VIEW_CAMERA_MIN_FOV > 0 && VIEW_CAMERA_MAX_FOV < 180);
    /* Both ends make a camera. */
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_look look = view_camera_file_look(scene);
    look.fov = VIEW_CAMERA_MIN_FOV;
    camera_of(scene, &look);
    look.fov = VIEW_CAMERA_MAX_FOV;
    camera_of(scene, &look);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(world_up_is_the_files_up_snapped_or_the_models_up_axis)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    /* cubes.scn: z is up, the camera looks down at an angle */
    assert_vec_near(view_camera_world_up(scene), (rt_vec3){0, 0, 1}, 0,
                    "cubes.scn");
    rt_scene_destroy(scene);
    scene = rt_test_load_source_scene("scenes/nff-sphere.nff");
    assert_vec_near(view_camera_world_up(scene), (rt_vec3){0, 0, 1}, 0,
                    "nff-sphere.nff (up 0 0 1)");
    rt_scene_destroy(scene);
    /* cube.obj names no up: OBJ's usual +y; --up-axis z gives z. */
    scene = rt_test_load_source_scene("tests/data/obj/cube.obj");
    assert_vec_near(view_camera_world_up(scene), (rt_vec3){0, 1, 0}, 0,
                    "cube.obj");
    rt_scene_destroy(scene);
    rt_load_options options;
    rt_load_options_init(&options);
    options.up_axis = RT_UP_NEG_Z;
    rt_error error;
    ck_assert_int_eq(rt_scene_load(rt_test_source_path(
                                       "tests/data/obj/cube.obj"),
                                   &options, &scene, &error),
                     RT_OK);
    assert_vec_near(view_camera_world_up(scene), (rt_vec3){0, 0, -1}, 0,
                    "cube.obj, -z up");
    /* The extent: the cube's [-1, 1]^3 diagonal. */
    ck_assert_double_eq_tol(view_camera_extent(scene), 2 * sqrt(3), 1e-15);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_picked_point_becomes_the_target_at_the_image_centre)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_scene_info info = rt_test_scene_info(scene);
    rt_vec3 up = view_camera_world_up(scene);
    rt_look look = view_camera_file_look(scene);
    /* The floor in the cube's shadow (docs/viewer.md's click). */
    rt_vec3 point;
    ck_assert(view_camera_pick(scene, &info.camera, info.width, info.height,
                               268, 124, &point));
    ck_assert_double_eq_tol(point.z, 0, 1e-12);  /* the floor is z = 0 */
    /* The point lies on that pixel's camera ray. */
    double x, y;
    project(&info.camera, info.width, info.height, point, &x, &y);
    ck_assert_double_eq_tol(x, 268.5, 1e-9);
    ck_assert_double_eq_tol(y, 124.5, 1e-9);
    rt_look aimed = look;
    ck_assert(view_camera_aim(&aimed, up, point));
    assert_vec_near(aimed.look_from, look.look_from, 0, "the observer");
    assert_vec_near(aimed.look_at, point, 0, "the target");
    rt_camera camera = camera_of(scene, &aimed);
    project(&camera, info.width, info.height, point, &x, &y);
    ck_assert_double_eq_tol(x, info.width / 2.0, 1e-9 * info.width);
    ck_assert_double_eq_tol(y, info.height / 2.0, 1e-9 * info.width);
    /* At twice the size the same spot is pixel (537, 249). */
    ck_assert(view_camera_pick(scene, &info.camera, 2 * info.width,
                               2 * info.height, 537, 249, &point));
    project(&info.camera, info.width, info.height, point, &x, &y);
    ck_assert_double_eq_tol(x, 268.75, 1e-9);
    ck_assert_double_eq_tol(y, 124.75, 1e-9);
    /* The observer itself is no target. */
    ck_assert(!view_camera_aim(&aimed, up, aimed.look_from));
    rt_scene_destroy(scene);
    /* A corner of nff-sphere.nff misses the sphere. */
    scene = rt_test_load_source_scene("scenes/nff-sphere.nff");
    info = rt_test_scene_info(scene);
    ck_assert(!view_camera_pick(scene, &info.camera, info.width, info.height,
                                0, 0, &point));
    ck_assert(view_camera_pick(scene, &info.camera, info.width, info.height,
                               info.width / 2, info.height / 2, &point));
    ck_assert_double_eq_tol(length(point), 1, 0.01);  /* radius 1 */
    rt_scene_destroy(scene);
}
END_TEST

/* ---- C: the camera as text ---- */

/* The line of `text` starting with `prefix`, copied into `line`. */
static int find_line(const char *text, const char *prefix, char *line,
                     size_t size)
{
    for (const char *p = text; *p; ) {
        const char *end = strchr(p, '\n');
        size_t n = end ? (size_t)(end - p) : strlen(p);
        if (strncmp(p, prefix, strlen(prefix)) == 0 && n < size) {
            memcpy(line, p, n);
            line[n] = '\0';
            return 1;
        }
        if (!end)
            break;
        p = end + 1;
    }
    return 0;
}

/* rt-export's camera for `path` with the option line `options`: parsed by
 * the programs' one command-line module, loaded by the library. */
static rt_camera export_camera(const char *path, const char *options)
{
    static const cli_program program = {
        "rt-export", "SCENE", "", "", CLI_GROUP_RENDER | CLI_GROUP_LOAD,
        NULL, 1, 1, "expected a scene file"};
    char words[4096];
    snprintf(words, sizeof words, "%s", options);
    char *argv[32];
    int argc = 0;
    argv[argc++] = "rt-export";
    for (char *w = strtok(words, " "); w && argc < 30; w = strtok(NULL, " "))
        argv[argc++] = w;
    char scene_path[4096];
    snprintf(scene_path, sizeof scene_path, "%s", path);
    argv[argc++] = scene_path;
    argv[argc] = NULL;
    cli_settings settings;
    ck_assert_int_eq(cli_parse(&program, argc, argv, &settings),
                     CLI_CONTINUE);
    ck_assert(settings.load.look_from_given && settings.load.look_at_given &&
              settings.load.up_given && settings.load.fov_given);
    rt_scene *scene = NULL;
    rt_error error;
    memset(&error, 0, sizeof error);
    ck_assert_msg(rt_scene_load(path, &settings.load, &scene, &error) ==
                      RT_OK, "%s", error.message);
    rt_camera camera = rt_test_scene_info(scene).camera;
    rt_scene_destroy(scene);
    return camera;
}

/* `scn` (a .scn text) with its first two records (the observer, the
 * screen) replaced by the lines `observer` and `screen`. */
static char *replace_camera_records(const char *scn, const char *observer,
                                    const char *screen)
{
    rt_test_text out = {0};
    int records = 0;
    for (const char *p = scn; *p; ) {
        const char *end = strchr(p, '\n');
        size_t n = end ? (size_t)(end - p + 1) : strlen(p);
        size_t skip = strspn(p, " \t");
        int record = p[skip] != '#' && p[skip] != '\n' && p[skip] != '\r' &&
                     p[skip] != '\0';
        if (record && records < 2)
            rt_test_text_add(&out, "%s\n", records++ == 0 ? observer
                                                          : screen);
        else
            rt_test_text_add(&out, "%.*s", (int)n, p);
        p += n;
    }
    return out.data;
}

/* The scene of `path` as .scn text (a .scn file as it is). */
static char *scn_text(const char *path, const rt_scene *scene)
{
    if (strstr(path, ".scn"))
        return rt_test_read_file(rt_test_source_path(path), NULL);
    rt_test_bytes bytes = {0};
    ck_assert_int_eq(rt_scene_write_scn(scene, 1, rt_test_bytes_add, &bytes,
                                        NULL, NULL),
                     RT_OK);
    rt_test_bytes_add(&bytes, "", 1);
    return (char *)bytes.data;
}

START_TEST(c_text_reads_back_as_rt_export_options_bit_for_bit)
{
    for (int s = 0; s < SCENE_FILES; s++) {
        rt_scene *scene = rt_test_load_source_scene(scene_files[s]);
        rt_look look = moved_look(scene);
        rt_camera camera = camera_of(scene, &look);
        char text[4096], line[2048];
        ck_assert_int_eq(view_camera_describe(scene, scene_files[s], &look,
                                              text, sizeof text, NULL),
                         RT_OK);
        ck_assert_msg(find_line(text, "--look-from ", line, sizeof line),
                      "%s", text);
        rt_camera exported =
            export_camera(rt_test_source_path(scene_files[s]), line);
        assert_same_camera(&exported, &camera, scene_files[s]);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(c_text_reads_back_as_scn_camera_records_bit_for_bit)
{
    for (int s = 0; s < SCENE_FILES; s++) {
        rt_scene *scene = rt_test_load_source_scene(scene_files[s]);
        rt_look look = moved_look(scene);
        rt_camera camera = camera_of(scene, &look);
        char text[4096];
        ck_assert_int_eq(view_camera_describe(scene, scene_files[s], &look,
                                              text, sizeof text, NULL),
                         RT_OK);
        /* The two lines after the comment that names them. */
        const char *records = strstr(text, "# .scn camera records");
        ck_assert_ptr_nonnull(records);
        char observer[1024], screen[1024];
        ck_assert(sscanf(strchr(records, '\n') + 1, "%1023[^\n]\n%1023[^\n]",
                         observer, screen) == 2);
        char *scn = scn_text(scene_files[s], scene);
        char *edited = replace_camera_records(scn, observer, screen);
        rt_scene *parsed = NULL;
        rt_error error;
        memset(&error, 0, sizeof error);
        ck_assert_msg(rt_scene_parse(edited, strlen(edited), "camera.scn",
                                     NULL, &parsed, &error) == RT_OK,
                      "%s\n%s", error.message, edited);
        rt_camera read = rt_test_scene_info(parsed).camera;
        assert_same_camera(&read, &camera, scene_files[s]);
        rt_scene_destroy(parsed);
        free(edited);
        free(scn);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(c_text_of_the_files_camera_needs_no_options)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    char text[4096];
    ck_assert_int_eq(view_camera_describe(scene, "cubes.scn", NULL, text,
                                          sizeof text, NULL),
                     RT_OK);
    ck_assert_ptr_nonnull(strstr(text, "no view options"));
    ck_assert_ptr_null(strstr(text, "--look-from"));
    /* Too small a buffer is refused, a look rt_scene_look refuses too. */
    rt_look look = view_camera_file_look(scene);
    rt_error error;
    ck_assert_int_eq(view_camera_describe(scene, "cubes.scn", &look, text,
                                          40, &error),
                     RT_ERR_LIMIT);
    look.look_at = look.look_from;
    ck_assert_int_eq(view_camera_describe(scene, "cubes.scn", &look, text,
                                          sizeof text, &error),
                     RT_ERR_ARGUMENT);
    rt_scene_destroy(scene);
}
END_TEST

/* ---- in the app: events, renders, Home, C ---- */

static void send(view_app *app, SDL_Event *event)
{
    ck_assert(view_app__move_event(app, event));
}

static void send_button(view_app *app, Uint32 type, int button, int x, int y,
                        int clicks)
{
    SDL_Event event;
    SDL_zero(event);
    event.type = type;
    event.button.button = (Uint8)button;
    event.button.state = type == SDL_MOUSEBUTTONDOWN ? SDL_PRESSED
                                                     : SDL_RELEASED;
    event.button.clicks = (Uint8)clicks;
    event.button.x = x;
    event.button.y = y;
    send(app, &event);
}

static void send_motion(view_app *app, int x, int y)
{
    SDL_Event event;
    SDL_zero(event);
    event.type = SDL_MOUSEMOTION;
    event.motion.x = x;
    event.motion.y = y;
    send(app, &event);
}

static void send_key(view_app *app, SDL_Keycode key)
{
    SDL_Event event;
    SDL_zero(event);
    event.type = SDL_KEYDOWN;
    event.key.state = SDL_PRESSED;
    event.key.keysym.sym = key;
    send(app, &event);
}

static unsigned generation(view_app *app)
{
    view_progress progress;
    view_session_get_progress(view_app_session(app), &progress);
    return progress.generation;
}

/* The app's picture equals the library's render with `camera` (NULL: the
 * scene's). */
static void assert_picture_of(view_app *app, const rt_camera *camera,
                              const char *name)
{
    const rt_image *shown = rt_test_view_app_image(app);
    const rt_scene *scene = view_session_scene(view_app_session(app));
    rt_render_options options = view_app__render_options(app, scene);
    options.camera = camera;
    rt_image expected = rt_test_render_with(scene, &options);
    rt_test_assert_same_image(shown, &expected, name);
    rt_image_release(&expected);
}

static view_app *cubes_app(void)
{
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(rt_test_view_app_load(app,
                                    rt_test_source_path("scenes/cubes.scn")));
    view_app__apply_moves(app);
    ck_assert(!app->move.moved);
    return app;
}

START_TEST(a_drag_renders_the_moved_camera_once_a_turn_and_home_the_files)
{
    view_app *app = cubes_app();
    rt_test_view_app_image(app);
    const rt_scene *scene = view_session_scene(view_app_session(app));
    rt_look file_look = view_camera_file_look(scene);
    unsigned before = generation(app);
    /* A left drag of three motions, applied in one turn. */
    send_button(app, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, 200, 200, 1);
    send_motion(app, 202, 201);     /* within the click's slop */
    send_motion(app, 230, 190);
    send_motion(app, 260, 185);
    send_button(app, SDL_MOUSEBUTTONUP, SDL_BUTTON_LEFT, 260, 185, 1);
    ck_assert_int_eq(generation(app), before);
    view_app__apply_moves(app);
    ck_assert_int_eq(generation(app), before + 1);
    ck_assert(app->move.moved);
    ck_assert_ptr_null(view_app_explanation(app));  /* a drag explains not */
    /* An orbit: the target and distance kept, the up the world's. */
    assert_vec_near(app->move.look.look_at, file_look.look_at, 0, "target");
    ck_assert_double_eq_tol(distance_of(&app->move.look),
                            distance_of(&file_look),
                            1e-12 * distance_of(&file_look));
    assert_vec_near(app->move.look.up, (rt_vec3){0, 0, 1}, 0, "up");
    rt_camera expected = camera_of(scene, &app->move.look);
    assert_same_camera(&app->move.camera, &expected, "the app's camera");
    assert_picture_of(app, &app->move.camera, "view_camera-drag");
    /* Nothing pending: no restart. */
    view_app__apply_moves(app);
    ck_assert_int_eq(generation(app), before + 1);
    /* Home: the file's camera exactly. */
    send_key(app, SDLK_HOME);
    ck_assert(!app->move.moved);
    ck_assert_int_eq(generation(app), before + 2);
    assert_picture_of(app, NULL, "view_camera-home");
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(a_click_without_motion_still_explains_the_pixel)
{
    view_app *app = cubes_app();
    rt_test_view_app_image(app);
    unsigned before = generation(app);
    send_button(app, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, 268, 124, 1);
    send_motion(app, 270, 122);     /* a hand's tremor */
    send_button(app, SDL_MOUSEBUTTONUP, SDL_BUTTON_LEFT, 270, 122, 1);
    view_app__apply_moves(app);
    ck_assert_int_eq(generation(app), before);
    ck_assert(!app->move.moved);
    const view_explanation *explanation = view_app_explanation(app);
    ck_assert_ptr_nonnull(explanation);
    ck_assert_int_eq(explanation->x, 270);
    ck_assert_int_eq(explanation->y, 122);
    /* A right click clears it; a right drag pans and explains nothing. */
    send_button(app, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_RIGHT, 100, 100, 1);
    send_button(app, SDL_MOUSEBUTTONUP, SDL_BUTTON_RIGHT, 100, 100, 1);
    ck_assert_ptr_null(view_app_explanation(app));
    rt_look look = view_camera_file_look(
        view_session_scene(view_app_session(app)));
    send_button(app, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_RIGHT, 100, 100, 1);
    send_motion(app, 120, 90);
    send_button(app, SDL_MOUSEBUTTONUP, SDL_BUTTON_RIGHT, 120, 90, 1);
    view_app__apply_moves(app);
    ck_assert(app->move.moved);
    ck_assert_ptr_null(view_app_explanation(app));
    ck_assert_double_eq_tol(distance_of(&app->move.look), distance_of(&look),
                            1e-12 * distance_of(&look));
    assert_vec_near(view_direction(&app->move.look), view_direction(&look),
                    1e-12, "a pan's direction of view");
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(wheel_keys_and_double_click_move_the_camera)
{
    view_app *app = cubes_app();
    const rt_scene *scene = view_session_scene(view_app_session(app));
    rt_look look = view_camera_file_look(scene);
    /* Two wheel notches towards the scene: the distance over 1.2^2. */
    SDL_Event event;
    SDL_zero(event);
    event.type = SDL_MOUSEWHEEL;
    event.wheel.y = 1;
    send(app, &event);
    send(app, &event);
    view_app__apply_moves(app);
    ck_assert_double_eq_tol(distance_of(&app->move.look),
                            distance_of(&look) / 1.44,
                            1e-12 * distance_of(&look));
    assert_vec_near(view_direction(&app->move.look), view_direction(&look),
                    1e-12, "a dolly's direction of view");
    /* ] widens the field of view, [ narrows it back. */
    look = app->move.look;
    send_key(app, SDLK_RIGHTBRACKET);
    view_app__apply_moves(app);
    ck_assert_double_eq_tol(app->move.look.fov, look.fov * 1.1, 1e-12);
    send_key(app, SDLK_LEFTBRACKET);
    view_app__apply_moves(app);
    ck_assert_double_eq_tol(app->move.look.fov, look.fov, 1e-12);
    /* Up: both points a step (2% of the extent) along the view. */
    look = app->move.look;
    send_key(app, SDLK_UP);
    view_app__apply_moves(app);
    rt_vec3 shift = sub(app->move.look.look_from, look.look_from);
    assert_vec_near(shift, sub(app->move.look.look_at, look.look_at), 1e-12,
                    "fly");
    double step = 0.02 * view_camera_extent(scene);
    ck_assert_double_eq_tol(length(shift), step, 1e-12 * step);
    assert_vec_near(unit(shift), view_direction(&look), 1e-12, "forward");
    /* A double-click on the floor: that point becomes the target. */
    rt_test_view_app_image(app);
    send_button(app, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, 268, 124, 1);
    send_button(app, SDL_MOUSEBUTTONUP, SDL_BUTTON_LEFT, 268, 124, 1);
    ck_assert_ptr_nonnull(view_app_explanation(app));
    rt_camera camera = app->move.camera;
    rt_vec3 point;
    ck_assert(view_camera_pick(scene, &camera, camera.width, camera.height,
                               268, 124, &point));
    send_button(app, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, 268, 124, 2);
    send_button(app, SDL_MOUSEBUTTONUP, SDL_BUTTON_LEFT, 268, 124, 2);
    view_app__apply_moves(app);
    assert_vec_near(app->move.look.look_at, point, 0, "picked target");
    ck_assert_ptr_null(view_app_explanation(app));
    assert_picture_of(app, &app->move.camera, "view_camera-picked");
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(c_writes_the_camera_beside_the_scene_never_over_a_file)
{
    char *dir = rt_test_temp_dir();
    char *scene_path = rt_test_join(dir, "cubes.scn");
    char *text = rt_test_read_file(rt_test_source_path("scenes/cubes.scn"),
                                   NULL);
    rt_test_write_file(scene_path, text);
    free(text);
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(rt_test_view_app_load(app, scene_path));
    char path[4096];
    /* At the file's camera. */
    ck_assert(view_app__print_camera(app, path, sizeof path));
    ck_assert_str_eq(path, rt_test_in_dir(dir, "cubes-camera.txt"));
    char *first = rt_test_read_file(path, NULL);
    ck_assert_ptr_nonnull(strstr(first, "no view options"));
    /* Moved: the next name, the first file unchanged. */
    send_key(app, SDLK_PAGEUP);
    view_app__apply_moves(app);
    ck_assert(view_app__print_camera(app, path, sizeof path));
    ck_assert_str_eq(path, rt_test_in_dir(dir, "cubes-camera-1.txt"));
    char *second = rt_test_read_file(path, NULL);
    char expected[4096];
    ck_assert_int_eq(view_camera_describe(
                         view_session_scene(view_app_session(app)),
                         scene_path, &app->move.look, expected,
                         sizeof expected, NULL),
                     RT_OK);
    ck_assert_str_eq(second, expected);
    char *again = rt_test_read_file(rt_test_in_dir(dir, "cubes-camera.txt"),
                                    NULL);
    ck_assert_str_eq(again, first);
    char line[2048];
    ck_assert(find_line(second, "--look-from ", line, sizeof line));
    rt_camera exported = export_camera(scene_path, line);
    assert_same_camera(&exported, &app->move.camera, "C's file");
    free(first);
    free(second);
    free(again);
    rt_test_view_app_close(app);
    free(scene_path);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(a_reload_of_the_same_file_keeps_the_view)
{
    char *dir = rt_test_temp_dir();
    char *scene_path = rt_test_join(dir, "cubes.scn");
    char *text = rt_test_read_file(rt_test_source_path("scenes/cubes.scn"),
                                   NULL);
    rt_test_write_file(scene_path, text);
    free(text);
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(rt_test_view_app_load(app, scene_path));
    send_key(app, SDLK_LEFT);
    view_app__apply_moves(app);
    ck_assert(app->move.moved);
    rt_look look = app->move.look;
    ck_assert(view_app_reload(app) && view_app_wait_load(app));
    view_app__apply_moves(app);
    ck_assert(app->move.moved);
    assert_vec_near(app->move.look.look_from, look.look_from, 0, "kept");
    assert_picture_of(app, &app->move.camera, "view_camera-reload");
    /* Another file starts from its own camera. */
    ck_assert(rt_test_view_app_load(
        app, rt_test_source_path("scenes/nff-sphere.nff")));
    view_app__apply_moves(app);
    ck_assert(!app->move.moved);
    assert_picture_of(app, NULL, "view_camera-other");
    rt_test_view_app_close(app);
    free(scene_path);
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *view_camera_suite(void)
{
    Suite *suite = suite_create("view_camera");
    TCase *moves = tcase_create("moves");
    tcase_set_timeout(moves, 120);  /* under valgrind */
    tcase_add_test(moves, the_first_target_is_what_the_axis_of_view_meets);
    tcase_add_test(moves, orbit_keeps_the_target_at_the_centre_and_its_distance);
    tcase_add_test(moves,
                   orbit_yaw_turns_about_the_world_up_and_pitch_stops_short_of_it);
    tcase_add_test(moves,
                   pan_moves_what_lies_at_the_targets_depth_with_the_cursor);
    tcase_add_test(moves, dolly_keeps_the_direction_and_scales_the_distance);
    tcase_add_test(moves, fly_moves_both_points_by_the_same_vector);
    tcase_add_test(moves, field_of_view_is_clamped);
    tcase_add_test(moves,
                   world_up_is_the_files_up_snapped_or_the_models_up_axis);
    tcase_add_test(moves, a_picked_point_becomes_the_target_at_the_image_centre);
    suite_add_tcase(suite, moves);
    TCase *text = tcase_create("text");
    tcase_set_timeout(text, 120);
    tcase_add_test(text, c_text_reads_back_as_rt_export_options_bit_for_bit);
    tcase_add_test(text, c_text_reads_back_as_scn_camera_records_bit_for_bit);
    tcase_add_test(text, c_text_of_the_files_camera_needs_no_options);
    suite_add_tcase(suite, text);
    TCase *app = tcase_create("app");
    tcase_set_timeout(app, 120);
    tcase_add_test(app,
                   a_drag_renders_the_moved_camera_once_a_turn_and_home_the_files);
    tcase_add_test(app, a_click_without_motion_still_explains_the_pixel);
    tcase_add_test(app, wheel_keys_and_double_click_move_the_camera);
    tcase_add_test(app, c_writes_the_camera_beside_the_scene_never_over_a_file);
    tcase_add_test(app, a_reload_of_the_same_file_keeps_the_view);
    suite_add_tcase(suite, app);
    return suite;
}

RT_CHECK_MAIN(view_camera_suite)
