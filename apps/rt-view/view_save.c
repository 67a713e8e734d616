/*
 * view_save.c - S (see view_app.h): what is rendered so far, saved with the
 * library's safe save under a name that replaces no earlier save (-o PATH
 * the first time for a complete image, else the first free numbered name,
 * "partial" for an image still rendering), never over a file the scene
 * was read from.
 */
#include "view_app_internal.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli_output.h"
#include "view_scene.h"

/* The finished rows (the others black) in a new image; their count in
 * *rows. */
static rt_status copy_finished_rows(view_app *app, rt_image *copy, int *rows)
{
    const rt_image *image = view_session_image(app->session);
    rt_status status = rt_image_init(copy, image->width, image->height, NULL);
    *rows = 0;
    if (status != RT_OK)
        return status;
    for (int y = 0; y < image->height; y++) {
        if (view_session_row_done(app->session, y)) {
            memcpy(rt_image_pixel(copy, 0, y), rt_image_pixel(image, 0, y),
                   (size_t)image->width * 3);
            (*rows)++;
        }
    }
    return RT_OK;
}

/* Where this save goes (see view_app.h); *claimed is 1 when the name was
 * created empty for it (to remove if the save fails). */
static int choose_save_path(view_app *app, int partial, char *path,
                            size_t size, int *claimed)
{
    char stem[4096];
    rt_error error;
    *claimed = 0;
    if (app->options.output) {
        if (!partial && !app->output_written) {
            int written = snprintf(path, size, "%s", app->options.output);
            return written >= 0 && (size_t)written < size;
        }
        snprintf(stem, sizeof stem, "%s", app->options.output);
    } else if (!view_scene_image_path(app->shown_path, app->options.format,
                                      stem, sizeof stem)) {
        view_app__show_message(app, "cannot save: the image's path is too "
                                    "long");
        return 0;
    }
    if (!view_save_claim_numbered(stem, partial ? "partial" : NULL, path,
                                  size, &error)) {
        char message[sizeof app->message];
        snprintf(message, sizeof message, "cannot save: %s", error.message);
        view_app__show_message(app, message);
        return 0;
    }
    *claimed = 1;
    return 1;
}

int view_app_save(view_app *app, char *path, size_t size)
{
    if (app->session == NULL) {
        view_app__show_message(app, "nothing to save: no scene is loaded");
        return 0;
    }
    rt_image copy;
    int rows;
    if (copy_finished_rows(app, &copy, &rows) != RT_OK) {
        view_app__show_message(app, "cannot save: out of memory");
        return 0;
    }
    int partial = rows < copy.height;
    int claimed;
    int saved = 0;
    char clash[sizeof app->message];
    if (!choose_save_path(app, partial, path, size, &claimed)) {
        /* the reason is shown */
    } else if (cli_output_clash(path, view_session_scene(app->session),
                                app->shown_path, 0, "the image", clash,
                                sizeof clash)) {
        /* -o names the scene, or a file the scene read: never over it */
        if (claimed)
            unlink(path);
        view_app__show_message(app, clash);
    } else {
        rt_error error;
        rt_save_options save = cli_save_options();
        rt_status status =
            rt_image_save(path, &copy, app->options.format, &save, &error);
        if (status == RT_OK) {
            saved = 1;
            if (!claimed)
                app->output_written = 1;
            if (partial)
                printf("%s (partial: %d of %d rows)\n", path, rows,
                       copy.height);
            else
                printf("%s\n", path);
            fflush(stdout);
        } else {
            if (claimed)
                unlink(path);   /* the empty file claimed for it */
            if (status == RT_ERR_INTERRUPTED)
                view_app__take_signal(app);  /* nothing else changed */
            else
                view_app__show_message(app, error.message);
        }
    }
    rt_image_release(&copy);
    return saved;
}
