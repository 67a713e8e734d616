/*
 * cli_output.h - the programs' two rules for what they write, besides the
 * library's save rule (raytrace/image.h):
 *
 *   - nothing is written over what was read.  Before a program renders
 *     (or converts) and again just before it saves, cli_output_clash
 *     compares the output, by device and inode once links are followed,
 *     with every file the load read: the scene file, the files the scene
 *     named (rt_scene_source_at: an OBJ's material libraries) and standard
 *     input.  rt-export, rt-export-mpi, rt-convert and rt-view's S all ask
 *     it, and refuse with one message that names both files.
 *   - a late failure keeps the work.  When the final save of a render
 *     fails (a full disk, a folder removed during the render, an output
 *     that has become an input), cli_keep_image saves the image under a
 *     new name next to the output, or in $TMPDIR or /tmp, and says where.
 *
 * Not thread-safe with other changes to the same folders (what is looked
 * at may change before it is written: the checks narrow the window, the
 * library's save keeps what it replaces whole either way).
 */
#ifndef RAYTRACE_CLI_OUTPUT_H
#define RAYTRACE_CLI_OUTPUT_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* How a kept image is named: "STEM.rescue-XXXXXX.EXT" (EXT .ppm or .png);
 * the X's are letters and digits, the name new in its folder. */
#define CLI_RESCUE_TAG ".rescue-"

/*
 * Whether writing at `output` ("-": standard output) would write over a
 * file the load of `scene` read: the file at `scene_path` (NULL: none),
 * the scene's sources, and standard input when `from_stdin`.  Only a
 * regular file counts (writing to a terminal, a FIFO or a device one reads
 * from destroys nothing); identities are (st_dev, st_ino) after following
 * links, so another spelling, a symbolic or a hard link are the same file.
 * Returns 1 with the refusal in message[0..size)
 *     "OUT: refusing to write WHAT over IN, the scene it comes from (the
 *      same file)"
 * (or "..., a file the scene read", "..., standard input, where the scene
 * was read from"), names with control bytes escaped; else 0.  `what` is
 * "the image" or "the scene".
 */
int cli_output_clash(const char *output, const rt_scene *scene,
                     const char *scene_path, int from_stdin,
                     const char *what, char *message, size_t size);

/* cli_output_clash as a program asks it, with `operand` the scene as it
 * was given on the command line ("-": standard input): prints
 * "PROGRAM: MESSAGE" on stderr and returns 1 when the output is an input,
 * else returns 0. */
int cli_refuse_input_as_output(const char *program, const char *output,
                               const rt_scene *scene, const char *operand,
                               const char *what);

/* The save options of every program (rt_image_save, rt_image_save_check,
 * rt_scene_save_scn): the termination signals held while a temporary file
 * exists, so that a program ended by Ctrl-C, kill or a closed terminal
 * during a save leaves the old file and no temporary one
 * (docs/saving-images.md, "Signals"). */
rt_save_options cli_save_options(void);

/*
 * Saves `image` (in `format`), whose save to `path` failed, under a new
 * name: first in path's folder (when path names a regular file, or
 * nothing yet), then in $TMPDIR (when set), then in /tmp; `path` NULL (an
 * image meant for standard output) starts at $TMPDIR, as "image".  The
 * name is claimed by creating it (mode 0600: it may sit in a shared /tmp)
 * and the image is saved over it with rt_image_save (cli_save_options).
 * Prints on stderr "PROGRAM: the image is kept in NAME" and returns 1; or
 * "PROGRAM: the image could not be kept either: REASON" and returns 0.
 */
int cli_keep_image(const char *program, const char *path,
                   const rt_image *image, rt_image_format format);

#endif /* RAYTRACE_CLI_OUTPUT_H */
