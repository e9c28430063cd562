/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wq_report.c
 * @brief Work queues, the reports of an item and of a queue (see mt/wq.h).
 */
#include "mt/wq.h"

#include "mt_sat.h"
#include "mt_wq_int.h"

/* ---- reports ------------------------------------------------------------------------------- */

/*@ requires valid: \valid_read(st);
    assigns \nothing;
    ensures guarded: st->runs == 0 ==> \result == 0;
*/
static uint32_t mean_run_us(const mt_wq_stats_t *st)
{
    return (st->runs == 0u) ? 0u : mt_clamp_u32(st->total_run_us / st->runs);
}

/*@ requires valid: \valid_read(st);
    assigns \nothing;
    ensures guarded: st->starts < 2 ==> \result == 0;
*/
static uint32_t mean_interval_us(const mt_wq_stats_t *st)
{
    return (st->starts < 2u) ? 0u
                             : mt_clamp_u32(mt_sub_sat_u64(st->last_start_us, st->first_start_us) /
                                            (st->starts - 1u));
}

/* The statistics and timer part of an item's report. */
/*@ requires valid: \valid_read(e) && \valid(r) && \separated(r, e);
    assigns r->starts, r->runs, r->mean_run_us, r->max_run_us, r->mean_interval_us,
            r->min_interval_us, r->max_interval_us, r->rate_mhz, r->max_latency_us, r->merged,
            r->missed, r->timer, r->period_us;
    ensures runs: r->runs == e->stats.runs && r->starts == e->stats.starts;
    ensures counts: r->merged == e->stats.merged && r->missed == e->stats.missed;
    ensures mean_guarded: e->stats.runs == 0 ==> r->mean_run_us == 0;
    ensures interval_guarded: e->stats.starts < 2 ==> r->mean_interval_us == 0 && r->rate_mhz == 0;
    ensures maxima: r->max_run_us == e->stats.max_run_us && r->min_interval_us == e->stats.min_interval_us &&
                    r->max_interval_us == e->stats.max_interval_us &&
                    r->max_latency_us == e->stats.max_latency_us;
    ensures timer: r->timer == e->timer && r->period_us == (e->timer == MT_WQ_TIMER_EVERY ? e->period_us : 0);
*/
static void fill_work_report(const mt_wq_slot_t *e, mt_work_report_t *r)
{
    uint32_t iv = mean_interval_us(&e->stats);

    r->starts = e->stats.starts;
    r->runs = e->stats.runs;
    r->mean_run_us = mean_run_us(&e->stats);
    r->max_run_us = e->stats.max_run_us;
    r->mean_interval_us = iv;
    r->min_interval_us = e->stats.min_interval_us;
    r->max_interval_us = e->stats.max_interval_us;
    r->rate_mhz = (iv == 0u) ? 0u : (1000000000u / iv);
    r->max_latency_us = e->stats.max_latency_us;
    r->merged = e->stats.merged;
    r->missed = e->stats.missed;
    r->timer = e->timer;
    r->period_us = (e->timer == MT_WQ_TIMER_EVERY) ? e->period_us : 0u;
}

void mt_work_report(const mt_work_t *w, mt_work_report_t *r)
{
    const mt_wq_t *q = w->wq;

    uint32_t queued;
    uint32_t running = 0u;

    mt_port_lock();
    queued = mt_wq_is_queued(q, w->slot);
    if (q->running == w->slot) {
        running = 1u;
    }
    fill_work_report(&q->slot[w->slot], r);
    r->queued = queued;
    r->running = running;
    mt_port_unlock();
}

void mt_wq_report(const mt_wq_t *q, mt_wq_report_t *r)
{
    mt_port_lock();
    r->name = q->name;
    r->starts = q->stats.starts;
    r->runs = q->stats.runs;
    r->mean_run_us = mean_run_us(&q->stats);
    r->max_run_us = q->stats.max_run_us;
    r->mean_interval_us = mean_interval_us(&q->stats);
    r->min_interval_us = q->stats.min_interval_us;
    r->max_interval_us = q->stats.max_interval_us;
    r->max_latency_us = q->stats.max_latency_us;
    r->merged = q->stats.merged;
    r->missed = q->stats.missed;
    r->items = q->nitems;
    r->depth = q->count;
    r->max_depth = q->max_depth;
    r->refused = q->refused;
    mt_port_unlock();
}
