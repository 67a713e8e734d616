/*
 * share.c - the scene and the files rank 0's load read, recorded,
 * broadcast and served to the other ranks, and the digest every rank
 * compares (share.h).
 */
#include "share.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *copy_of(const char *text, size_t length)
{
    char *copy = malloc(length + 1);
    if (copy != NULL) {
        if (length > 0)
            memcpy(copy, text, length);
        copy[length] = '\0';
    }
    return copy;
}

static void free_item(share_file *item)
{
    free(item->reference);
    free(item->file.data);
    free(item->file.name);
}

/* Appends a copy of `file` read under `reference`: 1, or 0 out of memory. */
static int keep(share_files *files, const char *reference,
                const rt_resolved_file *file)
{
    if (files->count == files->capacity) {
        int bigger = files->capacity ? 2 * files->capacity : 8;
        share_file *grown = realloc(files->items,
                                    (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return 0;
        files->items = grown;
        files->capacity = bigger;
    }
    share_file item = {copy_of(reference, strlen(reference)),
                       {copy_of(file->data, file->length), file->length,
                        copy_of(file->name, strlen(file->name)),
                        file->device, file->inode}};
    if (item.reference == NULL || item.file.data == NULL ||
        item.file.name == NULL) {
        free_item(&item);
        return 0;
    }
    files->items[files->count++] = item;
    return 1;
}

rt_status share_record(void *user, const char *scene_name,
                       const char *reference, size_t limit,
                       rt_resolved_file *file, rt_error *error)
{
    rt_status status = rt_resolve_in_folder(NULL, scene_name, reference,
                                            limit, file, error);
    if (status == RT_OK && !keep(user, reference, file)) {
        free(file->data);
        free(file->name);
        error->status = RT_ERR_NOMEM;
        snprintf(error->message, sizeof error->message,
                 "out of memory keeping a copy of a file for the other "
                 "ranks");
        return RT_ERR_NOMEM;
    }
    return status;
}

rt_status share_serve(void *user, const char *scene_name,
                      const char *reference, size_t limit,
                      rt_resolved_file *file, rt_error *error)
{
    (void)scene_name;
    const share_files *files = user;
    for (int i = 0; i < files->count; i++) {
        const share_file *item = &files->items[i];
        if (strcmp(item->reference, reference) != 0 ||
            item->file.length > limit)
            continue;
        *file = item->file;
        file->data = copy_of(item->file.data, item->file.length);
        file->name = copy_of(item->file.name, strlen(item->file.name));
        if (file->data == NULL || file->name == NULL) {
            free(file->data);
            free(file->name);
            error->status = RT_ERR_NOMEM;
            snprintf(error->message, sizeof error->message, "out of memory");
            return RT_ERR_NOMEM;
        }
        return RT_OK;
    }
    error->status = RT_ERR_IO;
    snprintf(error->message, sizeof error->message,
             "`%s` is not read: rank 0 did not read it", reference);
    return RT_ERR_IO;
}

/* Broadcasts `length` bytes (at most RT_MAX_SCENE_BYTES: one int count). */
static void broadcast_bytes(char **bytes, long long length, int rank,
                            MPI_Comm comm)
{
    if (rank != 0 && (*bytes = malloc((size_t)length + 1)) == NULL) {
        fprintf(stderr, "rt-export-mpi: rank %d: out of memory\n", rank);
        MPI_Abort(comm, 1);
    }
    if (length > 0)
        MPI_Bcast(*bytes, (int)length, MPI_BYTE, 0, comm);
    (*bytes)[length] = '\0';
}

void share_broadcast(share_files *files, int rank, MPI_Comm comm)
{
    int count = files->count;
    MPI_Bcast(&count, 1, MPI_INT, 0, comm);
    if (rank != 0) {
        files->items = calloc(count > 0 ? (size_t)count : 1,
                              sizeof *files->items);
        if (files->items == NULL) {
            fprintf(stderr, "rt-export-mpi: rank %d: out of memory\n", rank);
            MPI_Abort(comm, 1);
        }
        files->count = files->capacity = count;
    }
    for (int i = 0; i < count; i++) {
        share_file *item = &files->items[i];
        unsigned long long sizes[5] = {0};
        if (rank == 0) {
            sizes[0] = strlen(item->reference);
            sizes[1] = item->file.length;
            sizes[2] = strlen(item->file.name);
            sizes[3] = item->file.device;
            sizes[4] = item->file.inode;
        }
        MPI_Bcast(sizes, 5, MPI_UNSIGNED_LONG_LONG, 0, comm);
        broadcast_bytes(&item->reference, (long long)sizes[0], rank, comm);
        broadcast_bytes(&item->file.data, (long long)sizes[1], rank, comm);
        broadcast_bytes(&item->file.name, (long long)sizes[2], rank, comm);
        item->file.length = (size_t)sizes[1];
        item->file.device = sizes[3];
        item->file.inode = sizes[4];
    }
}

static uint64_t mix(uint64_t h, const void *data, size_t size)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < size; i++)
        h = (h ^ b[i]) * 1099511628211u;
    return h;
}

uint64_t share_digest(const rt_scene *scene)
{
    uint64_t h = 14695981039346656037u;
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    const rt_camera *c = &info.camera;
    h = mix(h, &c->observer, sizeof c->observer);
    h = mix(h, &c->screen_center, sizeof c->screen_center);
    h = mix(h, &c->right, sizeof c->right);
    h = mix(h, &c->up, sizeof c->up);
    h = mix(h, &c->aperture, sizeof c->aperture);
    h = mix(h, &c->focal_distance, sizeof c->focal_distance);
    int sizes[5] = {c->width, c->height, info.vertex_count, info.facet_count,
                    info.light_count};
    h = mix(h, sizes, sizeof sizes);
    h = mix(h, &info.background, sizeof info.background);
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        h = mix(h, &v, sizeof v);
    }
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        double numbers[4] = {f.reflection, f.transparency, f.refractive_index,
                             f.diffuse};
        h = mix(h, f.vertex, sizeof f.vertex);
        h = mix(h, numbers, sizeof numbers);
        h = mix(h, &f.color, sizeof f.color);
    }
    for (int i = 0; i < info.light_count; i++) {
        rt_light light;
        rt_scene_light(scene, i, &light);
        h = mix(h, &light.position, sizeof light.position);
        h = mix(h, &light.color, sizeof light.color);
    }
    return h;
}

void share_free(share_files *files)
{
    for (int i = 0; i < files->count; i++)
        free_item(&files->items[i]);
    free(files->items);
    memset(files, 0, sizeof *files);
}

void share_input_free(share_input *input)
{
    free(input->text);
    share_free(&input->files);
    memset(input, 0, sizeof *input);
}

/* Every rank: whether this rank's scene is rank 0's. */
static int same_scene(const rt_scene *scene, const char *name, int rank,
                      MPI_Comm comm)
{
    /* The same bytes, the same options: the same scene, unless the ranks
     * run different programs or were given different command lines. */
    unsigned long long digest = scene ? share_digest(scene) : 0;
    unsigned long long expected = digest;
    MPI_Bcast(&expected, 1, MPI_UNSIGNED_LONG_LONG, 0, comm);
    if (rank == 0 || scene == NULL || digest == expected)
        return 1;
    fprintf(stderr, "rt-export-mpi: rank %d: %s: the scene this rank built "
                    "from rank 0's bytes is not rank 0's (digest %016llx, "
                    "rank 0's %016llx): the ranks run different programs or "
                    "command lines; nothing is rendered\n",
            rank, name, digest, expected);
    return 0;
}

int share_scene(share_input *input, int verdict, const char *name,
                const rt_load_options *load, rt_scene **scene, int rank,
                MPI_Comm comm)
{
    long long header[2] = {verdict, (long long)input->length};
    MPI_Bcast(header, 2, MPI_LONG_LONG, 0, comm);
    if (header[0] != CLI_CONTINUE)
        return (int)header[0];
    /* <= RT_MAX_SCENE_BYTES (1 GiB): one count fits an int */
    broadcast_bytes(&input->text, header[1], rank, comm);
    input->length = (size_t)header[1];
    share_broadcast(&input->files, rank, comm);
    int failed = 0;
    if (rank != 0) {
        rt_error error;
        rt_load_options options = *load;
        options.resolve = share_serve;
        options.resolve_user = &input->files;
        if (rt_scene_parse(input->text, input->length, name, &options, scene,
                           &error) != RT_OK) {
            fprintf(stderr, "rt-export-mpi: rank %d: %s\n", rank,
                    error.message);
            *scene = NULL;
            failed = 1;
        }
    }
    failed |= !same_scene(*scene, name, rank, comm);
    MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm);
    return failed ? 1 : CLI_CONTINUE;
}
