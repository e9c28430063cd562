/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/proc.h
 * @brief Timer and IO procs: callbacks registered at run time and dispatched
 *        in registration order by a port thread (timer: 1 kHz, high priority;
 *        IO: low priority).
 *
 * Operating rules
 * - mt_proc_register() takes the kernel lock (registrations from several
 *   threads are serialised); the dispatcher never takes it.
 * - An entry is written completely before the count that makes it visible is
 *   published (release store); the dispatcher loads the count with acquire,
 *   so it never calls a half-written entry. Entries are append-only.
 * - Only the dispatching thread writes the statistics fields.
 * - The dispatcher is not re-entrant: a nested dispatch is refused with
 *   MT_E_BUSY and counted.
 * - A proc must not write the proc set that calls it (proof assumption A1).
 * - Unlike ArduPilot, which drops a ninth proc silently, registration reports
 *   MT_E_FULL, MT_E_DUPLICATE or MT_E_INVALID.
 */
#ifndef MT_PROC_H
#define MT_PROC_H

#include <stdint.h>

#include "mt/config.h"
#include "mt/status.h"
#include "mt_port.h"
#include "mt_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Callback. */
typedef void (*mt_proc_fn_t)(void *arg);

typedef struct {
    mt_proc_fn_t fn; /**< constant once published */
    void *arg;       /**< constant once published */
    uint32_t calls;  /**< completed calls (saturating) */
    uint32_t max_us; /**< longest call */
    uint64_t total_us; /**< sum of call times (saturating) */
} mt_proc_t;

typedef struct {
    mt_proc_t procs[MT_CFG_PROC_MAX];
    uint32_t count;            /**< published entries (release/acquire) */
    uint32_t running;          /**< 1 while a dispatch is under way */
    uint32_t refused;          /**< re-entrant dispatches refused (saturating) */
    uint32_t periods_missed;   /**< periods the dispatching thread missed (saturating) */
    uint64_t dispatches;       /**< completed dispatch rounds */
    uint32_t max_round_us;     /**< longest dispatch round */
} mt_proc_set_t;

/*@ predicate MtProcSetInv(mt_proc_set_t *p) =
        \valid(p) && p->count <= MT_CFG_PROC_MAX && (p->running == 0 || p->running == 1) &&
        (\forall integer i; 0 <= i < p->count ==> p->procs[i].fn != \null);

    predicate MtProcRegistered(mt_proc_set_t *p, mt_proc_fn_t fn, void *arg) =
        \exists integer i; 0 <= i < p->count && p->procs[i].fn == fn && p->procs[i].arg == arg;
*/

/* What mt_proc_register_i and mt_proc_register state alike, from L1 (the call) to L2 (its
 * return): the registered entries keep their function and argument. (The new entry's clauses
 * stay written out: as predicates of the entry, they made the CBMC coverage run of
 * mt_proc_register take over 18 minutes instead of 2 seconds.) */
/*@ predicate MtProcPrefixKept{L1, L2}(mt_proc_set_t *p) =
        \forall integer i; 0 <= i < \at(p->count, L1) ==>
            \at(p->procs[i].fn, L2) == \at(p->procs[i].fn, L1) &&
            \at(p->procs[i].arg, L2) == \at(p->procs[i].arg, L1);
*/

/** Empty set. [init] */
/*@ requires valid: \valid(p);
    assigns *p;
    ensures inv: MtProcSetInv(p);
    ensures empty: p->count == 0 && p->running == 0 && p->refused == 0 &&
                   p->periods_missed == 0 && p->dispatches == 0 && p->max_round_us == 0;
*/
void mt_proc_set_init(mt_proc_set_t *p);

/** Register fn(arg) (the lock-held core of mt_proc_register). I-class.
 *  @retval MT_OK appended at index count-1.
 *  @retval MT_E_INVALID fn is NULL.
 *  @retval MT_E_DUPLICATE the same (fn, arg) is already registered.
 *  @retval MT_E_FULL MT_CFG_PROC_MAX entries are registered. */
/*@ requires held: MtLocked == 1;
    requires inv: MtProcSetInv(p);
    assigns p->procs[p->count], p->count;
    ensures inv: MtProcSetInv(p);
    ensures bounded: p->count <= MT_CFG_PROC_MAX;
    ensures prefix: MtProcPrefixKept{Pre, Post}(p);
    behavior invalid:
      assumes fn == \null;
      ensures status: \result == MT_E_INVALID;
      ensures unchanged: p->count == \old(p->count);
    behavior duplicate:
      assumes fn != \null && MtProcRegistered(p, fn, arg);
      ensures status: \result == MT_E_DUPLICATE;
      ensures unchanged: p->count == \old(p->count);
    behavior full:
      assumes fn != \null && !MtProcRegistered(p, fn, arg) && p->count == MT_CFG_PROC_MAX;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: p->count == \old(p->count);
    behavior ok:
      assumes fn != \null && !MtProcRegistered(p, fn, arg) && p->count < MT_CFG_PROC_MAX;
      ensures status: \result == MT_OK;
      ensures appended: p->count == \old(p->count) + 1;
      ensures entry: p->procs[\old(p->count)].fn == fn && p->procs[\old(p->count)].arg == arg;
      ensures fresh: p->procs[\old(p->count)].calls == 0 && p->procs[\old(p->count)].max_us == 0 &&
                     p->procs[\old(p->count)].total_us == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_proc_register_i(mt_proc_set_t *p, mt_proc_fn_t fn, void *arg);

/** mt_proc_register_i() from task context (takes the kernel lock). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtProcSetInv(p);
    assigns p->procs[p->count], p->count, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtProcSetInv(p);
    ensures prefix: MtProcPrefixKept{Pre, Post}(p);
    behavior invalid:
      assumes fn == \null;
      ensures status: \result == MT_E_INVALID;
      ensures unchanged: p->count == \old(p->count);
    behavior duplicate:
      assumes fn != \null && MtProcRegistered(p, fn, arg);
      ensures status: \result == MT_E_DUPLICATE;
      ensures unchanged: p->count == \old(p->count);
    behavior full:
      assumes fn != \null && !MtProcRegistered(p, fn, arg) && p->count == MT_CFG_PROC_MAX;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: p->count == \old(p->count);
    behavior ok:
      assumes fn != \null && !MtProcRegistered(p, fn, arg) && p->count < MT_CFG_PROC_MAX;
      ensures status: \result == MT_OK;
      ensures appended: p->count == \old(p->count) + 1;
      ensures entry: p->procs[\old(p->count)].fn == fn && p->procs[\old(p->count)].arg == arg;
      ensures fresh: p->procs[\old(p->count)].calls == 0 && p->procs[\old(p->count)].max_us == 0 &&
                     p->procs[\old(p->count)].total_us == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_proc_register(mt_proc_set_t *p, mt_proc_fn_t fn, void *arg);

/** Call every published proc once, in registration order, timing each call (one clock
 *  reading per proc: a call's time runs from the end of the previous one).
 *  [dispatching thread only]
 *  @retval MT_OK
 *  @retval MT_E_BUSY called from inside a proc of the same set (refused, counted). */
/*@ requires inv: MtProcSetInv(p);
    assigns p->procs[0 .. MT_CFG_PROC_MAX - 1].calls, p->procs[0 .. MT_CFG_PROC_MAX - 1].max_us,
            p->procs[0 .. MT_CFG_PROC_MAX - 1].total_us, p->running, p->refused,
            p->dispatches, p->max_round_us, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_PROC(0) .. MT_CALL_PROC(MT_CFG_PROC_MAX - 1)];
    ensures inv: MtProcSetInv(p);
    behavior busy:
      assumes p->running == 1;
      ensures status: \result == MT_E_BUSY;
      ensures none_called: \forall integer i; 0 <= i < MT_CFG_PROC_MAX ==>
          MtCalls[MT_CALL_PROC(i)] == \old(MtCalls[MT_CALL_PROC(i)]);
      ensures counted: p->refused == (\old(p->refused) < 0xFFFFFFFF ? \old(p->refused) + 1 : \old(p->refused));
      ensures still_running: p->running == 1;
    behavior run:
      assumes p->running == 0;
      ensures status: \result == MT_OK;
      ensures idle: p->running == 0;
      ensures each_once: \forall integer i; 0 <= i < p->count ==>
          p->procs[i].calls == (\old(p->procs[i].calls) < 0xFFFFFFFF ? \old(p->procs[i].calls) + 1 : \old(p->procs[i].calls));
      ensures called_once: \forall integer i; 0 <= i < p->count ==>
          MtCalls[MT_CALL_PROC(i)] == MtCount64(\old(MtCalls[MT_CALL_PROC(i)]), 1);
      ensures others_not_called: \forall integer i; p->count <= i < MT_CFG_PROC_MAX ==>
          MtCalls[MT_CALL_PROC(i)] == \old(MtCalls[MT_CALL_PROC(i)]);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_proc_dispatch(mt_proc_set_t *p);

/** Advance an absolute deadline for a periodic thread (no drift): returns the
 *  number of whole periods that were missed and sets *deadline to the first
 *  period boundary after now. A thread sleeps until *deadline, dispatches,
 *  then calls this. */
/*@ requires valid: \valid(deadline);
    requires period: period_us >= 1;
    requires no_overflow: now <= 0xFFFFFFFFFFFFFFFF - 2 * (integer)period_us;
    requires sane: *deadline <= 0xFFFFFFFFFFFFFFFF - period_us;
    assigns *deadline;
    ensures future: *deadline > now;
    ensures grid: (*deadline - \old(*deadline)) % period_us == 0;
    ensures on_time: \old(*deadline) + period_us > now ==> \result == 0 && *deadline == \old(*deadline) + period_us;
    ensures late: \old(*deadline) + period_us <= now ==>
        \result == ((now - \old(*deadline)) / period_us <= 0xFFFFFFFF ? (now - \old(*deadline)) / period_us : 0xFFFFFFFF) &&
        *deadline > now && *deadline <= now + period_us;
*/
uint32_t mt_proc_period_next(uint64_t *deadline, uint64_t now, uint32_t period_us);

/** Add missed periods to the set's counter (saturating). [dispatching thread] */
/*@ requires inv: MtProcSetInv(p);
    assigns p->periods_missed;
    ensures inv: MtProcSetInv(p);
    ensures counted: p->periods_missed == (\old(p->periods_missed) + missed <= 0xFFFFFFFF ?
                        \old(p->periods_missed) + missed : 0xFFFFFFFF);
*/
void mt_proc_note_missed(mt_proc_set_t *p, uint32_t missed);

#ifdef __cplusplus
}
#endif

#endif /* MT_PROC_H */
