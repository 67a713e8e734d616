/*
 * probe.c - what a suite asks about the world it runs in (see probe.h).
 */
#include "probe.h"

#include <stdlib.h>
#include <string.h>

#include "raytrace/raytrace.h"
#include "suite.h"

int rt_test_under_valgrind(void)
{
    const char *preload = getenv("LD_PRELOAD");
    return preload != NULL && strstr(preload, "vgpreload") != NULL;
}

int rt_test_memcheck(void)
{
    const char *value = getenv("RT_TEST_MEMCHECK");
    return value != NULL && value[0] != '\0' && strcmp(value, "0") != 0;
}

int rt_test_have_python_json(void)
{
    return system("python3 -c 'import json' >/dev/null 2>&1") == 0;
}

int rt_test_loader_lists_its_files(void)
{
    rt_scene *scene;
    if (rt_scene_load(rt_test_source_path("tests/data/obj/cube.obj"), NULL,
                      &scene, NULL) != RT_OK)
        return 0;
    int count = rt_scene_source_count(scene);
    rt_scene_destroy(scene);
    return count >= 2;
}
