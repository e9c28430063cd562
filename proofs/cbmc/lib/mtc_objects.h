/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mtc_objects.h
 * @brief Nondeterministic kernel objects for the CBMC harnesses.
 *
 * Each constructor allocates a registered object (mtc_alloc) whose every field is
 * nondeterministic, except what is needed to give it storage of the right size. The
 * function's requires, assumed by the harness, then selects the legal states. Values are
 * not bounded: indices, capacities, counters and times range up to their types' maxima.
 * Only lengths that drive loops are bounded (proofs/assumptions.json lists every bound).
 */
#ifndef MTC_OBJECTS_H
#define MTC_OBJECTS_H

#include "mtc_logic.h"

/* Loop-driving lengths (bytes copied by one call, object size, table length). */
#define MTC_LEN_MAX 4u   /* bytes per ring read/write call */
#define MTC_ELEM_MAX 4u  /* bytes per object-ring element */
#define MTC_TASKS_MAX 3u /* entries in a task table */

/* Ring capacities (proofs/assumptions.json, B1). `make cbmc`: every capacity in [1, MTC_CAP_SMALL],
 * so every wrap pattern of the mirror indices occurs, with indices, counters and lengths
 * nondeterministic. `make cbmc-max` (MTC_BIG): the two largest capacities (2^30 - 1 and
 * 2^30 for the byte ring; for the object ring the two largest for each element size), with
 * 31-bit nondeterministic indices. Both tiers together cover the small and the extreme
 * capacities; a fully symbolic 30-bit capacity is too hard for the SAT back end within the
 * time budget. WP covers every capacity. */
#define MTC_CAP_SMALL 8u
#if defined(MTC_BIG)
#define MTC_CAP_TOP MT_BRING_CAP_MAX
#define MTC_ORING_CAP_TOP(elem) (MT_ORING_BYTES_MAX / (elem) - 1u)
#else
#define MTC_CAP_TOP MTC_CAP_SMALL
#define MTC_ORING_CAP_TOP(elem) MTC_CAP_SMALL
#endif
int mtc_cap_ok(uint32_t cap, uint32_t top);

/* A byte ring (capacity: see above) over its own buffer of cap bytes; every index, cache
 * and reservation nondeterministic in [0, 2^32) (the requires selects the legal ones). */
mt_bring_t *mtc_bring(void);

/* An object ring of any capacity, elements of 1..elem_max bytes, storage of
 * (cap + 1) * elem <= MT_ORING_BYTES_MAX bytes. */
mt_oring_t *mtc_oring(uint32_t elem_max);

/* A scheduler whose table has 1..nmax entries (own object); loop rate from
 * mtc_loop_rates_ok and task rates from mtc_task_rates (B13), every other field any value
 * (ticks, run ticks, statistics, times: up to their types' maxima). */
mt_sched_t *mtc_sched(uint32_t nmax);

/* A task table of n entries, any contents. */
mt_task_t *mtc_tasks(uint32_t n);

/* Loop rates (Hz): the minimum, a middle value and the maximum of the valid range; with
 * `invalid`, also values outside it (0, 49, 2001, UINT32_MAX). */
uint32_t mtc_loop_rate(int invalid);

/* Give each of the n tasks a rate (mHz) from a set relative to the loop rate: 0 (a fast
 * task), 1 (the slowest), 1000, loop_rate * 1000 / 3, loop_rate * 1000 (the fastest normal
 * task), loop_rate * 1000 + 1 and UINT32_MAX (invalid). Rates divide the loop rate in the
 * interval computation: a non-linear operand, hence a set (B13). */
void mtc_task_rates(mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz);

/* A proc set, any contents (the requires bounds count by MT_CFG_PROC_MAX). */
mt_proc_set_t *mtc_proc_set(void);

/* A semaphore: token any value, waiter NULL or a parked thread, merged any value. */
mt_sem_t *mtc_sem(void);

/* A time extender, any contents. */
mt_time_ext_t *mtc_time_ext(void);

/* A byte buffer of n bytes, any contents. */
uint8_t *mtc_bytes(uint32_t n);

/* One of the n values (nondeterministic choice). Used for the operand of a non-linear
 * operation (a product or quotient of two variables) whose other operand stays fully
 * nondeterministic (proofs/assumptions.json, B13). */
uint32_t mtc_pick_u32(const uint32_t *vals, uint32_t n);
#define MTC_PICK(arr) mtc_pick_u32((arr), (uint32_t)(sizeof(arr) / sizeof((arr)[0])))

/* A nondeterministic non-NULL callback (never called: assumption A1, proofs/assumptions.json). */
void *mtc_callback(void);

/* A work queue (MT_CFG_WQ_MAX_ITEMS = 2, Makefile.common, assumption B1) with every field
 * nondeterministic except the pointers: each slot's function is NULL or a callback stand-in,
 * each semaphore's waiter NULL or a parked thread (the requires, MtWqInv, then selects the
 * legal states: any permutation, head, count, counters, times, timers, single-shot states). */
mt_wq_t *mtc_wq(void);

/* Give each slot of q an interval from a set: 1, 3, 1000 and 0xFFFFFFFF us. It is the divisor
 * of mt_proc_period_next's 64-bit division when a timer fires (a non-linear operand, hence a
 * set: assumption B1); deadlines, times and every other field stay nondeterministic. */
void mtc_wq_periods(mt_wq_t *q);
/** Time window of the timer harnesses (assumption B9): now and every slot's deadline in
 *  [0, 2^21) with now < 2^20, or in [UINT64_MAX - 2^21, UINT64_MAX] with now >= UINT64_MAX - 2^20. */
void mtc_wq_time_window(const mt_wq_t *q, uint64_t now);
/** The port clock for the timer-proc harness (assumption B9): mt_port_now_us's contract
 *  (monotonic, recorded in MtPortNow), advancing by at most 2^20 us per read. */
uint64_t mtc_now_in_window(void);

/* A work item handle attached to q at a nondeterministic slot (the requires bounds it). */
mt_work_t *mtc_work(mt_wq_t *q);

/* A mission object with every field nondeterministic (the function's requires, MtMissionInv,
 * selects the legal states: any commands, kinds, jump targets, repeat counts, counters and
 * cursors the invariant allows), built with MT_CFG_MISSION_MAX_CMDS = 4 (Makefile.common,
 * assumption B1). */
mt_mission_t *mtc_mission(void);

/* A candidate command list of n commands, every field nondeterministic. */
mt_mission_cmd_t *mtc_mission_cmds(uint32_t n);

/* A topic (topic bus, built with BUS_CBMC_CFG: messages of 1..2 bytes, queues of 1..4, 2
 * notifiers, 2 reliable subscribers, 2 copy attempts; assumption B7) over its own storage of
 * size * qlen bytes; every other field nondeterministic (generations, stamps, counters up to
 * their maxima; notifier callbacks NULL or a callback stand-in). */
mt_topic_t *mtc_topic(void);

/* A subscriber of t: every field nondeterministic (the requires selects the legal ones), its
 * semaphore's waiter NULL or a parked thread. */
mt_sub_t *mtc_sub(mt_topic_t *t);

#endif /* MTC_OBJECTS_H */
