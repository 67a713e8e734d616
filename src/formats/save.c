/*
 * save.c - the one routine that writes a file at a path, for every image
 * format and the scene writer (rt__save; rt_image_save,
 * rt_image_save_check).
 *
 * The rule is stated in raytrace/image.h: what the path names decides how it
 * is written.  Regular files (and names not taken yet) are replaced
 * atomically through a temporary file in the same folder; devices, FIFOs
 * and sockets are streams and are written directly; a descriptor of this
 * process named as a file (/dev/fd/N, /proc/self/fd/N, /dev/stdout, what
 * bash's >(...) passes) is written through that very descriptor, at its
 * offset, so that what the caller wrote before and writes after stays; a
 * multiply linked file is rewritten in place from a complete temporary copy
 * so the links stay one file.  What the path names, its symbolic links
 * followed to the final target, is save_target.c's (rt__save_resolve): the
 * temporary file lands beside that target and the rename replaces it, not
 * the link.  When the caller's rt_save_options ask for it
 * (hold_termination_signals), SIGINT, SIGTERM and SIGHUP are blocked in the
 * calling thread while a temporary file exists and polled between writes,
 * so an interrupted save removes its temporary file first; by default the
 * save leaves the signal mask and the handlers alone.
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stddef.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

#include "base/error.h"
#include "base/sized.h"
#include "formats/formats.h"
#include "formats/save_target.h"
#include "raytrace/image.h"

/* Bytes gathered before each write(2). */
#define BUFFER_SIZE (1 << 16)

/* A buffered sink over a file descriptor that stops when a blocked
 * termination signal is pending (watch_signals). */
typedef struct fd_sink {
    int fd;
    int watch_signals;
    int interrupted;        /* the signal that stopped it, or 0 */
    int error;              /* errno of a failed write, or 0 */
    size_t used;
    unsigned char buffer[BUFFER_SIZE];
} fd_sink;

static const int watched[] = {SIGINT, SIGTERM, SIGHUP};
#define WATCHED_COUNT (sizeof watched / sizeof watched[0])

/* The termination signals that would end or reach the program: those it
 * ignores (a background job's SIGINT, nohup's SIGHUP) cannot interrupt a
 * save. */
static void termination_signals(sigset_t *set)
{
    sigemptyset(set);
    for (size_t i = 0; i < WATCHED_COUNT; i++) {
        struct sigaction action;
        if (sigaction(watched[i], NULL, &action) == 0 &&
            action.sa_handler != SIG_IGN)
            sigaddset(set, watched[i]);
    }
}

/* The termination signals blocked while a temporary file exists, when the
 * options ask (`held`), and the mask to restore. */
typedef struct signal_hold {
    int held;
    sigset_t previous;
} signal_hold;

static void hold_signals(signal_hold *h, int held)
{
    h->held = held;
    if (held) {
        sigset_t signals;
        termination_signals(&signals);
        pthread_sigmask(SIG_BLOCK, &signals, &h->previous);
    }
}

/* Restores the mask: a signal that came meanwhile is delivered now. */
static void release_signals(const signal_hold *h)
{
    if (h->held)
        pthread_sigmask(SIG_SETMASK, &h->previous, NULL);
}

/* A termination signal waiting for this thread or the process, or 0. */
static int pending_termination(void)
{
    sigset_t pending, watching;
    if (sigpending(&pending) != 0)
        return 0;
    termination_signals(&watching);
    for (size_t i = 0; i < WATCHED_COUNT; i++)
        if (sigismember(&pending, watched[i]) == 1 &&
            sigismember(&watching, watched[i]) == 1)
            return watched[i];
    return 0;
}

/* Writes everything, waiting for a descriptor the caller made
 * non-blocking (a write then blocks as on any other stream). */
static int write_all(int fd, const unsigned char *data, size_t size)
{
    while (size > 0) {
        ssize_t n = write(fd, data, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            struct pollfd ready = {.fd = fd, .events = POLLOUT};
            if (poll(&ready, 1, -1) < 0 && errno != EINTR)
                return 0;
            continue;
        }
        if (n <= 0)
            return n == 0 ? (errno = EIO, 0) : 0;
        data += n;
        size -= (size_t)n;
    }
    return 1;
}

static int sink_flush(fd_sink *s)
{
    if (s->watch_signals && (s->interrupted = pending_termination()) != 0)
        return 0;
    if (!write_all(s->fd, s->buffer, s->used)) {
        s->error = errno;
        return 0;
    }
    s->used = 0;
    return 1;
}

static int sink_write(void *user, const void *data, size_t size)
{
    fd_sink *s = user;
    const unsigned char *bytes = data;
    while (size > 0) {
        if (s->used == BUFFER_SIZE && !sink_flush(s))
            return 0;
        size_t n = BUFFER_SIZE - s->used < size ? BUFFER_SIZE - s->used : size;
        memcpy(s->buffer + s->used, bytes, n);
        s->used += n;
        bytes += n;
        size -= n;
    }
    return 1;
}

/* What messages call the producer's bytes. */
static const char *noun_of(const rt_producer *producer)
{
    return producer->noun != NULL ? producer->noun : "image";
}

/* The message for a temporary file that cannot be made in `folder`. */
static rt_status folder_error(rt_error *error, const char *path,
                              const char *folder, int saved,
                              const char *noun)
{
    const char *shown = folder[0] ? folder : "./";
    if (saved == ENOENT)
        return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                             "cannot write the %s: the folder %s does "
                             "not exist", noun, shown);
    if (saved == ENOTDIR)
        return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                             "cannot write the %s: %s is not a folder",
                             noun, shown);
    return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                         "cannot write the %s in the folder %s: %s",
                         noun, shown, strerror(saved));
}

/* The message for a temporary file that cannot be made beside `target`
 * (errno `saved`). */
static rt_status temporary_error(rt_error *error, const char *path,
                                 const char *target, int saved,
                                 const char *noun)
{
    char *folder = rt__save_folder_of(target);
    rt_status status =
        folder ? folder_error(error, path, folder, saved, noun)
               : rt__error_set(error, RT_ERR_NOMEM, path, 0, 0,
                               "out of memory");
    free(folder);
    return status;
}

/*
 * Creates a new file ".rt-save-XXXXXX" in the folder of `target` with mode
 * 0666 (the umask applies, as for any new file).  Returns its descriptor and
 * sets *temp, or -1 with errno set.
 */
static int create_temporary(const char *target, char **temp)
{
    static const char letters[] =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    char *folder = rt__save_folder_of(target);
    char *name = folder ? malloc(strlen(folder) + sizeof ".rt-save-XXXXXX")
                        : NULL;
    if (name == NULL) {
        free(folder);
        errno = ENOMEM;
        return -1;
    }
    struct timespec now;
    clock_gettime(CLOCK_REALTIME, &now);
    uint64_t state = (uint64_t)now.tv_nsec ^ ((uint64_t)now.tv_sec << 20) ^
                     ((uint64_t)getpid() << 40) ^ (uint64_t)(uintptr_t)name;
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; attempt++) {
        char suffix[7];
        for (int i = 0; i < 6; i++) {
            state = state * 6364136223846793005u + 1442695040888963407u;
            suffix[i] = letters[(state >> 33) % (sizeof letters - 1)];
        }
        suffix[6] = '\0';
        sprintf(name, "%s.rt-save-%s", folder, suffix);
        fd = open(name, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY,
                  0666);
        if (fd < 0 && errno != EEXIST)
            break;
    }
    free(folder);
    if (fd < 0) {
        int saved = errno;
        free(name);
        errno = saved;
        return -1;
    }
    *temp = name;
    return fd;
}

/* Gives the temporary file the replaced file's owner, group and mode
 * (owner and group only where the process may; chown first, as it clears
 * set-user-ID bits). */
static void keep_attributes(int fd, const struct stat *old)
{
    struct stat now;
    if (fstat(fd, &now) == 0 &&
        (now.st_uid != old->st_uid || now.st_gid != old->st_gid) &&
        fchown(fd, old->st_uid, old->st_gid) != 0)
        (void)!fchown(fd, (uid_t)-1, old->st_gid);
    (void)fchmod(fd, old->st_mode & 07777);
}

/* Produces the bytes into `s`, flushing the tail; the status says why it
 * stopped. */
static rt_status encode(fd_sink *s, const rt_producer *producer,
                        rt_error *error)
{
    rt_status status = producer->produce(sink_write, s, producer->what,
                                         error);
    if (status == RT_OK && s->used > 0 && !sink_flush(s))
        status = RT_ERR_IO;
    return status;
}

/* The error of a sink that stopped. */
static rt_status sink_error(const fd_sink *s, rt_status status,
                            const char *path, const char *noun,
                            rt_error *error)
{
    if (s->interrupted)
        return rt__error_set(error, RT_ERR_INTERRUPTED, path, 0, 0,
                             "save interrupted by signal %d; the file was "
                             "left as it was", s->interrupted);
    if (status == RT_ERR_IO)
        return rt__save_write_error(error, path, s->error ? s->error : EIO,
                                    noun);
    return status;          /* the encoder filled *error */
}

/* Copies the complete temporary file over the linked file in place, after
 * reserving its space, so the links keep pointing at one file. */
static int copy_in_place(int temp_fd, const char *target, fd_sink *s)
{
    off_t size = lseek(temp_fd, 0, SEEK_END);
    int fd = open(target, O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (size < 0 || fd < 0) {
        s->error = errno;
        if (fd >= 0)
            close(fd);
        return 0;
    }
    int reserved = size == 0 ? 0 : posix_fallocate(fd, 0, size);
    int ok = reserved == 0 || reserved == EINVAL || reserved == EOPNOTSUPP;
    if (!ok)
        s->error = reserved;
    for (off_t at = 0; ok && at < size;) {
        ssize_t n = pread(temp_fd, s->buffer, BUFFER_SIZE, at);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0 || !write_all(fd, s->buffer, (size_t)n)) {
            s->error = n == 0 ? EIO : errno;
            ok = 0;
            break;
        }
        at += n;
    }
    if (ok && (ftruncate(fd, size) != 0 || fsync(fd) != 0))
        ok = 0, s->error = errno;
    if (close(fd) != 0 && ok)
        ok = 0, s->error = errno;
    return ok;
}

/* Makes a rename durable: syncs the folder (best effort; some file systems
 * refuse fsync on a folder). */
static void sync_folder(const char *target)
{
    char *folder = rt__save_folder_of(target);
    if (folder == NULL)
        return;
    int fd = open(folder[0] ? folder : ".", O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
    free(folder);
}

/* Nothing there or a regular file: through a temporary file, the
 * termination signals held meanwhile when `hold`. */
static rt_status save_through_temporary(const char *path,
                                        const rt_save_target *d,
                                        const rt_producer *producer, int hold,
                                        rt_error *error)
{
    fd_sink *s = malloc(sizeof *s);
    if (s == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, path, 0, 0,
                             "out of memory");
    signal_hold signals;
    hold_signals(&signals, hold);

    rt_status status = RT_OK;
    char *temp = NULL;
    int fd = create_temporary(d->path, &temp);
    if (fd < 0) {
        status = temporary_error(error, path, d->path, errno,
                                 noun_of(producer));
        release_signals(&signals);
        free(s);
        return status;
    }
    *s = (fd_sink){.fd = fd, .watch_signals = hold};
    if (d->kind == RT__TARGET_REGULAR)
        keep_attributes(fd, &d->st);
    status = encode(s, producer, error);
    if (status == RT_OK && fsync(fd) != 0)
        status = RT_ERR_IO, s->error = errno;
    if (status == RT_OK && hold &&
        (s->interrupted = pending_termination()) != 0)
        status = RT_ERR_IO;
    if (status == RT_OK && d->kind == RT__TARGET_LINKED &&
        !copy_in_place(fd, d->path, s))
        status = RT_ERR_IO;
    if (close(fd) != 0 && status == RT_OK)
        status = RT_ERR_IO, s->error = errno;
    if (status == RT_OK && d->kind != RT__TARGET_LINKED) {
        if (rename(temp, d->path) != 0)
            status = RT_ERR_IO, s->error = errno;
        else
            sync_folder(d->path);
    }
    if (status != RT_OK || d->kind == RT__TARGET_LINKED)
        unlink(temp);
    if (status != RT_OK)
        status = sink_error(s, status, path, noun_of(producer), error);
    free(temp);
    free(s);
    /* A signal that came meanwhile is delivered now, the file in order. */
    release_signals(&signals);
    return status;
}

/* "cannot open for writing: reason" for errno. */
static rt_status cannot_open(rt_error *error, const char *path)
{
    return rt__save_io_error(error, path, errno, "cannot open for writing");
}

/* Opens a Unix socket's listener as a stream, or -1 with errno set. */
static int connect_socket(const char *path)
{
    struct sockaddr_un address = {.sun_family = AF_UNIX};
    if (strlen(path) >= sizeof address.sun_path) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(address.sun_path, path);
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd >= 0 && connect(fd, (struct sockaddr *)&address,
                           sizeof address) != 0) {
        int saved = errno;
        close(fd);
        errno = saved;
        fd = -1;
    }
    return fd;
}

/* Writes the bytes to descriptor `fd` as a stream, closing it when `owned`
 * (a descriptor of the caller's stays open). */
static rt_status stream_to(int fd, int owned, const char *path,
                           const rt_producer *producer, rt_error *error)
{
    fd_sink *s = malloc(sizeof *s);
    if (s == NULL) {
        if (owned)
            close(fd);
        return rt__error_set(error, RT_ERR_NOMEM, path, 0, 0,
                             "out of memory");
    }
    *s = (fd_sink){.fd = fd};
    rt_status status = encode(s, producer, error);
    if (owned && close(fd) != 0 && status == RT_OK)
        status = RT_ERR_IO, s->error = errno;
    if (status != RT_OK)
        status = sink_error(s, status, path, noun_of(producer), error);
    free(s);
    return status;
}

/* A device, FIFO, socket or another process's descriptor: opened and
 * written as a stream. */
static rt_status save_to_stream(const char *path, const rt_save_target *d,
                                const rt_producer *producer, rt_error *error)
{
    /* A regular file behind another process's /proc/PID/fd/N is rewritten
     * from its start: its offset is that process's. */
    int truncate = d->kind == RT__TARGET_STREAM && S_ISREG(d->st.st_mode);
    int fd = d->kind == RT__TARGET_SOCKET
                 ? connect_socket(d->path)
                 : open(d->path, O_WRONLY | O_CLOEXEC | O_NOCTTY |
                                     (truncate ? O_TRUNC : 0));
    if (fd < 0)
        return cannot_open(error, path);
    return stream_to(fd, 1, path, producer, error);
}

static int valid_image(const rt_image *image)
{
    return image != NULL && image->pixels != NULL && image->width > 0 &&
           image->height > 0 && image->stride >= (size_t)image->width * 3;
}

void rt_save_options_init(rt_save_options *options)
{
    if (options == NULL)
        return;
    memset(options, 0, sizeof *options);
    options->size = sizeof *options;
}

/* Copies the caller's options into *out as far as the caller's size
 * reaches; later fields keep their defaults (raytrace/render.h's rule for
 * growing option structs).  NULL: the defaults. */
static rt_status take_options(const rt_save_options *in, rt_save_options *out,
                              const char *path, rt_error *error)
{
    rt_save_options_init(out);
    if (in == NULL)
        return RT_OK;
    rt_status status = rt__options_size_check(in->size, sizeof *out, "save",
                                              path, error);
    if (status == RT_OK)
        RT__TAKE_FIELD(rt_save_options, in, out, hold_termination_signals)
    return status;
}

/* The start of every save and check of `path`: the caller's options taken
 * into *o and the destination resolved into *d (whose path is NULL, or
 * the caller's to free, whatever the status). */
static rt_status take_target(const char *path,
                             const rt_save_options *options,
                             const char *noun, rt_save_options *o,
                             rt_save_target *d, rt_error *error)
{
    memset(d, 0, sizeof *d);
    rt_status status = take_options(options, o, path, error);
    if (status != RT_OK)
        return status;
    return rt__save_resolve(path, d, noun, error);
}

rt_status rt__save(const char *path, const rt_producer *producer,
                   const rt_save_options *options, rt_error *error)
{
    if (path == NULL || path[0] == '\0' || producer == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, path, 0, 0,
                             "expected a path");
    rt_save_options o;
    rt_save_target d;
    rt_status status = take_target(path, options, noun_of(producer), &o, &d,
                                   error);
    /* A descriptor of this process: written through it, at its offset (at
     * the end when it appends), and left open; nothing is truncated or
     * replaced, so what the caller wrote before and writes after stays
     * around the bytes. */
    if (status == RT_OK && d.kind == RT__TARGET_DESCRIPTOR)
        status = stream_to(d.fd, 0, path, producer, error);
    else if (status == RT_OK)
        status = d.kind == RT__TARGET_STREAM || d.kind == RT__TARGET_SOCKET
                     ? save_to_stream(path, &d, producer, error)
                     : save_through_temporary(path, &d, producer,
                                              o.hold_termination_signals,
                                              error);
    free(d.path);
    return status;
}

/* What rt_image_save hands the save: an image and its format. */
typedef struct image_bytes {
    const rt_image *image;
    rt_image_format format;
} image_bytes;

static rt_status produce_image(rt_write_func write, void *user,
                               const void *what, rt_error *error)
{
    const image_bytes *b = what;
    return rt_image_write_to(write, user, b->image, b->format, error);
}

rt_status rt_image_save(const char *path, const rt_image *image,
                        rt_image_format format,
                        const rt_save_options *options, rt_error *error)
{
    if (path == NULL || path[0] == '\0' || !valid_image(image))
        return rt__error_set(error, RT_ERR_ARGUMENT, path, 0, 0,
                             "expected a path and an image");
    if (!rt_image_format_supported(format))
        return rt__image_format_refusal(format, error);
    image_bytes bytes = {image, format};
    rt_producer producer = {produce_image, &bytes, "image"};
    return rt__save(path, &producer, options, error);
}

rt_status rt_image_save_check(const char *path,
                              const rt_save_options *options,
                              rt_error *error)
{
    if (path == NULL || path[0] == '\0')
        return rt__error_set(error, RT_ERR_ARGUMENT, path, 0, 0,
                             "expected a path");
    rt_save_options o;
    rt_save_target d;
    rt_status status = take_target(path, options, "image", &o, &d, error);
    if (status != RT_OK) {
        free(d.path);
        return status;
    }
    int fd = -1;
    if (d.kind == RT__TARGET_DESCRIPTOR) {
        /* rt__save_resolve() found it open for writing: nothing more to try */
    } else if (d.kind == RT__TARGET_STREAM && !S_ISFIFO(d.st.st_mode)) {
        fd = open(d.path, O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
        if (fd < 0)
            status = cannot_open(error, path);
    } else if (d.kind == RT__TARGET_STREAM || d.kind == RT__TARGET_SOCKET) {
        /* A FIFO would wait for its reader: its permission is enough. */
        if (access(d.path, W_OK) != 0)
            status = cannot_open(error, path);
    } else {
        if (d.kind == RT__TARGET_LINKED &&
            (fd = open(d.path, O_WRONLY | O_CLOEXEC | O_NOCTTY)) < 0)
            status = cannot_open(error, path);
        /* The probe exists only between two calls: when the options hold
         * the signals, none may end the program in between, leaving it
         * behind. */
        signal_hold signals;
        hold_signals(&signals, o.hold_termination_signals);
        char *temp = NULL;
        int probe = status == RT_OK ? create_temporary(d.path, &temp) : 0;
        if (probe < 0) {
            status = temporary_error(error, path, d.path, errno, "image");
        } else if (status == RT_OK) {
            close(probe);
            unlink(temp);
            free(temp);
        }
        release_signals(&signals);
    }
    if (fd >= 0)
        close(fd);
    free(d.path);
    return status;
}
