/*
 * test_save.c - rt_image_save and rt_image_save_check: each rule
 * stated at the top of raytrace/image.h, checked by what the path names
 * afterwards (lstat, the bytes, the folder's listing); PNG decoded back with
 * libpng; the format chosen from an extension.
 *
 * One program, two suites.  Without arguments it runs what any user can
 * check (ctest: test_save).  With the argument `privileged` it runs what
 * needs root in a private mount namespace: a /dev of its own on a tmpfs
 * (null, full, stdout), read-only mounts, a file of another owner (ctest:
 * test_save_privileged); when the process cannot unshare, mount, mknod and
 * chown, it says why and exits 77, which ctest shows as a skip.
 *
 * Whatever changes the process (umask, signal dispositions, user, mount
 * namespace, standard output) happens in a forked child that reports through
 * a pipe and calls no Check function, so the suites also hold under
 * CK_FORK=no (valgrind).  Under RT_TEST_MEMCHECK the signal tests save a
 * smaller image.
 */
#define _GNU_SOURCE 1

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <grp.h>
#include <limits.h>
#include <sched.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#if RT_TEST_HAVE_LIBPNG
#include <png.h>
#endif

#include "testutil.h"

/* The user and group "nobody" on Debian and most systems. */
#define NOBODY 65534

/* What a file held before a save: recognisably not an image written here. */
static const char old_content[] = "P3\n1 1\n255\n9 8 7\n";

/* ------------------------------------------------------------------ */
/* Paths, files and folders                                             */

typedef struct path_t {
    char s[PATH_MAX];
} path_t;

static path_t at(const char *dir, const char *name)
{
    path_t p;
    int n = snprintf(p.s, sizeof p.s, "%s/%s", dir, name);
    ck_assert(n > 0 && (size_t)n < sizeof p.s);
    return p;
}

/* A new empty folder of mode 0700 under $TMPDIR or /tmp. */
static path_t scratch(void)
{
    const char *base = getenv("TMPDIR");
    path_t p = at(base && *base ? base : "/tmp", "rt-test-save-XXXXXX");
    ck_assert_msg(mkdtemp(p.s) != NULL, "mkdtemp: %s", strerror(errno));
    return p;
}

static int remove_entry(const char *path, const struct stat *st, int type,
                        struct FTW *walk)
{
    (void)st;
    (void)type;
    (void)walk;
    remove(path);
    return 0;
}

static void remove_tree(const path_t *dir)
{
    chmod(dir->s, 0700);
    nftw(dir->s, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

static void put(const char *path, const void *data, size_t size)
{
    FILE *file = fopen(path, "wb");
    ck_assert_msg(file != NULL, "%s: %s", path, strerror(errno));
    ck_assert_uint_eq(fwrite(data, 1, size, file), size);
    ck_assert_int_eq(fclose(file), 0);
}

/* Non-zero when the file at `path` holds exactly `size` bytes `data`. */
static int holds(const char *path, const void *data, size_t size)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return 0;
    const unsigned char *expected = data;
    unsigned char chunk[65536];
    size_t seen = 0;
    int same = 1;
    ssize_t n;
    while (same && (n = read(fd, chunk, sizeof chunk)) > 0) {
        same = seen + (size_t)n <= size &&
               memcmp(chunk, expected + seen, (size_t)n) == 0;
        seen += (size_t)n;
    }
    close(fd);
    return same && seen == size;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The names in `dir` (hidden ones too, not . and ..), sorted, joined by
 * spaces into `out`; "?" when the folder cannot be read. */
static void names_in(const char *dir, char *out, size_t size)
{
    snprintf(out, size, "?");
    DIR *d = opendir(dir);
    if (d == NULL)
        return;
    char *names[64];
    size_t count = 0;
    struct dirent *entry;
    while ((entry = readdir(d)) != NULL && count < 64)
        if (strcmp(entry->d_name, ".") && strcmp(entry->d_name, ".."))
            names[count++] = strdup(entry->d_name);
    closedir(d);
    qsort(names, count, sizeof names[0], by_name);
    out[0] = '\0';
    for (size_t i = 0; i < count; i++) {
        size_t used = strlen(out);
        snprintf(out + used, size - used, "%s%s", i ? " " : "",
                 names[i] ? names[i] : "?");
        free(names[i]);
    }
}

static void assert_names(const char *dir, const char *expected)
{
    char names[4096];
    names_in(dir, names, sizeof names);
    ck_assert_msg(strcmp(names, expected) == 0,
                  "%s holds `%s`, expected `%s` (a temporary file left, or "
                  "something created or replaced?)", dir, names, expected);
}

static mode_t kind_of(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 ? st.st_mode & S_IFMT : 0;
}

static void assert_link(const char *path, const char *target)
{
    char text[PATH_MAX];
    ssize_t n = readlink(path, text, sizeof text - 1);
    ck_assert_msg(n >= 0, "%s is no longer a symbolic link", path);
    text[n] = '\0';
    ck_assert_msg(strcmp(text, target) == 0,
                  "%s now points at `%s`, was `%s`", path, text, target);
}

/* ------------------------------------------------------------------ */
/* Images and their bytes                                               */

typedef rt_test_bytes bytes;

static int count_bytes(void *user, const void *data, size_t size)
{
    (void)data;
    *(size_t *)user += size;
    return 1;
}

/* A width x height image where every channel takes many values. */
static rt_status make_pattern(rt_image *image, int width, int height)
{
    rt_status status = rt_image_init(image, width, height, NULL);
    for (int y = 0; status == RT_OK && y < height; y++)
        for (int x = 0; x < width; x++) {
            unsigned char *p = rt_image_pixel(image, x, y);
            p[0] = (unsigned char)(x * 37 + y * 11);
            p[1] = (unsigned char)(x == y ? 255 : x * y);
            p[2] = (unsigned char)((x + y) % 3 ? 255 - x : y);
        }
    return status;
}

static rt_image pattern(int width, int height)
{
    rt_image image;
    ck_assert_int_eq(make_pattern(&image, width, height), RT_OK);
    return image;
}

static bytes encode(const rt_image *image, rt_image_format format)
{
    bytes b = {NULL, 0, 0};
    rt_error error = {0};
    rt_status status = rt_image_write_to(rt_test_bytes_add, &b, image,
                                         format, &error);
    ck_assert_msg(status == RT_OK, "rt_image_write_to: %s", error.message);
    return b;
}

static void save_ok(const char *path, const rt_image *image,
                    rt_image_format format)
{
    rt_error error = {0};
    rt_status status = rt_image_save(path, image, format, &error);
    ck_assert_msg(status == RT_OK, "saving to %s returned %s: %s", path,
                  rt_status_string(status), error.message);
}

/* Saves a small image at `path`, which must fail with RT_ERR_IO and a
 * message that names `path` and says `reason`; returns the message. */
static void save_refused(const char *path, const char *reason,
                         rt_error *error)
{
    rt_image image = pattern(6, 4);
    memset(error, 0, sizeof *error);
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6, error);
    rt_image_release(&image);
    ck_assert_msg(status == RT_ERR_IO, "saving to %s returned %s, expected "
                  "an input/output error", path, rt_status_string(status));
    ck_assert_int_eq(error->status, RT_ERR_IO);
    ck_assert_msg(strstr(error->message, path) != NULL,
                  "the message does not name %s: %s", path, error->message);
    ck_assert_msg(strstr(error->message, reason) != NULL,
                  "the message does not say `%s`: %s", reason,
                  error->message);
}

/* ------------------------------------------------------------------ */
/* Child processes                                                      */

/*
 * A job runs in a forked child; it returns the child's exit status and may
 * leave a line for the parent in `note`.  It calls no Check function (under
 * CK_FORK=no a failing assertion there would go on running the suite in the
 * child).
 */
typedef int (*job_fn)(void *arg, char *note, size_t size);

typedef struct child {
    pid_t pid;              /* -1 when fork or pipe failed */
    int note_fd;
} child;

static child start(job_fn job, void *arg)
{
    child c = {-1, -1};
    int fds[2];
    if (pipe(fds) != 0)
        return c;
    fflush(NULL);
    c.pid = fork();
    if (c.pid == 0) {
        close(fds[0]);
        char note[1024] = "";
        int code = job(arg, note, sizeof note);
        if (write(fds[1], note, strlen(note)) < 0)
            code = 99;
        _exit(code);
    }
    close(fds[1]);
    c.note_fd = fds[0];
    if (c.pid < 0)
        close(fds[0]);
    return c;
}

/* Reads the child's note and reaps it; returns its wait status. */
static int finish(child c, char *note, size_t size)
{
    size_t used = 0;
    ssize_t n;
    while (used + 1 < size &&
           (n = read(c.note_fd, note + used, size - used - 1)) > 0)
        used += (size_t)n;
    note[used] = '\0';
    close(c.note_fd);
    int status = -1;
    while (waitpid(c.pid, &status, 0) < 0 && errno == EINTR)
        ;
    return status;
}

/* Runs `job` to its end: its exit code, or 128 + the signal that ended
 * it. */
static int run_job(job_fn job, void *arg, char *note, size_t size)
{
    child c = start(job, arg);
    ck_assert_msg(c.pid > 0, "fork: %s", strerror(errno));
    int status = finish(c, note, size);
    return WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                               : WEXITSTATUS(status);
}

/* Writes the note for the parent and returns `code`. */
static int say(int code, char *note, size_t size, const char *format, ...)
    __attribute__((format(printf, 4, 5)));

static int say(int code, char *note, size_t size, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(note, size, format, args);
    va_end(args);
    return code;
}

/* Copies a stream into a file: from the path `from` (opened for reading,
 * as a FIFO's reader does) or from the descriptor `from_fd`. */
typedef struct copy_args {
    const char *from;
    int from_fd;
    int also_close;         /* a descriptor the copier must not keep, or -1 */
    const char *to;
} copy_args;

static int copy_job(void *arg, char *note, size_t size)
{
    const copy_args *a = arg;
    alarm(rt_test_memcheck() ? 600 : 60);     /* a save that never comes */
    if (a->also_close >= 0)
        close(a->also_close);
    int in = a->from ? open(a->from, O_RDONLY) : a->from_fd;
    int out = open(a->to, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || out < 0)
        return say(1, note, size, "copier: cannot open: %s",
                      strerror(errno));
    char chunk[16384];
    ssize_t n;
    while ((n = read(in, chunk, sizeof chunk)) > 0)
        if (write(out, chunk, (size_t)n) != n)
            return say(1, note, size, "copier: write: %s", strerror(errno));
    if (n < 0)
        return say(1, note, size, "copier: read: %s", strerror(errno));
    return close(out) == 0 ? 0 : say(1, note, size, "copier: close failed");
}

/* Accepts one connection on a listening socket and copies it to a file. */
typedef struct accept_args {
    int listener;
    const char *to;
} accept_args;

static int accept_job(void *arg, char *note, size_t size)
{
    const accept_args *a = arg;
    alarm(rt_test_memcheck() ? 600 : 60);
    int connection = accept(a->listener, NULL, NULL);
    if (connection < 0)
        return say(1, note, size, "accept: %s", strerror(errno));
    copy_args copy = {NULL, connection, a->listener, a->to};
    return copy_job(&copy, note, size);
}

/* ------------------------------------------------------------------ */
/* What the path names: regular files, modes, links                     */

typedef struct umask_case {
    const char *path;
    mode_t mask;
} umask_case;

static int save_with_umask(void *arg, char *note, size_t size)
{
    const umask_case *c = arg;
    umask(c->mask);
    rt_image image;
    if (make_pattern(&image, 5, 3) != RT_OK)
        return say(1, note, size, "no memory for the image");
    rt_error error = {0};
    rt_status status = rt_image_save(c->path, &image, RT_IMAGE_P6, &error);
    rt_image_release(&image);
    return status == RT_OK ? 0 : say(1, note, size, "%s", error.message);
}

START_TEST(a_new_file_gets_0666_minus_the_umask)
{
    static const mode_t masks[] = {077, 022, 002, 027};
    path_t dir = scratch();
    rt_image image = pattern(5, 3);
    bytes expected = encode(&image, RT_IMAGE_P6);
    for (size_t i = 0; i < sizeof masks / sizeof masks[0]; i++) {
        char name[32];
        snprintf(name, sizeof name, "umask-%03o.ppm", (unsigned)masks[i]);
        path_t path = at(dir.s, name);
        umask_case c = {path.s, masks[i]};
        char note[1024];
        int code = run_job(save_with_umask, &c, note, sizeof note);
        ck_assert_msg(code == 0, "umask %03o: %s", (unsigned)masks[i], note);
        struct stat st;
        ck_assert_int_eq(lstat(path.s, &st), 0);
        ck_assert(S_ISREG(st.st_mode));
        ck_assert_msg((st.st_mode & 07777) == (0666 & ~masks[i]),
                      "umask %03o gave mode %04o, expected %04o",
                      (unsigned)masks[i], (unsigned)(st.st_mode & 07777),
                      (unsigned)(0666 & ~masks[i]));
        ck_assert(holds(path.s, expected.data, expected.size));
    }
    assert_names(dir.s, "umask-002.ppm umask-022.ppm umask-027.ppm "
                        "umask-077.ppm");
    free(expected.data);
    rt_image_release(&image);
    remove_tree(&dir);
}
END_TEST

START_TEST(a_replaced_file_keeps_its_permission_bits)
{
    static const mode_t modes[] = {0600, 0640, 0604, 0755, 0444};
    path_t dir = scratch();
    path_t path = at(dir.s, "kept.ppm");
    rt_image image = pattern(9, 7);
    bytes expected = encode(&image, RT_IMAGE_P3);
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        unlink(path.s);
        put(path.s, old_content, sizeof old_content - 1);
        ck_assert_int_eq(chmod(path.s, modes[i]), 0);
        save_ok(path.s, &image, RT_IMAGE_P3);
        struct stat st;
        ck_assert_int_eq(lstat(path.s, &st), 0);
        ck_assert_msg((st.st_mode & 07777) == modes[i],
                      "a file of mode %04o came back %04o", (unsigned)modes[i],
                      (unsigned)(st.st_mode & 07777));
        ck_assert(holds(path.s, expected.data, expected.size));
        assert_names(dir.s, "kept.ppm");
    }
    free(expected.data);
    rt_image_release(&image);
    remove_tree(&dir);
}
END_TEST

/* The old file is longer than the image, so a copy in place that does not
 * truncate leaves a tail behind. */
START_TEST(a_file_with_two_hard_links_stays_one_file_holding_the_image)
{
    path_t dir = scratch();
    path_t first = at(dir.s, "first.ppm"), second = at(dir.s, "second.ppm");
    char long_old[5000];
    memset(long_old, '#', sizeof long_old);
    put(first.s, long_old, sizeof long_old);
    ck_assert_int_eq(link(first.s, second.s), 0);
    struct stat before;
    ck_assert_int_eq(stat(first.s, &before), 0);

    rt_image image = pattern(20, 10);
    bytes expected = encode(&image, RT_IMAGE_P6);
    ck_assert_uint_lt(expected.size, sizeof long_old);
    save_ok(first.s, &image, RT_IMAGE_P6);

    struct stat a, b;
    ck_assert_int_eq(lstat(first.s, &a), 0);
    ck_assert_int_eq(lstat(second.s, &b), 0);
    ck_assert_msg(a.st_ino == b.st_ino && a.st_ino == before.st_ino,
                  "the links were split (inodes %lu and %lu, was %lu)",
                  (unsigned long)a.st_ino, (unsigned long)b.st_ino,
                  (unsigned long)before.st_ino);
    ck_assert_uint_eq(a.st_nlink, 2);
    ck_assert_msg(holds(second.s, expected.data, expected.size),
                  "the other name does not hold the image (%ld bytes)",
                  (long)b.st_size);
    assert_names(dir.s, "first.ppm second.ppm");
    free(expected.data);
    rt_image_release(&image);
    remove_tree(&dir);
}
END_TEST

START_TEST(symbolic_links_stay_and_their_final_target_gets_the_image)
{
    path_t dir = scratch();
    path_t target = at(dir.s, "target.ppm");
    path_t sub = at(dir.s, "sub"), other = at(dir.s, "other");
    path_t final = at(dir.s, "other/final.ppm");
    ck_assert_int_eq(mkdir(sub.s, 0755), 0);
    ck_assert_int_eq(mkdir(other.s, 0755), 0);
    put(target.s, old_content, sizeof old_content - 1);
    ck_assert_int_eq(chmod(target.s, 0640), 0);
    put(final.s, old_content, sizeof old_content - 1);

    /* link name, what it holds, where the chain finally leads */
    struct {
        const char *name;
        char text[PATH_MAX];
        const char *lands;
    } links[] = {
        {"relative", "target.ppm", target.s},
        {"absolute", "", target.s},
        {"second", "target.ppm", target.s},
        {"first", "second", target.s},        /* a chain of two */
        {"sub/up", "../target.ppm", target.s}, /* relative to its folder */
        {"other/hop", "final.ppm", final.s},
        {"sub/across", "../other/hop", final.s},
    };
    snprintf(links[1].text, sizeof links[1].text, "%s", target.s);
    size_t count = sizeof links / sizeof links[0];
    for (size_t i = 0; i < count; i++)
        ck_assert_int_eq(symlink(links[i].text, at(dir.s, links[i].name).s),
                         0);

    for (size_t i = 0; i < count; i++) {
        path_t link = at(dir.s, links[i].name);
        rt_image image = pattern(4 + (int)i, 3);  /* a new image each time */
        bytes expected = encode(&image, RT_IMAGE_P6);
        save_ok(link.s, &image, RT_IMAGE_P6);
        for (size_t j = 0; j < count; j++)
            assert_link(at(dir.s, links[j].name).s, links[j].text);
        ck_assert_msg(kind_of(links[i].lands) == S_IFREG &&
                          holds(links[i].lands, expected.data, expected.size),
                      "saving through %s did not put the image in %s",
                      link.s, links[i].lands);
        free(expected.data);
        rt_image_release(&image);
    }
    struct stat st;
    ck_assert_int_eq(stat(target.s, &st), 0);
    ck_assert_uint_eq(st.st_mode & 07777, 0640);
    assert_names(dir.s, "absolute first other relative second sub "
                        "target.ppm");
    assert_names(sub.s, "across up");
    assert_names(other.s, "final.ppm hop");
    remove_tree(&dir);
}
END_TEST

START_TEST(a_dangling_link_gets_its_target_created_in_the_existing_folder)
{
    path_t dir = scratch();
    path_t sub = at(dir.s, "sub"), link = at(dir.s, "dangling");
    path_t created = at(dir.s, "sub/new.ppm");
    ck_assert_int_eq(mkdir(sub.s, 0755), 0);
    ck_assert_int_eq(symlink("sub/new.ppm", link.s), 0);
    rt_image image = pattern(11, 5);
    bytes expected = encode(&image, RT_IMAGE_P3);
    save_ok(link.s, &image, RT_IMAGE_P3);
    assert_link(link.s, "sub/new.ppm");
    ck_assert_msg(kind_of(created.s) == S_IFREG &&
                      holds(created.s, expected.data, expected.size),
                  "%s does not hold the image", created.s);
    assert_names(dir.s, "dangling sub");
    assert_names(sub.s, "new.ppm");
    free(expected.data);
    rt_image_release(&image);
    remove_tree(&dir);
}
END_TEST

START_TEST(a_loop_of_links_is_an_io_error_naming_the_path)
{
    path_t dir = scratch();
    path_t one = at(dir.s, "one"), two = at(dir.s, "two");
    path_t self = at(dir.s, "self");
    ck_assert_int_eq(symlink("two", one.s), 0);
    ck_assert_int_eq(symlink("one", two.s), 0);
    ck_assert_int_eq(symlink("self", self.s), 0);
    const char *paths[] = {one.s, self.s};
    for (int i = 0; i < 2; i++) {
        rt_error error;
        save_refused(paths[i], strerror(ELOOP), &error);
        rt_error check = {0};
        ck_assert_int_eq(rt_image_save_check(paths[i], &check), RT_ERR_IO);
        ck_assert_str_eq(check.message, error.message);
    }
    assert_link(one.s, "two");
    assert_link(two.s, "one");
    assert_link(self.s, "self");
    assert_names(dir.s, "one self two");
    remove_tree(&dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Streams: FIFO and socket                                             */

/*
 * Saves a 300 x 200 P6 image (180 KB, more than a pipe holds, so the save
 * must stream while the other side reads) to dir/`name`, a FIFO or socket
 * made by the caller, which `job` (given `arg`) reads into `received`.  The
 * save must succeed, the reader get exactly the image's bytes, and `name`
 * stay what it was, alone in its folder.
 */
static void assert_streamed(const path_t *dir, const char *name,
                            job_fn job, void *arg, const char *received)
{
    path_t path = at(dir->s, name);
    mode_t kind = kind_of(path.s);
    rt_image image = pattern(300, 200);
    bytes expected = encode(&image, RT_IMAGE_P6);
    child reader = start(job, arg);
    ck_assert_int_gt(reader.pid, 0);
    rt_error error = {0};
    rt_status status = rt_image_save(path.s, &image, RT_IMAGE_P6, &error);
    rt_image_release(&image);
    if (kind_of(path.s) != kind)
        kill(reader.pid, SIGKILL);  /* it waits for a writer that is gone */
    char note[1024];
    int wait_status = finish(reader, note, sizeof note);

    ck_assert_msg(kind_of(path.s) == kind, "%s was replaced", path.s);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    ck_assert_msg(WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0,
                  "the reader failed (wait status %#x): %s", wait_status,
                  note);
    ck_assert_msg(holds(received, expected.data, expected.size),
                  "the reader did not get exactly the image's %zu bytes",
                  expected.size);
    assert_names(dir->s, name);
    free(expected.data);
}

START_TEST(a_fifo_is_streamed_to_its_reader_and_stays_a_fifo)
{
    path_t dir = scratch(), elsewhere = scratch();
    path_t fifo = at(dir.s, "fifo"), received = at(elsewhere.s, "received");
    ck_assert_int_eq(mkfifo(fifo.s, 0600), 0);
    copy_args copy = {fifo.s, -1, -1, received.s};
    assert_streamed(&dir, "fifo", copy_job, &copy, received.s);
    remove_tree(&dir);
    remove_tree(&elsewhere);
}
END_TEST

START_TEST(a_unix_socket_is_streamed_to_its_listener_and_stays)
{
    path_t dir = scratch(), elsewhere = scratch();
    path_t socket_path = at(dir.s, "socket");
    path_t received = at(elsewhere.s, "received");
    struct sockaddr_un address = {.sun_family = AF_UNIX};
    ck_assert_uint_lt(strlen(socket_path.s), sizeof address.sun_path);
    strcpy(address.sun_path, socket_path.s);
    int listener = socket(AF_UNIX, SOCK_STREAM, 0);
    ck_assert_int_ge(listener, 0);
    ck_assert_int_eq(bind(listener, (struct sockaddr *)&address,
                          sizeof address), 0);
    ck_assert_int_eq(listen(listener, 1), 0);
    accept_args args = {listener, received.s};
    assert_streamed(&dir, "socket", accept_job, &args, received.s);
    close(listener);
    remove_tree(&dir);
    remove_tree(&elsewhere);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Refusals: directory, missing folder, folder without write permission */

START_TEST(a_directory_is_refused_as_a_directory_and_nothing_is_created)
{
    path_t dir = scratch();
    path_t folder = at(dir.s, "image.ppm"), link = at(dir.s, "link");
    ck_assert_int_eq(mkdir(folder.s, 0755), 0);
    put(at(folder.s, "keep").s, "k", 1);
    ck_assert_int_eq(symlink("image.ppm", link.s), 0);
    rt_error error;
    save_refused(folder.s, "is a directory", &error);
    save_refused(link.s, "is a directory", &error);
    assert_link(link.s, "image.ppm");
    assert_names(dir.s, "image.ppm link");
    assert_names(folder.s, "keep");
    remove_tree(&dir);
}
END_TEST

START_TEST(a_missing_folder_is_named_in_the_error_and_nothing_is_created)
{
    path_t dir = scratch();
    path_t missing = at(dir.s, "missing"), deep = at(dir.s, "a/b/c");
    path_t link = at(dir.s, "link");
    ck_assert_int_eq(symlink("nowhere/new.ppm", link.s), 0);
    rt_error error;
    save_refused(at(missing.s, "out.ppm").s, "does not exist", &error);
    ck_assert_msg(strstr(error.message, missing.s) != NULL,
                  "the message does not name the folder: %s", error.message);
    save_refused(at(deep.s, "out.ppm").s, "does not exist", &error);
    ck_assert_msg(strstr(error.message, deep.s) != NULL,
                  "the message does not name the folder: %s", error.message);
    save_refused(link.s, "does not exist", &error);
    ck_assert_msg(strstr(error.message, "nowhere") != NULL,
                  "the message does not name the link's folder: %s",
                  error.message);
    assert_link(link.s, "nowhere/new.ppm");
    assert_names(dir.s, "link");
    remove_tree(&dir);
}
END_TEST

/* Saves and checks in a folder the process may not write to; as root, the
 * child first becomes nobody (root writes anywhere permissions apply). */
static int save_without_permission(void *arg, char *note, size_t size)
{
    const char *dir = arg;
    if (geteuid() == 0 && (setgroups(0, NULL) != 0 || setgid(NOBODY) != 0 ||
                           setuid(NOBODY) != 0))
        return say(3, note, size, "cannot become user %d: %s",
                   NOBODY, strerror(errno));
    rt_image image;
    if (make_pattern(&image, 4, 4) != RT_OK)
        return say(1, note, size, "no memory for the image");
    const char *names[] = {"new.ppm", "old.ppm"};
    for (int i = 0; i < 2; i++) {
        path_t path = at(dir, names[i]);
        rt_error error = {0}, check = {0};
        rt_status status = rt_image_save(path.s, &image, RT_IMAGE_P6, &error);
        rt_status checked = rt_image_save_check(path.s, &check);
        if (status != RT_ERR_IO || !strstr(error.message, path.s) ||
            !strstr(error.message, strerror(EACCES))) {
            rt_image_release(&image);
            return say(1, note, size, "saving %s: %s, `%s`", path.s,
                          rt_status_string(status), error.message);
        }
        if (checked != RT_ERR_IO || strcmp(check.message, error.message)) {
            rt_image_release(&image);
            return say(1, note, size, "checking %s: %s, `%s`", path.s,
                          rt_status_string(checked), check.message);
        }
    }
    rt_image_release(&image);
    return 0;
}

START_TEST(a_folder_without_write_permission_is_refused_and_left_as_it_was)
{
    path_t dir = scratch();
    path_t old = at(dir.s, "old.ppm");
    put(old.s, old_content, sizeof old_content - 1);
    if (geteuid() == 0)
        ck_assert_int_eq(chown(dir.s, NOBODY, NOBODY), 0);
    ck_assert_int_eq(chmod(dir.s, 0555), 0);
    char note[1024];
    int code = run_job(save_without_permission, dir.s, note, sizeof note);
    chmod(dir.s, 0700);
    if (code == 3) {
        fprintf(stderr, "test_save: read-only folder skipped here (%s); "
                        "test_save_privileged checks a read-only mount\n",
                note);
    } else {
        ck_assert_msg(code == 0, "%s", note);
    }
    ck_assert(holds(old.s, old_content, sizeof old_content - 1));
    assert_names(dir.s, "old.ppm");
    remove_tree(&dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Signals during a save                                                */

typedef enum disposition { KEEP_DEFAULT, CATCH, IGNORE } disposition;

typedef struct signal_case {
    const char *path;
    int number;
    disposition disposition;
    int side;
} signal_case;

static volatile sig_atomic_t caught;

static void on_signal(int number)
{
    caught = number;
}

/* In a child: default dispositions and an empty mask, then `disposition`
 * for the signal, then a large P3 save; exit code = the save's status. */
static int save_while_signalled(void *arg, char *note, size_t size)
{
    const signal_case *c = arg;
    static const int termination[] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++)
        signal(termination[i], SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    if (c->disposition == CATCH) {
        struct sigaction action;
        memset(&action, 0, sizeof action);
        action.sa_handler = on_signal;
        sigemptyset(&action.sa_mask);
        sigaction(c->number, &action, NULL);
    } else if (c->disposition == IGNORE) {
        signal(c->number, SIG_IGN);
    }
    rt_image image;
    if (make_pattern(&image, c->side, c->side) != RT_OK)
        return say(90, note, size, "no memory for the image");
    rt_error error = {0};
    rt_status status = rt_image_save(c->path, &image, RT_IMAGE_P3, &error);
    rt_image_release(&image);
    snprintf(note, size, "caught=%d; %s", (int)caught,
             status == RT_OK ? "saved" : error.message);
    return (int)status;
}

static double seconds_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int has_temporary(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    int found = 0;
    while (d != NULL && !found && (entry = readdir(d)) != NULL)
        found = strncmp(entry->d_name, ".rt-save-", 9) == 0;
    if (d != NULL)
        closedir(d);
    return found;
}

/* Waits until a temporary file shows in `dir` while `pid` runs. */
static int temporary_appears(const char *dir, pid_t pid)
{
    double deadline = seconds_now() + (rt_test_memcheck() ? 600 : 60);
    const struct timespec pause = {0, 100000};
    while (seconds_now() < deadline) {
        if (has_temporary(dir))
            return 1;
        siginfo_t info;
        memset(&info, 0, sizeof info);
        if (waitid(P_PID, (id_t)pid, &info, WEXITED | WNOHANG | WNOWAIT) ==
                0 && info.si_pid == pid)
            return 0;           /* it ended first */
        nanosleep(&pause, NULL);
    }
    return 0;
}

static int signal_side(void)
{
    if (!rt_test_memcheck())
        return 2000;
    static int told;
    if (!told++)
        fprintf(stderr, "test_save: RT_TEST_MEMCHECK: the signal tests save "
                        "a 300 x 300 image instead of 2000 x 2000\n");
    return 300;
}

typedef struct signal_run {
    path_t dir, out;
    int wait_status;
    char note[1024];
} signal_run;

/* Starts a child saving over dir/out.ppm (which holds old_content), sends
 * it `number` once its temporary file exists, and waits for it. */
static signal_run save_and_signal(int number, disposition d)
{
    signal_run run;
    run.dir = scratch();
    run.out = at(run.dir.s, "out.ppm");
    put(run.out.s, old_content, sizeof old_content - 1);
    signal_case c = {run.out.s, number, d, signal_side()};
    child saver = start(save_while_signalled, &c);
    ck_assert_int_gt(saver.pid, 0);
    int seen = temporary_appears(run.dir.s, saver.pid);
    kill(saver.pid, seen ? number : SIGKILL);
    run.wait_status = finish(saver, run.note, sizeof run.note);
    ck_assert_msg(seen, "no temporary file appeared while saving (wait "
                  "status %#x): %s", run.wait_status, run.note);
    return run;
}

static void assert_left_as_it_was(signal_run *run)
{
    ck_assert_msg(holds(run->out.s, old_content, sizeof old_content - 1),
                  "the previous file was changed");
    assert_names(run->dir.s, "out.ppm");
    remove_tree(&run->dir);
}

static void killed_by(int number)
{
    signal_run run = save_and_signal(number, KEEP_DEFAULT);
    ck_assert_msg(WIFSIGNALED(run.wait_status) &&
                      WTERMSIG(run.wait_status) == number,
                  "the saving program was not killed by signal %d (wait "
                  "status %#x): %s", number, run.wait_status, run.note);
    assert_left_as_it_was(&run);
}

START_TEST(sigterm_kills_the_saving_program_and_leaves_the_old_file)
{
    killed_by(SIGTERM);
}
END_TEST

START_TEST(sigint_kills_the_saving_program_and_leaves_the_old_file)
{
    killed_by(SIGINT);
}
END_TEST

START_TEST(sighup_kills_the_saving_program_and_leaves_the_old_file)
{
    killed_by(SIGHUP);
}
END_TEST

START_TEST(a_handled_sigterm_makes_the_save_return_interrupted)
{
    signal_run run = save_and_signal(SIGTERM, CATCH);
    ck_assert_msg(WIFEXITED(run.wait_status) &&
                      WEXITSTATUS(run.wait_status) == RT_ERR_INTERRUPTED,
                  "the save did not return RT_ERR_INTERRUPTED (wait status "
                  "%#x): %s", run.wait_status, run.note);
    ck_assert_msg(strstr(run.note, "caught=15;") != NULL,
                  "the handler did not run after the save: %s", run.note);
    ck_assert_msg(strstr(run.note, run.out.s) != NULL,
                  "the message does not name the path: %s", run.note);
    assert_left_as_it_was(&run);
}
END_TEST

START_TEST(an_ignored_sigint_does_not_stop_the_save)
{
    signal_run run = save_and_signal(SIGINT, IGNORE);
    ck_assert_msg(WIFEXITED(run.wait_status) &&
                      WEXITSTATUS(run.wait_status) == RT_OK,
                  "the save did not complete (wait status %#x): %s",
                  run.wait_status, run.note);
    rt_image image = pattern(signal_side(), signal_side());
    size_t size = 0;
    ck_assert_int_eq(rt_image_write_to(count_bytes, &size, &image,
                                       RT_IMAGE_P3, NULL), RT_OK);
    rt_image_release(&image);
    struct stat st;
    ck_assert_int_eq(stat(run.out.s, &st), 0);
    ck_assert_msg((size_t)st.st_size == size,
                  "out.ppm has %ld bytes, the image %zu", (long)st.st_size,
                  size);
    char header[32];
    int side = signal_side();
    snprintf(header, sizeof header, "P3\n%d %d\n255\n", side, side);
    FILE *file = fopen(run.out.s, "rb");
    ck_assert_ptr_nonnull(file);
    char start[32] = "";
    size_t n = fread(start, 1, strlen(header), file);
    fclose(file);
    ck_assert_msg(n == strlen(header) && !memcmp(start, header, n),
                  "out.ppm does not start with the image's header");
    assert_names(run.dir.s, "out.ppm");
    remove_tree(&run.dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* rt_image_save_check                                                  */

START_TEST(save_check_accepts_what_can_be_written_and_creates_nothing)
{
    path_t dir = scratch();
    path_t old = at(dir.s, "old.ppm"), fifo = at(dir.s, "fifo");
    path_t dangling = at(dir.s, "dangling"), linked = at(dir.s, "linked");
    put(old.s, old_content, sizeof old_content - 1);
    ck_assert_int_eq(link(old.s, linked.s), 0);
    ck_assert_int_eq(mkfifo(fifo.s, 0600), 0);
    ck_assert_int_eq(symlink("new.ppm", dangling.s), 0);
    /* a FIFO without a reader must not make the check wait */
    path_t paths[] = {at(dir.s, "new.ppm"), old, linked, fifo, dangling};
    for (int i = 0; i < 5; i++) {
        rt_error error = {0};
        rt_status status = rt_image_save_check(paths[i].s, &error);
        ck_assert_msg(status == RT_OK, "checking %s: %s", paths[i].s,
                      error.message);
    }
    ck_assert(holds(old.s, old_content, sizeof old_content - 1));
    ck_assert_int_eq(kind_of(fifo.s), S_IFIFO);
    assert_link(dangling.s, "new.ppm");
    assert_names(dir.s, "dangling fifo linked old.ppm");
    remove_tree(&dir);
}
END_TEST

START_TEST(save_check_refuses_what_the_save_refuses_with_its_message)
{
    path_t dir = scratch();
    path_t folder = at(dir.s, "folder"), plain = at(dir.s, "plain");
    path_t loop = at(dir.s, "loop");
    ck_assert_int_eq(mkdir(folder.s, 0755), 0);
    put(plain.s, "x", 1);
    ck_assert_int_eq(symlink("loop", loop.s), 0);
    path_t paths[] = {at(dir.s, "missing/out.ppm"), folder, loop,
                      at(dir.s, "plain/out.ppm")};
    rt_image image = pattern(3, 3);
    for (int i = 0; i < 4; i++) {
        rt_error check = {0}, error = {0};
        rt_status checked = rt_image_save_check(paths[i].s, &check);
        rt_status status = rt_image_save(paths[i].s, &image, RT_IMAGE_P6,
                                         &error);
        ck_assert_msg(checked == RT_ERR_IO && status == RT_ERR_IO,
                      "%s: the check returned %s, the save %s", paths[i].s,
                      rt_status_string(checked), rt_status_string(status));
        ck_assert_str_eq(check.message, error.message);
        ck_assert_msg(strstr(check.message, paths[i].s) != NULL,
                      "the message does not name the path: %s",
                      check.message);
    }
    rt_image_release(&image);
    assert_names(dir.s, "folder loop plain");
    assert_names(folder.s, "");
    remove_tree(&dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Formats                                                              */

#if RT_TEST_HAVE_LIBPNG
/* Decodes PNG bytes as 8-bit RGB with libpng's simplified API; the pixels
 * are malloc'd, rows packed. */
static unsigned char *decode_png(const bytes *png, int *width, int *height)
{
    png_image decoded;
    memset(&decoded, 0, sizeof decoded);
    decoded.version = PNG_IMAGE_VERSION;
    ck_assert_msg(png_image_begin_read_from_memory(&decoded, png->data,
                                                   png->size),
                  "libpng refused the header: %s", decoded.message);
    decoded.format = PNG_FORMAT_RGB;
    unsigned char *pixels = malloc(PNG_IMAGE_SIZE(decoded));
    ck_assert_ptr_nonnull(pixels);
    int ok = png_image_finish_read(&decoded, NULL, pixels, 0, NULL);
    if (!ok)
        free(pixels);
    ck_assert_msg(ok, "libpng could not decode it: %s", decoded.message);
    *width = (int)decoded.width;
    *height = (int)decoded.height;
    return pixels;
}
#endif

START_TEST(png_decodes_back_to_every_byte_of_the_image)
{
    path_t dir = scratch();
    path_t path = at(dir.s, "image.png");
    if (!rt_image_format_supported(RT_IMAGE_PNG)) {
        rt_image image = pattern(4, 4);
        rt_error error = {0};
        ck_assert_int_eq(rt_image_save(path.s, &image, RT_IMAGE_PNG, &error),
                         RT_ERR_FORMAT);
        ck_assert_msg(strstr(error.message, "libpng") != NULL,
                      "the refusal does not mention libpng: %s",
                      error.message);
        bytes b = {NULL, 0, 0};
        ck_assert_int_eq(rt_image_write_to(rt_test_bytes_add, &b, &image,
                                           RT_IMAGE_PNG, NULL),
                         RT_ERR_FORMAT);
        ck_assert_uint_eq(b.size, 0);
        assert_names(dir.s, "");
        rt_image_release(&image);
        remove_tree(&dir);
        fprintf(stderr, "test_save: this build has no PNG: checked the "
                        "refusal, round trip skipped\n");
        return;
    }
#if RT_TEST_HAVE_LIBPNG
    /* a view of 97 x 61 pixels with rows of 100: the padding must not
     * leak into the file */
    rt_image wide = pattern(100, 61);
    rt_image view = wide;
    view.width = 97;
    bytes png = encode(&view, RT_IMAGE_PNG);
    int width = 0, height = 0;
    unsigned char *pixels = decode_png(&png, &width, &height);
    ck_assert_int_eq(width, view.width);
    ck_assert_int_eq(height, view.height);
    int bad_x = -1, bad_y = -1;
    for (int y = 0; y < height && bad_x < 0; y++)
        for (int x = 0; x < width && bad_x < 0; x++)
            if (memcmp(pixels + ((size_t)y * (size_t)width + (size_t)x) * 3,
                       rt_image_pixel(&view, x, y), 3) != 0)
                bad_x = x, bad_y = y;
    ck_assert_msg(bad_x < 0, "pixel (%d, %d) decodes to another colour",
                  bad_x, bad_y);
    /* the file holds the very bytes the sink got */
    save_ok(path.s, &view, RT_IMAGE_PNG);
    ck_assert(holds(path.s, png.data, png.size));
    assert_names(dir.s, "image.png");
    free(pixels);
    free(png.data);
    rt_image_release(&wide);
    remove_tree(&dir);
#else
    remove_tree(&dir);
    ck_abort_msg("the library writes PNG but this test was built without "
                 "libpng to decode it (tests/save.cmake)");
#endif
}
END_TEST

static unsigned long be32(const unsigned char *p)
{
    return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 |
           (unsigned long)p[2] << 8 | (unsigned long)p[3];
}

START_TEST(png_has_no_gamma_or_colour_space_chunk)
{
    if (!rt_image_format_supported(RT_IMAGE_PNG)) {
        fprintf(stderr, "test_save: this build has no PNG: chunk test "
                        "skipped\n");
        return;
    }
    rt_image image = pattern(33, 17);
    bytes png = encode(&image, RT_IMAGE_PNG);
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G',
                                               '\r', '\n', 0x1a, '\n'};
    ck_assert_uint_gt(png.size, 8 + 25);
    ck_assert(memcmp(png.data, signature, 8) == 0);
    char types[1024] = "";
    size_t at_byte = 8;
    while (at_byte + 12 <= png.size) {
        unsigned long length = be32(png.data + at_byte);
        ck_assert_uint_le(length, png.size - at_byte - 12);
        char type[5];
        memcpy(type, png.data + at_byte + 4, 4);
        type[4] = '\0';
        ck_assert_uint_lt(strlen(types) + 6, sizeof types);
        strcat(types, types[0] ? " " : "");
        strcat(types, type);
        static const char *const forbidden[] = {"gAMA", "sRGB", "iCCP",
                                                "cHRM"};
        for (int i = 0; i < 4; i++)
            ck_assert_msg(strcmp(type, forbidden[i]) != 0,
                          "the PNG has a %s chunk (chunks: %s)", type,
                          types);
        at_byte += 12 + length;
    }
    ck_assert_uint_eq(at_byte, png.size);
    ck_assert_msg(strncmp(types, "IHDR ", 5) == 0 &&
                      strcmp(types + strlen(types) - 4, "IEND") == 0,
                  "chunks: %s", types);
    const unsigned char *header = png.data + 16;
    ck_assert_uint_eq(be32(header), 33);
    ck_assert_uint_eq(be32(header + 4), 17);
    ck_assert_uint_eq(header[8], 8);   /* bits per channel */
    ck_assert_uint_eq(header[9], 2);   /* RGB */
    ck_assert_uint_eq(header[12], 0);  /* not interlaced */
    free(png.data);
    rt_image_release(&image);
}
END_TEST

START_TEST(the_format_comes_from_the_extension_whatever_its_case)
{
    static const struct {
        const char *path;
        rt_status status;
        rt_image_format format;
    } cases[] = {
        {"out.png", RT_OK, RT_IMAGE_PNG},
        {"OUT.PNG", RT_OK, RT_IMAGE_PNG},
        {"dir/x.Png", RT_OK, RT_IMAGE_PNG},
        {"out.ppm", RT_OK, RT_IMAGE_P6},
        {"out.PPM", RT_OK, RT_IMAGE_P6},
        {"out.pnm", RT_OK, RT_IMAGE_P6},
        {"a.png.ppm", RT_OK, RT_IMAGE_P6},
        {"out.jpg", RT_ERR_FORMAT, 0},
        {"out", RT_ERR_FORMAT, 0},
        {"out.", RT_ERR_FORMAT, 0},
        {"out.pngx", RT_ERR_FORMAT, 0},
        {"dir.png/out", RT_ERR_FORMAT, 0},
        {".png", RT_ERR_FORMAT, 0},
        {"-", RT_ERR_FORMAT, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_image_format format = (rt_image_format)12345;
        rt_status status = rt_image_format_from_path(cases[i].path, &format,
                                                     NULL);
        ck_assert_msg(status == cases[i].status, "%s: %s", cases[i].path,
                      rt_status_string(status));
        rt_image_format expected = status == RT_OK ? cases[i].format
                                                   : (rt_image_format)12345;
        ck_assert_msg(format == expected, "%s: format %d, expected %d",
                      cases[i].path, (int)format, (int)expected);
    }
}
END_TEST

/* ------------------------------------------------------------------ */
/* Privileged: root in a private mount namespace                        */

static int private_mounts(char *note, size_t size)
{
    /* "none" as the type: the kernel ignores it here, but valgrind checks
     * that it is a string */
    if (unshare(CLONE_NEWNS) != 0 ||
        mount("none", "/", "none", MS_REC | MS_PRIVATE, NULL) != 0)
        return say(3, note, size, "no private mount namespace: %s",
                   strerror(errno));
    return 0;
}

/* A /dev of this child's own: null, full, and stdout -> /proc/self/fd/1. */
static int private_dev(char *note, size_t size)
{
    int code = private_mounts(note, size);
    if (code != 0)
        return code;
    if (mount("rt-test-save", "/dev", "tmpfs", MS_NOSUID,
              "size=64k,mode=0755") != 0)
        return say(3, note, size, "no tmpfs on /dev: %s",
                   strerror(errno));
    if (mknod("/dev/null", S_IFCHR | 0666, makedev(1, 3)) != 0 ||
        mknod("/dev/full", S_IFCHR | 0666, makedev(1, 7)) != 0)
        return say(3, note, size, "mknod: %s", strerror(errno));
    if (symlink("/proc/self/fd/1", "/dev/stdout") != 0)
        return say(3, note, size, "symlink: %s", strerror(errno));
    return 0;
}

static int is_device(const char *path, unsigned major_number,
                     unsigned minor_number)
{
    struct stat st;
    return lstat(path, &st) == 0 && S_ISCHR(st.st_mode) &&
           major(st.st_rdev) == major_number &&
           minor(st.st_rdev) == minor_number;
}

/* What the probe needs before the privileged tests can run. */
static int privileges_job(void *arg, char *note, size_t size)
{
    (void)arg;
    int code = private_dev(note, size);
    if (code != 0)
        return code;
    int fd = open("/dev/full", O_WRONLY);
    if (fd < 0)
        return say(1, note, size, "cannot open a device node made by "
                      "mknod: %s", strerror(errno));
    close(fd);
    if (mkdir("/dev/probe", 0755) != 0 ||
        mount("rt-test-save", "/dev/probe", "tmpfs", MS_RDONLY,
              "size=16k") != 0)
        return say(1, note, size, "no read-only tmpfs: %s", strerror(errno));
    if (close(open("/dev/owned", O_WRONLY | O_CREAT, 0600)) != 0 ||
        chown("/dev/owned", NOBODY, NOBODY) != 0)
        return say(1, note, size, "cannot give a file to user %d: %s",
                      NOBODY, strerror(errno));
    return 0;
}

static const char dev_listing[] = "full null stdout";

/* A device of the private /dev, what a save there must return (with
 * `reason` in its message when it fails) and the numbers it must keep. */
typedef struct device_case {
    const char *path;
    rt_status expected;
    const char *reason;
    unsigned major_number, minor_number;
} device_case;

static int save_to_device(void *arg, char *note, size_t size)
{
    const device_case *c = arg;
    int code = private_dev(note, size);
    if (code != 0)
        return code;
    rt_image image;
    if (make_pattern(&image, 64, 48) != RT_OK)
        return say(1, note, size, "no memory for the image");
    rt_error error = {0}, check = {0};
    rt_status status = rt_image_save(c->path, &image, RT_IMAGE_P3, &error);
    /* the check only opens the device: a full one passes */
    rt_status checked = rt_image_save_check(c->path, &check);
    rt_image_release(&image);
    char names[256];
    names_in("/dev", names, sizeof names);
    if (status != c->expected ||
        (status != RT_OK && (error.status != status ||
                             !strstr(error.message, c->path) ||
                             !strstr(error.message, c->reason))))
        return say(1, note, size, "saving to %s returned %s: %s", c->path,
                   rt_status_string(status), error.message);
    if (checked != RT_OK)
        return say(1, note, size, "checking %s: %s", c->path, check.message);
    if (!is_device(c->path, c->major_number, c->minor_number))
        return say(1, note, size, "%s is no longer the device %u, %u",
                   c->path, c->major_number, c->minor_number);
    if (strcmp(names, dev_listing) != 0)
        return say(1, note, size, "/dev holds `%s`", names);
    return 0;
}

START_TEST(saving_to_dev_null_succeeds_and_leaves_the_device)
{
    device_case c = {"/dev/null", RT_OK, "", 1, 3};
    char note[1024];
    int code = run_job(save_to_device, &c, note, sizeof note);
    ck_assert_msg(code == 0, "%s", note);
}
END_TEST

START_TEST(saving_to_dev_full_says_no_space_and_leaves_the_device)
{
    device_case c = {"/dev/full", RT_ERR_IO, strerror(ENOSPC), 1, 7};
    char note[1024];
    int code = run_job(save_to_device, &c, note, sizeof note);
    ck_assert_msg(code == 0, "%s", note);
}
END_TEST

/* Standard output is a pipe read by a copier into `arg` (a file); the
 * image (larger than a pipe holds) goes to /dev/stdout. */
static int save_to_dev_stdout(void *arg, char *note, size_t size)
{
    const char *received = arg;
    int code = private_dev(note, size);
    if (code != 0)
        return code;
    rt_image image;
    if (make_pattern(&image, 200, 150) != RT_OK)
        return say(1, note, size, "no memory for the image");
    bytes expected = {NULL, 0, 0};
    rt_status status = rt_image_write_to(rt_test_bytes_add, &expected,
                                         &image, RT_IMAGE_P6, NULL);
    int fds[2];
    if (status != RT_OK || pipe(fds) != 0 || dup2(fds[1], 1) != 1)
        return say(1, note, size, "cannot set up the pipe");
    close(fds[1]);
    copy_args copy = {NULL, fds[0], 1, received};
    child reader = start(copy_job, &copy);
    close(fds[0]);
    rt_error error = {0};
    status = rt_image_save("/dev/stdout", &image, RT_IMAGE_P6, &error);
    close(1);
    char reader_note[1024];
    int wait_status = reader.pid > 0
                          ? finish(reader, reader_note, sizeof reader_note)
                          : -1;
    rt_image_release(&image);
    int same = holds(received, expected.data, expected.size);
    size_t expected_size = expected.size;
    free(expected.data);
    char target[64] = "";
    ssize_t n = readlink("/dev/stdout", target, sizeof target - 1);
    target[n > 0 ? n : 0] = '\0';
    char names[256];
    names_in("/dev", names, sizeof names);
    if (status != RT_OK)
        return say(1, note, size, "save: %s", error.message);
    if (!WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0)
        return say(1, note, size, "the reader failed: %s", reader_note);
    if (!same)
        return say(1, note, size, "the pipe did not carry exactly the "
                      "image's %zu bytes", expected_size);
    if (strcmp(target, "/proc/self/fd/1") != 0)
        return say(1, note, size, "/dev/stdout is no longer the link "
                      "(readlink: `%s`)", target);
    if (strcmp(names, dev_listing) != 0)
        return say(1, note, size, "/dev holds `%s`", names);
    return 0;
}

START_TEST(saving_to_dev_stdout_sends_the_bytes_through_the_pipe)
{
    path_t dir = scratch();
    path_t received = at(dir.s, "received");
    char note[1024];
    int code = run_job(save_to_dev_stdout, received.s, note, sizeof note);
    remove_tree(&dir);
    ck_assert_msg(code == 0, "%s", note);
}
END_TEST

START_TEST(a_file_of_another_owner_keeps_its_owner_group_and_mode)
{
    path_t dir = scratch();
    path_t path = at(dir.s, "theirs.ppm");
    put(path.s, old_content, sizeof old_content - 1);
    ck_assert_int_eq(chown(path.s, NOBODY, NOBODY), 0);
    ck_assert_int_eq(chmod(path.s, 0640), 0);
    rt_image image = pattern(12, 8);
    bytes expected = encode(&image, RT_IMAGE_P6);
    save_ok(path.s, &image, RT_IMAGE_P6);
    struct stat st;
    ck_assert_int_eq(lstat(path.s, &st), 0);
    ck_assert_msg(st.st_uid == NOBODY && st.st_gid == NOBODY,
                  "owner %u:%u after the save, was %d:%d",
                  (unsigned)st.st_uid, (unsigned)st.st_gid, NOBODY, NOBODY);
    ck_assert_uint_eq(st.st_mode & 07777, 0640);
    ck_assert(holds(path.s, expected.data, expected.size));
    assert_names(dir.s, "theirs.ppm");
    free(expected.data);
    rt_image_release(&image);
    remove_tree(&dir);
}
END_TEST

/* Saves and checks at `path`, which must both fail on a read-only file
 * system; returns 0 or fills `note`. */
static int refused_read_only(const char *path, char *note, size_t size)
{
    rt_image image;
    if (make_pattern(&image, 8, 8) != RT_OK)
        return say(1, note, size, "no memory for the image");
    rt_error error = {0}, check = {0};
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6, &error);
    rt_status checked = rt_image_save_check(path, &check);
    rt_image_release(&image);
    if (status != RT_ERR_IO || !strstr(error.message, path) ||
        !strstr(error.message, strerror(EROFS)))
        return say(1, note, size, "saving %s: %s: %s", path,
                      rt_status_string(status), error.message);
    if (checked != RT_ERR_IO || strcmp(check.message, error.message))
        return say(1, note, size, "checking %s: %s: %s", path,
                      rt_status_string(checked), check.message);
    return 0;
}

/* dir/ro: an empty tmpfs mounted read-only; dir/bound: a read-only bind
 * mount of itself, holding old.ppm. */
static int save_on_read_only_mounts(void *arg, char *note, size_t size)
{
    const char *dir = arg;
    int code = private_mounts(note, size);
    if (code != 0)
        return code;
    path_t ro = at(dir, "ro"), bound = at(dir, "bound");
    if (mount("rt-test-save", ro.s, "tmpfs", MS_RDONLY, "size=16k") != 0 ||
        mount(bound.s, bound.s, "none", MS_BIND, NULL) != 0 ||
        mount("none", bound.s, "none", MS_REMOUNT | MS_BIND | MS_RDONLY,
              NULL) != 0)
        return say(1, note, size, "mount: %s", strerror(errno));
    if (refused_read_only(at(ro.s, "new.ppm").s, note, size) ||
        refused_read_only(at(bound.s, "old.ppm").s, note, size))
        return 1;
    char names[256];
    names_in(ro.s, names, sizeof names);
    if (strcmp(names, "") != 0)
        return say(1, note, size, "the read-only tmpfs holds `%s`", names);
    return 0;
}

START_TEST(a_read_only_mount_is_refused_and_left_as_it_was)
{
    path_t dir = scratch();
    path_t ro = at(dir.s, "ro"), bound = at(dir.s, "bound");
    path_t old = at(bound.s, "old.ppm");
    ck_assert_int_eq(mkdir(ro.s, 0755), 0);
    ck_assert_int_eq(mkdir(bound.s, 0755), 0);
    put(old.s, old_content, sizeof old_content - 1);
    char note[1024];
    int code = run_job(save_on_read_only_mounts, dir.s, note, sizeof note);
    ck_assert_msg(code == 0, "%s", note);
    ck_assert(holds(old.s, old_content, sizeof old_content - 1));
    assert_names(bound.s, "old.ppm");
    assert_names(ro.s, "");
    remove_tree(&dir);
}
END_TEST

/* ------------------------------------------------------------------ */

static Suite *save_suite(void)
{
    Suite *s = suite_create("save");
    TCase *tc = tcase_create("what the path names");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, a_new_file_gets_0666_minus_the_umask);
    tcase_add_test(tc, a_replaced_file_keeps_its_permission_bits);
    tcase_add_test(tc, a_file_with_two_hard_links_stays_one_file_holding_the_image);
    tcase_add_test(tc, symbolic_links_stay_and_their_final_target_gets_the_image);
    tcase_add_test(tc, a_dangling_link_gets_its_target_created_in_the_existing_folder);
    tcase_add_test(tc, a_loop_of_links_is_an_io_error_naming_the_path);
    tcase_add_test(tc, a_fifo_is_streamed_to_its_reader_and_stays_a_fifo);
    tcase_add_test(tc, a_unix_socket_is_streamed_to_its_listener_and_stays);
    tcase_add_test(tc, a_directory_is_refused_as_a_directory_and_nothing_is_created);
    tcase_add_test(tc, a_missing_folder_is_named_in_the_error_and_nothing_is_created);
    tcase_add_test(tc, a_folder_without_write_permission_is_refused_and_left_as_it_was);
    suite_add_tcase(s, tc);

    tc = tcase_create("signals during a save");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, sigterm_kills_the_saving_program_and_leaves_the_old_file);
    tcase_add_test(tc, sigint_kills_the_saving_program_and_leaves_the_old_file);
    tcase_add_test(tc, sighup_kills_the_saving_program_and_leaves_the_old_file);
    tcase_add_test(tc, a_handled_sigterm_makes_the_save_return_interrupted);
    tcase_add_test(tc, an_ignored_sigint_does_not_stop_the_save);
    suite_add_tcase(s, tc);

    tc = tcase_create("checking before rendering");
    tcase_add_test(tc, save_check_accepts_what_can_be_written_and_creates_nothing);
    tcase_add_test(tc, save_check_refuses_what_the_save_refuses_with_its_message);
    suite_add_tcase(s, tc);

    tc = tcase_create("formats");
    tcase_add_test(tc, png_decodes_back_to_every_byte_of_the_image);
    tcase_add_test(tc, png_has_no_gamma_or_colour_space_chunk);
    tcase_add_test(tc, the_format_comes_from_the_extension_whatever_its_case);
    suite_add_tcase(s, tc);
    return s;
}

static Suite *privileged_suite(void)
{
    Suite *s = suite_create("save, privileged");
    TCase *tc = tcase_create("root in a private mount namespace");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, saving_to_dev_null_succeeds_and_leaves_the_device);
    tcase_add_test(tc, saving_to_dev_full_says_no_space_and_leaves_the_device);
    tcase_add_test(tc, saving_to_dev_stdout_sends_the_bytes_through_the_pipe);
    tcase_add_test(tc, a_file_of_another_owner_keeps_its_owner_group_and_mode);
    tcase_add_test(tc, a_read_only_mount_is_refused_and_left_as_it_was);
    suite_add_tcase(s, tc);
    return s;
}

int main(int argc, char **argv)
{
    if (argc == 1)
        return rt_test_run_suite(save_suite());
    if (argc != 2 || strcmp(argv[1], "privileged") != 0) {
        fprintf(stderr, "usage: %s [privileged]\n", argv[0]);
        return 2;
    }
    char note[1024] = "";
    child probe = start(privileges_job, NULL);
    int status = probe.pid > 0 ? finish(probe, note, sizeof note) : -1;
    if (status != 0) {
        printf("test_save_privileged: skipped: needs root in a private "
               "mount namespace (%s)\n",
               note[0] ? note : "the probe did not run");
        return 77;
    }
    return rt_test_run_suite(privileged_suite());
}
