/*
 * cli_output.c - nothing written over what was read, and a late failure
 * that keeps the work (see cli_output.h).
 */
#include "cli_output.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli_text.h"

#define SHOWN_NAME 1024         /* a name in a message, escaped */
#define CLAIM_TRIES 100         /* new names tried in one folder */

/* The regular file `path` ("-": standard output) names, links followed. */
static int regular_file(const char *path, struct stat *st)
{
    int found = strcmp(path, "-") == 0 ? fstat(STDOUT_FILENO, st) == 0
                                       : stat(path, st) == 0;
    return found && S_ISREG(st->st_mode);
}

static int same_file(const struct stat *a, const struct stat *b)
{
    return a->st_dev == b->st_dev && a->st_ino == b->st_ino;
}

static int refuse(const char *output, const char *what, const char *input,
                  const char *which, char *message, size_t size)
{
    char shown_output[SHOWN_NAME], shown_input[SHOWN_NAME];
    snprintf(message, size, "%s: refusing to write %s over %s%s (the same "
             "file)",
             cli_printable(strcmp(output, "-") ? output : "<stdout>",
                           shown_output, sizeof shown_output),
             what, cli_printable(input, shown_input, sizeof shown_input),
             which);
    return 1;
}

int cli_output_clash(const char *output, const rt_scene *scene,
                     const char *scene_path, int from_stdin,
                     const char *what, char *message, size_t size)
{
    struct stat out, in;
    if (output == NULL || !regular_file(output, &out))
        return 0;
    if (scene_path != NULL && strcmp(scene_path, "-") != 0 &&
        regular_file(scene_path, &in) && same_file(&out, &in))
        return refuse(output, what, scene_path, ", the scene it comes from",
                      message, size);
    if (from_stdin && fstat(STDIN_FILENO, &in) == 0 && S_ISREG(in.st_mode) &&
        same_file(&out, &in))
        return refuse(output, what, "standard input",
                      ", where the scene was read from", message, size);
    int count = rt_scene_source_count(scene);
    for (int i = 0; i < count; i++) {
        const rt_scene_source *source = rt_scene_source_at(scene, i);
        if ((source->device != 0 || source->inode != 0) &&
            source->device == (uint64_t)out.st_dev &&
            source->inode == (uint64_t)out.st_ino)
            return refuse(output, what, source->name,
                          ", a file the scene read", message, size);
    }
    return 0;
}

int cli_refuse_input_as_output(const char *program, const char *output,
                               const rt_scene *scene, const char *operand,
                               const char *what)
{
    int from_stdin = strcmp(operand, "-") == 0;
    char message[2 * SHOWN_NAME + 128];
    if (!cli_output_clash(output, scene, from_stdin ? NULL : operand,
                          from_stdin, what, message, sizeof message))
        return 0;
    fprintf(stderr, "%s: %s\n", program, message);
    return 1;
}

/* ------------------------------------------------------------------ */
/* Keeping an image whose save failed                                  */

/* Six letters and digits, different at each call. */
static void random_tag(char tag[7])
{
    static const char digits[] = "abcdefghijklmnopqrstuvwxyz"
                                 "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    static uint64_t state;
    struct timespec now;
    clock_gettime(CLOCK_REALTIME, &now);
    state ^= (uint64_t)now.tv_nsec * 0x9e3779b97f4a7c15u ^
             (uint64_t)getpid() << 32 ^ (uint64_t)now.tv_sec;
    for (int i = 0; i < 6; i++) {
        state ^= state << 13; /* xorshift64 */
        state ^= state >> 7;
        state ^= state << 17;
        tag[i] = digits[state % (sizeof digits - 1)];
    }
    tag[6] = '\0';
}

/* Creates a new file FOLDER STEM.rescue-XXXXXX EXT; its name in name[].
 * Returns 1, or 0 with errno set. */
static int claim(const char *folder, const char *stem, const char *ext,
                 char *name, size_t size)
{
    for (int i = 0; i < CLAIM_TRIES; i++) {
        char tag[7];
        random_tag(tag);
        int n = snprintf(name, size, "%s%s" CLI_RESCUE_TAG "%s%s", folder,
                         stem, tag, ext);
        if (n < 0 || (size_t)n >= size) {
            errno = ENAMETOOLONG;
            return 0;
        }
        int fd = open(name, O_WRONLY | O_CREAT | O_EXCL, 0600);
        if (fd >= 0) {
            close(fd);
            return 1;
        }
        if (errno != EEXIST)
            return 0;
    }
    return 0;
}

/* path's base name without its extension ("dir/out.ppm" -> "out"). */
static void stem_of(const char *path, char *stem, size_t size)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t length = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    snprintf(stem, size, "%.*s", (int)length, length ? base : "image");
}

rt_save_options cli_save_options(void)
{
    rt_save_options options;
    rt_save_options_init(&options);
    options.hold_termination_signals = 1;
    return options;
}

int cli_keep_image(const char *program, const char *path,
                   const rt_image *image, rt_image_format format)
{
    char stem[256], folders[3][4096];
    int count = 0;
    struct stat st;
    stem_of(path != NULL ? path : "image", stem, sizeof stem);
    /* next to the output, unless it is a device, a FIFO or a socket */
    if (path != NULL && (stat(path, &st) != 0 || S_ISREG(st.st_mode))) {
        const char *slash = strrchr(path, '/');
        snprintf(folders[count++], sizeof folders[0], "%.*s",
                 slash ? (int)(slash - path + 1) : 0, path);
    }
    const char *tmpdir = getenv("TMPDIR");
    if (tmpdir != NULL && tmpdir[0] != '\0')
        snprintf(folders[count++], sizeof folders[0], "%s%s", tmpdir,
                 tmpdir[strlen(tmpdir) - 1] == '/' ? "" : "/");
    snprintf(folders[count++], sizeof folders[0], "/tmp/");
    const char *ext = format == RT_IMAGE_PNG ? ".png" : ".ppm";
    char reason[RT_ERROR_MESSAGE_SIZE + SHOWN_NAME] = "no folder to try";
    for (int i = 0; i < count; i++) {
        if (i > 0 && strcmp(folders[i], folders[i - 1]) == 0)
            continue;
        char name[4096 + 300], shown[SHOWN_NAME];
        if (!claim(folders[i], stem, ext, name, sizeof name)) {
            snprintf(reason, sizeof reason, "%s: %s",
                     cli_printable(folders[i][0] ? folders[i] : "./", shown,
                                   sizeof shown),
                     strerror(errno));
            continue;
        }
        rt_error error;
        rt_save_options save = cli_save_options();
        if (rt_image_save(name, image, format, &save, &error) == RT_OK) {
            fprintf(stderr, "%s: the image is kept in %s\n", program,
                    cli_printable(name, shown, sizeof shown));
            return 1;
        }
        unlink(name);
        snprintf(reason, sizeof reason, "%s", error.message);
    }
    fprintf(stderr, "%s: the image could not be kept either: %s\n", program,
            reason);
    return 0;
}
