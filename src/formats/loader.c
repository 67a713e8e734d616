/*
 * loader.c - one loader for every scene format: the format from the name's
 * extension or the caller's choice, the file read with the limits every
 * reader shares, the list of files the load reads (resolve.h: the scene
 * file, then those it names, through the options' resolver), and the
 * dispatch to the format's own module (scn.c, nff.c, obj.c, ply.c).  A
 * file whose extension names no format is refused, listing the formats; a
 * file without one, and text from memory whose name names no format (a
 * name there is a label), are read as .scn.  Each reader
 * is a client of the scene builder, and ends with rt__reader_finish
 * (reader.c).
 */
#include <ctype.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/sized.h"
#include "base/file.h"
#include "formats/reader.h"
#include "formats/resolve.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"
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
    if (!(o->up_axis >= RT_UP_AUTO && o->up_axis <= RT_UP_NEG_Z))
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "an up axis of %d: expected an rt_up_axis",
                             (int)o->up_axis);
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
    rt_status status = rt__options_size_check(in->size, sizeof *out, "load",
                                              name, error);
    if (status != RT_OK)
        return status;
#define TAKE(field) RT__TAKE_FIELD(rt_load_options, in, out, field)
    TAKE(format) TAKE(tessellation) TAKE(width) TAKE(height)
    TAKE(look_from_given) TAKE(look_at_given) TAKE(up_given) TAKE(fov_given)
    TAKE(look_from) TAKE(look_at) TAKE(up) TAKE(fov) TAKE(lights)
    TAKE(light_count) TAKE(cancel) TAKE(resolve) TAKE(resolve_user) TAKE(up_axis)
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
    case RT_SCENE_FORMAT_PLY:
        return "ply";
    case RT_SCENE_FORMAT_AUTO:
        return "auto";
    }
    return "unknown";
}

static rt_status refuse_scene_extension(const char *path, rt_error *error)
{
    return rt__error_set(error, RT_ERR_FORMAT, path, 0, 0,
                         "cannot tell the scene format: expected the "
                         "extension .scn, .nff, .obj or .ply (or give the "
                         "format: --input-format)");
}

rt_status rt_scene_format_from_path(const char *path, rt_scene_format *format,
                                    rt_error *error)
{
    if (path == NULL || format == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a path and a format to fill");
    const char *dot = rt__path_extension(path);
    if (dot == NULL || strlen(dot) != 4)
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
                 {"obj", RT_SCENE_FORMAT_OBJ},
                 {"ply", RT_SCENE_FORMAT_PLY}};
    for (size_t i = 0; i < sizeof known / sizeof known[0]; i++)
        if (strcmp(extension, known[i].extension) == 0) {
            *format = known[i].format;
            return RT_OK;
        }
    return refuse_scene_extension(path, error);
}

/* The format `options` give, or that of `name`'s extension; .scn for a
 * name without one (or none).  An extension that names no format is
 * RT_ERR_FORMAT with `strict` (a file's path), .scn without (a name given
 * to text in memory, which callers use as a label). */
static rt_status format_of(const char *name, const rt_load_options *options,
                           int strict, rt_scene_format *format,
                           rt_error *error)
{
    *format = options->format;
    if (*format != RT_SCENE_FORMAT_AUTO)
        return RT_OK;
    *format = RT_SCENE_FORMAT_SCN;
    if (name == NULL || rt__path_extension(name) == NULL)
        return RT_OK;
    if (!strict) {
        /* on failure *format stays .scn */
        (void)rt_scene_format_from_path(name, format, NULL);
        return RT_OK;
    }
    return rt_scene_format_from_path(name, format, error);
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
    rt_scene_format format;
    rt_status status = format_of(name, options, 0, &format, error);
    if (status != RT_OK)
        return status;
    rt_files files;
    if (rt__files_init(&files,
                       options->resolve ? options->resolve : default_resolve,
                       options->resolve_user, name, text, length,
                       scene_file) != RT_OK)
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0,
                             "out of memory");
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
    case RT_SCENE_FORMAT_PLY:
        status = rt__ply_parse(text, length, name, options, scene, error);
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

rt_status rt_scene_parse(const char *text, size_t length, const char *name,
                         const rt_load_options *options, rt_scene **scene,
                         rt_error *error)
{
    rt_status status = rt__parse_arguments(text, length, name, scene, error);
    if (status != RT_OK)
        return status;
    rt_load_options taken;
    status = take_options(options, &taken, name, error);
    if (status != RT_OK)
        return status;
    return parse_taken(text, length, name, &taken, NULL, NULL, scene, error);
}

rt_status rt_scene_load(const char *path, const rt_load_options *options,
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
    /* The format first: an unknown extension is not read at all, and
     * a PLY's body is binary (no NUL stops its read). */
    rt_scene_format format;
    status = format_of(path, &taken, 1, &format, error);
    if (status != RT_OK)
        return status;
    char *data;
    size_t length;
    rt_file_identity identity;
    status = rt__read_scene_file_identified(path,
                                            format != RT_SCENE_FORMAT_PLY,
                                            &data, &length, &identity,
                                            error);
    if (status != RT_OK)
        return status;
    rt_scene_source self = {path, identity.device, identity.inode, length};
    status = parse_taken(data, length, path, &taken, &self,
                         rt_resolve_in_folder, scene, error);
    free(data);
    return status;
}
