/*
 * version.c - the version of the library that is actually linked.
 */
#include "raytrace/version.h"

const char *rt_version_string(void)
{
    return RT_VERSION_STRING;
}
