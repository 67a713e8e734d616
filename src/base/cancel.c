/*
 * cancel.c - the cancellation flag of raytrace/render.h: raised by any
 * thread, polled by the loads (the scene builder, the kernels' and the
 * octree's construction) and by the renders.  It lives in the base layer
 * because every layer above polls it.
 */
#include <stdlib.h>

#include "base/cancel.h"
#include "base/error.h"

rt_status rt_cancel_create(rt_cancel **cancel, rt_error *error)
{
    if (cancel == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a pointer to fill");
    *cancel = malloc(sizeof **cancel);
    if (*cancel == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory for a cancellation flag");
    atomic_init(&(*cancel)->raised, 0);
    return RT_OK;
}

void rt_cancel_destroy(rt_cancel *cancel)
{
    free(cancel);
}

void rt_cancel_request(rt_cancel *cancel)
{
    if (cancel != NULL)
        atomic_store(&cancel->raised, 1);
}

void rt_cancel_reset(rt_cancel *cancel)
{
    if (cancel != NULL)
        atomic_store(&cancel->raised, 0);
}

int rt_cancel_requested(const rt_cancel *cancel)
{
    return cancel != NULL && atomic_load(&((rt_cancel *)cancel)->raised);
}
