/*
 * reader.c - what every scene reader shares (reader.h): the poll of a
 * load's cancellation flag.
 */
#include "formats/reader.h"

#include "base/error.h"
#include "raytrace/render.h"

int rt__load_cancelled(const rt_load_options *options)
{
    return options != NULL && options->cancel != NULL &&
           rt_cancel_requested(options->cancel);
}

rt_status rt__load_cancel(rt_error *error, const char *name)
{
    return rt__error_set(error, RT_ERR_CANCELLED, name ? name : "<memory>",
                         0, 0, "the load was cancelled");
}
