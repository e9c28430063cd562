// SPDX-License-Identifier: Apache-2.0
// Timer and IO proc sets (mt/proc.h): registration statuses (H-1), dispatch
// order and statistics in simulated time, re-entrancy, the drift-free period
// arithmetic, and a real dispatching thread.
#include <atomic>
#include <thread>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::RealTime;
using mt_test::Rng;
using mt_test::SimTime;
using mt_test::wait_until;

void noop(void *)
{
}
void noop2(void *)
{
}

int g_tags[16];

TEST(ProcRegister, Statuses)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    EXPECT_EQ(p.count, 0u);
    EXPECT_EQ(p.running, 0u);
    EXPECT_EQ(p.dispatches, 0u);

    EXPECT_EQ(mt_proc_register(&p, nullptr, nullptr), MT_E_INVALID);
    EXPECT_EQ(p.count, 0u);
    EXPECT_EQ(mt_proc_register(&p, noop, &g_tags[0]), MT_OK);
    EXPECT_EQ(p.count, 1u);
    EXPECT_EQ(p.procs[0].fn, noop);
    EXPECT_EQ(p.procs[0].arg, &g_tags[0]);
    EXPECT_EQ(p.procs[0].calls, 0u);
    EXPECT_EQ(mt_proc_register(&p, noop, &g_tags[0]), MT_E_DUPLICATE); // same (fn, arg)
    EXPECT_EQ(p.count, 1u);
    EXPECT_EQ(mt_proc_register(&p, noop, &g_tags[1]), MT_OK);  // same fn, other arg
    EXPECT_EQ(mt_proc_register(&p, noop2, &g_tags[0]), MT_OK); // other fn, same arg
    EXPECT_EQ(mt_proc_register(&p, noop, nullptr), MT_OK);     // NULL arg is an arg
    EXPECT_EQ(mt_proc_register(&p, noop, nullptr), MT_E_DUPLICATE);
    EXPECT_EQ(p.count, 4u);
}

// H-1 regression: ArduPilot dropped the ninth proc silently; here it is refused
// with MT_E_FULL and the first eight stay intact.
TEST(ProcRegister, H1NinthIsFull)
{
    static_assert(MT_CFG_PROC_MAX == 8u, "the test assumes the default proc capacity");
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    for (uint32_t k = 0; k < MT_CFG_PROC_MAX; ++k) {
        ASSERT_EQ(mt_proc_register(&p, noop, &g_tags[k]), MT_OK) << k;
    }
    EXPECT_EQ(mt_proc_register(&p, noop, &g_tags[8]), MT_E_FULL);
    EXPECT_EQ(mt_proc_register(&p, noop2, nullptr), MT_E_FULL);
    EXPECT_EQ(p.count, MT_CFG_PROC_MAX);
    // the other problems are still reported as such on a full set
    EXPECT_EQ(mt_proc_register(&p, noop, &g_tags[3]), MT_E_DUPLICATE);
    EXPECT_EQ(mt_proc_register(&p, nullptr, nullptr), MT_E_INVALID);
    for (uint32_t k = 0; k < MT_CFG_PROC_MAX; ++k) {
        EXPECT_EQ(p.procs[k].arg, &g_tags[k]);
    }
}

TEST(ProcRegister, LockHeldCore)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    mt_port_lock();
    EXPECT_EQ(mt_proc_register_i(&p, noop, nullptr), MT_OK);
    EXPECT_EQ(mt_proc_register_i(&p, noop, nullptr), MT_E_DUPLICATE);
    EXPECT_EQ(mt_proc_register_i(&p, nullptr, nullptr), MT_E_INVALID);
    mt_port_unlock();
    EXPECT_EQ(p.count, 1u);
}

// ---- dispatch in simulated time ---------------------------------------------

struct Recorder {
    std::vector<int> order;
    mt_proc_set_t *set = nullptr;
    mt_status_t nested = MT_OK;
};

struct Entry {
    Recorder *rec;
    int id;
    std::vector<uint64_t> costs; // simulated run time per call (cycled)
    size_t call = 0;
    bool reenter = false;
};

void entry_fn(void *arg)
{
    Entry *e = static_cast<Entry *>(arg);
    e->rec->order.push_back(e->id);
    if (!e->costs.empty()) {
        mt_posix_sim_advance(e->costs[e->call % e->costs.size()]);
    }
    ++e->call;
    if (e->reenter) {
        e->rec->nested = mt_proc_dispatch(e->rec->set);
    }
}

using ProcSim = SimTime;

TEST_F(ProcSim, DispatchEmptySet)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    EXPECT_EQ(mt_proc_dispatch(&p), MT_OK);
    EXPECT_EQ(p.dispatches, 1u);
    EXPECT_EQ(p.running, 0u);
}

TEST_F(ProcSim, DispatchOrderIsRegistrationOrder)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    Recorder rec;
    std::vector<Entry> es;
    es.reserve(MT_CFG_PROC_MAX);
    const int ids[] = {5, 2, 7, 0, 3, 6, 1, 4}; // registration order != id order
    for (int id : ids) {
        es.push_back(Entry{&rec, id, {}, 0u, false});
        ASSERT_EQ(mt_proc_register(&p, entry_fn, &es.back()), MT_OK);
    }
    for (int round = 0; round < 3; ++round) {
        rec.order.clear();
        EXPECT_EQ(mt_proc_dispatch(&p), MT_OK);
        EXPECT_EQ(rec.order, std::vector<int>(std::begin(ids), std::end(ids)));
    }
    for (uint32_t k = 0; k < MT_CFG_PROC_MAX; ++k) {
        EXPECT_EQ(p.procs[k].calls, 3u);
    }
    EXPECT_EQ(p.dispatches, 3u);
}

TEST_F(ProcSim, PerProcStatisticsInSimulatedTime)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    Recorder rec;
    Entry a{&rec, 0, {5u, 40u, 20u}, 0u, false};
    Entry b{&rec, 1, {250u}, 0u, false};
    Entry c{&rec, 2, {}, 0u, false}; // takes no time
    ASSERT_EQ(mt_proc_register(&p, entry_fn, &a), MT_OK);
    ASSERT_EQ(mt_proc_register(&p, entry_fn, &b), MT_OK);
    ASSERT_EQ(mt_proc_register(&p, entry_fn, &c), MT_OK);
    const uint64_t t0 = mt_port_now_us();
    for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(mt_proc_dispatch(&p), MT_OK);
    }
    EXPECT_EQ(mt_port_now_us() - t0, 65u + 750u);
    EXPECT_EQ(p.procs[0].calls, 3u);
    EXPECT_EQ(p.procs[0].max_us, 40u);
    EXPECT_EQ(p.procs[0].total_us, 65u);
    EXPECT_EQ(p.procs[1].calls, 3u);
    EXPECT_EQ(p.procs[1].max_us, 250u);
    EXPECT_EQ(p.procs[1].total_us, 750u);
    EXPECT_EQ(p.procs[2].calls, 3u);
    EXPECT_EQ(p.procs[2].max_us, 0u);
    EXPECT_EQ(p.procs[2].total_us, 0u);
    EXPECT_EQ(p.max_round_us, 290u); // 40 + 250
    EXPECT_EQ(p.dispatches, 3u);
}

TEST_F(ProcSim, LongCallSaturatesMaxAt32Bits)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    Recorder rec;
    Entry a{&rec, 0, {0x100000005ull}, 0u, false}; // longer than 2^32 us
    ASSERT_EQ(mt_proc_register(&p, entry_fn, &a), MT_OK);
    ASSERT_EQ(mt_proc_dispatch(&p), MT_OK);
    EXPECT_EQ(p.procs[0].max_us, 0xFFFFFFFFu); // not 5 (truncated)
    EXPECT_EQ(p.procs[0].total_us, 0x100000005ull);
    EXPECT_EQ(p.max_round_us, 0xFFFFFFFFu);
}

TEST_F(ProcSim, ReentrantDispatchIsRefusedAndCounted)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    Recorder rec;
    rec.set = &p;
    Entry a{&rec, 0, {}, 0u, true};
    Entry b{&rec, 1, {}, 0u, false};
    ASSERT_EQ(mt_proc_register(&p, entry_fn, &a), MT_OK);
    ASSERT_EQ(mt_proc_register(&p, entry_fn, &b), MT_OK);
    EXPECT_EQ(mt_proc_dispatch(&p), MT_OK);
    EXPECT_EQ(rec.nested, MT_E_BUSY);
    EXPECT_EQ(p.refused, 1u);
    EXPECT_EQ(rec.order, (std::vector<int>{0, 1})); // the nested call ran nothing
    EXPECT_EQ(p.procs[0].calls, 1u);
    EXPECT_EQ(p.procs[1].calls, 1u);
    EXPECT_EQ(p.running, 0u);
    EXPECT_EQ(p.dispatches, 1u);
    EXPECT_EQ(mt_proc_dispatch(&p), MT_OK); // the set is usable afterwards
    EXPECT_EQ(p.refused, 2u);
    EXPECT_EQ(p.dispatches, 2u);
}

// ---- period arithmetic ------------------------------------------------------------

TEST(ProcPeriod, OnTime)
{
    uint64_t d = 1000u;
    EXPECT_EQ(mt_proc_period_next(&d, 1000u, 1000u), 0u); // woke exactly on the deadline
    EXPECT_EQ(d, 2000u);
    EXPECT_EQ(mt_proc_period_next(&d, 2999u, 1000u), 0u); // one us before the next one
    EXPECT_EQ(d, 3000u);
    EXPECT_EQ(mt_proc_period_next(&d, 0u, 1000u), 0u); // a clock behind the deadline
    EXPECT_EQ(d, 4000u);
}

TEST(ProcPeriod, LateCountsMissedPeriodsAndStaysOnTheGrid)
{
    uint64_t d = 1000u;
    EXPECT_EQ(mt_proc_period_next(&d, 2000u, 1000u), 1u); // exactly one period late
    EXPECT_EQ(d, 3000u);
    EXPECT_EQ(mt_proc_period_next(&d, 7500u, 1000u), 4u); // 4.5 periods late
    EXPECT_EQ(d, 8000u);
    EXPECT_EQ(mt_proc_period_next(&d, 8000u + 3u * 777u, 777u), 3u);
    EXPECT_EQ(d, 8000u + 4u * 777u);

    Rng rng(9u);
    for (int k = 0; k < 100000; ++k) {
        const uint32_t period = rng.range(1u, 5000u);
        const uint64_t d0 = rng.next() >> 20;
        const uint64_t now = d0 + rng.below(20u * period + 1u);
        uint64_t dd = d0;
        const uint32_t missed = mt_proc_period_next(&dd, now, period);
        ASSERT_GT(dd, now);
        ASSERT_EQ((dd - d0) % period, 0u);
        if (d0 + period > now) {
            ASSERT_EQ(missed, 0u);
            ASSERT_EQ(dd, d0 + period);
        } else {
            ASSERT_EQ(missed, (now - d0) / period);
            ASSERT_LE(dd, now + period);
        }
    }
}

TEST(ProcPeriod, NoDriftOverAMillionPeriods)
{
    const uint32_t period = 1000u;
    const uint64_t d0 = 5000u;
    uint64_t d = d0;
    uint64_t missed_total = 0u;
    Rng rng(11u);
    // a thread that wakes up to 999 us after each deadline
    for (uint32_t k = 0; k < 1000000u; ++k) {
        missed_total += mt_proc_period_next(&d, d + rng.below(period), period);
    }
    EXPECT_EQ(d, d0 + 1000000ull * period); // exactly on the grid: no drift
    EXPECT_EQ(missed_total, 0u);

    // the same with every 1000th wake-up several periods late: every period is
    // either served or counted as missed, and the grid is kept
    const uint64_t d1 = d;
    for (uint32_t k = 0; k < 1000000u; ++k) {
        const uint64_t now =
            (k % 1000u == 999u) ? d + rng.range(period, 5u * period - 1u) : d + rng.below(period);
        missed_total += mt_proc_period_next(&d, now, period);
    }
    EXPECT_GE(missed_total, 1000u);
    EXPECT_EQ(d, d1 + (1000000ull + missed_total) * period);
}

TEST(ProcPeriod, NoteMissedSaturates)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    mt_proc_note_missed(&p, 3u);
    EXPECT_EQ(p.periods_missed, 3u);
    mt_proc_note_missed(&p, 0u);
    EXPECT_EQ(p.periods_missed, 3u);
    mt_proc_note_missed(&p, 0xFFFFFFFCu);
    EXPECT_EQ(p.periods_missed, 0xFFFFFFFFu); // exact, not saturated yet
    p.periods_missed = 0xFFFFFFF0u;
    mt_proc_note_missed(&p, 0x20u);
    EXPECT_EQ(p.periods_missed, 0xFFFFFFFFu); // saturated, not wrapped to 0x10
    mt_proc_note_missed(&p, 0xFFFFFFFFu);
    EXPECT_EQ(p.periods_missed, 0xFFFFFFFFu);
}

// ---- a real dispatching thread ------------------------------------------------------

struct Counter {
    std::atomic<uint32_t> n{0u};
};

void count_fn(void *arg)
{
    static_cast<Counter *>(arg)->n.fetch_add(1u);
}

using ProcReal = RealTime;

TEST_F(ProcReal, StartRejectsBadArguments)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    mt_posix_proc_thread_t t{};
    EXPECT_EQ(mt_posix_proc_thread_start(&t, nullptr, 1000u, MT_PRIO_TIMER), MT_E_INVALID);
    EXPECT_EQ(mt_posix_proc_thread_start(&t, &p, 0u, MT_PRIO_TIMER), MT_E_INVALID);
    mt_posix_sim_enable(mt_test::kSimStartUs);
    EXPECT_EQ(mt_posix_proc_thread_start(&t, &p, 1000u, MT_PRIO_TIMER), MT_E_INVALID);
    mt_posix_sim_disable();
}

TEST_F(ProcReal, TimerThreadRunsProcsAndStopsCleanly)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    Counter a;
    Counter b;
    ASSERT_EQ(mt_proc_register(&p, count_fn, &a), MT_OK);
    mt_posix_proc_thread_t t{};
    ASSERT_EQ(mt_posix_proc_thread_start(&t, &p, 1000u, MT_PRIO_TIMER), MT_OK);
    EXPECT_TRUE(wait_until([&] { return a.n.load() >= 5u; }));
    // registration while the thread dispatches (safe publication)
    ASSERT_EQ(mt_proc_register(&p, count_fn, &b), MT_OK);
    EXPECT_TRUE(wait_until([&] { return b.n.load() >= 5u; }));
    mt_posix_proc_thread_stop(&t);
    EXPECT_EQ(t.impl, nullptr);

    const uint32_t na = a.n.load();
    const uint32_t nb = b.n.load();
    EXPECT_GE(na, 5u);
    EXPECT_GE(nb, 5u);
    // after the join the statistics are stable and agree with the procs' own counts
    EXPECT_EQ(p.procs[0].calls, na);
    EXPECT_EQ(p.procs[1].calls, nb);
    EXPECT_EQ(p.dispatches, na);
    EXPECT_LE(nb, na);
    EXPECT_EQ(p.running, 0u);
    EXPECT_EQ(p.refused, 0u);
    mt_posix_proc_thread_stop(&t); // a second stop is harmless
}

TEST_F(ProcReal, IoThreadRegistrationsFromSeveralThreads)
{
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    Counter c[MT_CFG_PROC_MAX];
    mt_posix_proc_thread_t t{};
    ASSERT_EQ(mt_posix_proc_thread_start(&t, &p, 500u, MT_PRIO_IO), MT_OK);
    std::vector<std::thread> regs;
    std::atomic<uint32_t> ok{0u};
    std::atomic<uint32_t> dup{0u};
    for (uint32_t k = 0; k < 4u; ++k) {
        regs.emplace_back([&, k] {
            for (uint32_t j = 0; j < MT_CFG_PROC_MAX; ++j) {
                // threads race to register the same eight procs
                const mt_status_t st =
                    mt_proc_register(&p, count_fn, &c[(j + 2u * k) % MT_CFG_PROC_MAX]);
                if (st == MT_OK) {
                    ok.fetch_add(1u);
                } else if (st == MT_E_DUPLICATE) {
                    dup.fetch_add(1u);
                }
            }
        });
    }
    for (auto &th : regs) {
        th.join();
    }
    EXPECT_EQ(ok.load(), MT_CFG_PROC_MAX);
    EXPECT_EQ(dup.load(), 4u * MT_CFG_PROC_MAX - MT_CFG_PROC_MAX);
    for (auto &cc : c) {
        EXPECT_TRUE(wait_until([&] { return cc.n.load() >= 3u; }));
    }
    mt_posix_proc_thread_stop(&t);
    for (uint32_t k = 0; k < MT_CFG_PROC_MAX; ++k) {
        const Counter *owner = static_cast<const Counter *>(p.procs[k].arg);
        EXPECT_EQ(p.procs[k].calls, owner->n.load());
    }
}

} // namespace
