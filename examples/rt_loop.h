/*
 * rt_loop.h - the fixed-rate loop of the real-time examples (rig_realtime.c,
 * rig_sil.c): what a program needs to run as a real-time task on Linux and
 * to time its steps.  Header-only, for the examples; not part of the library.
 *
 *   rt_task()               lock the memory, ask for SCHED_FIFO, pin to the
 *                           last processor; prints what it got (a task without
 *                           the rights runs as an ordinary process)
 *   rt_start(&next)         the loop's time origin
 *   rt_wait(&next, period)  sleep to the next period (TIMER_ABSTIME: no drift)
 *   rt_now_us()             a monotonic clock [us]
 *   rt_report(us, n, label) sorts the n step times and prints min, median,
 *                           p99 and max
 */
#ifndef RT_LOOP_H
#define RT_LOOP_H

#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

static double rt_now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e6 * (double)ts.tv_sec + 1e-3 * (double)ts.tv_nsec;
}

/* real-time task: no page faults, not preempted by ordinary processes, not
 * moved between processors */
static void rt_task(void)
{
    struct sched_param sp;
    const int locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
    int pinned = 0;
#ifdef __linux__
    cpu_set_t cpus;
    const long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    CPU_ZERO(&cpus);
    CPU_SET(ncpu > 1 ? (int)ncpu - 1 : 0, &cpus);
    pinned = sched_setaffinity(0, sizeof cpus, &cpus) == 0;
#endif
    sp.sched_priority = sched_get_priority_max(SCHED_FIFO) - 1;
    printf("memory %slocked, SCHED_FIFO %s, %s\n", locked ? "" : "not ",
           sched_setscheduler(0, SCHED_FIFO, &sp) == 0 ? "on" : "refused",
           pinned ? "pinned to the last processor" : "not pinned");
}

static void rt_start(struct timespec *next)
{
    clock_gettime(CLOCK_MONOTONIC, next);
}

static void rt_wait(struct timespec *next, double period)
{
    next->tv_nsec += (long)(period * 1e9);
    while (next->tv_nsec >= 1000000000L) {
        next->tv_nsec -= 1000000000L;
        next->tv_sec++;
    }
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, next, NULL);
}

static int rt_cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void rt_report(double *us, long n, double period, const char *label)
{
    if (n < 1)
        return;
    qsort(us, (size_t)n, sizeof us[0], rt_cmp);
    printf("%ld steps of %.1f ms%s: step time min %.1f us, median %.1f us, p99 %.1f us, "
           "max %.1f us\n", n, period * 1e3, label, us[0], us[n / 2],
           us[(long)(0.99 * (n - 1))], us[n - 1]);
}

#endif
