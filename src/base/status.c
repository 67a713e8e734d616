/*
 * status.c - the descriptions of rt_status values, generated from the same
 * table as the enum (RT_STATUS_MAP in raytrace/status.h).
 */
#include "raytrace/status.h"

const char *rt_status_string(rt_status status)
{
    switch (status) {
#define RT_STATUS_CASE_(name, value, text)                                   \
    case name:                                                               \
        return text;
        RT_STATUS_MAP(RT_STATUS_CASE_)
#undef RT_STATUS_CASE_
    }
    return "unknown status";
}
