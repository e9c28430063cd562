/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file bench_util.h
 * @brief Helpers shared by the bench programs (C and C++): time, CPU pinning,
 *        an optimisation barrier, medians.
 *
 * Every callgrind entry point is a NOINL extern "C" function named bench_*,
 * so `valgrind --tool=callgrind --toggle-collect=bench_xxx` counts exactly the
 * instructions executed inside it (and its callees).
 */
#ifndef BENCH_UTIL_H
#define BENCH_UTIL_H

#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#ifdef __cplusplus
#define BENCH_EXTERN_C extern "C"
#else
#define BENCH_EXTERN_C
#endif

#define NOINL __attribute__((noinline, noclone))

/* Keep v in a register the compiler cannot see through (costs 0 instructions). */
#define BENCH_OPAQUE(v) __asm__ volatile("" : "+r"(v))
/* Compiler-only memory barrier. */
#define BENCH_CLOBBER() __asm__ volatile("" ::: "memory")

static inline double bench_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Pin the calling thread to cpu; returns 1 on success, 0 if not possible. */
static inline int bench_pin(int cpu)
{
    cpu_set_t set;
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (cpu < 0 || n <= 0 || cpu >= n) {
        return 0;
    }
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return pthread_setaffinity_np(pthread_self(), sizeof(set), &set) == 0;
}

static inline int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) ? -1 : (x > y) ? 1 : 0;
}

/* Sort v in place; return the median. */
static inline double bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof(double), bench_cmp_double);
    return (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static inline long bench_env_long(const char *name, long dflt, long minimum)
{
    const char *s = getenv(name);
    long v = dflt;
    if (s != NULL && *s != '\0') {
        v = strtol(s, NULL, 10);
    }
    return (v < minimum) ? minimum : v;
}

/* One line of machine-readable output: "RESULT key value". The driver
 * (bench/run.py) parses these. */
#define BENCH_RESULT(key, fmt, ...) printf("RESULT %s " fmt "\n", key, __VA_ARGS__)

#endif /* BENCH_UTIL_H */
