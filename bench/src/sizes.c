/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file sizes.c
 * @brief RAM per kernel object: one array per type whose size is
 *        sizeof(type). Compiled (not linked) for the target; bench/run.py reads
 *        the symbol sizes with `nm -S`. Build with -DMT_CFG_SCHED_MAX_TASKS=N
 *        and/or -DMT_CFG_CACHE_LINE=N for the variants.
 */
#include "mt/mt.h"

char bench_sizeof_mt_bring_t[sizeof(mt_bring_t)];
char bench_sizeof_mt_oring_t[sizeof(mt_oring_t)];
char bench_sizeof_mt_sem_t[sizeof(mt_sem_t)];
char bench_sizeof_mt_proc_set_t[sizeof(mt_proc_set_t)];
char bench_sizeof_mt_proc_t[sizeof(mt_proc_t)];
char bench_sizeof_mt_sched_t[sizeof(mt_sched_t)];
char bench_sizeof_mt_task_state_t[sizeof(mt_task_state_t)];
char bench_sizeof_mt_task_t[sizeof(mt_task_t)];
char bench_sizeof_mt_time_ext_t[sizeof(mt_time_ext_t)];
