/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/wq.h
 * @brief Work queues (PX4 style): work items run to completion, in FIFO order,
 *        by one thread per queue; scheduled now, after a delay or on an interval
 *        (from the 1 kHz timer procs), with merged activations counted. This header
 *        has the rules, the types, attach, immediate activation and the runners; the
 *        timers are in mt/wq_timer.h (mt/mt.h includes both).
 *
 * Operating rules
 * - A queue (mt_wq_t) is served by one thread of the port at its own priority
 *   (prio_base + prio_offset; hal_posix/ and hal_chibios/ start it). The
 *   thread body is mt_wq_thread_body(): wait on the queue's binary semaphore
 *   `wake`, pop the oldest queued item, run it with the kernel lock released,
 *   repeat. Items of one queue never run concurrently; items of different
 *   queues are pre-empted by priority only.
 * - An item (mt_work_t: run function and argument) is attached to exactly one
 *   queue, for good (mt_wq_attach); the queue holds MT_CFG_WQ_MAX_ITEMS items
 *   and refuses more with MT_E_FULL. The queue keeps each item's state and
 *   statistics in a slot record; the item handle names the slot.
 * - The FIFO is bounded with no heap: `order` is a permutation of the slot
 *   numbers whose positions head, head + 1, ... (modulo the capacity), count
 *   of them, are the queued items, oldest first; `where` is its inverse. An
 *   item is queued at most once, so the FIFO never overflows.
 * - Scheduling an item that is already queued merges into the pending run:
 *   MT_W_WQ_MERGED, counted in the item's and the queue's `merged` (PX4
 *   merges silently). Scheduling an item while it runs queues it again: it
 *   runs once more afterwards. Every activation is therefore a run, a counted
 *   merge, or still queued (tla/Wq.tla, NoLostActivation).
 * - Delayed and interval items: a per-slot timer (the queue's bounded timer
 *   registry) that mt_wq_timer_tick_i() checks; register mt_wq_timer_proc
 *   with the queue as argument in the 1 kHz timer proc set. Interval items
 *   keep absolute deadlines (no drift, mt_proc_period_next); periods the
 *   timer could not serve in time are counted in `missed`.
 * - Single shot (PX4 WorkItemSingleShot): mt_work_run_wait() schedules an item
 *   and waits, with a timeout, for a run that starts after the call to end.
 * - Topic notifications: mt_work_notify_i() has the `void (*)(void *)` shape
 *   of a publish callback (uORB SubscriptionCallback); the argument is the
 *   mt_work_t to schedule, with the lock held.
 * - Locking: every field is written under the kernel lock, except that run
 *   statistics are written only by the runner (the context whose run is in
 *   progress, `running`); a second runner is refused with MT_E_BUSY. A run
 *   function must not block; it may schedule any item, itself included.
 * - Function classes: no suffix = task context (takes the kernel lock);
 *   `_i` = kernel lock held (task or ISR); `_isr` = interrupt handler.
 * - Contracts are sequential (assumption C2); where the lock is released
 *   (around a run and while a single-shot caller waits) the helpers' contracts
 *   allow for what other contexts may change (assumption W2). The interleavings are checked by
 *   tla/Wq.tla.
 */
#ifndef MT_WQ_H
#define MT_WQ_H

#include <stdint.h>

#include "mt/config.h"
#include "mt/proc.h"
#include "mt/sem.h"
#include "mt/status.h"
#include "mt_port.h"
#include "mt_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** No slot (mt_wq_t.running when no run is in progress). */
#define MT_WQ_NONE 0xFFFFFFFFu

/** Timer states of a slot. */
#define MT_WQ_TIMER_OFF 0u   /**< no timer */
#define MT_WQ_TIMER_ONCE 1u  /**< one activation at deadline_us (delayed item) */
#define MT_WQ_TIMER_EVERY 2u /**< activations every period_us from deadline_us */

/** Single-shot states of a slot (mt_work_run_wait). */
#define MT_WQ_SHOT_NONE 0u  /**< nobody waits */
#define MT_WQ_SHOT_ARMED 1u /**< a caller waits for the next run to start */
#define MT_WQ_SHOT_RUN 2u   /**< the run the caller waits for is in progress */
#define MT_WQ_SHOT_DONE 3u  /**< that run has ended; the caller has not returned yet */

/** Run function of a work item. */
typedef void (*mt_work_fn_t)(void *arg);

/** Statistics of an item or of a whole queue (microseconds; saturating). */
typedef struct {
    uint64_t starts;          /**< runs started */
    uint64_t runs;            /**< runs completed */
    uint64_t total_run_us;    /**< sum of run times */
    uint64_t first_start_us;  /**< start of the first run */
    uint64_t last_start_us;   /**< start of the latest run */
    uint32_t max_run_us;      /**< longest run */
    uint32_t min_interval_us; /**< shortest time between two starts (0 before two starts) */
    uint32_t max_interval_us; /**< longest time between two starts */
    uint32_t max_latency_us;  /**< longest time from the first pending activation to the start */
    uint32_t merged;          /**< activations merged into a pending run */
    uint32_t missed;          /**< interval periods the timer could not serve in time */
} mt_wq_stats_t;

/** State of one attached item, kept by its queue. */
typedef struct {
    mt_work_fn_t fn;        /**< run function (constant once attached) */
    void *arg;              /**< its argument (constant once attached) */
    uint64_t queued_us;     /**< time of the first activation of the pending run */
    uint64_t deadline_us;   /**< next activation of the timer */
    uint32_t period_us;     /**< interval of an EVERY timer (>= 1) */
    uint32_t timer;         /**< MT_WQ_TIMER_* */
    uint32_t shot;          /**< MT_WQ_SHOT_* */
    mt_sem_t done;          /**< single-shot completion */
    mt_wq_stats_t stats;
} mt_wq_slot_t;

typedef struct mt_wq {
    const char *name;          /**< for reports and the thread name */
    mt_prio_base_t prio_base;  /**< priority of the serving thread: base ... */
    int8_t prio_offset;        /**< ... plus offset */
    uint8_t order[MT_CFG_WQ_MAX_ITEMS]; /**< FIFO position -> slot (a permutation) */
    uint8_t where[MT_CFG_WQ_MAX_ITEMS]; /**< slot -> FIFO position (its inverse) */
    uint32_t nitems;           /**< attached items: slots [0, nitems) */
    uint32_t head;             /**< position of the oldest queued item */
    uint32_t count;            /**< queued items */
    uint32_t running;          /**< slot whose run is in progress, or MT_WQ_NONE */
    uint32_t stop;             /**< 1: the serving thread is asked to return */
    uint32_t max_depth;        /**< most items queued at once */
    uint32_t refused;          /**< runs refused to a second runner (saturating) */
    uint64_t run_start_us;     /**< start of the run in progress */
    mt_sem_t wake;             /**< signalled on every activation and at stop */
    mt_wq_stats_t stats;       /**< the queue's totals */
    mt_wq_slot_t slot[MT_CFG_WQ_MAX_ITEMS];
} mt_wq_t;

/** A work item: run function and argument; attached to one queue. */
typedef struct mt_work {
    mt_work_fn_t fn;  /**< run function */
    void *arg;        /**< its argument */
    mt_wq_t *wq;      /**< the queue (NULL until attached) */
    uint32_t slot;    /**< its slot in that queue */
} mt_work_t;

/** Report of one item (derived values computed without division by zero). */
typedef struct {
    uint64_t starts;           /**< runs started */
    uint64_t runs;             /**< runs completed */
    uint32_t mean_run_us;      /**< 0 before the first completed run */
    uint32_t max_run_us;
    uint32_t mean_interval_us; /**< mean time between starts; 0 before two starts */
    uint32_t min_interval_us;
    uint32_t max_interval_us;
    uint32_t rate_mhz;         /**< 10^9 / mean interval (millihertz); 0 before two starts */
    uint32_t max_latency_us;
    uint32_t merged;
    uint32_t missed;
    uint32_t queued;           /**< 1 while a run is pending */
    uint32_t running;          /**< 1 while it runs */
    uint32_t timer;            /**< MT_WQ_TIMER_* */
    uint32_t period_us;        /**< interval of an EVERY timer, else 0 */
} mt_work_report_t;

/** Report of a queue. */
typedef struct {
    const char *name;
    uint64_t starts;
    uint64_t runs;
    uint32_t mean_run_us;
    uint32_t max_run_us;
    uint32_t mean_interval_us; /**< between starts of any of its items */
    uint32_t min_interval_us;
    uint32_t max_interval_us;
    uint32_t max_latency_us;
    uint32_t merged;
    uint32_t missed;
    uint32_t items;            /**< attached */
    uint32_t depth;            /**< queued now */
    uint32_t max_depth;
    uint32_t refused;
} mt_wq_report_t;

// cppcheck-suppress misra-c2012-20.1 ; D-107 ACSL only (empty to C), after the types it names
#include "mt_spec_wq.h"

/** Set up an empty queue whose thread is to run at base + offset (the port
 *  checks the priority when it creates the thread). [init] */
/*@ requires valid: \valid(q);
    assigns *q;
    ensures inv: MtWqInv(q);
    ensures empty: q->nitems == 0 && q->count == 0 && q->running == MT_WQ_NONE && q->stop == 0;
    ensures prio: q->name == name && q->prio_base == base && q->prio_offset == offset;
    ensures zeroed: MtWqStatsFresh(&q->stats) && q->max_depth == 0 && q->refused == 0;
    ensures no_wake: q->wake.token == 0 && q->wake.waiter == \null;
*/
void mt_wq_init(mt_wq_t *q, const char *name, mt_prio_base_t base, int8_t offset);

/** Set up an item (not attached yet). [init] */
/*@ requires valid: \valid(w);
    assigns *w;
    ensures fields: w->fn == fn && w->arg == arg;
    ensures detached: w->wq == \null && w->slot == 0;
*/
void mt_work_init(mt_work_t *w, mt_work_fn_t fn, void *arg);

/* What mt_wq_attach_i and mt_wq_attach state alike, from L1 (the call) to L2 (its return):
 * MtWqAttachKept  a refusal: the queue's item count and the item's queue unchanged;
 * MtWqAppended    the item is attached to q at the slot after the last, one more item;
 * MtWqSlotEntry   its slot holds the item's function and argument;
 * MtWqSlotNoWaiter  its single-shot semaphore has no token and no waiter. */
/*@ predicate MtWqAttachKept{L1, L2}(mt_wq_t *q, mt_work_t *w) =
        \at(q->nitems, L2) == \at(q->nitems, L1) && \at(w->wq, L2) == \at(w->wq, L1);

    predicate MtWqAppended{L1, L2}(mt_wq_t *q, mt_work_t *w) =
        \at(w->wq, L2) == q && \at(w->slot, L2) == \at(q->nitems, L1) &&
        \at(q->nitems, L2) == \at(q->nitems, L1) + 1;

    predicate MtWqSlotEntry(mt_wq_t *q, mt_work_t *w) =
        q->slot[w->slot].fn == w->fn && q->slot[w->slot].arg == w->arg;

    predicate MtWqSlotNoWaiter(mt_wq_t *q, integer k) =
        q->slot[k].done.token == 0 && q->slot[k].done.waiter == \null;
*/

/** Attach an item to a queue (the lock-held core of mt_wq_attach). I-class.
 *  @retval MT_OK attached to slot nitems - 1, idle, statistics zero.
 *  @retval MT_E_INVALID the item has no run function.
 *  @retval MT_E_DUPLICATE the item is already attached (to this or another queue).
 *  @retval MT_E_FULL the queue holds MT_CFG_WQ_MAX_ITEMS items. */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires item: MtWorkApart(q, w);
    assigns w->wq, w->slot, q->nitems, q->slot[q->nitems];
    ensures inv: MtWqInv(q);
    ensures others: MtWqFnsKept{Pre, Post}(q);
    behavior invalid:
      assumes w->fn == \null;
      ensures status: \result == MT_E_INVALID;
      ensures unchanged: MtWqAttachKept{Pre, Post}(q, w);
    behavior duplicate:
      assumes w->fn != \null && w->wq != \null;
      ensures status: \result == MT_E_DUPLICATE;
      ensures unchanged: MtWqAttachKept{Pre, Post}(q, w);
    behavior full:
      assumes w->fn != \null && w->wq == \null && q->nitems == MT_CFG_WQ_MAX_ITEMS;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: MtWqAttachKept{Pre, Post}(q, w);
    behavior ok:
      assumes w->fn != \null && w->wq == \null && q->nitems < MT_CFG_WQ_MAX_ITEMS;
      ensures status: \result == MT_OK;
      ensures attached: MtWqAppended{Pre, Post}(q, w);
      ensures item: MtWorkAttached(w);
      ensures entry: MtWqSlotEntry(q, w);
      ensures idle: MtWqSlotIdle(q, w->slot);
      ensures fresh: MtWqStatsFresh(&q->slot[w->slot].stats);
      ensures no_waiter: MtWqSlotNoWaiter(q, w->slot);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_wq_attach_i(mt_wq_t *q, mt_work_t *w);

/** mt_wq_attach_i() from task context (takes the kernel lock). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    requires item: MtWorkApart(q, w);
    assigns w->wq, w->slot, q->nitems, q->slot[q->nitems], MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv(q);
    ensures others: MtWqFnsKept{Pre, Post}(q);
    behavior invalid:
      assumes w->fn == \null;
      ensures status: \result == MT_E_INVALID;
      ensures unchanged: MtWqAttachKept{Pre, Post}(q, w);
    behavior duplicate:
      assumes w->fn != \null && w->wq != \null;
      ensures status: \result == MT_E_DUPLICATE;
      ensures unchanged: MtWqAttachKept{Pre, Post}(q, w);
    behavior full:
      assumes w->fn != \null && w->wq == \null && q->nitems == MT_CFG_WQ_MAX_ITEMS;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: MtWqAttachKept{Pre, Post}(q, w);
    behavior ok:
      assumes w->fn != \null && w->wq == \null && q->nitems < MT_CFG_WQ_MAX_ITEMS;
      ensures status: \result == MT_OK;
      ensures attached: MtWqAppended{Pre, Post}(q, w);
      ensures item: MtWorkAttached(w);
      ensures entry: MtWqSlotEntry(q, w);
      ensures idle: MtWqSlotIdle(q, w->slot);
      ensures fresh: MtWqStatsFresh(&q->slot[w->slot].stats);
      ensures no_waiter: MtWqSlotNoWaiter(q, w->slot);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_wq_attach(mt_wq_t *q, mt_work_t *w);

/** Activate an item now: queue it at the end of the FIFO and wake the queue's
 *  thread, or merge into its pending run. I-class (task or ISR, lock held).
 *  @retval MT_OK queued (it was idle, or running: it runs once more).
 *  @retval MT_W_WQ_MERGED it was already queued: merged into that run (counted). */
/*@ requires held: MtLocked == 1;
    requires item: MtWorkAttached(w);
    assigns w->wq->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], w->wq->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            w->wq->count, w->wq->max_depth, w->wq->slot[w->slot].queued_us,
            w->wq->slot[w->slot].stats.merged, w->wq->stats.merged, w->wq->wake, MtPortNow, MtPortWakes;
    ensures item: MtWorkAttached(w);
    ensures queued: MtWqQueued(w->wq, w->slot);
    ensures fifo_kept: MtWqFifoKept{Pre, Post}(w->wq);
    ensures others_idle: MtWqIdleKept{Pre, Post}(w->wq, w->slot);
    ensures time: MtPortNow >= \old(MtPortNow);
    behavior queue:
      assumes !MtWqQueued(w->wq, w->slot);
      ensures status: \result == MT_OK;
      ensures tail: MtWorkAppended{Pre, Post}(w);
      ensures stamped: w->wq->slot[w->slot].queued_us == MtPortNow;
      ensures depth: MtWqDepth{Pre, Post}(w->wq);
      ensures not_merged: MtWqMergesKept{Pre, Post}(w->wq, w->slot);
      ensures woken: MtWqWoken{Pre, Post}(w->wq);
    behavior merge:
      assumes MtWqQueued(w->wq, w->slot);
      ensures status: \result == MT_W_WQ_MERGED;
      ensures same: w->wq->count == \old(w->wq->count);
      ensures counted: MtWqMergesCounted{Pre, Post}(w->wq, w->slot);
      ensures stamp_kept: w->wq->slot[w->slot].queued_us == \old(w->wq->slot[w->slot].queued_us);
      ensures depth_kept: w->wq->max_depth == \old(w->wq->max_depth);
      ensures not_woken: MtWqNotWoken{Pre, Post}(w->wq);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_schedule_i(mt_work_t *w);

/** mt_work_schedule_i() from task context. */
/*@ requires not_held: MtLocked == 0;
    requires item: MtWorkAttached(w);
    assigns w->wq->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], w->wq->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            w->wq->count, w->wq->max_depth, w->wq->slot[w->slot].queued_us,
            w->wq->slot[w->slot].stats.merged, w->wq->stats.merged, w->wq->wake, MtPortNow, MtPortWakes, MtLocked;
    ensures released: MtLocked == 0;
    ensures item: MtWorkAttached(w);
    ensures queued: MtWqQueued(w->wq, w->slot);
    ensures status: MtWqScheduleStatus(\result);
    ensures merged: MtWorkMerged{Pre, Post}(w, \result);
    ensures fifo_kept: MtWqFifoKept{Pre, Post}(w->wq);
    ensures others_idle: MtWqIdleKept{Pre, Post}(w->wq, w->slot);
    ensures time: MtPortNow >= \old(MtPortNow);
    behavior queue:
      assumes !MtWqQueued(w->wq, w->slot);
      ensures status: \result == MT_OK;
      ensures tail: MtWorkAppended{Pre, Post}(w);
      ensures stamped: w->wq->slot[w->slot].queued_us == MtPortNow;
      ensures depth: MtWqDepth{Pre, Post}(w->wq);
      ensures not_merged: MtWqMergesKept{Pre, Post}(w->wq, w->slot);
      ensures woken: MtWqWoken{Pre, Post}(w->wq);
    behavior merge:
      assumes MtWqQueued(w->wq, w->slot);
      ensures status: \result == MT_W_WQ_MERGED;
      ensures same: w->wq->count == \old(w->wq->count);
      ensures counted: MtWqMergesCounted{Pre, Post}(w->wq, w->slot);
      ensures stamp_kept: w->wq->slot[w->slot].queued_us == \old(w->wq->slot[w->slot].queued_us);
      ensures depth_kept: w->wq->max_depth == \old(w->wq->max_depth);
      ensures not_woken: MtWqNotWoken{Pre, Post}(w->wq);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_schedule(mt_work_t *w);

/** mt_work_schedule_i() from an interrupt handler. */
/*@ requires not_held: MtLocked == 0;
    requires item: MtWorkAttached(w);
    assigns w->wq->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], w->wq->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            w->wq->count, w->wq->max_depth, w->wq->slot[w->slot].queued_us,
            w->wq->slot[w->slot].stats.merged, w->wq->stats.merged, w->wq->wake, MtPortNow, MtPortWakes, MtLocked;
    ensures released: MtLocked == 0;
    ensures item: MtWorkAttached(w);
    ensures queued: MtWqQueued(w->wq, w->slot);
    ensures status: MtWqScheduleStatus(\result);
    ensures merged: MtWorkMerged{Pre, Post}(w, \result);
    ensures fifo_kept: MtWqFifoKept{Pre, Post}(w->wq);
    ensures others_idle: MtWqIdleKept{Pre, Post}(w->wq, w->slot);
    ensures time: MtPortNow >= \old(MtPortNow);
    behavior queue:
      assumes !MtWqQueued(w->wq, w->slot);
      ensures status: \result == MT_OK;
      ensures tail: MtWorkAppended{Pre, Post}(w);
      ensures stamped: w->wq->slot[w->slot].queued_us == MtPortNow;
      ensures depth: MtWqDepth{Pre, Post}(w->wq);
      ensures not_merged: MtWqMergesKept{Pre, Post}(w->wq, w->slot);
      ensures woken: MtWqWoken{Pre, Post}(w->wq);
    behavior merge:
      assumes MtWqQueued(w->wq, w->slot);
      ensures status: \result == MT_W_WQ_MERGED;
      ensures same: w->wq->count == \old(w->wq->count);
      ensures counted: MtWqMergesCounted{Pre, Post}(w->wq, w->slot);
      ensures stamp_kept: w->wq->slot[w->slot].queued_us == \old(w->wq->slot[w->slot].queued_us);
      ensures depth_kept: w->wq->max_depth == \old(w->wq->max_depth);
      ensures not_woken: MtWqNotWoken{Pre, Post}(w->wq);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_schedule_isr(mt_work_t *w);

/** Notification callback (the `void (*)(void *)` of a publish hook): schedule
 *  the mt_work_t at `item` with the lock held, as mt_work_schedule_i(); a
 *  merge is counted in the item's statistics. I-class. */
/*@ requires held: MtLocked == 1;
    requires item: MtWorkAttached((mt_work_t *)item);
    assigns ((mt_work_t *)item)->wq->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            ((mt_work_t *)item)->wq->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            ((mt_work_t *)item)->wq->count, ((mt_work_t *)item)->wq->max_depth,
            ((mt_work_t *)item)->wq->slot[((mt_work_t *)item)->slot].queued_us,
            ((mt_work_t *)item)->wq->slot[((mt_work_t *)item)->slot].stats.merged,
            ((mt_work_t *)item)->wq->stats.merged, ((mt_work_t *)item)->wq->wake, MtPortNow, MtPortWakes;
    ensures item: MtWorkAttached((mt_work_t *)item);
    ensures queued: MtWqQueued(((mt_work_t *)item)->wq, ((mt_work_t *)item)->slot);
*/
void mt_work_notify_i(void *item);

/** Run the oldest queued item once, with the lock released while it runs
 *  (task context; normally called by the queue's thread).
 *  @retval MT_OK an item ran (its statistics and the queue's are updated; a
 *          single-shot caller waiting for that run is released).
 *  @retval MT_E_EMPTY nothing is queued.
 *  @retval MT_E_BUSY another runner's run is in progress (refused, counted). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    assigns *q, MtPortNow, MtPortWakes, MtLocked, MtCalls[MT_CALL_WORK(0) .. MT_CALL_WORK(MT_CFG_WQ_MAX_ITEMS - 1)];
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv(q);
    ensures items_kept: MtWqItemsKept{Pre, Post}(q);
    behavior busy:
      assumes q->running != MT_WQ_NONE;
      ensures status: \result == MT_E_BUSY;
      ensures none_called: MtWqNoneCalled{Pre, Post};
      ensures counted: q->refused == MtWqInc32(\old(q->refused));
      ensures still: q->running == \old(q->running) && q->count == \old(q->count);
    behavior empty:
      assumes q->running == MT_WQ_NONE && q->count == 0;
      ensures status: \result == MT_E_EMPTY;
      ensures unchanged: q->running == MT_WQ_NONE && q->count == 0 &&
                         q->stats.runs == \old(q->stats.runs);
      ensures none_called: MtWqNoneCalled{Pre, Post};
    behavior run:
      assumes q->running == MT_WQ_NONE && q->count > 0;
      ensures status: \result == MT_OK;
      ensures idle: q->running == MT_WQ_NONE;
      ensures ran: q->slot[\old(q->order[q->head])].stats.runs ==
                   MtWqInc64(\old(q->slot[q->order[q->head]].stats.runs));
      ensures started: q->slot[\old(q->order[q->head])].stats.starts ==
                       MtWqInc64(\old(q->slot[q->order[q->head]].stats.starts));
      ensures ran_wq: q->stats.runs == MtWqInc64(\old(q->stats.runs));
      ensures called_once: MtWqCalledOnly{Pre, Post}(\old(q->order[q->head]));
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_wq_run_once(mt_wq_t *q);

/** Run queued items until none is left or max have run (task context; for
 *  tests in simulated time and for draining at shutdown): mt_wq_run_once()
 *  until it returns something else than MT_OK. Returns the number of items
 *  run; fewer than max only when the queue was found empty, or when another
 *  runner's run was in progress at the call (then none, and the refusal is
 *  counted unless max is 0). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    assigns *q, MtPortNow, MtPortWakes, MtLocked, MtCalls[MT_CALL_WORK(0) .. MT_CALL_WORK(MT_CFG_WQ_MAX_ITEMS - 1)];
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv(q);
    ensures bounded: \result <= max;
    ensures items_kept: MtWqItemsKept{Pre, Post}(q);
    behavior busy:
      assumes q->running != MT_WQ_NONE;
      ensures none: \result == 0;
      ensures none_called: MtWqNoneCalled{Pre, Post};
      ensures counted: q->refused == (max > 0 ? MtWqInc32(\old(q->refused)) : \old(q->refused));
      ensures still: q->running == \old(q->running);
    behavior idle:
      assumes q->running == MT_WQ_NONE;
      ensures drained: \result < max ==> q->count == 0;
      ensures ran_wq: q->stats.runs == MtWqAdd64(\old(q->stats.runs), \result);
      ensures idle: q->running == MT_WQ_NONE;
    complete behaviors;
    disjoint behaviors;
*/
uint32_t mt_wq_run_pending(mt_wq_t *q, uint32_t max);

/** One round of the queue's thread: return at once if a stop was requested;
 *  else run one item, or, when none could run, wait on `wake`.
 *  @retval MT_OK go on.
 *  @retval MT_E_STATE a stop was requested (mt_wq_request_stop).
 *  @retval MT_E_BUSY another thread already waits on this queue. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    assigns *q, MtPortNow, MtPortWakes, MtPortHandoffs, MtLocked, MtCalls[MT_CALL_WORK(0) .. MT_CALL_WORK(MT_CFG_WQ_MAX_ITEMS - 1)];
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv(q);
    behavior stop:
      assumes q->stop != 0;
      ensures status: \result == MT_E_STATE;
    behavior serve:
      assumes q->stop == 0;
      ensures status: \result == MT_OK || \result == MT_E_BUSY;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_wq_serve_once(mt_wq_t *q);

/** Body of the queue's thread (an mt_thread_fn_t; the argument is the
 *  queue): mt_wq_serve_once() until it returns anything but MT_OK. It does
 *  not terminate unless a stop is requested (no loop variant). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv((mt_wq_t *)arg);
    assigns *((mt_wq_t *)arg), MtPortNow, MtPortWakes, MtPortHandoffs, MtLocked, MtCalls[MT_CALL_WORK(0) .. MT_CALL_WORK(MT_CFG_WQ_MAX_ITEMS - 1)];
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv((mt_wq_t *)arg);
*/
void mt_wq_thread_body(void *arg);

/** Ask the queue's thread to return (it finishes the run in progress). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    assigns q->stop, q->wake, MtPortWakes, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv(q);
    ensures stopping: q->stop == 1;
    ensures woken: MtWqWoken{Pre, Post}(q);
*/
void mt_wq_request_stop(mt_wq_t *q);

/** Single shot: activate the item and wait, up to timeout_us (0: do not
 *  wait; MT_WAIT_FOREVER: no limit), for a run of it that starts after this
 *  call to end. Task context; not from the item's own queue thread.
 *  @retval MT_OK such a run has ended.
 *  @retval MT_E_TIMEOUT it has not ended in time (the activation stays; the
 *          run still happens, and leaves no stale completion behind).
 *  @retval MT_E_BUSY another caller is already waiting for this item. */
/*@ requires not_held: MtLocked == 0;
    requires item: MtWorkAttached(w);
    assigns *(w->wq), MtPortNow, MtPortWakes, MtPortHandoffs, MtLocked;
    ensures released: MtLocked == 0;
    ensures item: MtWorkAttached(w);
    behavior busy:
      assumes w->wq->slot[w->slot].shot != MT_WQ_SHOT_NONE;
      ensures status: \result == MT_E_BUSY;
      ensures unchanged: MtWorkShotKept{Pre, Post}(w);
    behavior wait:
      assumes w->wq->slot[w->slot].shot == MT_WQ_SHOT_NONE;
      ensures status: \result == MT_OK || \result == MT_E_TIMEOUT;
      ensures disarmed: w->wq->slot[w->slot].shot == MT_WQ_SHOT_NONE;
      ensures no_stale: w->wq->slot[w->slot].done.token == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_run_wait(mt_work_t *w, uint64_t timeout_us);

/** Report of one item (a snapshot taken under the kernel lock). */
/*@ requires not_held: MtLocked == 0;
    requires item: MtWorkAttached(w);
    requires out: \valid(r) && \separated(r, w, w->wq);
    assigns *r, MtLocked;
    ensures released: MtLocked == 0;
    ensures runs: MtWorkReportRuns(r, &w->wq->slot[w->slot].stats);
    ensures counts: MtWorkReportCounts(r, &w->wq->slot[w->slot].stats);
    ensures mean_guarded: w->wq->slot[w->slot].stats.runs == 0 ==> r->mean_run_us == 0;
    ensures interval_guarded: MtWorkReportIntervalGuarded(r, &w->wq->slot[w->slot].stats);
    ensures queued: (r->queued == 0 || r->queued == 1) && (r->queued == 1 <==> \old(MtWqQueued(w->wq, w->slot)));
    ensures running: r->running == (w->wq->running == w->slot ? 1 : 0);
    ensures times: MtWorkReportTimes(r, &w->wq->slot[w->slot].stats);
    ensures timer: r->timer == w->wq->slot[w->slot].timer &&
        r->period_us == (w->wq->slot[w->slot].timer == MT_WQ_TIMER_EVERY ? w->wq->slot[w->slot].period_us : 0);
*/
void mt_work_report(const mt_work_t *w, mt_work_report_t *r);

/** Report of a queue (a snapshot taken under the kernel lock). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    requires out: \valid(r) && \separated(r, q);
    assigns *r, MtLocked;
    ensures released: MtLocked == 0;
    ensures runs: r->runs == q->stats.runs && r->starts == q->stats.starts;
    ensures counts: MtWqReportCounts(r, q);
    ensures sizes: r->items == q->nitems && r->depth == q->count && r->max_depth == q->max_depth;
    ensures mean_guarded: q->stats.runs == 0 ==> r->mean_run_us == 0;
    ensures interval_guarded: q->stats.starts < 2 ==> r->mean_interval_us == 0;
    ensures name: r->name == q->name;
    ensures times: MtWqReportTimes(r, &q->stats);
*/
void mt_wq_report(const mt_wq_t *q, mt_wq_report_t *r);

#ifdef __cplusplus
}
#endif

#endif /* MT_WQ_H */
