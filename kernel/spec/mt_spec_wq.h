/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_wq.h
 * @brief ACSL logic for the work queues (mt/wq.h): the FIFO and the queue invariant, what an
 *        operation keeps, the clauses that the task, `_i` and `_isr` forms of an operation
 *        share, and the named clauses of the timer tick, the single shot and the reports.
 *
 * The predicates read mt_wq_t and mt_work_t, so mt/wq.h includes this header after its types
 * and before its contracts: include mt/wq.h, not this header. Only ACSL lives here: to a C
 * compiler this header is empty.
 */
#ifndef MT_SPEC_WQ_H
#define MT_SPEC_WQ_H

#ifndef MT_WQ_H
#error "mt_spec_wq.h is included by mt/wq.h, after the work queue types"
#endif

/* FIFO positions relative to the head, the queue invariant, an attached item. */
/*@ logic integer MtWqRel(mt_wq_t *q, integer p) =
        p >= q->head ? p - q->head : p + MT_CFG_WQ_MAX_ITEMS - q->head;

    logic integer MtWqTail(mt_wq_t *q) =
        q->head + q->count < MT_CFG_WQ_MAX_ITEMS ? q->head + q->count
                                                  : q->head + q->count - MT_CFG_WQ_MAX_ITEMS;

    predicate MtWqQueued(mt_wq_t *q, integer s) = MtWqRel(q, q->where[s]) < q->count;

    predicate MtWqFifo(mt_wq_t *q) =
        q->nitems <= MT_CFG_WQ_MAX_ITEMS && q->head < MT_CFG_WQ_MAX_ITEMS &&
        q->count <= MT_CFG_WQ_MAX_ITEMS &&
        (\forall integer p; 0 <= p < MT_CFG_WQ_MAX_ITEMS ==>
            q->order[p] < MT_CFG_WQ_MAX_ITEMS && q->where[q->order[p]] == p) &&
        (\forall integer s; 0 <= s < MT_CFG_WQ_MAX_ITEMS ==>
            q->where[s] < MT_CFG_WQ_MAX_ITEMS && q->order[q->where[s]] == s) &&
        (\forall integer p; 0 <= p < MT_CFG_WQ_MAX_ITEMS ==>
            MtWqRel(q, p) < q->count ==> q->order[p] < q->nitems);

    predicate MtWqSlots(mt_wq_t *q) =
        (\forall integer s; 0 <= s < MT_CFG_WQ_MAX_ITEMS ==>
            MtSemInv(&q->slot[s].done) && q->slot[s].shot <= MT_WQ_SHOT_DONE &&
            q->slot[s].timer <= MT_WQ_TIMER_EVERY &&
            (q->slot[s].timer == MT_WQ_TIMER_EVERY ==> q->slot[s].period_us >= 1)) &&
        (\forall integer s; 0 <= s < q->nitems ==> q->slot[s].fn != \null);

    predicate MtWqRunner(mt_wq_t *q) =
        (q->running == MT_WQ_NONE || q->running < q->nitems) && q->stop <= 1;

    predicate MtWqInv(mt_wq_t *q) =
        \valid(q) && MtWqFifo(q) && MtWqSlots(q) && MtWqRunner(q) && MtSemInv(&q->wake);

    predicate MtWorkAttached(mt_work_t *w) =
        \valid_read(w) && w->wq != \null && \separated(w, w->wq) && MtWqInv(w->wq) &&
        w->slot < w->wq->nitems;
*/

/* Every item queued at L1 is still queued at L2, at the same distance from the head: FIFO
 * order is kept (an activation only appends). No item but s became queued. Attached items
 * stay attached with their functions. */
/*@ predicate MtWqFifoKept{L1, L2}(mt_wq_t *q) =
        \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==> \at(MtWqQueued(q, t), L1) ==>
            \at(MtWqQueued(q, t), L2) && \at(MtWqRel(q, q->where[t]), L2) == \at(MtWqRel(q, q->where[t]), L1);

    predicate MtWqItemsKept{L1, L2}(mt_wq_t *q) =
        \at(q->nitems, L2) >= \at(q->nitems, L1) &&
        \forall integer t; 0 <= t < \at(q->nitems, L1) ==>
            \at(q->slot[t].fn, L2) == \at(q->slot[t].fn, L1) && \at(q->slot[t].arg, L2) == \at(q->slot[t].arg, L1);

    lemma MtWqItemsKept_trans{L1, L2, L3}: \forall mt_wq_t *q;
        MtWqItemsKept{L1, L2}(q) ==> MtWqItemsKept{L2, L3}(q) ==> MtWqItemsKept{L1, L3}(q);

    predicate MtWqIdleKept{L1, L2}(mt_wq_t *q, integer s) =
        \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==> t != s ==>
            !\at(MtWqQueued(q, t), L1) ==> !\at(MtWqQueued(q, t), L2);
*/

/* Item callbacks called from L1 to L2 (the ghost MtCalls, mt_invoke.h): none, or item s's
 * once and no other. */
/*@ predicate MtWqNoneCalled{L1, L2} =
        \forall integer k; 0 <= k < MT_CFG_WQ_MAX_ITEMS ==>
            \at(MtCalls[MT_CALL_WORK(k)], L2) == \at(MtCalls[MT_CALL_WORK(k)], L1);

    predicate MtWqCalledOnly{L1, L2}(integer s) =
        \at(MtCalls[MT_CALL_WORK(s)], L2) == MtCount64(\at(MtCalls[MT_CALL_WORK(s)], L1), 1) &&
        \forall integer k; 0 <= k < MT_CFG_WQ_MAX_ITEMS ==> k != s ==>
            \at(MtCalls[MT_CALL_WORK(k)], L2) == \at(MtCalls[MT_CALL_WORK(k)], L1);
*/

/* The queue's saturating counters (one more, or n more, stopping at the type's maximum) and a timer
 * deadline d microseconds after now (stopping at the end of 64-bit time). */
/*@ logic integer MtWqInc32(integer x) = x < 0xFFFFFFFF ? x + 1 : 0xFFFFFFFF;

    logic integer MtWqInc64(integer x) = x < 0xFFFFFFFFFFFFFFFF ? x + 1 : 0xFFFFFFFFFFFFFFFF;

    logic integer MtWqAdd64(integer x, integer n) =
        x + n <= 0xFFFFFFFFFFFFFFFF ? x + n : 0xFFFFFFFFFFFFFFFF;

    logic integer MtWqAfter(integer now, integer d) =
        now + d <= 0xFFFFFFFFFFFFFFFF ? now + d : 0xFFFFFFFFFFFFFFFF;
*/

/* Slot s as attached: idle (not queued, no timer, no single-shot waiter), and statistics st
 * that start from zero. */
/*@ predicate MtWqSlotIdle(mt_wq_t *q, integer s) =
        !MtWqQueued(q, s) && q->slot[s].timer == MT_WQ_TIMER_OFF && q->slot[s].shot == MT_WQ_SHOT_NONE;

    predicate MtWqStatsFresh(mt_wq_stats_t *st) =
        st->starts == 0 && st->runs == 0 && st->total_run_us == 0 && st->first_start_us == 0 &&
        st->last_start_us == 0 && st->max_run_us == 0 && st->min_interval_us == 0 &&
        st->max_interval_us == 0 && st->max_latency_us == 0 && st->merged == 0 && st->missed == 0;
*/

/* The clauses that the task, `_i` and `_isr` forms of an operation share (mt_wq_attach and
 * _i; mt_work_schedule, _i and _isr; mt_work_schedule_delayed and _i; mt_work_cancel and _i):
 * - MtWorkApart: an item to attach, apart from the queue;
 * - MtWqScheduleStatus: the statuses the task forms return;
 * - MtWorkMerged: merged exactly when the item was queued at L1;
 * - MtWorkTimer: the item's timer state is v (armed, stopped). */
/*@ predicate MtWorkApart(mt_wq_t *q, mt_work_t *w) = \valid(w) && \separated(w, q);

    predicate MtWqScheduleStatus(integer r) = r == MT_OK || r == MT_W_WQ_MERGED;

    predicate MtWorkMerged{L1, L2}(mt_work_t *w, integer r) =
        r == MT_W_WQ_MERGED <==> \at(MtWqQueued(w->wq, w->slot), L1);

    predicate MtWorkTimer(mt_work_t *w, integer v) = w->wq->slot[w->slot].timer == v;
*/

/* The item's timer (state, deadline, period) is the same at L2 as at L1. */
/*@ predicate MtWorkTimerKept{L1, L2}(mt_work_t *w) =
        \at(w->wq->slot[w->slot].timer, L2) == \at(w->wq->slot[w->slot].timer, L1) &&
        \at(w->wq->slot[w->slot].deadline_us, L2) == \at(w->wq->slot[w->slot].deadline_us, L1) &&
        \at(w->wq->slot[w->slot].period_us, L2) == \at(w->wq->slot[w->slot].period_us, L1);
*/

/* Attached slots (those below nitems at L1) keep their functions and arguments at L2. */
/*@ predicate MtWqFnsKept{L1, L2}(mt_wq_t *q) =
        \forall integer s; 0 <= s < \at(q->nitems, L1) ==>
            \at(q->slot[s].fn, L2) == \at(q->slot[s].fn, L1) && \at(q->slot[s].arg, L2) == \at(q->slot[s].arg, L1);
*/

/* Item w was appended at L2: one more queued item, w the last of them. */
/*@ predicate MtWorkAppended{L1, L2}(mt_work_t *w) =
        \at(w->wq->count, L2) == \at(w->wq->count, L1) + 1 &&
        \at(MtWqRel(w->wq, w->wq->where[w->slot]), L2) == \at(w->wq->count, L1);
*/

/* What an activation of slot s of q states, in every form (mt_wq_schedule_slot_i,
 * mt_work_schedule_i and its task and ISR forms), from L1 to L2:
 * MtWqDepth          the depth mark is raised to the queue's new length (kept otherwise);
 * MtWqMergesKept     neither merge count moved (a queued activation);
 * MtWqMergesCounted  both merge counts moved, saturating (a merged activation);
 * MtWqWoken          the thread's semaphore was signalled (mt/sem.h: MtSemSignalled);
 * MtWqNotWoken       it was not (MtSemUnsignalled). */
/*@ predicate MtWqDepth{L1, L2}(mt_wq_t *q) =
        \at(q->max_depth, L2) == (\at(q->max_depth, L1) < \at(q->count, L2) ?
                                  \at(q->count, L2) : \at(q->max_depth, L1));

    predicate MtWqMergesKept{L1, L2}(mt_wq_t *q, integer s) =
        \at(q->slot[s].stats.merged, L2) == \at(q->slot[s].stats.merged, L1) &&
        \at(q->stats.merged, L2) == \at(q->stats.merged, L1);

    predicate MtWqMergesCounted{L1, L2}(mt_wq_t *q, integer s) =
        \at(q->slot[s].stats.merged, L2) == MtWqInc32(\at(q->slot[s].stats.merged, L1)) &&
        \at(q->stats.merged, L2) == MtWqInc32(\at(q->stats.merged, L1));

    predicate MtWqWoken{L1, L2}(mt_wq_t *q) = MtSemSignalled{L1, L2}(\at(&q->wake, L1));

    predicate MtWqNotWoken{L1, L2}(mt_wq_t *q) = MtSemUnsignalled{L1, L2}(\at(&q->wake, L1));
*/

/* The timer tick at now (mt_wq_timer_tick_i) from L1 to L2, over the slots attached at L2:
 * the item of a due timer is queued, a timer not due is unchanged, a due ONCE timer is
 * stopped, every EVERY timer is ahead of now; what was queued at L1 still is. */
/*@ predicate MtWqTickDueQueued{L1, L2}(mt_wq_t *q, integer now) =
        \forall integer s; 0 <= s < \at(q->nitems, L2) ==>
            \at(q->slot[s].timer, L1) != MT_WQ_TIMER_OFF ==> \at(q->slot[s].deadline_us, L1) <= now ==>
            \at(MtWqQueued(q, s), L2);

    predicate MtWqQueuedKept{L1, L2}(mt_wq_t *q) =
        \forall integer s; 0 <= s < MT_CFG_WQ_MAX_ITEMS ==>
            \at(MtWqQueued(q, s), L1) ==> \at(MtWqQueued(q, s), L2);

    predicate MtWqTickNotDue{L1, L2}(mt_wq_t *q, integer now) =
        \forall integer s; 0 <= s < \at(q->nitems, L2) ==>
            (\at(q->slot[s].timer, L1) == MT_WQ_TIMER_OFF || \at(q->slot[s].deadline_us, L1) > now) ==>
            \at(q->slot[s].timer, L2) == \at(q->slot[s].timer, L1) &&
            \at(q->slot[s].deadline_us, L2) == \at(q->slot[s].deadline_us, L1);

    predicate MtWqTickOnceStops{L1, L2}(mt_wq_t *q, integer now) =
        \forall integer s; 0 <= s < \at(q->nitems, L2) ==>
            \at(q->slot[s].timer, L1) == MT_WQ_TIMER_ONCE ==> \at(q->slot[s].deadline_us, L1) <= now ==>
            \at(q->slot[s].timer, L2) == MT_WQ_TIMER_OFF;

    predicate MtWqEveryAhead(mt_wq_t *q, integer now) =
        \forall integer s; 0 <= s < q->nitems ==>
            q->slot[s].timer == MT_WQ_TIMER_EVERY ==> q->slot[s].deadline_us > now;
*/

/* A single shot refused (another caller waits): the item's single-shot state and the queue's
 * length are the same at L2 as at L1. */
/*@ predicate MtWorkShotKept{L1, L2}(mt_work_t *w) =
        \at(w->wq->slot[w->slot].shot, L2) == \at(w->wq->slot[w->slot].shot, L1) &&
        \at(w->wq->count, L2) == \at(w->wq->count, L1);
*/

/* Reports: an item's report r and the statistics st it was taken from (mt_work_report); a
 * queue's report r and its queue q (mt_wq_report). */
/*@ predicate MtWorkReportRuns(mt_work_report_t *r, mt_wq_stats_t *st) =
        r->runs == st->runs && r->starts == st->starts;

    predicate MtWorkReportCounts(mt_work_report_t *r, mt_wq_stats_t *st) =
        r->merged == st->merged && r->missed == st->missed;

    predicate MtWorkReportIntervalGuarded(mt_work_report_t *r, mt_wq_stats_t *st) =
        st->starts < 2 ==> r->mean_interval_us == 0 && r->rate_mhz == 0;

    predicate MtWqReportCounts(mt_wq_report_t *r, mt_wq_t *q) =
        r->merged == q->stats.merged && r->missed == q->stats.missed && r->refused == q->refused;
*/

/* The time fields each report copies (the means and the rate, 64-bit quotients, are pinned
 * only when zero: see the reports' mean_guarded clauses). */
/*@ predicate MtWorkReportTimes(mt_work_report_t *r, mt_wq_stats_t *st) =
        r->max_run_us == st->max_run_us && r->min_interval_us == st->min_interval_us &&
        r->max_interval_us == st->max_interval_us && r->max_latency_us == st->max_latency_us;

    predicate MtWqReportTimes(mt_wq_report_t *r, mt_wq_stats_t *st) =
        r->max_run_us == st->max_run_us && r->min_interval_us == st->min_interval_us &&
        r->max_interval_us == st->max_interval_us && r->max_latency_us == st->max_latency_us;
*/

#endif /* MT_SPEC_WQ_H */
