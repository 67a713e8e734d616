/*
 * test_save_privileged.c - the rules of rt_image_save (raytrace/image.h)
 * that need root in a private mount namespace: a /dev of its own on a tmpfs
 * (null, full, stdout), read-only mounts, a file of another owner.  When
 * the process cannot unshare, mount, mknod and chown, it says why and exits
 * 77, which ctest shows as a skip.
 *
 * Each case runs in a forked child that makes the namespace, saves, and
 * reports through a pipe without calling Check (support/child.h), so the
 * suite also holds under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1

#include <errno.h>
#include <fcntl.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Privileged: root in a private mount namespace                        */

static int private_mounts(char *note, size_t size)
{
    /* "none" as the type: the kernel ignores it here, but valgrind checks
     * that it is a string */
    if (unshare(CLONE_NEWNS) != 0 ||
        mount("none", "/", "none", MS_REC | MS_PRIVATE, NULL) != 0)
        return rt_test_say(3, note, size, "no private mount namespace: %s",
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
        return rt_test_say(3, note, size, "no tmpfs on /dev: %s",
                           strerror(errno));
    if (mknod("/dev/null", S_IFCHR | 0666, makedev(1, 3)) != 0 ||
        mknod("/dev/full", S_IFCHR | 0666, makedev(1, 7)) != 0)
        return rt_test_say(3, note, size, "mknod: %s", strerror(errno));
    if (symlink("/proc/self/fd/1", "/dev/stdout") != 0)
        return rt_test_say(3, note, size, "symlink: %s", strerror(errno));
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
        return rt_test_say(1, note, size, "cannot open a device node made by "
                      "mknod: %s", strerror(errno));
    close(fd);
    if (mkdir("/dev/probe", 0755) != 0 ||
        mount("rt-test-save", "/dev/probe", "tmpfs", MS_RDONLY,
              "size=16k") != 0)
        return rt_test_say(1, note, size, "no read-only tmpfs: %s",
                           strerror(errno));
    if (close(open("/dev/owned", O_WRONLY | O_CREAT, 0600)) != 0 ||
        chown("/dev/owned", RT_TEST_NOBODY, RT_TEST_NOBODY) != 0)
        return rt_test_say(1, note, size, "cannot give a file to user %d: %s",
                      RT_TEST_NOBODY, strerror(errno));
    return 0;
}

static const char dev_listing[] = "full null stdout";

/* In a job: 1 when `dir` holds exactly `expected`; else 0, the note saying
 * what it holds. */
static int dir_holds(const char *dir, const char *expected, char *note,
                     size_t size)
{
    char *names = rt_test_dir_names(dir);
    int same = names != NULL && strcmp(names, expected) == 0;
    if (!same)
        rt_test_say(0, note, size, "%s holds `%s`", dir, names ? names : "?");
    free(names);
    return same;
}

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
    if (rt_test_make_pattern(&image, 64, 48) != RT_OK)
        return rt_test_say(1, note, size, "no memory for the image");
    rt_error error = {0}, check = {0};
    rt_status status =
        rt_image_save(c->path, &image, RT_IMAGE_P3, NULL, &error);
    /* the check only opens the device: a full one passes */
    rt_status checked = rt_image_save_check(c->path, NULL, &check);
    rt_image_release(&image);
    if (status != c->expected ||
        (status != RT_OK && (error.status != status ||
                             !strstr(error.message, c->path) ||
                             !strstr(error.message, c->reason))))
        return rt_test_say(1, note, size, "saving to %s returned %s: %s",
                           c->path,
                           rt_status_string(status), error.message);
    if (checked != RT_OK)
        return rt_test_say(1, note, size, "checking %s: %s", c->path,
                           check.message);
    if (!is_device(c->path, c->major_number, c->minor_number))
        return rt_test_say(1, note, size, "%s is no longer the device %u, %u",
                           c->path, c->major_number, c->minor_number);
    if (!dir_holds("/dev", dev_listing, note, size))
        return 1;
    return 0;
}

START_TEST(saving_to_dev_null_succeeds_and_leaves_the_device)
{
    device_case c = {"/dev/null", RT_OK, "", 1, 3};
    char note[1024];
    int code = rt_test_in_child(save_to_device, &c, note, sizeof note);
    ck_assert_msg(code == 0, "%s", note);
}
END_TEST

START_TEST(saving_to_dev_full_says_no_space_and_leaves_the_device)
{
    device_case c = {"/dev/full", RT_ERR_IO, strerror(ENOSPC), 1, 7};
    char note[1024];
    int code = rt_test_in_child(save_to_device, &c, note, sizeof note);
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
    if (rt_test_make_pattern(&image, 200, 150) != RT_OK)
        return rt_test_say(1, note, size, "no memory for the image");
    rt_test_bytes expected = {NULL, 0, 0};
    rt_status status = rt_image_write_to(rt_test_bytes_add, &expected,
                                         &image, RT_IMAGE_P6, NULL);
    int fds[2];
    if (status != RT_OK || pipe(fds) != 0 || dup2(fds[1], 1) != 1)
        return rt_test_say(1, note, size, "cannot set up the pipe");
    close(fds[1]);
    rt_test_copy copy = {NULL, fds[0], 1, received};
    rt_test_child reader = rt_test_child_start(rt_test_copy_job, &copy);
    close(fds[0]);
    rt_error error = {0};
    status = rt_image_save("/dev/stdout", &image, RT_IMAGE_P6, NULL, &error);
    close(1);
    char reader_note[1024];
    int wait_status = reader.pid > 0
                          ? rt_test_child_finish(&reader, reader_note,
                                                 sizeof reader_note)
                          : -1;
    rt_image_release(&image);
    int same = rt_test_file_holds(received, expected.data, expected.size);
    size_t expected_size = expected.size;
    free(expected.data);
    char target[64] = "";
    ssize_t n = readlink("/dev/stdout", target, sizeof target - 1);
    target[n > 0 ? n : 0] = '\0';
    if (status != RT_OK)
        return rt_test_say(1, note, size, "save: %s", error.message);
    if (!WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0)
        return rt_test_say(1, note, size, "the reader failed: %s", reader_note);
    if (!same)
        return rt_test_say(1, note, size, "the pipe did not carry exactly the "
                      "image's %zu bytes", expected_size);
    if (strcmp(target, "/proc/self/fd/1") != 0)
        return rt_test_say(1, note, size, "/dev/stdout is no longer the link "
                      "(readlink: `%s`)", target);
    if (!dir_holds("/dev", dev_listing, note, size))
        return 1;
    return 0;
}

START_TEST(saving_to_dev_stdout_sends_the_bytes_through_the_pipe)
{
    char *dir = rt_test_temp_dir();
    rt_test_path received = rt_test_path_at(dir, "received");
    char note[1024];
    int code = rt_test_in_child(save_to_dev_stdout, received.s, note,
                                sizeof note);
    rt_test_remove_dir(dir);
    ck_assert_msg(code == 0, "%s", note);
}
END_TEST

START_TEST(a_file_of_another_owner_keeps_its_owner_group_and_mode)
{
    char *dir = rt_test_temp_dir();
    rt_test_path path = rt_test_path_at(dir, "theirs.ppm");
    rt_test_write_bytes(path.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    ck_assert_int_eq(chown(path.s, RT_TEST_NOBODY, RT_TEST_NOBODY), 0);
    ck_assert_int_eq(chmod(path.s, 0640), 0);
    rt_image image = rt_test_pattern(12, 8);
    rt_test_bytes expected = rt_test_encode(&image, RT_IMAGE_P6);
    rt_test_save_ok(path.s, &image, RT_IMAGE_P6);
    struct stat st;
    ck_assert_int_eq(lstat(path.s, &st), 0);
    ck_assert_msg(st.st_uid == RT_TEST_NOBODY && st.st_gid == RT_TEST_NOBODY,
                  "owner %u:%u after the save, was %d:%d",
                  (unsigned)st.st_uid, (unsigned)st.st_gid, RT_TEST_NOBODY,
                      RT_TEST_NOBODY);
    ck_assert_uint_eq(st.st_mode & 07777, 0640);
    ck_assert(rt_test_file_holds(path.s, expected.data, expected.size));
    rt_test_assert_dir_holds(dir, "theirs.ppm");
    free(expected.data);
    rt_image_release(&image);
    rt_test_remove_dir(dir);
}
END_TEST

/* Saves and checks at `path`, which must both fail on a read-only file
 * system; returns 0 or fills `note`. */
static int refused_read_only(const char *path, char *note, size_t size)
{
    rt_image image;
    if (rt_test_make_pattern(&image, 8, 8) != RT_OK)
        return rt_test_say(1, note, size, "no memory for the image");
    rt_error error = {0}, check = {0};
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6, NULL, &error);
    rt_status checked = rt_image_save_check(path, NULL, &check);
    rt_image_release(&image);
    if (status != RT_ERR_IO || !strstr(error.message, path) ||
        !strstr(error.message, strerror(EROFS)))
        return rt_test_say(1, note, size, "saving %s: %s: %s", path,
                      rt_status_string(status), error.message);
    if (checked != RT_ERR_IO || strcmp(check.message, error.message))
        return rt_test_say(1, note, size, "checking %s: %s: %s", path,
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
    rt_test_path ro = rt_test_path_at(dir, "ro"),
                 bound = rt_test_path_at(dir, "bound");
    if (mount("rt-test-save", ro.s, "tmpfs", MS_RDONLY, "size=16k") != 0 ||
        mount(bound.s, bound.s, "none", MS_BIND, NULL) != 0 ||
        mount("none", bound.s, "none", MS_REMOUNT | MS_BIND | MS_RDONLY,
              NULL) != 0)
        return rt_test_say(1, note, size, "mount: %s", strerror(errno));
    if (refused_read_only(rt_test_path_at(ro.s, "new.ppm").s, note, size) ||
        refused_read_only(rt_test_path_at(bound.s, "old.ppm").s, note, size))
        return 1;
    if (!dir_holds(ro.s, "", note, size))
        return 1;
    return 0;
}

START_TEST(a_read_only_mount_is_refused_and_left_as_it_was)
{
    char *dir = rt_test_temp_dir();
    rt_test_path ro = rt_test_path_at(dir, "ro"),
                 bound = rt_test_path_at(dir, "bound");
    rt_test_path old = rt_test_path_at(bound.s, "old.ppm");
    ck_assert_int_eq(mkdir(ro.s, 0755), 0);
    ck_assert_int_eq(mkdir(bound.s, 0755), 0);
    rt_test_write_bytes(old.s, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    char note[1024];
    int code = rt_test_in_child(save_on_read_only_mounts, dir, note,
                                sizeof note);
    ck_assert_msg(code == 0, "%s", note);
    ck_assert(rt_test_file_holds(old.s, rt_test_previous_ppm,
                                 sizeof rt_test_previous_ppm - 1));
    rt_test_assert_dir_holds(bound.s, "old.ppm");
    rt_test_assert_dir_holds(ro.s, "");
    rt_test_remove_dir(dir);
}
END_TEST

/* ------------------------------------------------------------------ */

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

int main(void)
{
    char note[1024] = "";
    rt_test_child probe = rt_test_child_start(privileges_job, NULL);
    int status = probe.pid > 0 ? rt_test_child_finish(&probe, note,
                                                      sizeof note) : -1;
    if (status != 0) {
        printf("test_save_privileged: skipped: needs root in a private "
               "mount namespace (%s)\n",
               note[0] ? note : "the probe did not run");
        return 77;
    }
    return rt_test_run_suite(privileged_suite());
}
