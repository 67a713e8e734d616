/*
 * share.h - the same scene on every rank (rt-export-mpi, docs/mpi.md): rank
 * 0 reads the scene and, through a recording resolver over
 * rt_resolve_in_folder, every file it names; all those bytes go to every
 * rank, which parses the scene from them with a resolver that serves only
 * them, so that no worker reads its own disk (a worker without the OBJ's
 * material library, or with another one, renders the same picture).  Then
 * every rank checks that it built the scene rank 0 built, by a digest of
 * everything the picture depends on.  Only rank 0 reads anything, and
 * only rank 0's verdict on the command line and the scene counts: every
 * rank returns it.
 */
#ifndef RAYTRACE_MPI_SHARE_H
#define RAYTRACE_MPI_SHARE_H

#include <mpi.h>
#include <stdint.h>

#include "cli.h"
#include "raytrace/raytrace.h"

/* A file rank 0's load read, as its resolver gave it. */
typedef struct share_file {
    char *reference;            /* as the scene spells it */
    rt_resolved_file file;      /* its bytes, name and identity */
} share_file;

/* The files of one load: recorded on rank 0, received on the others. */
typedef struct share_files {
    share_file *items;
    int count, capacity;
} share_files;

/* Rank 0's resolver (`user`: a share_files): rt_resolve_in_folder, with a
 * copy of each file it gives kept in the list.  RT_ERR_NOMEM when the
 * copy cannot be made. */
rt_status share_record(void *user, const char *scene_name,
                       const char *reference, size_t limit,
                       rt_resolved_file *file, rt_error *error);

/* The other ranks' resolver (`user`: a share_files): a copy of the file
 * rank 0 read under `reference`; any other name is refused, as it was on
 * rank 0.  Reads no disk. */
rt_status share_serve(void *user, const char *scene_name,
                      const char *reference, size_t limit,
                      rt_resolved_file *file, rt_error *error);

/* Every rank: the list goes from rank 0 to the others (called by all
 * ranks of `comm`, after the scene's bytes).  A rank out of memory aborts
 * the job (a collective cannot be left half done). */
void share_broadcast(share_files *files, int rank, MPI_Comm comm);

/* FNV-1a over the scene's camera, image size, background, vertices,
 * facets and lights, bit for bit: equal digests, equal pictures. */
uint64_t share_digest(const rt_scene *scene);

void share_free(share_files *files);

/* What rank 0's load read: the scene's bytes and the files it names. */
typedef struct share_input {
    char *text;                 /* NUL-terminated after `length` bytes */
    size_t length;
    share_files files;          /* recorded by share_record */
} share_input;

/*
 * Every rank of `comm`: rank 0's `verdict` goes to every rank; when it is
 * CLI_CONTINUE the scene's bytes and its files follow, every other rank
 * parses them (named `name`, with `load` and share_serve as the resolver)
 * into *scene, and every rank checks that it built rank 0's scene (rank 0
 * passes its own in *scene) by share_digest.  Returns CLI_CONTINUE, or the
 * exit status every rank returns: rank 0's verdict, or 1 when a rank's
 * scene differs or does not parse (that rank says so).
 */
int share_scene(share_input *input, int verdict, const char *name,
                const rt_load_options *load, rt_scene **scene, int rank,
                MPI_Comm comm);

void share_input_free(share_input *input);

#endif /* RAYTRACE_MPI_SHARE_H */
