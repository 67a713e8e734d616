/*
 * scenes.c - scenes for the tests (see scenes.h).
 */
#include "scenes.h"

#include <check.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "suite.h"

const char rt_test_small_scene[] =
    "0 0 10\n"
    "0 0 5 4 0 5 40 30\n"
    "3\n"
    "-3 -3 0\n"
    "3 -3 0\n"
    "0 3 0\n"
    "1\n"
    "1 2 3 0.25 200 100 50\n"
    "10 20 30\n"
    "0 0 4 255 255 255\n";

const char rt_test_centred_facet_scene[] =
    "0,0,-5\n"
    "0,0,0, 1,0,0, 40,30\n"
    "3\n-1,-1,2\n1,-1,2\n0,1,2\n"
    "1\n1,2,3, 0, 200,100,50\n"
    "10,20,30\n"
    "0,0,-5, 255,255,255\n";

rt_scene *rt_test_scene_from_string(const char *text)
{
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status =
        rt_scene_parse(text, strlen(text), "<test>", NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "scene did not load: %s", error.message);
    return scene;
}

rt_scene *rt_test_load_source_scene(const char *relative)
{
    rt_scene *scene = NULL;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status =
        rt_scene_load(rt_test_source_path(relative), NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s did not load: %s", relative,
                  error.message);
    return scene;
}

rt_status rt_test_parse_obj(const char *text, const rt_load_options *given,
                            rt_scene **scene, rt_error *error)
{
    rt_load_options options;
    if (given != NULL)
        options = *given;
    else
        rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_OBJ;
    return rt_scene_parse(text, strlen(text), NULL, &options, scene, error);
}

rt_status rt_test_parse_refused(const char *text, size_t length,
                                rt_error *error)
{
    rt_scene *scene = (rt_scene *)1;
    memset(error, 0, sizeof *error);
    rt_status status =
        rt_scene_parse(text, length, "hostile.scn", NULL, &scene, error);
    ck_assert_msg(status != RT_OK, "a hostile scene loaded");
    ck_assert_ptr_null(scene);
    ck_assert_int_eq(error->status, status);
    ck_assert_msg(error->message[0] != '\0', "a refusal without a message");
    return status;
}

void rt_test_write_two_facet_scene(const char *path, const char *background)
{
    FILE *file = fopen(path, "w");
    ck_assert_msg(file != NULL, "cannot write %s", path);
    fprintf(file,
            "0,0,10\n0,0,5, 4,0,5, 64,48\n6\n"
            "-9.37,-5.73,0\n9.71,-5.38,0\n0.31,13.1,0\n"
            "-1.13,-1.27,2\n1.58,-0.93,2\n-0.17,1.74,2\n2\n"
            "1,2,3, 0, 180,180,180\n4,5,6, 0.4, 40,120,255\n"
            "%s\n-3.875,0.125,4, 255,255,255\n",
            background);
    ck_assert_int_eq(fclose(file), 0);
}

rt_scene_info rt_test_scene_info(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    return info;
}

int rt_test_count_warnings(const rt_scene *scene, const char *words)
{
    int n = 0, count = rt_test_scene_info(scene).warning_count;
    for (int i = 0; i < count; i++)
        n += strstr(rt_scene_warning(scene, i)->message, words) != NULL;
    return n;
}

void rt_test_text_add(rt_test_text *text, const char *format, ...)
{
    for (;;) {
        size_t room = text->capacity - text->length;
        va_list args;
        va_start(args, format);
        int n = vsnprintf(text->data ? text->data + text->length : NULL,
                          text->data ? room : 0, format, args);
        va_end(args);
        ck_assert_int_ge(n, 0);
        if (text->data != NULL && (size_t)n < room) {
            text->length += (size_t)n;
            return;
        }
        size_t capacity = text->capacity ? 2 * text->capacity : 4096;
        while (capacity <= text->length + (size_t)n)
            capacity *= 2;
        char *grown = realloc(text->data, capacity);
        ck_assert_ptr_nonnull(grown);
        text->data = grown;
        text->capacity = capacity;
    }
}
