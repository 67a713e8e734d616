/*
 * cancel.h - what an rt_cancel flag is (internal): the public functions
 * are in raytrace/render.h and cancel.c; the loops that poll it often
 * (every pixel, every few thousand facets) read it here directly.
 */
#ifndef RAYTRACE_CANCEL_H
#define RAYTRACE_CANCEL_H

#include <stdatomic.h>

#include "raytrace/render.h"

struct rt_cancel {
    atomic_int raised;
};

/* Non-zero when `cancel` (not NULL) is raised: a relaxed read, for the
 * polls of hot loops (a flag raised meanwhile is seen at a later poll). */
static inline int rt__cancel_raised(const rt_cancel *cancel)
{
    return atomic_load_explicit(&((rt_cancel *)cancel)->raised,
                                memory_order_relaxed);
}

#endif /* RAYTRACE_CANCEL_H */
