/*
 * loader.c - one loader for every scene format: the format from the name's
 * extension or the caller's choice, the file read with the limits every
 * reader shares, the list of files the load reads (resolve.h: the scene
 * file, then those it names, through the options' resolver), and the
 * dispatch to the format's own module (scn.c, nff.c, obj.c).  Each reader
 * is a client of the scene builder.
 */
#include <ctype.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/file.h"
#include "formats/formats.h"
#include "formats/framing.h"
#include "formats/reader.h"
#include "formats/resolve.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"
#include "scene/scene_build.h"
#include "base/vecmath.h"

void rt_load_options_init(rt_load_options *options)
{
    if (options == NULL)
        return;
    memset(options, 0, sizeof *options);
    options->size = sizeof *options;
    options->format = RT_SCENE_FORMAT_AUTO;
}

/* RT_OK when every field of `o` lies in its domain (raytrace/scene.h),
 * whatever the format reads; else the refusal, naming the field. */
static rt_status check_options(const rt_load_options *o, const char *name,
                               rt_error *error)
{
    if (o->tessellation != 0 && !(o->tessellation > 0 && o->tessellation < 1))
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected a tessellation tolerance in (0, 1), "
                             "found %g", o->tessellation);
    if (o->width < 0 || o->width > RT_MAX_IMAGE_SIDE || o->height < 0 ||
        o->height > RT_MAX_IMAGE_SIDE)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "an image of %d x %d pixels: expected each side "
                             "0 (the default) or 1..%d", o->width, o->height,
                             RT_MAX_IMAGE_SIDE);
    if (o->fov_given && !(o->fov > 0 && o->fov < 180))
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "a field of view of %g degrees: expected more "
                             "than 0 and less than 180", o->fov);
    const char *vector = o->look_from_given && !v3_is_finite(o->look_from)
                             ? "look_from"
                         : o->look_at_given && !v3_is_finite(o->look_at)
                             ? "look_at"
                         : o->up_given && !v3_is_finite(o->up) ? "up"
                                                               : NULL;
    if (vector != NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected finite coordinates for %s", vector);
    if (o->light_count < 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "a light count of %d: expected 0 (the file's "
                             "lights) or more", o->light_count);
    if (o->light_count > 0 && o->lights == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "%d lights: expected an array of lights",
                             o->light_count);
    return RT_OK;
}

/* Copies the caller's options into *out as far as the caller's size
 * reaches; later fields keep their defaults (raytrace/render.h's rule for
 * growing option structs).  NULL: the defaults. */
static rt_status take_options(const rt_load_options *in, rt_load_options *out,
                              const char *name, rt_error *error)
{
    rt_load_options_init(out);
    if (in == NULL)
        return RT_OK;
    if (in->size == 0 || in->size > sizeof *out)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "load options of %zu bytes: expected 1..%zu "
                             "(set by rt_load_options_init)",
                             in->size, sizeof *out);
#define TAKE(field)                                                          \
    if (offsetof(rt_load_options, field) + sizeof in->field <= in->size)      \
        out->field = in->field;
    TAKE(format) TAKE(tessellation) TAKE(width) TAKE(height)
    TAKE(look_from_given) TAKE(look_at_given) TAKE(up_given) TAKE(fov_given)
    TAKE(look_from) TAKE(look_at) TAKE(up) TAKE(fov) TAKE(lights)
    TAKE(light_count) TAKE(cancel) TAKE(resolve) TAKE(resolve_user)
#undef TAKE
    return check_options(out, name, error);
}

const char *rt_scene_format_name(rt_scene_format format)
{
    switch (format) {
    case RT_SCENE_FORMAT_SCN:
        return "scn";
    case RT_SCENE_FORMAT_NFF:
        return "nff";
    case RT_SCENE_FORMAT_OBJ:
        return "obj";
    case RT_SCENE_FORMAT_AUTO:
        return "auto";
    }
    return "unknown";
}

static rt_status refuse_scene_extension(const char *path, rt_error *error)
{
    return rt__error_set(error, RT_ERR_FORMAT, path, 0, 0,
                         "cannot tell the scene format: expected the "
                         "extension .scn, .nff or .obj");
}

rt_status rt_scene_format_from_path(const char *path, rt_scene_format *format,
                                    rt_error *error)
{
    if (path == NULL || format == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a path and a format to fill");
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    if (dot == NULL || dot == base || strlen(dot) != 4)
        return refuse_scene_extension(path, error);
    char extension[4];
    for (int i = 0; i < 3; i++)
        extension[i] = (char)tolower((unsigned char)dot[1 + i]);
    extension[3] = '\0';
    static const struct {
        const char *extension;
        rt_scene_format format;
    } known[] = {{"scn", RT_SCENE_FORMAT_SCN},
                 {"nff", RT_SCENE_FORMAT_NFF},
                 {"obj", RT_SCENE_FORMAT_OBJ}};
    for (size_t i = 0; i < sizeof known / sizeof known[0]; i++)
        if (strcmp(extension, known[i].extension) == 0) {
            *format = known[i].format;
            return RT_OK;
        }
    return refuse_scene_extension(path, error);
}

#define PI 3.14159265358979323846

/*
 * The view of `options` applied to the camera of `d`: what is not given
 * keeps the file's value (observer O, look-at A, horizontal field of view
 * 2 atan(|AB| / |AO|); up: the file's AC, or, when the direction of view
 * changes, the coordinate axis nearest to it).  Returns NULL, or what is
 * wrong.
 */
static const char *apply_view(rt_scene_desc *d, const rt_load_options *o)
{
    rt_vec3 from = d->observer, at = d->screen_center;
    rt_vec3 ao = v3_sub(d->observer, d->screen_center);
    rt_vec3 ab = v3_sub(d->screen_right, d->screen_center);
    rt_vec3 up = v3_cross(ao, ab);
    double fov = 2 * atan(v3_length(ab) / v3_length(ao)) * 180 / PI;
    if (o->look_from_given)
        from = o->look_from;
    if (o->look_at_given)
        at = o->look_at;
    if (o->up_given) {
        up = o->up;
    } else if (o->look_from_given || o->look_at_given) {
        /* A new direction of view: the file's up leans with the file's
         * view, so take the axis nearest to it (the scene's vertical,
         * for a camera that looked down at it). */
        rt_vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        rt_vec3 unit = v3_normalize(up), best = axes[2];
        double best_dot = 0;
        for (int i = 0; i < 3; i++) {
            double along = v3_dot(unit, axes[i]);
            if (fabs(along) > fabs(best_dot)) {
                best_dot = along;
                best = axes[i];
            }
        }
        up = best_dot < 0 ? v3_scale(best, -1) : best;
    }
    if (o->fov_given)
        fov = o->fov;
    rt_view view = {from, at, up, fov, d->width, 0};
    switch (rt__frame_view(&view, &d->observer, &d->screen_center,
                           &d->screen_right)) {
    case RT_FRAME_OK:
        return NULL;
    case RT_FRAME_FOV:
        return "the field of view is not in (0, 180) degrees";
    case RT_FRAME_SAME_POINT:
        return "the look-from point is the look-at point";
    case RT_FRAME_UP_ALONG_VIEW:
        return "the up direction is along the view";
    }
    return NULL;
}

rt_status rt__reader_finish(rt_scene_desc *desc, const char *name,
                            const int *facet_lines, const rt_notes *notes,
                            const rt_load_options *options, rt_scene **scene,
                            rt_error *error)
{
    if (options != NULL && (options->look_from_given ||
                            options->look_at_given || options->up_given ||
                            options->fov_given)) {
        const char *wrong = apply_view(desc, options);
        if (wrong != NULL)
            return rt__error_set(error, RT_ERR_CAMERA, name, 0, 0,
                                 "expected a view, found that %s", wrong);
    }
    if (options != NULL && options->light_count > 0) {
        if (options->lights == NULL)
            return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                                 "expected an array of lights");
        desc->light_position = options->lights[0].position;
        desc->light_color = options->lights[0].color;
        desc->more_lights = options->lights + 1;
        desc->more_light_count = options->light_count - 1;
    }
    return rt__scene_build(desc, name, facet_lines, notes,
                           options != NULL ? options->cancel : NULL, scene,
                           error);
}

/* The load of `text` with the options taken: `scene_file` (may be NULL)
 * is the file it was read from, `default_resolve` the resolver used when
 * the options give none. */
static rt_status parse_taken(const char *text, size_t length,
                             const char *name, const rt_load_options *options,
                             const rt_scene_source *scene_file,
                             rt_resolve_func default_resolve,
                             rt_scene **scene, rt_error *error)
{
    if (options->cancel != NULL && rt_cancel_requested(options->cancel))
        return rt__error_set(error, RT_ERR_CANCELLED,
                             name ? name : "<memory>", 0, 0,
                             "the load was cancelled");
    rt_scene_format format = options->format;
    if (format == RT_SCENE_FORMAT_AUTO &&
        (name == NULL || rt_scene_format_from_path(name, &format,
                                                   NULL) != RT_OK))
        format = RT_SCENE_FORMAT_SCN;
    rt_files files;
    if (rt__files_init(&files,
                       options->resolve ? options->resolve : default_resolve,
                       options->resolve_user, name, text, length,
                       scene_file) != RT_OK)
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0,
                             "out of memory");
    rt_status status;
    switch (format) {
    case RT_SCENE_FORMAT_SCN:
        status = rt__scn_parse(text, length, name, options, scene, error);
        break;
    case RT_SCENE_FORMAT_OBJ:
        status = rt__obj_parse(text, length, name, options, &files, scene,
                               error);
        break;
    case RT_SCENE_FORMAT_NFF:
        status = rt__nff_parse(text, length, name, options, scene, error);
        break;
    default:
        status = rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                               "expected a scene format, found %d",
                               (int)format);
        break;
    }
    if (status == RT_OK)
        rt__files_attach(&files, *scene);
    rt__files_free(&files);
    return status;
}

rt_status rt_scene_parse_with(const char *text, size_t length,
                              const char *name,
                              const rt_load_options *options,
                              rt_scene **scene, rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected a pointer to fill with the scene");
    *scene = NULL;
    if (text == NULL && length > 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected scene text");
    rt_load_options taken;
    rt_status status = take_options(options, &taken, name, error);
    if (status != RT_OK)
        return status;
    return parse_taken(text, length, name, &taken, NULL, NULL, scene, error);
}

rt_status rt_scene_load_with(const char *path, const rt_load_options *options,
                             rt_scene **scene, rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, path, 0, 0,
                             "expected a pointer to fill with the scene");
    *scene = NULL;
    if (path == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a path");
    rt_load_options taken;
    rt_status status = take_options(options, &taken, path, error);
    if (status != RT_OK)
        return status;
    char *data;
    size_t length;
    rt_file_identity identity;
    status = rt__read_text_file_identified(path, &data, &length, &identity,
                                           error);
    if (status != RT_OK)
        return status;
    rt_scene_source self = {path, identity.device, identity.inode, length};
    status = parse_taken(data, length, path, &taken, &self,
                         rt_resolve_in_folder, scene, error);
    free(data);
    return status;
}

rt_status rt_scene_load(const char *path, rt_scene **scene, rt_error *error)
{
    return rt_scene_load_with(path, NULL, scene, error);
}
