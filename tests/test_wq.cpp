// SPDX-License-Identifier: Apache-2.0
// Work queues (mt/wq.h): attach statuses, FIFO order, merged activations
// (MT_W_WQ_MERGED, counted), scheduling while running, the runner guard,
// delayed and interval items on the timer (absolute deadlines, missed
// periods), cancel, single-shot waits and their timeout, statistics and
// reports, the queue thread on the host port, and a concurrency stress test
// (several schedulers, an ISR-like thread and a timer thread against the
// queue thread) that checks runs + merges == activations.
//
// Timing is checked in simulated time (no thread runs the queue: the test runs
// it with mt_wq_run_pending); the thread tests only check counts and order.
#include <atomic>
#include <cstdio>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::kSimStartUs;
using mt_test::RealTime;
using mt_test::SimTime;

// What one run of a probe item does.
struct Probe {
    int id = 0;
    std::vector<int> *order = nullptr; // run order, shared by the items of a test
    uint32_t runs = 0u;
    uint32_t spend_us = 0u;   // simulated run time
    uint32_t reschedule = 0u; // times to schedule itself again from its run
    mt_work_t *self = nullptr;
    mt_work_t *other = nullptr;      // scheduled once from the first run
    mt_wq_t *queue = nullptr;        // for the nested-runner test
    mt_status_t nested = MT_OK;      // mt_wq_run_once from inside the run
    mt_status_t self_status = MT_OK; // status of the last self-schedule
};

void probe_run(void *arg)
{
    Probe *p = static_cast<Probe *>(arg);
    p->runs++;
    if (p->order != nullptr) {
        p->order->push_back(p->id);
    }
    if (p->spend_us != 0u) {
        mt_posix_sim_advance(p->spend_us);
    }
    if (p->reschedule > 0u) {
        p->reschedule--;
        p->self_status = mt_work_schedule(p->self);
    }
    if (p->other != nullptr) {
        (void)mt_work_schedule(p->other);
        p->other = nullptr;
    }
    if (p->queue != nullptr) {
        p->nested = mt_wq_run_once(p->queue);
        p->queue = nullptr;
    }
}

void noop(void *)
{
}

// A queue with n probe items attached (heap: mt_wq_t is a few kB).
struct Rig {
    std::unique_ptr<mt_wq_t> q{new mt_wq_t};
    std::vector<mt_work_t> w;
    std::vector<Probe> p;
    std::vector<int> order;

    explicit Rig(uint32_t n, const char *name = "wq_test") : w(n), p(n)
    {
        mt_wq_init(q.get(), name, MT_PRIO_SPI, -1);
        for (uint32_t i = 0; i < n; ++i) {
            p[i].id = static_cast<int>(i);
            p[i].order = &order;
            p[i].self = &w[i];
            mt_work_init(&w[i], probe_run, &p[i]);
            EXPECT_EQ(mt_wq_attach(q.get(), &w[i]), MT_OK);
        }
    }
    mt_wq_t *wq()
    {
        return q.get();
    }
    uint32_t run(uint32_t max = 1000u)
    {
        return mt_wq_run_pending(q.get(), max);
    }
    mt_work_report_t report(uint32_t i)
    {
        mt_work_report_t r;
        mt_work_report(&w[i], &r);
        return r;
    }
    mt_wq_report_t qreport()
    {
        mt_wq_report_t r;
        mt_wq_report(q.get(), &r);
        return r;
    }
    uint32_t tick(uint64_t now)
    {
        mt_port_lock();
        const uint32_t n = mt_wq_timer_tick_i(q.get(), now);
        mt_port_unlock();
        return n;
    }
};

uint64_t now_us()
{
    return mt_port_now_us();
}

using WqSim = SimTime;
using WqThread = RealTime;

// ---------------------------------------------------------------- init and attach

TEST_F(WqSim, InitEmptyQueue)
{
    Rig r(0u, "empty");
    const mt_wq_report_t rep = r.qreport();
    EXPECT_STREQ(rep.name, "empty");
    EXPECT_EQ(rep.items, 0u);
    EXPECT_EQ(rep.depth, 0u);
    EXPECT_EQ(rep.runs, 0u);
    EXPECT_EQ(rep.mean_run_us, 0u);
    EXPECT_EQ(rep.mean_interval_us, 0u);
    EXPECT_EQ(r.wq()->running, MT_WQ_NONE);
    EXPECT_EQ(r.wq()->prio_base, MT_PRIO_SPI);
    EXPECT_EQ(r.wq()->prio_offset, -1);
    EXPECT_EQ(mt_wq_run_once(r.wq()), MT_E_EMPTY);
    EXPECT_EQ(r.run(), 0u);
}

TEST_F(WqSim, AttachStatuses)
{
    Rig r(0u);
    mt_work_t a;
    mt_work_t nofn;
    mt_work_init(&a, noop, nullptr);
    mt_work_init(&nofn, nullptr, nullptr);

    EXPECT_EQ(mt_wq_attach(r.wq(), &nofn), MT_E_INVALID);
    EXPECT_EQ(nofn.wq, nullptr);
    EXPECT_EQ(r.wq()->nitems, 0u);

    EXPECT_EQ(mt_wq_attach(r.wq(), &a), MT_OK);
    EXPECT_EQ(a.wq, r.wq());
    EXPECT_EQ(a.slot, 0u);
    EXPECT_EQ(r.wq()->slot[0].fn, &noop);

    // attached already: to this queue, and to another one
    EXPECT_EQ(mt_wq_attach(r.wq(), &a), MT_E_DUPLICATE);
    Rig other(0u);
    EXPECT_EQ(mt_wq_attach(other.wq(), &a), MT_E_DUPLICATE);
    EXPECT_EQ(a.wq, r.wq());
    EXPECT_EQ(r.wq()->nitems, 1u);
    EXPECT_EQ(other.wq()->nitems, 0u);
}

TEST_F(WqSim, AttachFullQueueIsRefused)
{
    Rig r(MT_CFG_WQ_MAX_ITEMS);
    EXPECT_EQ(r.wq()->nitems, MT_CFG_WQ_MAX_ITEMS);
    mt_work_t extra;
    mt_work_init(&extra, noop, nullptr);
    EXPECT_EQ(mt_wq_attach(r.wq(), &extra), MT_E_FULL);
    EXPECT_EQ(extra.wq, nullptr);
    EXPECT_EQ(r.wq()->nitems, MT_CFG_WQ_MAX_ITEMS);
    // every slot can be queued at once: the FIFO never overflows
    for (uint32_t i = 0; i < MT_CFG_WQ_MAX_ITEMS; ++i) {
        EXPECT_EQ(mt_work_schedule(&r.w[i]), MT_OK);
    }
    EXPECT_EQ(r.wq()->count, MT_CFG_WQ_MAX_ITEMS);
    for (uint32_t i = 0; i < MT_CFG_WQ_MAX_ITEMS; ++i) {
        EXPECT_EQ(mt_work_schedule(&r.w[i]), MT_W_WQ_MERGED);
    }
    EXPECT_EQ(r.run(), MT_CFG_WQ_MAX_ITEMS);
    for (uint32_t i = 0; i < MT_CFG_WQ_MAX_ITEMS; ++i) {
        EXPECT_EQ(r.order[i], static_cast<int>(i));
        EXPECT_EQ(r.p[i].runs, 1u);
    }
    EXPECT_EQ(r.qreport().max_depth, MT_CFG_WQ_MAX_ITEMS);
}

// ---------------------------------------------------------------- schedule now

TEST_F(WqSim, ScheduleRunsOnceInFifoOrder)
{
    Rig r(3u);
    EXPECT_EQ(mt_work_schedule(&r.w[2]), MT_OK);
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    EXPECT_EQ(mt_work_schedule(&r.w[1]), MT_OK);
    EXPECT_EQ(r.qreport().depth, 3u);
    EXPECT_EQ(r.run(), 3u);
    EXPECT_EQ(r.order, (std::vector<int>{2, 0, 1}));
    EXPECT_EQ(mt_wq_run_once(r.wq()), MT_E_EMPTY);
    // again in another order: the permutation keeps working after wrapping
    for (int round = 0; round < 5; ++round) {
        r.order.clear();
        EXPECT_EQ(mt_work_schedule(&r.w[1]), MT_OK);
        EXPECT_EQ(mt_work_schedule(&r.w[2]), MT_OK);
        EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
        EXPECT_EQ(mt_wq_run_once(r.wq()), MT_OK);
        EXPECT_EQ(mt_work_schedule(&r.w[1]), MT_OK); // ran already: queued again, at the end
        EXPECT_EQ(r.run(), 3u);
        EXPECT_EQ(r.order, (std::vector<int>{1, 2, 0, 1}));
    }
}

TEST_F(WqSim, MergedScheduleIsCountedPerItemAndQueue)
{
    Rig r(2u);
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_W_WQ_MERGED);
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_W_WQ_MERGED);
    EXPECT_EQ(mt_work_schedule(&r.w[1]), MT_OK);
    EXPECT_EQ(mt_work_schedule(&r.w[1]), MT_W_WQ_MERGED);
    EXPECT_EQ(r.report(0).merged, 2u);
    EXPECT_EQ(r.report(1).merged, 1u);
    EXPECT_EQ(r.qreport().merged, 3u);
    EXPECT_EQ(r.report(0).queued, 1u);
    EXPECT_EQ(r.run(), 2u);
    // one run per item: runs + merges == activations
    EXPECT_EQ(r.p[0].runs + r.report(0).merged, 3u);
    EXPECT_EQ(r.p[1].runs + r.report(1).merged, 2u);
    EXPECT_EQ(r.report(0).runs, 1u);
    EXPECT_EQ(r.report(0).queued, 0u);
}

TEST_F(WqSim, ScheduleFromIsrAndLockHeldContexts)
{
    Rig r(2u);
    EXPECT_EQ(mt_work_schedule_isr(&r.w[0]), MT_OK);
    EXPECT_EQ(mt_work_schedule_isr(&r.w[0]), MT_W_WQ_MERGED);
    mt_port_lock();
    EXPECT_EQ(mt_work_schedule_i(&r.w[1]), MT_OK);
    EXPECT_EQ(mt_work_schedule_i(&r.w[1]), MT_W_WQ_MERGED);
    mt_port_unlock();
    EXPECT_EQ(r.run(), 2u);
    EXPECT_EQ(r.order, (std::vector<int>{0, 1}));
    EXPECT_EQ(r.qreport().merged, 2u);
}

TEST_F(WqSim, NotifyCallbackSchedulesWithTheLockHeld)
{
    Rig r(1u);
    void (*notify)(void *) = mt_work_notify_i; // the publish-hook shape
    mt_port_lock();
    notify(&r.w[0]);
    notify(&r.w[0]); // merged, counted (the hook returns nothing)
    mt_port_unlock();
    EXPECT_EQ(r.report(0).queued, 1u);
    EXPECT_EQ(r.report(0).merged, 1u);
    EXPECT_EQ(r.run(), 1u);
    EXPECT_EQ(r.p[0].runs, 1u);
}

TEST_F(WqSim, ScheduleWhileRunningRunsOnceMore)
{
    Rig r(2u);
    r.p[0].reschedule = 2u; // its run schedules itself twice (once per run)
    r.p[0].other = &r.w[1]; // and item 1 once
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    EXPECT_EQ(r.run(), 4u);
    // run 1 of item 0 queues 0 then 1; run 2 of 0 queues 0 behind 1
    EXPECT_EQ(r.order, (std::vector<int>{0, 0, 1, 0}));
    EXPECT_EQ(r.p[0].runs, 3u);
    EXPECT_EQ(r.p[0].self_status, MT_OK); // not a merge: it was running, not queued
    EXPECT_EQ(r.report(0).merged, 0u);
    EXPECT_EQ(r.p[1].runs, 1u);
}

TEST_F(WqSim, SecondRunnerIsRefusedAndCounted)
{
    Rig r(2u);
    r.p[0].queue = r.wq(); // item 0 calls mt_wq_run_once on its own queue
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    EXPECT_EQ(mt_work_schedule(&r.w[1]), MT_OK);
    EXPECT_EQ(mt_wq_run_once(r.wq()), MT_OK);
    EXPECT_EQ(r.p[0].nested, MT_E_BUSY);
    EXPECT_EQ(r.p[1].runs, 0u); // not run inside item 0's run
    EXPECT_EQ(r.qreport().refused, 1u);
    EXPECT_EQ(r.run(), 1u);
    EXPECT_EQ(r.p[1].runs, 1u);
    EXPECT_EQ(r.wq()->running, MT_WQ_NONE);
}

TEST_F(WqSim, RunPendingStopsAtItsLimit)
{
    Rig r(3u);
    for (uint32_t i = 0; i < 3u; ++i) {
        EXPECT_EQ(mt_work_schedule(&r.w[i]), MT_OK);
    }
    EXPECT_EQ(r.run(2u), 2u);
    EXPECT_EQ(r.qreport().depth, 1u);
    EXPECT_EQ(r.run(0u), 0u);
    EXPECT_EQ(r.run(), 1u);
}

// A work item that calls mt_wq_run_pending on its own queue while it runs.
struct NestedPending {
    mt_wq_t *q;
    uint32_t max;
    uint32_t got;
};

void nested_pending(void *arg)
{
    auto *n = static_cast<NestedPending *>(arg);
    n->got = mt_wq_run_pending(n->q, n->max);
}

TEST_F(WqSim, RunPendingDuringARunRunsNoneAndCountsTheRefusal)
{
    Rig r(1u);
    NestedPending a{r.wq(), 5u, 99u};
    NestedPending zero{r.wq(), 0u, 99u};
    mt_work_t wa;
    mt_work_t wz;
    mt_work_init(&wa, nested_pending, &a);
    mt_work_init(&wz, nested_pending, &zero);
    ASSERT_EQ(mt_wq_attach(r.wq(), &wa), MT_OK);
    ASSERT_EQ(mt_wq_attach(r.wq(), &wz), MT_OK);
    EXPECT_EQ(mt_work_schedule(&wa), MT_OK);
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    EXPECT_EQ(mt_wq_run_once(r.wq()), MT_OK); // wa: its run_pending is refused
    EXPECT_EQ(a.got, 0u);
    EXPECT_EQ(r.p[0].runs, 0u);
    EXPECT_EQ(r.qreport().refused, 1u);
    EXPECT_EQ(mt_work_schedule(&wz), MT_OK);
    EXPECT_EQ(r.run(1u), 1u); // the probe (queued before wz)
    EXPECT_EQ(r.p[0].runs, 1u);
    EXPECT_EQ(r.run(), 1u); // wz: max 0 runs nothing and is not a refusal
    EXPECT_EQ(zero.got, 0u);
    EXPECT_EQ(r.qreport().refused, 1u);
    EXPECT_EQ(r.qreport().runs, 3u);
    EXPECT_EQ(r.qreport().depth, 0u);
}

// ---------------------------------------------------------------- timers

TEST_F(WqSim, DelayedItemFiresOnceAtItsDeadline)
{
    Rig r(1u);
    const uint64_t t0 = now_us();
    mt_work_schedule_delayed(&r.w[0], 5000u);
    EXPECT_EQ(r.report(0).timer, MT_WQ_TIMER_ONCE);
    EXPECT_EQ(r.tick(t0 + 4999u), 0u);
    EXPECT_EQ(r.report(0).queued, 0u);
    EXPECT_EQ(r.tick(t0 + 5000u), 1u);
    EXPECT_EQ(r.report(0).queued, 1u);
    EXPECT_EQ(r.report(0).timer, MT_WQ_TIMER_OFF);
    EXPECT_EQ(r.tick(t0 + 10000u), 0u);
    EXPECT_EQ(r.run(), 1u);
    EXPECT_EQ(r.p[0].runs, 1u);
}

TEST_F(WqSim, DelayZeroFiresAtTheNextTickAndRearmReplaces)
{
    Rig r(1u);
    const uint64_t t0 = now_us();
    mt_work_schedule_delayed(&r.w[0], 0u);
    EXPECT_EQ(r.tick(t0), 1u);
    mt_work_schedule_delayed(&r.w[0], 1000u);
    mt_work_schedule_delayed(&r.w[0], 3000u); // replaces the first
    EXPECT_EQ(r.tick(t0 + 1000u), 0u);
    EXPECT_EQ(r.tick(t0 + 3000u), 1u);
    EXPECT_EQ(r.report(0).merged, 1u); // still queued from the first tick: merged
    EXPECT_EQ(r.run(), 1u);
}

TEST_F(WqSim, IntervalItemKeepsAbsoluteDeadlines)
{
    Rig r(1u);
    const uint64_t t0 = now_us();
    EXPECT_EQ(mt_work_schedule_interval(&r.w[0], 1000u, 500u), MT_OK);
    EXPECT_EQ(r.report(0).period_us, 1000u);
    EXPECT_EQ(r.tick(t0 + 499u), 0u);
    // late ticks (+300 us) do not move the grid: 500, 1500, 2500, ...
    for (uint64_t k = 0; k < 10u; ++k) {
        EXPECT_EQ(r.tick(t0 + 500u + (k * 1000u) + 300u), 1u) << k;
        EXPECT_EQ(r.wq()->slot[0].deadline_us, t0 + 500u + ((k + 1u) * 1000u)) << k;
        EXPECT_EQ(r.run(), 1u);
    }
    EXPECT_EQ(r.p[0].runs, 10u);
    EXPECT_EQ(r.report(0).missed, 0u);
    EXPECT_EQ(r.report(0).merged, 0u);
    EXPECT_EQ(r.report(0).timer, MT_WQ_TIMER_EVERY);
}

TEST_F(WqSim, IntervalCountsMissedPeriods)
{
    Rig r(1u);
    const uint64_t t0 = now_us();
    EXPECT_EQ(mt_work_schedule_interval(&r.w[0], 1000u, 0u), MT_OK);
    EXPECT_EQ(r.tick(t0), 1u);
    // the timer stalls: next tick 3.5 periods later; deadlines t0+1000, +2000, +3000 passed,
    // one activation now, two periods missed, next deadline t0+4000
    EXPECT_EQ(r.tick(t0 + 3500u), 1u);
    EXPECT_EQ(r.report(0).missed, 2u);
    EXPECT_EQ(r.qreport().missed, 2u);
    EXPECT_EQ(r.wq()->slot[0].deadline_us, t0 + 4000u);
    EXPECT_EQ(r.report(0).merged, 1u); // not run in between: the second activation merged
    EXPECT_EQ(r.run(), 1u);
    // periods: served (1 run) + merged (1) + missed (2) == 4 deadlines passed (t0..t0+3000)
    EXPECT_EQ(r.p[0].runs + r.report(0).merged + r.report(0).missed, 4u);
}

TEST_F(WqSim, IntervalZeroIsInvalidAndChangesNothing)
{
    Rig r(1u);
    mt_work_schedule_delayed(&r.w[0], 700u);
    const uint64_t d = r.wq()->slot[0].deadline_us;
    EXPECT_EQ(mt_work_schedule_interval(&r.w[0], 0u, 0u), MT_E_INVALID);
    EXPECT_EQ(r.report(0).timer, MT_WQ_TIMER_ONCE);
    EXPECT_EQ(r.wq()->slot[0].deadline_us, d);
    mt_port_lock();
    EXPECT_EQ(mt_work_schedule_interval_i(&r.w[0], 0u, 5u), MT_E_INVALID);
    mt_port_unlock();
}

TEST_F(WqSim, CancelStopsTheTimerButNotAQueuedRun)
{
    Rig r(1u);
    const uint64_t t0 = now_us();
    EXPECT_EQ(mt_work_cancel(&r.w[0]), MT_E_STATE); // nothing armed
    EXPECT_EQ(mt_work_schedule_interval(&r.w[0], 1000u, 0u), MT_OK);
    EXPECT_EQ(r.tick(t0), 1u);
    EXPECT_EQ(mt_work_cancel(&r.w[0]), MT_OK);
    EXPECT_EQ(mt_work_cancel(&r.w[0]), MT_E_STATE);
    EXPECT_EQ(r.tick(t0 + 1000u), 0u);
    EXPECT_EQ(r.tick(t0 + 5000u), 0u);
    EXPECT_EQ(r.run(), 1u); // the activation before the cancel still runs
    mt_work_schedule_delayed(&r.w[0], 10u);
    mt_port_lock();
    EXPECT_EQ(mt_work_cancel_i(&r.w[0]), MT_OK);
    mt_port_unlock();
    EXPECT_EQ(r.tick(t0 + 6000u), 0u);
    EXPECT_EQ(r.p[0].runs, 1u);
}

TEST_F(WqSim, TimerProcDrivesTheQueueFromAProcSet)
{
    Rig r(2u);
    mt_proc_set_t timer_procs;
    mt_proc_set_init(&timer_procs);
    ASSERT_EQ(mt_proc_register(&timer_procs, mt_wq_timer_proc, r.wq()), MT_OK);
    EXPECT_EQ(mt_work_schedule_interval(&r.w[0], 2000u, 0u), MT_OK);
    mt_work_schedule_delayed(&r.w[1], 3000u);
    for (int ms = 0; ms < 10; ++ms) { // 10 ms of 1 kHz timer, the queue run after each
        EXPECT_EQ(mt_proc_dispatch(&timer_procs), MT_OK);
        r.run();
        mt_posix_sim_advance(1000u);
    }
    EXPECT_EQ(r.p[0].runs, 5u); // at 0, 2, 4, 6, 8 ms
    EXPECT_EQ(r.p[1].runs, 1u); // at 3 ms
    EXPECT_EQ(r.report(0).missed, 0u);
    EXPECT_EQ(r.report(0).merged, 0u);
}

// ---------------------------------------------------------------- single shot

TEST_F(WqSim, RunWaitTimesOutWithoutARunAndLeavesNothingStale)
{
    Rig r(1u);
    const uint64_t t0 = now_us();
    // nobody runs the queue in simulated time: the wait times out (time moves by the timeout)
    EXPECT_EQ(mt_work_run_wait(&r.w[0], 2500u), MT_E_TIMEOUT);
    EXPECT_GE(now_us(), t0 + 2500u);
    EXPECT_EQ(r.wq()->slot[0].shot, MT_WQ_SHOT_NONE);
    EXPECT_EQ(r.report(0).queued, 1u);                      // the activation stays and runs later
    EXPECT_EQ(mt_work_run_wait(&r.w[0], 0u), MT_E_TIMEOUT); // 0: do not wait; merged
    EXPECT_EQ(r.report(0).merged, 1u);
    EXPECT_EQ(r.run(), 1u);
    EXPECT_EQ(r.p[0].runs, 1u);
    EXPECT_EQ(r.wq()->slot[0].done.token, 0u); // no completion token left behind
    EXPECT_EQ(r.wq()->slot[0].shot, MT_WQ_SHOT_NONE);
}

TEST_F(WqThread, RunWaitReturnsAfterTheRunOnTheQueueThread)
{
    Rig r(1u);
    mt_posix_wq_thread_t th;
    ASSERT_EQ(mt_posix_wq_start(&th, r.wq()), MT_OK);
    for (uint32_t k = 1; k <= 20u; ++k) {
        ASSERT_EQ(mt_work_run_wait(&r.w[0], 10000000u), MT_OK) << k;
        EXPECT_EQ(r.p[0].runs, k); // the run ended before the wait returned
    }
    EXPECT_EQ(mt_work_run_wait(&r.w[0], MT_WAIT_FOREVER), MT_OK);
    mt_posix_wq_stop(&th);
    EXPECT_EQ(r.p[0].runs, 21u);
    EXPECT_EQ(r.wq()->slot[0].done.token, 0u);
}

TEST_F(WqThread, SecondSingleShotWaiterIsBusy)
{
    Rig r(1u); // no queue thread: the first waiter waits until its timeout
    std::atomic<int> first{-1};
    std::thread waiter([&] { first = mt_work_run_wait(&r.w[0], 3000000u); });
    ASSERT_TRUE(mt_test::wait_until([&] {
        mt_port_lock();
        const bool armed = r.wq()->slot[0].shot != MT_WQ_SHOT_NONE;
        mt_port_unlock();
        return armed;
    }));
    EXPECT_EQ(mt_work_run_wait(&r.w[0], 1000u), MT_E_BUSY);
    // now run the item: the first waiter is released with MT_OK
    EXPECT_EQ(mt_wq_run_pending(r.wq(), 10u), 1u);
    waiter.join();
    EXPECT_EQ(first.load(), MT_OK);
    EXPECT_EQ(r.wq()->slot[0].shot, MT_WQ_SHOT_NONE);
}

// ---------------------------------------------------------------- statistics

TEST_F(WqSim, StatisticsRunTimesIntervalsLatency)
{
    Rig r(2u);
    r.p[0].spend_us = 100u;
    const uint64_t t0 = now_us();
    // starts at t0+700 (latency 700), t0+1700, t0+3700; run times 100 us each
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    mt_posix_sim_advance(700u);
    EXPECT_EQ(r.run(), 1u);
    mt_posix_sim_advance(900u); // now t0+1700
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    EXPECT_EQ(r.run(), 1u);
    mt_posix_sim_advance(1900u); // now t0+3700
    EXPECT_EQ(mt_work_schedule(&r.w[0]), MT_OK);
    r.p[0].spend_us = 400u;
    EXPECT_EQ(r.run(), 1u);
    (void)t0;

    const mt_work_report_t a = r.report(0);
    EXPECT_EQ(a.starts, 3u);
    EXPECT_EQ(a.runs, 3u);
    EXPECT_EQ(a.max_run_us, 400u);
    EXPECT_EQ(a.mean_run_us, 200u); // (100 + 100 + 400) / 3
    EXPECT_EQ(a.min_interval_us, 1000u);
    EXPECT_EQ(a.max_interval_us, 2000u);
    EXPECT_EQ(a.mean_interval_us, 1500u);
    EXPECT_EQ(a.rate_mhz, 666666u); // 10^9 / 1500
    EXPECT_EQ(a.max_latency_us, 700u);
    EXPECT_EQ(a.running, 0u);

    // an item that never ran reports zeros, no division by zero
    const mt_work_report_t b = r.report(1);
    EXPECT_EQ(b.runs, 0u);
    EXPECT_EQ(b.mean_run_us, 0u);
    EXPECT_EQ(b.mean_interval_us, 0u);
    EXPECT_EQ(b.rate_mhz, 0u);

    const mt_wq_report_t q = r.qreport();
    EXPECT_EQ(q.runs, 3u);
    EXPECT_EQ(q.starts, 3u);
    EXPECT_EQ(q.max_run_us, 400u);
    EXPECT_EQ(q.mean_run_us, 200u);
    EXPECT_EQ(q.mean_interval_us, 1500u);
    EXPECT_EQ(q.max_latency_us, 700u);
    EXPECT_EQ(q.items, 2u);
    EXPECT_EQ(q.depth, 0u);
    EXPECT_EQ(q.max_depth, 1u);
}

TEST_F(WqSim, ReportShowsRunningWhileTheItemRuns)
{
    Rig r(1u);
    static mt_work_report_t inside;
    static mt_work_t *self;
    self = &r.w[0];
    mt_work_t w;
    mt_work_init(
        &w, [](void *) { mt_work_report(self, &inside); }, nullptr);
    ASSERT_EQ(mt_wq_attach(r.wq(), &w), MT_OK);
    self = &w;
    EXPECT_EQ(mt_work_schedule(&w), MT_OK);
    EXPECT_EQ(r.run(), 1u);
    EXPECT_EQ(inside.running, 1u);
    EXPECT_EQ(inside.starts, 1u);
    EXPECT_EQ(inside.runs, 0u); // completed runs: not yet
}

// ---------------------------------------------------------------- the queue thread

TEST_F(WqThread, QueueThreadRunsItemsAndStops)
{
    Rig r(3u);
    mt_posix_wq_thread_t th;
    ASSERT_EQ(mt_posix_wq_start(&th, r.wq()), MT_OK);
    for (int k = 0; k < 50; ++k) {
        (void)mt_work_schedule(&r.w[static_cast<size_t>(k % 3)]);
    }
    ASSERT_TRUE(mt_test::wait_until([&] {
        const mt_wq_report_t q = r.qreport();
        return q.depth == 0u && r.wq()->running == MT_WQ_NONE && q.runs + q.merged == 50u;
    }));
    mt_posix_wq_stop(&th);
    EXPECT_EQ(mt_wq_serve_once(r.wq()), MT_E_STATE); // the stop request stays
}

TEST_F(WqThread, SecondServingThreadIsBusy)
{
    Rig r(1u);
    mt_posix_wq_thread_t th;
    ASSERT_EQ(mt_posix_wq_start(&th, r.wq()), MT_OK);
    ASSERT_TRUE(mt_test::wait_until([&] { return mt_test::sem_has_waiter(&r.wq()->wake); }));
    EXPECT_EQ(mt_wq_serve_once(r.wq()), MT_E_BUSY); // the thread already waits on `wake`
    mt_posix_wq_stop(&th);
}

TEST_F(WqSim, HostQueueThreadIsRefusedInSimulatedTime)
{
    Rig r(0u);
    mt_posix_wq_thread_t th;
    EXPECT_EQ(mt_posix_wq_start(&th, r.wq()), MT_E_INVALID);
}

// ---------------------------------------------------------------- stress (TSan)

struct Counted {
    std::atomic<uint32_t> inside{0};
    std::atomic<uint32_t> overlap{0};
    std::atomic<uint64_t> runs{0};
    std::atomic<uint32_t> *queue_inside = nullptr;
    std::atomic<uint32_t> *queue_overlap = nullptr;
};

void counted_run(void *arg)
{
    Counted *c = static_cast<Counted *>(arg);
    if (c->inside.fetch_add(1u) != 0u) {
        c->overlap++;
    }
    if (c->queue_inside->fetch_add(1u) != 0u) {
        (*c->queue_overlap)++;
    }
    c->runs++;
    for (volatile int k = 0; k < 50; k = k + 1) {
    }
    c->queue_inside->fetch_sub(1u);
    c->inside.fetch_sub(1u);
}

TEST_F(WqThread, StressSchedulersIsrTimerAgainstQueueThread)
{
    constexpr uint32_t kItems = 4u;
    constexpr uint32_t kPerThread = mt_test::kTsan ? 3000u : 20000u;
    std::unique_ptr<mt_wq_t> q(new mt_wq_t);
    mt_wq_init(q.get(), "stress", MT_PRIO_SPI, 0);
    std::vector<mt_work_t> w(kItems);
    std::vector<Counted> c(kItems);
    std::atomic<uint32_t> q_inside{0};
    std::atomic<uint32_t> q_overlap{0};
    for (uint32_t i = 0; i < kItems; ++i) {
        c[i].queue_inside = &q_inside;
        c[i].queue_overlap = &q_overlap;
        mt_work_init(&w[i], counted_run, &c[i]);
        ASSERT_EQ(mt_wq_attach(q.get(), &w[i]), MT_OK);
    }
    ASSERT_EQ(mt_work_schedule_interval(&w[3], 500u, 0u), MT_OK);
    mt_work_schedule_delayed(&w[2], 2000u);

    std::atomic<uint64_t> ok{0};
    std::atomic<uint64_t> merged{0};
    std::atomic<uint64_t> fired{0};
    std::atomic<uint64_t> busy{0};
    std::atomic<bool> timer_stop{false};

    mt_posix_wq_thread_t th;
    ASSERT_EQ(mt_posix_wq_start(&th, q.get()), MT_OK);

    auto count = [&](mt_status_t st) {
        if (st == MT_OK) {
            ok++;
        } else if (st == MT_W_WQ_MERGED) {
            merged++;
        } else {
            ADD_FAILURE() << "unexpected status " << mt_status_str(st);
        }
    };
    std::vector<std::thread> ts;
    for (uint32_t t = 0; t < 3u; ++t) { // task-context schedulers
        ts.emplace_back([&, t] {
            mt_test::Rng rng(t + 11u);
            for (uint32_t k = 0; k < kPerThread; ++k) {
                count(mt_work_schedule(&w[rng.below(kItems)]));
                if (rng.below(64u) == 0u) {
                    std::this_thread::yield();
                }
            }
        });
    }
    ts.emplace_back([&] { // an "ISR": schedule_isr and the lock-held notify hook
        mt_test::Rng rng(99u);
        for (uint32_t k = 0; k < kPerThread; ++k) {
            mt_work_t *item = &w[rng.below(kItems)];
            if ((k & 1u) == 0u) {
                count(mt_work_schedule_isr(item));
            } else {
                mt_port_lock();
                const bool was =
                    (item->wq->where[item->slot] + MT_CFG_WQ_MAX_ITEMS - item->wq->head) %
                        MT_CFG_WQ_MAX_ITEMS <
                    item->wq->count;
                mt_work_notify_i(item);
                mt_port_unlock();
                count(was ? MT_W_WQ_MERGED : MT_OK);
            }
        }
    });
    ts.emplace_back([&] { // a second runner racing the queue thread
        for (uint32_t k = 0; k < kPerThread / 4u; ++k) {
            if (mt_wq_run_once(q.get()) == MT_E_BUSY) {
                busy++;
            }
            std::this_thread::yield();
        }
    });
    std::thread timer([&] { // the timer procs: tick the queue's timers
        while (!timer_stop.load()) {
            mt_port_lock();
            fired += mt_wq_timer_tick_i(q.get(), mt_port_now_us());
            mt_port_unlock();
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    });
    for (auto &t : ts) {
        t.join();
    }
    timer_stop = true;
    timer.join();
    ASSERT_TRUE(mt_test::wait_until([&] {
        mt_port_lock();
        const bool idle = q->count == 0u && q->running == MT_WQ_NONE;
        mt_port_unlock();
        return idle;
    }));
    mt_posix_wq_stop(&th);

    uint64_t runs = 0u;
    uint64_t item_merged = 0u;
    for (uint32_t i = 0; i < kItems; ++i) {
        mt_work_report_t r;
        mt_work_report(&w[i], &r);
        EXPECT_EQ(c[i].overlap.load(), 0u) << "item " << i << " ran twice at once";
        EXPECT_EQ(r.runs, c[i].runs.load());
        EXPECT_EQ(r.starts, r.runs);
        runs += r.runs;
        item_merged += r.merged;
    }
    EXPECT_EQ(q_overlap.load(), 0u) << "two items of one queue ran at once";
    mt_wq_report_t qr;
    mt_wq_report(q.get(), &qr);
    const uint64_t activations = ok.load() + merged.load() + fired.load();
    EXPECT_EQ(runs + item_merged, activations) << "an activation was lost";
    EXPECT_GE(item_merged, merged.load()); // timer activations may merge too
    EXPECT_EQ(qr.merged, item_merged);
    EXPECT_EQ(qr.runs, runs);
    EXPECT_GT(fired.load(), 0u);
    EXPECT_GE(qr.refused, busy.load()); // the queue thread may be refused too
    EXPECT_GE(runs, 1u);
    // the race happened: merges, a refused second runner (informational)
    std::printf("wq stress: %llu activations (%llu timer), %llu runs, %llu merged, %u refused\n",
                static_cast<unsigned long long>(activations),
                static_cast<unsigned long long>(fired.load()),
                static_cast<unsigned long long>(runs), static_cast<unsigned long long>(item_merged),
                qr.refused);
}

} // namespace
