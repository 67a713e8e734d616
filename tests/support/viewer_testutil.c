/*
 * viewer_testutil.c - helpers of the viewer's test suites (see
 * viewer_testutil.h).
 */
#include "viewer_testutil.h"

#include <dirent.h>
#include <pthread.h>
#include <stdio.h>
#include <time.h>

#include "testutil.h"

double viewer_now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void viewer_sleep_ms(int ms)
{
    struct timespec ts = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&ts, NULL);
}

int viewer_thread_count(void)
{
    DIR *dir = opendir("/proc/self/task");
    ck_assert_msg(dir != NULL, "cannot open /proc/self/task");
    int count = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL)
        if (entry->d_name[0] != '.')
            count++;
    closedir(dir);
    return count;
}

int viewer_settled_thread_count(int expected, double seconds)
{
    double deadline = viewer_now_seconds() + seconds;
    int count;
    while ((count = viewer_thread_count()) > expected &&
           viewer_now_seconds() < deadline)
        viewer_sleep_ms(1);
    return count;
}

static void *do_nothing(void *argument)
{
    return argument;
}

int viewer_baseline_thread_count(void)
{
    pthread_t thread;
    ck_assert_int_eq(pthread_create(&thread, NULL, do_nothing, NULL), 0);
    ck_assert_int_eq(pthread_join(thread, NULL), 0);
    return viewer_settled_thread_count(1, 0.2);
}

void viewer_write_scene(const char *path, const char *background)
{
    FILE *file = fopen(path, "w");
    ck_assert_msg(file != NULL, "cannot write %s", path);
    fprintf(file,
            "0,0,10\n0,0,5, 4,0,5, 64,48\n6\n"
            "-9.37,-5.73,0\n9.71,-5.38,0\n0.31,13.1,0\n"
            "-1.13,-1.27,2\n1.58,-0.93,2\n-0.17,1.74,2\n2\n"
            "1,2,3, 0, 180,180,180\n4,5,6, 0.4, 40,120,255\n"
            "%s\n-3.875,0.125,4, 255,255,255\n",
            background);
    ck_assert_int_eq(fclose(file), 0);
}
