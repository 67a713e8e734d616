/*
 * threads.c - the threads of this process (see threads.h).
 */
#include "threads.h"

#include <check.h>
#include <dirent.h>
#include <pthread.h>

#include "clock.h"

int rt_test_thread_count(void)
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

int rt_test_settled_thread_count(int expected, double seconds)
{
    double deadline = rt_test_now() + seconds;
    int count;
    while ((count = rt_test_thread_count()) > expected &&
           rt_test_now() < deadline)
        rt_test_sleep_ms(1);
    return count;
}

static void *do_nothing(void *argument)
{
    return argument;
}

int rt_test_baseline_thread_count(void)
{
    pthread_t thread;
    ck_assert_int_eq(pthread_create(&thread, NULL, do_nothing, NULL), 0);
    ck_assert_int_eq(pthread_join(thread, NULL), 0);
    return rt_test_settled_thread_count(1, 0.2);
}
