/*
 * test_save.c - rt_image_save and rt_image_save_check: each rule stated at
 * the top of raytrace/image.h about what a path names, checked by what the
 * path names afterwards (lstat, the bytes, the folder's listing): regular
 * files and their modes, hard and symbolic links, FIFOs and sockets,
 * refusals, and the check before rendering.  The other rules have suites of
 * their own: signals during a save (test_save_signals.c), the formats
 * (test_save_formats.c), what needs root in a private mount namespace
 * (test_save_privileged.c), descriptors (test_save_streams.c).
 *
 * Whatever changes the process (umask, signal dispositions, user, mount
 * namespace, standard output) happens in a forked child that reports through
 * a pipe and calls no Check function (support/child.h), so the suites also
 * hold under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1

#include <errno.h>
#include <grp.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include "testutil.h"

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
        return rt_test_say(1, note, size, "accept: %s", strerror(errno));
    rt_test_copy copy = {NULL, connection, a->listener, a->to};
    return rt_test_copy_job(&copy, note, size);
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
    if (rt_test_make_pattern(&image, 5, 3) != RT_OK)
        return rt_test_say(1, note, size, "no memory for the image");
    rt_error error = {0};
    rt_status status =
        rt_image_save(c->path, &image, RT_IMAGE_P6, NULL, &error);
    rt_image_release(&image);
    return status == RT_OK ? 0 : rt_test_say(1, note, size, "%s",
                                             error.message);
}

START_TEST(a_new_file_gets_0666_minus_the_umask)
{
    static const mode_t masks[] = {077, 022, 002, 027};
    char *dir = rt_test_temp_dir();
    rt_image image = rt_test_pattern(5, 3);
    rt_test_bytes expected = rt_test_encode(&image, RT_IMAGE_P6);
    for (size_t i = 0; i < sizeof masks / sizeof masks[0]; i++) {
        char name[32];
        snprintf(name, sizeof name, "umask-%03o.ppm", (unsigned)masks[i]);
        rt_test_path path = rt_test_path_at(dir, name);
        umask_case c = {path.s, masks[i]};
        char note[1024];
        int code = rt_test_in_child(save_with_umask, &c, note, sizeof note);
        ck_assert_msg(code == 0, "umask %03o: %s", (unsigned)masks[i], note);
        struct stat st;
        ck_assert_int_eq(lstat(path.s, &st), 0);
        ck_assert(S_ISREG(st.st_mode));
        ck_assert_msg((st.st_mode & 07777) == (0666 & ~masks[i]),
                      "umask %03o gave mode %04o, expected %04o",
                      (unsigned)masks[i], (unsigned)(st.st_mode & 07777),
                      (unsigned)(0666 & ~masks[i]));
        ck_assert(rt_test_file_holds(path.s, expected.data, expected.size));
    }
    rt_test_assert_dir_holds(dir, "umask-002.ppm umask-022.ppm umask-027.ppm "
                        "umask-077.ppm");
    free(expected.data);
    rt_image_release(&image);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(a_replaced_file_keeps_its_permission_bits)
{
    static const mode_t modes[] = {0600, 0640, 0604, 0755, 0444};
    char *dir = rt_test_temp_dir();
    rt_test_path path = rt_test_path_at(dir, "kept.ppm");
    rt_image image = rt_test_pattern(9, 7);
    rt_test_bytes expected = rt_test_encode(&image, RT_IMAGE_P3);
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        unlink(path.s);
        rt_test_write_bytes(path.s, rt_test_previous_ppm,
                            sizeof rt_test_previous_ppm - 1);
        ck_assert_int_eq(chmod(path.s, modes[i]), 0);
        rt_test_save_ok(path.s, &image, RT_IMAGE_P3);
        struct stat st;
        ck_assert_int_eq(lstat(path.s, &st), 0);
        ck_assert_msg((st.st_mode & 07777) == modes[i],
                      "a file of mode %04o came back %04o", (unsigned)modes[i],
                      (unsigned)(st.st_mode & 07777));
        ck_assert(rt_test_file_holds(path.s, expected.data, expected.size));
        rt_test_assert_dir_holds(dir, "kept.ppm");
    }
    free(expected.data);
    rt_image_release(&image);
    rt_test_remove_dir(dir);
}
END_TEST

/* The old file is longer than the image, so a copy in place that does not
 * truncate leaves a tail behind. */
START_TEST(a_file_with_two_hard_links_stays_one_file_holding_the_image)
{
    char *dir = rt_test_temp_dir();
    rt_test_path first = rt_test_path_at(dir, "first.ppm"),
                 second = rt_test_path_at(dir, "second.ppm");
    char long_old[5000];
    memset(long_old, '#', sizeof long_old);
    rt_test_write_bytes(first.s, long_old, sizeof long_old);
    ck_assert_int_eq(link(first.s, second.s), 0);
    struct stat before;
    ck_assert_int_eq(stat(first.s, &before), 0);

    rt_image image = rt_test_pattern(20, 10);
    rt_test_bytes expected = rt_test_encode(&image, RT_IMAGE_P6);
    ck_assert_uint_lt(expected.size, sizeof long_old);
    rt_test_save_ok(first.s, &image, RT_IMAGE_P6);

    struct stat a, b;
    ck_assert_int_eq(lstat(first.s, &a), 0);
    ck_assert_int_eq(lstat(second.s, &b), 0);
    ck_assert_msg(a.st_ino == b.st_ino && a.st_ino == before.st_ino,
                  "the links were split (inodes %lu and %lu, was %lu)",
                  (unsigned long)a.st_ino, (unsigned long)b.st_ino,
                  (unsigned long)before.st_ino);
    ck_assert_uint_eq(a.st_nlink, 2);
    ck_assert_msg(rt_test_file_holds(second.s, expected.data, expected.size),
                  "the other name does not hold the image (%ld bytes)",
                  (long)b.st_size);
    rt_test_assert_dir_holds(dir, "first.ppm second.ppm");
    free(expected.data);
    rt_image_release(&image);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(symbolic_links_stay_and_their_final_target_gets_the_image)
{
    char *dir = rt_test_temp_dir();
    rt_test_path target = rt_test_path_at(dir, "target.ppm");
    rt_test_path sub = rt_test_path_at(dir, "sub"),
                 other = rt_test_path_at(dir, "other");
    rt_test_path final = rt_test_path_at(dir, "other/final.ppm");
    ck_assert_int_eq(mkdir(sub.s, 0755), 0);
    ck_assert_int_eq(mkdir(other.s, 0755), 0);
    rt_test_write_bytes(target.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    ck_assert_int_eq(chmod(target.s, 0640), 0);
    rt_test_write_bytes(final.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);

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
        ck_assert_int_eq(symlink(links[i].text,
                                 rt_test_path_at(dir, links[i].name).s),
                         0);

    for (size_t i = 0; i < count; i++) {
        rt_test_path link = rt_test_path_at(dir, links[i].name);
        /* a new image each time */
        rt_image image = rt_test_pattern(4 + (int)i, 3);
        rt_test_bytes expected = rt_test_encode(&image, RT_IMAGE_P6);
        rt_test_save_ok(link.s, &image, RT_IMAGE_P6);
        for (size_t j = 0; j < count; j++)
            rt_test_assert_link(rt_test_path_at(dir, links[j].name).s,
                                links[j].text);
        ck_assert_msg(rt_test_file_kind(links[i].lands) == S_IFREG &&
                          rt_test_file_holds(links[i].lands, expected.data,
                                             expected.size),
                      "saving through %s did not put the image in %s",
                      link.s, links[i].lands);
        free(expected.data);
        rt_image_release(&image);
    }
    struct stat st;
    ck_assert_int_eq(stat(target.s, &st), 0);
    ck_assert_uint_eq(st.st_mode & 07777, 0640);
    rt_test_assert_dir_holds(dir, "absolute first other relative second sub "
                        "target.ppm");
    rt_test_assert_dir_holds(sub.s, "across up");
    rt_test_assert_dir_holds(other.s, "final.ppm hop");
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(a_dangling_link_gets_its_target_created_in_the_existing_folder)
{
    char *dir = rt_test_temp_dir();
    rt_test_path sub = rt_test_path_at(dir, "sub"),
                 link = rt_test_path_at(dir, "dangling");
    rt_test_path created = rt_test_path_at(dir, "sub/new.ppm");
    ck_assert_int_eq(mkdir(sub.s, 0755), 0);
    ck_assert_int_eq(symlink("sub/new.ppm", link.s), 0);
    rt_image image = rt_test_pattern(11, 5);
    rt_test_bytes expected = rt_test_encode(&image, RT_IMAGE_P3);
    rt_test_save_ok(link.s, &image, RT_IMAGE_P3);
    rt_test_assert_link(link.s, "sub/new.ppm");
    ck_assert_msg(rt_test_file_kind(created.s) == S_IFREG &&
                      rt_test_file_holds(created.s, expected.data,
                                         expected.size),
                  "%s does not hold the image", created.s);
    rt_test_assert_dir_holds(dir, "dangling sub");
    rt_test_assert_dir_holds(sub.s, "new.ppm");
    free(expected.data);
    rt_image_release(&image);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(a_loop_of_links_is_an_io_error_naming_the_path)
{
    char *dir = rt_test_temp_dir();
    rt_test_path one = rt_test_path_at(dir, "one"),
                 two = rt_test_path_at(dir, "two");
    rt_test_path self = rt_test_path_at(dir, "self");
    ck_assert_int_eq(symlink("two", one.s), 0);
    ck_assert_int_eq(symlink("one", two.s), 0);
    ck_assert_int_eq(symlink("self", self.s), 0);
    const char *paths[] = {one.s, self.s};
    for (int i = 0; i < 2; i++) {
        rt_error error;
        rt_test_save_refused(paths[i], strerror(ELOOP), &error);
        rt_error check = {0};
        ck_assert_int_eq(rt_image_save_check(paths[i], NULL, &check),
                         RT_ERR_IO);
        ck_assert_str_eq(check.message, error.message);
    }
    rt_test_assert_link(one.s, "two");
    rt_test_assert_link(two.s, "one");
    rt_test_assert_link(self.s, "self");
    rt_test_assert_dir_holds(dir, "one self two");
    rt_test_remove_dir(dir);
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
static void assert_streamed(const char *dir, const char *name,
                            rt_test_job job, void *arg, const char *received)
{
    rt_test_path path = rt_test_path_at(dir, name);
    mode_t kind = rt_test_file_kind(path.s);
    rt_image image = rt_test_pattern(300, 200);
    rt_test_bytes expected = rt_test_encode(&image, RT_IMAGE_P6);
    rt_test_child reader = rt_test_child_start(job, arg);
    ck_assert_int_gt(reader.pid, 0);
    rt_error error = {0};
    rt_status status =
        rt_image_save(path.s, &image, RT_IMAGE_P6, NULL, &error);
    rt_image_release(&image);
    if (rt_test_file_kind(path.s) != kind)
        kill(reader.pid, SIGKILL);  /* it waits for a writer that is gone */
    char note[1024];
    int wait_status = rt_test_child_finish(&reader, note, sizeof note);

    ck_assert_msg(rt_test_file_kind(path.s) == kind, "%s was replaced", path.s);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    ck_assert_msg(WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0,
                  "the reader failed (wait status %#x): %s", wait_status,
                  note);
    ck_assert_msg(rt_test_file_holds(received, expected.data, expected.size),
                  "the reader did not get exactly the image's %zu bytes",
                  expected.size);
    rt_test_assert_dir_holds(dir, name);
    free(expected.data);
}

START_TEST(a_fifo_is_streamed_to_its_reader_and_stays_a_fifo)
{
    char *dir = rt_test_temp_dir(), *elsewhere = rt_test_temp_dir();
    rt_test_path fifo = rt_test_path_at(dir, "fifo"),
                 received = rt_test_path_at(elsewhere, "received");
    ck_assert_int_eq(mkfifo(fifo.s, 0600), 0);
    rt_test_copy copy = {fifo.s, -1, -1, received.s};
    assert_streamed(dir, "fifo", rt_test_copy_job, &copy, received.s);
    rt_test_remove_dir(dir);
    rt_test_remove_dir(elsewhere);
}
END_TEST

START_TEST(a_unix_socket_is_streamed_to_its_listener_and_stays)
{
    char *dir = rt_test_temp_dir(), *elsewhere = rt_test_temp_dir();
    rt_test_path socket_path = rt_test_path_at(dir, "socket");
    rt_test_path received = rt_test_path_at(elsewhere, "received");
    struct sockaddr_un address = {.sun_family = AF_UNIX};
    ck_assert_uint_lt(strlen(socket_path.s), sizeof address.sun_path);
    strcpy(address.sun_path, socket_path.s);
    int listener = socket(AF_UNIX, SOCK_STREAM, 0);
    ck_assert_int_ge(listener, 0);
    ck_assert_int_eq(bind(listener, (struct sockaddr *)&address,
                          sizeof address), 0);
    ck_assert_int_eq(listen(listener, 1), 0);
    accept_args args = {listener, received.s};
    assert_streamed(dir, "socket", accept_job, &args, received.s);
    close(listener);
    rt_test_remove_dir(dir);
    rt_test_remove_dir(elsewhere);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Refusals: directory, missing folder, folder without write permission */

START_TEST(a_directory_is_refused_as_a_directory_and_nothing_is_created)
{
    char *dir = rt_test_temp_dir();
    rt_test_path folder = rt_test_path_at(dir, "image.ppm"),
                 link = rt_test_path_at(dir, "link");
    ck_assert_int_eq(mkdir(folder.s, 0755), 0);
    rt_test_write_bytes(rt_test_path_at(folder.s, "keep").s, "k", 1);
    ck_assert_int_eq(symlink("image.ppm", link.s), 0);
    rt_error error;
    rt_test_save_refused(folder.s, "is a directory", &error);
    rt_test_save_refused(link.s, "is a directory", &error);
    rt_test_assert_link(link.s, "image.ppm");
    rt_test_assert_dir_holds(dir, "image.ppm link");
    rt_test_assert_dir_holds(folder.s, "keep");
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(a_missing_folder_is_named_in_the_error_and_nothing_is_created)
{
    char *dir = rt_test_temp_dir();
    rt_test_path missing = rt_test_path_at(dir, "missing"),
                 deep = rt_test_path_at(dir, "a/b/c");
    rt_test_path link = rt_test_path_at(dir, "link");
    ck_assert_int_eq(symlink("nowhere/new.ppm", link.s), 0);
    rt_error error;
    rt_test_save_refused(rt_test_path_at(missing.s, "out.ppm").s,
                         "does not exist", &error);
    ck_assert_msg(strstr(error.message, missing.s) != NULL,
                  "the message does not name the folder: %s", error.message);
    rt_test_save_refused(rt_test_path_at(deep.s, "out.ppm").s,
                         "does not exist", &error);
    ck_assert_msg(strstr(error.message, deep.s) != NULL,
                  "the message does not name the folder: %s", error.message);
    rt_test_save_refused(link.s, "does not exist", &error);
    ck_assert_msg(strstr(error.message, "nowhere") != NULL,
                  "the message does not name the link's folder: %s",
                  error.message);
    rt_test_assert_link(link.s, "nowhere/new.ppm");
    rt_test_assert_dir_holds(dir, "link");
    rt_test_remove_dir(dir);
}
END_TEST

/* Saves and checks in a folder the process may not write to; as root, the
 * child first becomes nobody (root writes anywhere permissions apply). */
static int save_without_permission(void *arg, char *note, size_t size)
{
    const char *dir = arg;
    if (geteuid() == 0 &&
        (setgroups(0, NULL) != 0 || setgid(RT_TEST_NOBODY) != 0 ||
         setuid(RT_TEST_NOBODY) != 0))
        return rt_test_say(3, note, size, "cannot become user %d: %s",
                           RT_TEST_NOBODY, strerror(errno));
    rt_image image;
    if (rt_test_make_pattern(&image, 4, 4) != RT_OK)
        return rt_test_say(1, note, size, "no memory for the image");
    const char *names[] = {"new.ppm", "old.ppm"};
    for (int i = 0; i < 2; i++) {
        rt_test_path path = rt_test_path_at(dir, names[i]);
        rt_error error = {0}, check = {0};
        rt_status status =
            rt_image_save(path.s, &image, RT_IMAGE_P6, NULL, &error);
        rt_status checked = rt_image_save_check(path.s, NULL, &check);
        if (status != RT_ERR_IO || !strstr(error.message, path.s) ||
            !strstr(error.message, strerror(EACCES))) {
            rt_image_release(&image);
            return rt_test_say(1, note, size, "saving %s: %s, `%s`", path.s,
                          rt_status_string(status), error.message);
        }
        if (checked != RT_ERR_IO || strcmp(check.message, error.message)) {
            rt_image_release(&image);
            return rt_test_say(1, note, size, "checking %s: %s, `%s`", path.s,
                          rt_status_string(checked), check.message);
        }
    }
    rt_image_release(&image);
    return 0;
}

START_TEST(a_folder_without_write_permission_is_refused_and_left_as_it_was)
{
    char *dir = rt_test_temp_dir();
    rt_test_path old = rt_test_path_at(dir, "old.ppm");
    rt_test_write_bytes(old.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    if (geteuid() == 0)
        ck_assert_int_eq(chown(dir, RT_TEST_NOBODY, RT_TEST_NOBODY), 0);
    ck_assert_int_eq(chmod(dir, 0555), 0);
    char note[1024];
    int code = rt_test_in_child(save_without_permission, dir, note,
                                sizeof note);
    chmod(dir, 0700);
    if (code == 3) {
        fprintf(stderr, "test_save: read-only folder skipped here (%s); "
                        "test_save_privileged checks a read-only mount\n",
                note);
    } else {
        ck_assert_msg(code == 0, "%s", note);
    }
    ck_assert(rt_test_file_holds(old.s, rt_test_previous_ppm,
                                 sizeof rt_test_previous_ppm - 1));
    rt_test_assert_dir_holds(dir, "old.ppm");
    rt_test_remove_dir(dir);
}
END_TEST

/* ------------------------------------------------------------------ */
/* rt_image_save_check                                                  */

START_TEST(save_check_accepts_what_can_be_written_and_creates_nothing)
{
    char *dir = rt_test_temp_dir();
    rt_test_path old = rt_test_path_at(dir, "old.ppm"),
                 fifo = rt_test_path_at(dir, "fifo");
    rt_test_path dangling = rt_test_path_at(dir, "dangling"),
                 linked = rt_test_path_at(dir, "linked");
    rt_test_write_bytes(old.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    ck_assert_int_eq(link(old.s, linked.s), 0);
    ck_assert_int_eq(mkfifo(fifo.s, 0600), 0);
    ck_assert_int_eq(symlink("new.ppm", dangling.s), 0);
    /* a FIFO without a reader must not make the check wait */
    rt_test_path paths[] = {rt_test_path_at(dir, "new.ppm"), old, linked, fifo,
                            dangling};
    for (int i = 0; i < 5; i++) {
        rt_error error = {0};
        rt_status status = rt_image_save_check(paths[i].s, NULL, &error);
        ck_assert_msg(status == RT_OK, "checking %s: %s", paths[i].s,
                      error.message);
    }
    ck_assert(rt_test_file_holds(old.s, rt_test_previous_ppm,
                                 sizeof rt_test_previous_ppm - 1));
    ck_assert_int_eq(rt_test_file_kind(fifo.s), S_IFIFO);
    rt_test_assert_link(dangling.s, "new.ppm");
    rt_test_assert_dir_holds(dir, "dangling fifo linked old.ppm");
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(save_check_refuses_what_the_save_refuses_with_its_message)
{
    char *dir = rt_test_temp_dir();
    rt_test_path folder = rt_test_path_at(dir, "folder"),
                 plain = rt_test_path_at(dir, "plain");
    rt_test_path loop = rt_test_path_at(dir, "loop");
    ck_assert_int_eq(mkdir(folder.s, 0755), 0);
    rt_test_write_bytes(plain.s, "x", 1);
    ck_assert_int_eq(symlink("loop", loop.s), 0);
    rt_test_path paths[] = {rt_test_path_at(dir, "missing/out.ppm"), folder,
                            loop,
                      rt_test_path_at(dir, "plain/out.ppm")};
    rt_image image = rt_test_pattern(3, 3);
    for (int i = 0; i < 4; i++) {
        rt_error check = {0}, error = {0};
        rt_status checked = rt_image_save_check(paths[i].s, NULL, &check);
        rt_status status = rt_image_save(paths[i].s, &image, RT_IMAGE_P6,
                                         NULL, &error);
        ck_assert_msg(checked == RT_ERR_IO && status == RT_ERR_IO,
                      "%s: the check returned %s, the save %s", paths[i].s,
                      rt_status_string(checked), rt_status_string(status));
        ck_assert_str_eq(check.message, error.message);
        ck_assert_msg(strstr(check.message, paths[i].s) != NULL,
                      "the message does not name the path: %s",
                      check.message);
    }
    rt_image_release(&image);
    rt_test_assert_dir_holds(dir, "folder loop plain");
    rt_test_assert_dir_holds(folder.s, "");
    rt_test_remove_dir(dir);
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

    tc = tcase_create("checking before rendering");
    tcase_add_test(tc, save_check_accepts_what_can_be_written_and_creates_nothing);
    tcase_add_test(tc, save_check_refuses_what_the_save_refuses_with_its_message);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(save_suite)
