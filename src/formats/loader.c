/*
 * loader.c - one loader for every scene format: the format from the name's
 * extension or the caller's choice, the file read with the limits every
 * reader shares, and the dispatch to the format's own module (scn.c,
 * nff.c, obj.c).  Each reader is a client of the scene builder.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "file.h"
#include "formats/formats.h"
#include "formats/reader.h"
#include "raytrace/scene.h"

void rt_load_options_init(rt_load_options *options)
{
    memset(options, 0, sizeof *options);
    options->format = RT_SCENE_FORMAT_AUTO;
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
        break;
    }
    return "auto";
}

rt_status rt_scene_format_from_path(const char *path, rt_scene_format *format)
{
    if (path == NULL)
        return RT_ERR_ARGUMENT;
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    if (dot == NULL || dot == base || strlen(dot) != 4)
        return RT_ERR_FORMAT;
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
    return RT_ERR_FORMAT;
}

rt_status rt_scene_parse_with(const char *text, size_t length,
                              const char *name,
                              const rt_load_options *options,
                              rt_scene **scene, rt_error *error)
{
    if (scene == NULL)
        return RT_ERR_ARGUMENT;
    *scene = NULL;
    rt_load_options defaults;
    if (options == NULL) {
        rt_load_options_init(&defaults);
        options = &defaults;
    }
    rt_scene_format format = options->format;
    if (format == RT_SCENE_FORMAT_AUTO &&
        (name == NULL || rt_scene_format_from_path(name, &format) != RT_OK))
        format = RT_SCENE_FORMAT_SCN;
    switch (format) {
    case RT_SCENE_FORMAT_SCN:
        return rt_scene_parse(text, length, name, scene, error);
    case RT_SCENE_FORMAT_NFF:
    case RT_SCENE_FORMAT_OBJ:
        return rt__error_set(error, RT_ERR_FORMAT, name, 0, 0,
                             "cannot read %s scenes: this version of the "
                             "library reads only .scn",
                             rt_scene_format_name(format));
    case RT_SCENE_FORMAT_AUTO:
        break;
    }
    return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                         "expected a scene format, found %d", (int)format);
}

rt_status rt_scene_load_with(const char *path, const rt_load_options *options,
                             rt_scene **scene, rt_error *error)
{
    if (scene == NULL)
        return RT_ERR_ARGUMENT;
    *scene = NULL;
    if (path == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a path");
    char *data;
    size_t length;
    rt_status status = rt__read_text_file(path, &data, &length, error);
    if (status != RT_OK)
        return status;
    status = rt_scene_parse_with(data, length, path, options, scene, error);
    free(data);
    return status;
}

rt_status rt_scene_load(const char *path, rt_scene **scene, rt_error *error)
{
    return rt_scene_load_with(path, NULL, scene, error);
}
