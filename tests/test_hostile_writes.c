/*
 * test_hostile_writes.c - failing writes: a failing sink, a full device, a
 * missing directory, a directory as destination, the longest file name, a
 * file-size limit and a full tmpfs; the file at the destination is the old
 * one or the complete new one, never a partial one, and no temporary file is
 * left behind.
 *
 * Tests that need a child process fork one themselves, so that they also
 * hold under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Nothing lost: failing writes                                         */

/* A sink that fails on its n-th call and counts calls after a failure. */
typedef struct failing_sink {
    int calls, fail_at, calls_after_failure;
    size_t bytes;
} failing_sink;

static int failing_write(void *user, const void *data, size_t size)
{
    failing_sink *s = user;
    (void)data;
    if (s->calls > s->fail_at)
        s->calls_after_failure++;
    if (s->calls++ == s->fail_at)
        return 0;
    s->bytes += size;
    return 1;
}

START_TEST(failing_sink_stops_the_writer_with_an_io_error)
{
    rt_image image = rt_test_pattern(37, 11);
    rt_image_format formats[2] = {RT_IMAGE_P3, RT_IMAGE_P6};
    for (int f = 0; f < 2; f++) {
        failing_sink count = {0, INT_MAX, 0, 0};
        ck_assert_int_eq(rt_image_write_to(failing_write, &count, &image,
                                           formats[f], NULL),
                         RT_OK);
        ck_assert_int_gt(count.calls, 2);
        for (int n = 0; n < count.calls; n++) {
            failing_sink s = {0, n, 0, 0};
            ck_assert_int_eq(rt_image_write_to(failing_write, &s, &image,
                                               formats[f], NULL),
                             RT_ERR_IO);
            ck_assert_msg(s.calls_after_failure == 0,
                          "P%d: the writer went on after the sink failed "
                          "on call %d", (int)formats[f], n);
        }
    }
    rt_image_release(&image);
}
END_TEST

/*
 * rt_image_write_file on a full device: the bytes sit in the FILE's buffer,
 * so success can only be known after a flush.  A writer that answers RT_OK
 * when nothing reached the device lets a caller believe an image was saved.
 */
START_TEST(image_write_file_reports_a_full_device)
{
    FILE *full = fopen("/dev/full", "wb");
    if (full == NULL) {
        fprintf(stderr, "test_hostile_writes: no /dev/full; skipped\n");
        return;
    }
    rt_image image = rt_test_pattern(4, 4);
    rt_status status = rt_image_write_file(full, &image, RT_IMAGE_P6, NULL);
    fclose(full);
    rt_image_release(&image);
    ck_assert_msg(status == RT_ERR_IO,
                  "writing to /dev/full returned %s, expected an "
                  "input/output error", rt_status_string(status));
}
END_TEST

START_TEST(save_into_a_missing_directory_leaves_nothing)
{
    char *dir = rt_test_temp_dir();
    char *path = rt_test_join(dir, "missing/out.ppm");
    rt_image image = rt_test_pattern(8, 8);
    rt_error error;
    ck_assert_int_eq(rt_image_save(path, &image, RT_IMAGE_P6, NULL, &error),
                     RT_ERR_IO);
    ck_assert_int_eq(error.status, RT_ERR_IO);
    char expected[PATH_MAX + 128];
    snprintf(expected, sizeof expected,
             "%s: cannot write the image: the folder %s/missing/ does not "
             "exist", path, dir);
    ck_assert_str_eq(error.message, expected);
    rt_test_assert_dir_holds(dir, "");
    /* a path through a regular file, which no user (root included) can
     * write into */
    char *file = rt_test_join(dir, "plain");
    rt_test_write_bytes(file, "x", 1);
    char *through = rt_test_join(dir, "plain/out.ppm");
    ck_assert_int_eq(rt_image_save(through, &image, RT_IMAGE_P6, NULL, &error),
                     RT_ERR_IO);
    ck_assert_ptr_nonnull(strstr(error.message, "plain/ is not a folder"));
    rt_test_assert_dir_holds(dir, "plain");
    /* a read-only directory, when permissions apply to this user */
    ck_assert_int_eq(chmod(dir, 0555), 0);
    char *in_readonly = rt_test_join(dir, "out.ppm");
    rt_status status =
        rt_image_save(in_readonly, &image, RT_IMAGE_P6, NULL, &error);
    ck_assert_int_eq(chmod(dir, 0755), 0);
    if (geteuid() != 0) {
        ck_assert_int_eq(status, RT_ERR_IO);
        ck_assert_ptr_nonnull(strstr(error.message, "Permission denied"));
        rt_test_assert_dir_holds(dir, "plain");
    }
    free(in_readonly);
    free(through);
    free(file);
    free(path);
    rt_image_release(&image);
    rt_test_remove_dir(dir);
}
END_TEST

/* Saving over a directory fails at the rename: the directory stays and the
 * temporary file is removed. */
START_TEST(save_over_a_directory_fails_and_removes_its_temporary_file)
{
    char *dir = rt_test_temp_dir();
    char *target = rt_test_join(dir, "image.ppm");
    ck_assert_int_eq(mkdir(target, 0755), 0);
    rt_image image = rt_test_pattern(8, 8);
    rt_error error;
    ck_assert_int_eq(rt_image_save(target, &image, RT_IMAGE_P6, NULL, &error),
                     RT_ERR_IO);
    ck_assert_ptr_nonnull(strstr(error.message, "cannot write the image"));
    rt_test_assert_dir_holds(dir, "image.ppm");
    struct stat st;
    ck_assert_int_eq(stat(target, &st), 0);
    ck_assert(S_ISDIR(st.st_mode));
    rt_image_release(&image);
    free(target);
    rt_test_remove_dir(dir);
}
END_TEST

/* A destination name of NAME_MAX bytes is a valid file name; the temporary
 * name must fit too. */
START_TEST(save_to_the_longest_file_name_works)
{
    char *dir = rt_test_temp_dir();
    char name[256];
    long name_max = pathconf(dir, _PC_NAME_MAX);
    size_t length = name_max > 0 && name_max < 255 ? (size_t)name_max : 255;
    memset(name, 'n', length);
    memcpy(name + length - 4, ".ppm", 4);
    name[length] = '\0';
    char *path = rt_test_join(dir, name);
    rt_image image = rt_test_pattern(3, 2);
    rt_error error;
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6, NULL, &error);
    char *names = rt_test_dir_names(dir);
    ck_assert_ptr_nonnull(names);
    rt_image_release(&image);
    free(path);
    rt_test_remove_dir(dir);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    ck_assert_str_eq(names, name);
    free(names);
}
END_TEST

/* In a child: saves a 200 x 200 image over the previous file in `dir`,
 * which the caller has made too small to hold it; the save must fail. */
static int save_must_fail(const char *dir, char *message, size_t size)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/out.ppm", dir);
    rt_image image;
    if (rt_image_init(&image, 200, 200, NULL) != RT_OK) {
        snprintf(message, size, "no memory for the image");
        return 2;
    }
    rt_error error;
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6, NULL, &error);
    rt_image_release(&image);
    snprintf(message, size, "%s", status == RT_OK ? "saved" : error.message);
    return status == RT_ERR_IO ? 0 : 1;
}

/* A disk that fills up: a file-size limit makes the write fail (EFBIG)
 * half-way through, as a full disk would (ENOSPC). */
static int save_with_file_size_limit(void *arg, char *message, size_t size)
{
    signal(SIGXFSZ, SIG_IGN);
    struct rlimit limit = {16384, 16384};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) {
        snprintf(message, size, "setrlimit: %s", strerror(errno));
        return 2;
    }
    return save_must_fail(arg, message, size);
}

static void check_failed_save(const char *dir, int code, const char *message,
                              const char *reason)
{
    ck_assert_msg(code == 0, "the save did not fail as it should: %s",
                  message);
    ck_assert_msg(strstr(message, reason) != NULL,
                  "the message does not say `%s`: %s", reason, message);
    char *path = rt_test_join(dir, "out.ppm");
    rt_test_assert_previous_intact(path);
    free(path);
    rt_test_assert_dir_holds(dir, "out.ppm");
}

START_TEST(save_that_exceeds_the_file_size_limit_keeps_the_previous_file)
{
    char *dir = rt_test_temp_dir();
    char *path = rt_test_join(dir, "out.ppm");
    rt_test_write_bytes(path, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1);
    char message[1024];
    int code = rt_test_in_child(save_with_file_size_limit, dir, message,
                                sizeof message);
    check_failed_save(dir, code, message, "File too large");
    free(path);
    rt_test_remove_dir(dir);
}
END_TEST

/* A full disk for real: a 64 KB tmpfs mounted in a private mount namespace
 * of a child (needs root or CAP_SYS_ADMIN; skipped otherwise). */
static int save_on_a_full_tmpfs(void *arg, char *message, size_t size)
{
    const char *dir = arg;
    if (unshare(CLONE_NEWNS) != 0 ||
        /* the type is ignored here, but valgrind checks it is a string */
        mount("none", "/", "none", MS_REC | MS_PRIVATE, NULL) != 0 ||
        mount("rt-hostile", dir, "tmpfs", 0, "size=64k,mode=0755") != 0) {
        snprintf(message, size, "no tmpfs: %s", strerror(errno));
        return 3;
    }
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/out.ppm", dir);
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || write(fd, rt_test_previous_ppm,
                        sizeof rt_test_previous_ppm - 1) !=
                      (ssize_t)(sizeof rt_test_previous_ppm - 1)) {
        snprintf(message, size, "cannot write the previous file");
        return 2;
    }
    close(fd);
    int code = save_must_fail(dir, message, size);
    if (code != 0)
        return code;
    /* check the tmpfs from inside: the caller cannot see it */
    char text[600];
    snprintf(text, sizeof text, "%s", message);
    FILE *file = fopen(path, "rb");
    char data[64] = "";
    size_t n = file ? fread(data, 1, sizeof data, file) : 0;
    if (file)
        fclose(file);
    if (n != sizeof rt_test_previous_ppm - 1 ||
        memcmp(data, rt_test_previous_ppm, n) != 0) {
        snprintf(message, size, "the previous file was changed: %s", text);
        return 1;
    }
    DIR *d = opendir(dir);
    struct dirent *entry;
    int others = 0;
    while (d && (entry = readdir(d)) != NULL)
        others += entry->d_name[0] != '.' && strcmp(entry->d_name, "out.ppm");
    if (d)
        closedir(d);
    if (others) {
        snprintf(message, size, "a temporary file was left: %s", text);
        return 1;
    }
    snprintf(message, size, "%s", text);
    return 0;
}

START_TEST(save_on_a_full_disk_keeps_the_previous_file)
{
    char *dir = rt_test_temp_dir();
    char message[1024];
    int code = rt_test_in_child(save_on_a_full_tmpfs, dir, message,
                                sizeof message);
    rt_test_remove_dir(dir);
    if (code == 3) {
        fprintf(stderr,
                "test_hostile_writes: full-disk test skipped (%s); the "
                "file-size limit test covers it\n",
                message);
    } else {
        ck_assert_msg(code == 0, "%s", message);
        ck_assert_msg(strstr(message, "No space left on device") != NULL,
                      "the message does not say the disk is full: %s",
                      message);
    }
}
END_TEST

static Suite *hostile_writes_suite(void)
{
    Suite *s = suite_create("hostile_writes");
    TCase *tc = tcase_create("nothing lost");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, failing_sink_stops_the_writer_with_an_io_error);
    tcase_add_test(tc, image_write_file_reports_a_full_device);
    tcase_add_test(tc, save_into_a_missing_directory_leaves_nothing);
    tcase_add_test(tc, save_over_a_directory_fails_and_removes_its_temporary_file);
    tcase_add_test(tc, save_to_the_longest_file_name_works);
    tcase_add_test(tc, save_that_exceeds_the_file_size_limit_keeps_the_previous_file);
    tcase_add_test(tc, save_on_a_full_disk_keeps_the_previous_file);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(hostile_writes_suite)
