/*
 * test_save_streams.c - saving to a descriptor the caller already opened.
 * /dev/fd/N, /proc/self/fd/N, /dev/stdout, /dev/stderr and bash's process
 * substitution are written through the descriptor, at its offset (at the
 * end when it appends), so what the caller wrote before and writes after
 * stays around the image; nothing is reopened, truncated or replaced.  With
 * test_save.c this checks each row of the table of destinations in
 * docs/saving-images.md (that page names the test of each row).
 *
 * One program, two suites.  Without arguments: the library's rt_image_save,
 * rt_image_save_check and rt_scene_save_scn on descriptors (ctest:
 * test_save_streams).  With the argument `shell`: the same destinations as
 * a user spells them to rt-export in bash (ctest: test_save_streams_shell),
 * exiting 77, a visible skip, when bash or rt-export is absent.
 *
 * Whatever replaces standard output or error, or must run beside the save
 * (a pipe's reader, another process holding a descriptor), is a forked
 * child that calls no Check function and reports through its exit status
 * and a note, so the suites also hold under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1       /* F_SETPIPE_SZ */

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Names, files and bytes                                               */

typedef rt_test_bytes bytes;

/* "/dev/fd/N" and the like, for descriptor `fd`. */
typedef struct fd_path {
    char s[96];
} fd_path;

static fd_path fd_name(const char *format, int fd)
{
    fd_path p;
    snprintf(p.s, sizeof p.s, format, fd);
    return p;
}

/* A scratch folder (the support library's) and the names made in it,
 * freed with it. */
typedef struct folder {
    char *dir;
    char *names[4];
    int count;
} folder;

static folder new_folder(void)
{
    return (folder){rt_test_temp_dir(), {NULL}, 0};
}

static const char *in(folder *f, const char *name)
{
    ck_assert_int_lt(f->count, 4);
    return f->names[f->count++] = rt_test_join(f->dir, name);
}

static void folder_remove(folder *f)
{
    for (int i = 0; i < f->count; i++)
        free(f->names[i]);
    rt_test_remove_dir(f->dir);
}

/* The P6 bytes of `image`. */
static bytes encode(const rt_image *image)
{
    bytes b = {NULL, 0, 0};
    ck_assert_int_eq(rt_image_write_to(rt_test_bytes_add, &b, image,
                                       RT_IMAGE_P6, NULL), RT_OK);
    return b;
}

/* Fails unless the file at `path` holds exactly `before`, then the bytes
 * of `middle`, then `after` (`middle` NULL: none). */
static void assert_holds(const char *path, const char *before,
                         const bytes *middle, const char *after)
{
    size_t size;
    char *got = rt_test_read_file(path, &size);
    ck_assert_msg(got != NULL, "%s cannot be read", path);
    size_t b = strlen(before), m = middle ? middle->size : 0,
           a = strlen(after);
    ck_assert_msg(size == b + m + a, "%s holds %zu bytes, expected %zu "
                  "(%zu before, %zu of the save, %zu after)", path, size,
                  b + m + a, b, m, a);
    ck_assert_msg(memcmp(got, before, b) == 0, "%s lost what came before "
                  "the save", path);
    ck_assert_msg(m == 0 || memcmp(got + b, middle->data, m) == 0,
                  "%s does not hold the saved bytes after the first %zu",
                  path, b);
    ck_assert_msg(memcmp(got + b + m, after, a) == 0, "%s lost what came "
                  "after the save", path);
    free(got);
}

static ino_t inode_of(const char *path)
{
    struct stat st;
    ck_assert_int_eq(stat(path, &st), 0);
    return st.st_ino;
}

static void write_text_fd(int fd, const char *text)
{
    ck_assert_int_eq(write(fd, text, strlen(text)), (ssize_t)strlen(text));
}

static void save_ok(const char *path, const rt_image *image)
{
    rt_error error = {0};
    rt_status status = rt_image_save(path, image, RT_IMAGE_P6, NULL, &error);
    ck_assert_msg(status == RT_OK, "saving to %s: %s", path, error.message);
}

/* ------------------------------------------------------------------ */
/* Children                                                             */

/* A reader of the pipe `fds`, copying it into the file `to` until the
 * writers are gone (rt_test_copy_job in a child). */
static rt_test_child start_reader(const int fds[2], const char *to)
{
    rt_test_copy copy = {NULL, fds[0], fds[1], to};
    rt_test_child reader = rt_test_child_start(rt_test_copy_job, &copy);
    ck_assert_msg(reader.pid > 0, "fork: %s", strerror(errno));
    close(fds[0]);
    return reader;
}

static void assert_reader_done(rt_test_child *reader)
{
    char note[1024];
    int status = rt_test_child_finish(reader, note, sizeof note);
    ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0,
                  "the pipe's reader failed: %s", note);
}

/* ------------------------------------------------------------------ */
/* The library: descriptors other than 0, 1 and 2                       */

/* Saves an image larger than a pipe holds to /dev/fd/N, N the write end
 * of a pipe (made non-blocking and small when `non_blocking`) whose reader
 * must receive exactly its bytes. */
static void through_a_pipe(int non_blocking)
{
    folder dir = new_folder();
    const char *got = in(&dir, "received");
    rt_image image = rt_test_pattern(200, 150);
    bytes expected = encode(&image);
    int fds[2];
    ck_assert_int_eq(pipe(fds), 0);
    if (non_blocking) {
        (void)fcntl(fds[1], F_SETPIPE_SZ, 4096);  /* full at once */
        ck_assert_int_eq(fcntl(fds[1], F_SETFL, O_NONBLOCK), 0);
    }
    rt_test_child reader = start_reader(fds, got);
    save_ok(fd_name("/dev/fd/%d", fds[1]).s, &image);
    close(fds[1]);
    assert_reader_done(&reader);
    assert_holds(got, "", &expected, "");
    rt_image_release(&image);
    free(expected.data);
    folder_remove(&dir);
}

START_TEST(dev_fd_to_a_pipe_carries_the_image_to_its_reader)
{
    through_a_pipe(0);
}
END_TEST

START_TEST(a_non_blocking_pipe_is_waited_for_not_refused)
{
    through_a_pipe(1);
}
END_TEST

/* Saves through `format` (a name of the descriptor) into a file opened for
 * appending after "HEADER\n", then appends "TRAILER\n" through the same
 * descriptor: the file must hold all three, and be the same file. */
static void append_through(const char *format)
{
    folder dir = new_folder();
    const char *file = in(&dir, "log");
    rt_test_write_file(file, "HEADER\n");
    ino_t before = inode_of(file);
    int fd = open(file, O_WRONLY | O_APPEND);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(lseek(fd, 0, SEEK_SET), 0);  /* appending ignores it */
    rt_image image = rt_test_pattern(7, 5);
    bytes expected = encode(&image);
    fd_path name = fd_name(format, fd);
    save_ok(name.s, &image);
    write_text_fd(fd, "TRAILER\n");
    close(fd);
    assert_holds(file, "HEADER\n", &expected, "TRAILER\n");
    ck_assert_msg(inode_of(file) == before, "%s replaced the file", name.s);
    rt_image_release(&image);
    free(expected.data);
    folder_remove(&dir);
}

START_TEST(dev_fd_to_a_file_opened_for_appending_keeps_before_and_after)
{
    append_through("/dev/fd/%d");
}
END_TEST

START_TEST(proc_self_fd_to_a_file_opened_for_appending_keeps_before_and_after)
{
    append_through("/proc/self/fd/%d");
}
END_TEST

START_TEST(this_process_s_own_proc_pid_fd_is_its_descriptor_too)
{
    char format[64];
    snprintf(format, sizeof format, "/proc/%ld/fd/%%d", (long)getpid());
    append_through(format);
}
END_TEST

START_TEST(dev_fd_to_a_positioned_file_writes_at_its_offset_truncating_nothing)
{
    folder dir = new_folder();
    const char *file = in(&dir, "image.bin");
    char old[301];
    memset(old, 'x', 300);
    old[300] = '\0';
    rt_test_write_file(file, old);
    int fd = open(file, O_RDWR);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(lseek(fd, 7, SEEK_SET), 7);
    rt_image image = rt_test_pattern(6, 4); /* 83 bytes, inside the 300 */
    bytes expected = encode(&image);
    save_ok(fd_name("/dev/fd/%d", fd).s, &image);
    ck_assert_int_eq(lseek(fd, 0, SEEK_CUR), 7 + (off_t)expected.size);
    close(fd);
    assert_holds(file, "xxxxxxx", &expected, old + 7 + expected.size);
    rt_image_release(&image);
    free(expected.data);
    folder_remove(&dir);
}
END_TEST

START_TEST(a_link_to_dev_fd_writes_through_the_descriptor_and_stays_a_link)
{
    folder dir = new_folder();
    const char *file = in(&dir, "log"),
               *link = in(&dir, "out.ppm");
    rt_test_write_file(file, "HEADER\n");
    int fd = open(file, O_WRONLY | O_APPEND);
    ck_assert_int_ge(fd, 0);
    fd_path name = fd_name("/dev/fd/%d", fd);
    ck_assert_int_eq(symlink(name.s, link), 0);
    rt_image image = rt_test_pattern(5, 3);
    bytes expected = encode(&image);
    save_ok(link, &image);
    close(fd);
    assert_holds(file, "HEADER\n", &expected, "");
    struct stat st;
    ck_assert_int_eq(lstat(link, &st), 0);
    ck_assert_msg(S_ISLNK(st.st_mode), "the link was replaced");
    rt_image_release(&image);
    free(expected.data);
    folder_remove(&dir);
}
END_TEST

START_TEST(a_scene_saved_to_dev_fd_goes_through_the_descriptor)
{
    rt_scene *scene;
    rt_error error = {0};
    ck_assert_msg(rt_scene_load(rt_test_source_path("scenes/cubes.scn"), NULL,
                                &scene, &error) == RT_OK,
                  "%s", error.message);
    bytes expected = {NULL, 0, 0};
    ck_assert_int_eq(rt_scene_write_scn(scene, 0, rt_test_bytes_add, &expected,
                                        NULL, NULL), RT_OK);
    folder dir = new_folder();
    const char *file = in(&dir, "scenes.txt");
    rt_test_write_file(file, "# before\n");
    int fd = open(file, O_WRONLY | O_APPEND);
    ck_assert_int_ge(fd, 0);
    rt_status status = rt_scene_save_scn(scene, fd_name("/dev/fd/%d", fd).s,
                                         0, NULL, NULL, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    write_text_fd(fd, "# after\n");
    close(fd);
    assert_holds(file, "# before\n", &expected, "# after\n");
    free(expected.data);
    rt_scene_destroy(scene);
    folder_remove(&dir);
}
END_TEST

/* A save and a check at `path` both fail with RT_ERR_IO and a message that
 * names `path` and says `reason`. */
static void assert_refused(const char *path, const char *reason)
{
    rt_image image = rt_test_pattern(4, 4);
    rt_error saved = {0}, checked = {0};
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6, NULL, &saved);
    rt_status check = rt_image_save_check(path, NULL, &checked);
    rt_image_release(&image);
    ck_assert_msg(status == RT_ERR_IO && check == RT_ERR_IO,
                  "%s: the save returned %s, the check %s", path,
                  rt_status_string(status), rt_status_string(check));
    ck_assert_msg(strstr(saved.message, path) && strstr(saved.message, reason),
                  "the save's message does not name %s and say `%s`: %s",
                  path, reason, saved.message);
    ck_assert_str_eq(checked.message, saved.message);
}

START_TEST(a_closed_descriptor_is_refused_by_number)
{
    int fd = open("/dev/null", O_WRONLY);
    ck_assert_int_ge(fd, 0);
    close(fd);
    assert_refused(fd_name("/dev/fd/%d", fd).s, "is not open");
    assert_refused(fd_name("/proc/self/fd/%d", fd).s, "is not open");
}
END_TEST

START_TEST(a_descriptor_open_for_reading_is_refused_and_left_as_it_was)
{
    folder dir = new_folder();
    const char *file = in(&dir, "kept");
    rt_test_write_file(file, "kept as it was\n");
    int fd = open(file, O_RDONLY);
    ck_assert_int_ge(fd, 0);
    char reason[64];
    snprintf(reason, sizeof reason, "descriptor %d is open for reading only",
             fd);
    assert_refused(fd_name("/dev/fd/%d", fd).s, reason);
    close(fd);
    assert_holds(file, "kept as it was\n", NULL, "");
    folder_remove(&dir);
}
END_TEST

START_TEST(the_check_accepts_an_open_descriptor_and_moves_nothing)
{
    folder dir = new_folder();
    const char *file = in(&dir, "log");
    rt_test_write_file(file, "HEADER\n");
    int fd = open(file, O_RDWR);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(lseek(fd, 3, SEEK_SET), 3);
    rt_error error = {0};
    ck_assert_msg(rt_image_save_check(fd_name("/dev/fd/%d", fd).s, NULL,
                                      &error) == RT_OK,
                  "%s", error.message);
    ck_assert_int_eq(lseek(fd, 0, SEEK_CUR), 3);
    close(fd);
    assert_holds(file, "HEADER\n", NULL, "");
    folder_remove(&dir);
}
END_TEST

/* Another process's descriptor cannot be written through: its file is
 * opened again and rewritten from its start (docs/saving-images.md). */
typedef struct holder_fds {
    int wait_fd;            /* read until the test closes the other end */
    int other_end;          /* that end, which the holder must not keep */
} holder_fds;

static int hold_open_until_closed(void *arg, char *note, size_t size)
{
    (void)note, (void)size;
    const holder_fds *h = arg;
    close(h->other_end);
    char byte;
    alarm(600);
    return read(h->wait_fd, &byte, 1) == 0 ? 0 : 1;
}

START_TEST(another_process_s_descriptor_has_its_file_rewritten_from_the_start)
{
    folder dir = new_folder();
    const char *file = in(&dir, "theirs");
    rt_test_write_file(file, "an old content longer than nothing\n");
    int fd = open(file, O_WRONLY | O_APPEND);
    int wait_fds[2];
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(pipe(wait_fds), 0);
    holder_fds h = {wait_fds[0], wait_fds[1]};
    /* the holder keeps fd open */
    rt_test_child holder = rt_test_child_start(hold_open_until_closed, &h);
    ck_assert_msg(holder.pid > 0, "fork: %s", strerror(errno));
    close(wait_fds[0]);
    close(fd);              /* only the holder has it now */
    char name[64];
    snprintf(name, sizeof name, "/proc/%ld/fd/%d", (long)holder.pid, fd);
    rt_image image = rt_test_pattern(5, 5);
    bytes expected = encode(&image);
    rt_error error = {0};
    rt_status status = rt_image_save(name, &image, RT_IMAGE_P6, NULL, &error);
    close(wait_fds[1]);
    char note[64];
    ck_assert_int_ne(rt_test_child_finish(&holder, note, sizeof note), -1);
    ck_assert_msg(status == RT_OK, "%s: %s", name, error.message);
    assert_holds(file, "", &expected, "");
    rt_image_release(&image);
    free(expected.data);
    folder_remove(&dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The library: standard output and error, in a child                  */

typedef struct standard_case {
    int target;             /* 1 or 2 */
    const char *name;       /* /dev/stdout, /dev/stderr, /dev/fd/1 ... */
    const char *file;       /* what the descriptor is opened on */
    int flags;              /* how (O_APPEND as >>, O_TRUNC as >) */
    const char *first;      /* what the child writes before the save */
    const char *then;       /* and after */
} standard_case;

static int save_to_standard(void *arg, char *note, size_t size)
{
    const standard_case *c = arg;
    int fd = open(c->file, O_WRONLY | c->flags);
    if (fd < 0 || dup2(fd, c->target) != c->target)
        return snprintf(note, size, "cannot open %.900s", c->file), 1;
    close(fd);
    rt_image image;
    if (rt_image_init(&image, 9, 7, NULL) != RT_OK)
        return snprintf(note, size, "no memory"), 1;
    memset(image.pixels, 0x5a, image.stride * 7);
    rt_error error = {0};
    ssize_t first = write(c->target, c->first, strlen(c->first));
    rt_status status =
        rt_image_save(c->name, &image, RT_IMAGE_P6, NULL, &error);
    ssize_t then = write(c->target, c->then, strlen(c->then));
    rt_image_release(&image);
    if (status != RT_OK)
        return snprintf(note, size, "%s: %s", c->name, error.message), 1;
    if (first != (ssize_t)strlen(c->first) ||
        then != (ssize_t)strlen(c->then))
        return snprintf(note, size, "the child's own writes failed"), 1;
    return 0;
}

/* Runs case `c` on a file that held `old`; it must then hold `kept`, the
 * child's first text, the image, and its last text. */
static void standard_case_run(standard_case c, const char *old,
                              const char *kept)
{
    folder dir = new_folder();
    const char *file = in(&dir, "out");
    rt_test_write_file(file, old);
    c.file = file;
    char note[1024];
    int code = rt_test_in_child(save_to_standard, &c, note, sizeof note);
    ck_assert_msg(code == 0, "%s", note);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 9, 7, NULL), RT_OK);
    memset(image.pixels, 0x5a, image.stride * 7);
    bytes expected = encode(&image);
    char before[256];
    snprintf(before, sizeof before, "%s%s", kept, c.first);
    assert_holds(file, before, &expected, c.then);
    rt_image_release(&image);
    free(expected.data);
    folder_remove(&dir);
}

START_TEST(dev_stdout_appended_to_a_log_keeps_the_log)
{
    /* rt-export ... -o /dev/stdout >> log */
    standard_case c = {1, "/dev/stdout", NULL, O_APPEND, "", "next entry\n"};
    standard_case_run(c, "the log so far\n", "the log so far\n");
}
END_TEST

START_TEST(dev_stdout_between_the_callers_writes_keeps_header_and_trailer)
{
    /* { echo HEADER; rt-export ... -o /dev/stdout; echo TRAILER; } > f */
    standard_case c = {1, "/dev/stdout", NULL, O_TRUNC, "HEADER\n",
                       "TRAILER\n"};
    standard_case_run(c, "what > truncates\n", "");
}
END_TEST

START_TEST(dev_stderr_and_dev_fd_2_are_descriptor_2)
{
    standard_case c = {2, "/dev/stderr", NULL, O_APPEND, "before\n",
                       "after\n"};
    standard_case_run(c, "", "");
    c.name = "/dev/fd/2";
    standard_case_run(c, "old\n", "old\n");
}
END_TEST

/* ------------------------------------------------------------------ */
/* rt-export in bash                                                    */

static const char *bash_path(void)
{
    static const char *const candidates[] = {"/bin/bash", "/usr/bin/bash"};
    for (size_t i = 0; i < sizeof candidates / sizeof candidates[0]; i++)
        if (access(candidates[i], X_OK) == 0)
            return candidates[i];
    return NULL;
}

#ifdef RT_EXPORT_PATH
/* The render every shell case makes: small, but more than a pipe holds. */
#define RENDER "\"$1\" \"$2\" --size 200x150 -q"

/* Runs `script` in bash in `dir` with $1 rt-export and $2 a scene, after
 * rendering $1's image to reference.ppm the plain way; fails the test
 * unless it exits 0.  Returns the reference image. */
static bytes run_shell(folder *dir, const char *script)
{
    char whole[4096];
    snprintf(whole, sizeof whole,
             "set -e; " RENDER " -o reference.ppm >/dev/null; %s", script);
    const char *args[] = {"-c", whole, "bash", RT_EXPORT_PATH,
                          rt_test_source_path("scenes/cubes.scn"), NULL};
    rt_test_output r = rt_test_run(dir->dir, bash_path(), args);
    ck_assert_msg(r.code == 0, "bash -c '%s' failed (%d): %s", script, r.code,
                  r.err);
    rt_test_output_free(&r);
    const char *reference = in(dir, "reference.ppm");
    size_t size;
    char *data = rt_test_read_file(reference, &size);
    ck_assert_ptr_nonnull(data);
    ck_assert_uint_gt(size, 65536);
    return (bytes){(unsigned char *)data, size, size};
}

/* Runs `script` and checks that dir/`file` holds `before`, the reference
 * image, `after`. */
static void shell_case(const char *script, const char *file,
                       const char *before, const char *after)
{
    folder dir = new_folder();
    const char *path = in(&dir, file);
    bytes reference = run_shell(&dir, script);
    assert_holds(path, before, &reference, after);
    free(reference.data);
    folder_remove(&dir);
}

START_TEST(rt_export_into_a_process_substitution_delivers_the_image)
{
    shell_case(RENDER " -o >(cat > got.ppm); wait $!", "got.ppm", "", "");
}
END_TEST

START_TEST(rt_export_to_dev_fd_1_into_a_pipe_delivers_the_image)
{
    shell_case(RENDER " -o /dev/fd/1 | cat > got.ppm", "got.ppm", "", "");
}
END_TEST

START_TEST(rt_export_to_proc_self_fd_1_writes_the_shell_s_file)
{
    shell_case(RENDER " -o /proc/self/fd/1 > got.ppm", "got.ppm", "", "");
}
END_TEST

START_TEST(rt_export_to_dev_stdout_appended_to_a_log_keeps_the_log)
{
    shell_case("echo old > log; " RENDER " -o /dev/stdout >> log; "
               "echo new >> log", "log", "old\n", "new\n");
}
END_TEST

START_TEST(rt_export_to_dev_stdout_between_two_echos_keeps_both)
{
    shell_case("{ echo HEADER; " RENDER " -o /dev/stdout; echo TRAILER; } "
               "> f", "f", "HEADER\n", "TRAILER\n");
}
END_TEST

START_TEST(rt_export_to_dev_fd_3_opened_for_appending_keeps_before_and_after)
{
    shell_case("echo pre > f; exec 3>>f; echo mid >&3; " RENDER
               " -o /dev/fd/3; echo post >&3; exec 3>&-", "f", "pre\nmid\n",
               "post\n");
}
END_TEST
#endif

/* ------------------------------------------------------------------ */

static Suite *descriptors_suite(void)
{
    Suite *s = suite_create("save_streams");
    TCase *tc = tcase_create("descriptors");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, dev_fd_to_a_pipe_carries_the_image_to_its_reader);
    tcase_add_test(tc, a_non_blocking_pipe_is_waited_for_not_refused);
    tcase_add_test(tc, dev_fd_to_a_file_opened_for_appending_keeps_before_and_after);
    tcase_add_test(tc, proc_self_fd_to_a_file_opened_for_appending_keeps_before_and_after);
    tcase_add_test(tc, this_process_s_own_proc_pid_fd_is_its_descriptor_too);
    tcase_add_test(tc, dev_fd_to_a_positioned_file_writes_at_its_offset_truncating_nothing);
    tcase_add_test(tc, a_link_to_dev_fd_writes_through_the_descriptor_and_stays_a_link);
    tcase_add_test(tc, a_scene_saved_to_dev_fd_goes_through_the_descriptor);
    tcase_add_test(tc, a_closed_descriptor_is_refused_by_number);
    tcase_add_test(tc, a_descriptor_open_for_reading_is_refused_and_left_as_it_was);
    tcase_add_test(tc, the_check_accepts_an_open_descriptor_and_moves_nothing);
    tcase_add_test(tc, another_process_s_descriptor_has_its_file_rewritten_from_the_start);
    suite_add_tcase(s, tc);
    tc = tcase_create("standard_streams");
    tcase_add_test(tc, dev_stdout_appended_to_a_log_keeps_the_log);
    tcase_add_test(tc, dev_stdout_between_the_callers_writes_keeps_header_and_trailer);
    tcase_add_test(tc, dev_stderr_and_dev_fd_2_are_descriptor_2);
    suite_add_tcase(s, tc);
    return s;
}

#ifdef RT_EXPORT_PATH
static Suite *shell_suite(void)
{
    Suite *s = suite_create("save_streams_shell");
    TCase *tc = tcase_create("rt_export_in_bash");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, rt_export_into_a_process_substitution_delivers_the_image);
    tcase_add_test(tc, rt_export_to_dev_fd_1_into_a_pipe_delivers_the_image);
    tcase_add_test(tc, rt_export_to_proc_self_fd_1_writes_the_shell_s_file);
    tcase_add_test(tc, rt_export_to_dev_stdout_appended_to_a_log_keeps_the_log);
    tcase_add_test(tc, rt_export_to_dev_stdout_between_two_echos_keeps_both);
    tcase_add_test(tc, rt_export_to_dev_fd_3_opened_for_appending_keeps_before_and_after);
    suite_add_tcase(s, tc);
    return s;
}
#endif

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "shell") == 0) {
#ifdef RT_EXPORT_PATH
        if (bash_path() != NULL && access(RT_EXPORT_PATH, X_OK) == 0)
            return rt_test_run_suite(shell_suite());
        printf("skipped: no bash, or rt-export was not built\n");
#else
        printf("skipped: rt-export is not part of this build\n");
#endif
        return RT_TEST_SKIPPED;
    }
    return rt_test_run_suite(descriptors_suite());
}
