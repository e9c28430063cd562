// SPDX-License-Identifier: Apache-2.0
// Tick scheduler (mt/sched.h) in simulated time. Tasks "spend" their run time
// with mt_posix_sim_advance; the main loop is mt_sched_loop_once paced by the
// POSIX metronome. Regressions of ArduPilot defects S-1, S-3, S-4, S-5, S-7 and
// S-8 (reference/ardupilot.md §3.1) are named as such.
#include <cstring>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::Rng;
using mt_test::SimTime;

void dummy(void *)
{
}

// ---- validation -------------------------------------------------------------------

mt_task_t entry(uint32_t rate_mhz, uint32_t budget_us, uint8_t prio, mt_task_fn_t fn = dummy)
{
    mt_task_t t;
    t.name = "t";
    t.fn = fn;
    t.arg = nullptr;
    t.rate_mhz = rate_mhz;
    t.budget_us = budget_us;
    t.priority = prio;
    return t;
}

mt_status_t validate(const std::vector<mt_task_t> &v, uint32_t rate, uint32_t *bad)
{
    return mt_sched_validate(v.data(), static_cast<uint32_t>(v.size()), rate, bad);
}

// A valid 400 Hz table: two fast tasks, three normal ones.
std::vector<mt_task_t> good_table()
{
    return {entry(0u, 0u, 0u), entry(0u, 500u, 2u), entry(MT_HZ(400), 100u, 3u),
            entry(MT_HZ(50), 2500u, 3u), entry(100u, 1u, 200u)};
}

TEST(SchedValidate, GoodTable)
{
    uint32_t bad = 1234u;
    const auto v = good_table();
    EXPECT_EQ(validate(v, 400u, &bad), MT_OK);
    for (uint32_t i = 0; i < v.size(); ++i) {
        EXPECT_EQ(mt_sched_check_entry(v.data(), static_cast<uint32_t>(v.size()), i, 400u), MT_OK);
    }
}

TEST(SchedValidate, LoopRate)
{
    uint32_t bad = 0u;
    const auto v = good_table();
    EXPECT_EQ(validate(v, 49u, &bad), MT_E_LOOP_RATE);
    EXPECT_EQ(bad, v.size());
    EXPECT_EQ(validate(v, 2001u, &bad), MT_E_LOOP_RATE);
    EXPECT_EQ(validate(v, 0u, &bad), MT_E_LOOP_RATE);
    EXPECT_EQ(validate(v, 0xFFFFFFFFu, &bad), MT_E_LOOP_RATE);
    // limits are inclusive (the table is re-made valid for each rate)
    std::vector<mt_task_t> low = {entry(0u, 0u, 0u), entry(MT_HZ(50), 20000u, 3u)};
    EXPECT_EQ(validate(low, 50u, &bad), MT_OK);
    std::vector<mt_task_t> high = {entry(0u, 0u, 0u), entry(MT_HZ(2000), 500u, 3u)};
    EXPECT_EQ(validate(high, 2000u, &bad), MT_OK);
    // the loop rate is checked before the count
    EXPECT_EQ(mt_sched_validate(nullptr, 0u, 49u, &bad), MT_E_LOOP_RATE);
}

TEST(SchedValidate, TaskCount)
{
    uint32_t bad = 77u;
    EXPECT_EQ(mt_sched_validate(nullptr, 0u, 400u, &bad), MT_E_TASK_COUNT);
    EXPECT_EQ(bad, 0u);
    std::vector<mt_task_t> v(MT_CFG_SCHED_MAX_TASKS + 1u, entry(MT_HZ(10), 10u, 3u));
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_COUNT);
    EXPECT_EQ(bad, MT_CFG_SCHED_MAX_TASKS + 1u);
    v.pop_back();
    EXPECT_EQ(validate(v, 400u, &bad), MT_OK); // exactly the maximum
}

TEST(SchedValidate, TaskOrder)
{
    uint32_t bad = 0u;
    std::vector<mt_task_t> v = {entry(MT_HZ(10), 10u, 3u), entry(MT_HZ(10), 10u, 5u),
                                entry(MT_HZ(10), 10u, 4u), entry(MT_HZ(10), 10u, 1u)};
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_ORDER);
    EXPECT_EQ(bad, 2u);
    v[2].priority = 5u; // equal priorities are fine
    v[3].priority = 9u;
    EXPECT_EQ(validate(v, 400u, &bad), MT_OK);
    // a fast task after a normal one
    std::vector<mt_task_t> w = {entry(MT_HZ(10), 10u, 3u), entry(0u, 0u, 0u)};
    EXPECT_EQ(validate(w, 400u, &bad), MT_E_TASK_ORDER);
    EXPECT_EQ(bad, 1u);
}

TEST(SchedValidate, TaskRate)
{
    uint32_t bad = 0u;
    std::vector<mt_task_t> v = good_table();
    v[3].rate_mhz = 0u; // normal task with rate 0
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_RATE);
    EXPECT_EQ(bad, 3u);
    v[3].rate_mhz = MT_HZ(400) + 1u; // above the loop rate
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_RATE);
    EXPECT_EQ(bad, 3u);
    v[3].rate_mhz = MT_HZ(400); // exactly the loop rate
    EXPECT_EQ(validate(v, 400u, &bad), MT_OK);
    v[3].rate_mhz = 1u; // 0.001 Hz
    EXPECT_EQ(validate(v, 400u, &bad), MT_OK);
    v[1].rate_mhz = 1u; // fast task with a rate
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_RATE);
    EXPECT_EQ(bad, 1u);
    // the same rate is fine at a higher loop rate
    std::vector<mt_task_t> w = {entry(MT_HZ(1000), 100u, 3u)};
    EXPECT_EQ(validate(w, 400u, &bad), MT_E_TASK_RATE);
    EXPECT_EQ(validate(w, 1000u, &bad), MT_OK);
}

// S-5 regression: a normal task with budget 0 passed ArduPilot's budget test
// even with no time left; here it is refused at init.
TEST(SchedValidate, TaskBudgetS5ZeroBudgetAndOverPeriod)
{
    uint32_t bad = 0u;
    std::vector<mt_task_t> v = good_table();
    v[4].budget_us = 0u;
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_BUDGET);
    EXPECT_EQ(bad, 4u);
    v[4].budget_us = 2501u; // longer than the 2500 us period
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_BUDGET);
    EXPECT_EQ(bad, 4u);
    v[4].budget_us = 2500u;
    EXPECT_EQ(validate(v, 400u, &bad), MT_OK);
    v[0].budget_us = 2501u; // a fast task's budget is bounded by the period too
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_BUDGET);
    EXPECT_EQ(bad, 0u);
    v[0].budget_us = 0u; // ... but may be 0 (allowance: the whole period)
    EXPECT_EQ(validate(v, 400u, &bad), MT_OK);
}

TEST(SchedValidate, TaskFn)
{
    uint32_t bad = 0u;
    std::vector<mt_task_t> v = good_table();
    v[2].fn = nullptr;
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_FN);
    EXPECT_EQ(bad, 2u);
    v[2].rate_mhz = 0u; // several problems: the missing function is reported
    v[2].budget_us = 0u;
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_FN);
}

TEST(SchedValidate, FirstFaultyEntryIsReported)
{
    uint32_t bad = 0u;
    std::vector<mt_task_t> v = good_table();
    v[4].budget_us = 0u;
    v[2].rate_mhz = 0u;
    EXPECT_EQ(validate(v, 400u, &bad), MT_E_TASK_RATE);
    EXPECT_EQ(bad, 2u);
}

TEST(SchedValidate, CheckEntryPerEntry)
{
    std::vector<mt_task_t> v = {
        entry(0u, 0u, 0u),                  // 0 ok (fast)
        entry(5u, 0u, 1u),                  // 1 fast with a rate
        entry(MT_HZ(10), 3000u, 2u),        // 2 fast with a rate (checked before budget)
        entry(0u, 3000u, 2u),               // 3 fast, budget over the period
        entry(MT_HZ(10), 10u, 3u, nullptr), // 4 no function
        entry(0u, 10u, 3u),                 // 5 normal, rate 0
        entry(MT_HZ(10), 0u, 3u),           // 6 normal, budget 0
        entry(MT_HZ(10), 2501u, 3u),        // 7 normal, budget over the period
        entry(MT_HZ(10), 10u, 9u),          // 8 ok
        entry(MT_HZ(10), 10u, 8u),          // 9 priority below the previous one
        entry(MT_HZ(401), 10u, 9u),         // 10 above the loop rate
        entry(MT_HZ(10), 10u, 9u),          // 11 ok
    };
    const mt_status_t want[] = {MT_OK,        MT_E_TASK_RATE,  MT_E_TASK_RATE,   MT_E_TASK_BUDGET,
                                MT_E_TASK_FN, MT_E_TASK_RATE,  MT_E_TASK_BUDGET, MT_E_TASK_BUDGET,
                                MT_OK,        MT_E_TASK_ORDER, MT_E_TASK_RATE,   MT_OK};
    ASSERT_EQ(v.size(), sizeof(want) / sizeof(want[0]));
    for (uint32_t i = 0; i < v.size(); ++i) {
        EXPECT_EQ(mt_sched_check_entry(v.data(), static_cast<uint32_t>(v.size()), i, 400u), want[i])
            << "entry " << i;
    }
}

TEST(SchedInit, RejectedInitLeavesSchedulerUntouched)
{
    auto s = std::make_unique<mt_sched_t>();
    auto ref = std::make_unique<mt_sched_t>();
    std::memset(s.get(), 0xA5, sizeof(*s));
    std::memcpy(ref.get(), s.get(), sizeof(*s));
    uint32_t bad = 0u;

    std::vector<mt_task_t> v = good_table();
    EXPECT_EQ(mt_sched_init(s.get(), v.data(), static_cast<uint32_t>(v.size()), 49u, &bad),
              MT_E_LOOP_RATE);
    EXPECT_EQ(std::memcmp(s.get(), ref.get(), sizeof(*s)), 0);
    EXPECT_EQ(mt_sched_init(s.get(), v.data(), 0u, 400u, &bad), MT_E_TASK_COUNT);
    EXPECT_EQ(std::memcmp(s.get(), ref.get(), sizeof(*s)), 0);
    v[3].priority = 1u;
    EXPECT_EQ(mt_sched_init(s.get(), v.data(), static_cast<uint32_t>(v.size()), 400u, &bad),
              MT_E_TASK_RATE);
    EXPECT_EQ(bad, 3u);
    EXPECT_EQ(std::memcmp(s.get(), ref.get(), sizeof(*s)), 0);
    v = good_table();
    v[4].budget_us = 0u;
    EXPECT_EQ(mt_sched_init(s.get(), v.data(), static_cast<uint32_t>(v.size()), 400u, &bad),
              MT_E_TASK_BUDGET);
    EXPECT_EQ(std::memcmp(s.get(), ref.get(), sizeof(*s)), 0);

    // an accepted table sets up a fresh scheduler
    v = good_table();
    ASSERT_EQ(mt_sched_init(s.get(), v.data(), static_cast<uint32_t>(v.size()), 400u, &bad), MT_OK);
    EXPECT_EQ(s->tasks, v.data());
    EXPECT_EQ(s->ntasks, v.size());
    EXPECT_EQ(s->loop_rate_hz, 400u);
    EXPECT_EQ(s->period_us, 2500u);
    EXPECT_EQ(s->current, MT_SCHED_IDLE);
    EXPECT_EQ(s->tick, 0u);
    EXPECT_EQ(s->run_tick, 0u);
    EXPECT_EQ(s->extra_us, 0u);
    const uint32_t intervals[] = {1u, 1u, 1u, 8u, 4000u};
    for (uint32_t i = 0; i < v.size(); ++i) {
        EXPECT_EQ(s->st[i].interval, intervals[i]) << i;
        EXPECT_EQ(s->st[i].runs, 0u);
        EXPECT_EQ(s->st[i].last_run, 0u);
        EXPECT_EQ(s->st[i].slips, 0u);
        EXPECT_EQ(s->st[i].overruns, 0u);
    }
}

// ---- simulated-time harness -----------------------------------------------------------

struct Harness;

struct Ctx {
    Harness *h = nullptr;
    int index = -1;
    uint64_t cost_us = 0u;
    std::function<uint64_t(uint64_t)> cost_of_run; // overrides cost_us when set
    std::function<void(Ctx &)> body;               // extra work inside the task
    std::vector<uint64_t> ticks;                   // tick of every run
    int32_t crumb = 0;                             // breadcrumb seen inside
    uint32_t avail_inside = 0u;                    // time_available_us at start
};

struct Harness {
    mt_sched_t s{};
    mt_posix_metronome_t m{};
    std::vector<mt_task_t> tasks;
    std::deque<Ctx> ctx;
    std::vector<int> this_tick; // task indices run in the last loop, in order
    uint64_t late_us = 0u;      // sample delivered late by this much (eats the budget)
    int32_t crumb_in_wait = 0;
    uint32_t rate_hz = 0u;
    // when set: the sample time is read from a simulated hardware counter,
    // extended to 64 bits by mt_time_extend as a port on a board does
    std::function<uint64_t()> port_clock;
    uint64_t clock_mismatches = 0u;

    Ctx &add(uint32_t rate_mhz, uint32_t budget_us, uint8_t prio, uint64_t cost_us)
    {
        ctx.emplace_back();
        Ctx &c = ctx.back();
        c.h = this;
        c.index = static_cast<int>(tasks.size());
        c.cost_us = cost_us;
        mt_task_t t = entry(rate_mhz, budget_us, prio, task_fn);
        t.name = "task";
        t.arg = &c;
        tasks.push_back(t);
        return c;
    }
    mt_status_t init(uint32_t hz)
    {
        uint32_t bad = 0u;
        rate_hz = hz;
        mt_posix_metronome_init(&m, 1000000u / hz);
        return mt_sched_init(&s, tasks.data(), static_cast<uint32_t>(tasks.size()), hz, &bad);
    }
    static uint64_t wait(void *p)
    {
        Harness *h = static_cast<Harness *>(p);
        h->crumb_in_wait = h->s.current;
        uint64_t sample = mt_posix_metronome_wait(&h->m);
        if (h->port_clock) {
            const uint64_t from_counter = h->port_clock();
            h->clock_mismatches += (from_counter != sample) ? 1u : 0u;
            sample = from_counter;
        }
        if (h->late_us != 0u) {
            mt_posix_sim_advance(h->late_us);
        }
        h->this_tick.clear();
        return sample;
    }
    void loop()
    {
        mt_sched_loop_once(&s, wait, this);
    }
    void loops(uint64_t n)
    {
        for (uint64_t k = 0; k < n; ++k) {
            loop();
        }
    }
    mt_task_report_t report(uint32_t i) const
    {
        mt_task_report_t r;
        mt_sched_task_report(&s, i, &r);
        return r;
    }
    mt_loop_report_t loop_report() const
    {
        mt_loop_report_t r;
        mt_sched_loop_report(&s, &r);
        return r;
    }
    static void task_fn(void *arg)
    {
        Ctx *c = static_cast<Ctx *>(arg);
        Harness *h = c->h;
        c->ticks.push_back(h->s.tick);
        c->crumb = h->s.current;
        c->avail_inside = mt_sched_time_available_us(&h->s);
        h->this_tick.push_back(c->index);
        const uint64_t run_no = c->ticks.size() - 1u;
        if (c->body) {
            c->body(*c);
        }
        mt_posix_sim_advance(c->cost_of_run ? c->cost_of_run(run_no) : c->cost_us);
    }
};

class SchedSim : public SimTime
{
  protected:
    std::unique_ptr<Harness> h = std::make_unique<Harness>();
};

// ---- rates and fast tasks -------------------------------------------------------------

TEST_F(SchedSim, FiftyHzTaskAt400HzRunsEvery8Ticks)
{
    Ctx &fast = h->add(0u, 0u, 0u, 10u);
    Ctx &t50 = h->add(MT_HZ(50), 200u, 3u, 100u);
    ASSERT_EQ(h->init(400u), MT_OK);
    const uint64_t t0 = mt_port_now_us();
    h->loops(4000u);
    EXPECT_EQ(h->s.tick, 4000u);
    EXPECT_EQ(fast.ticks.size(), 4000u);
    ASSERT_EQ(t50.ticks.size(), 500u);
    for (size_t k = 0; k < t50.ticks.size(); ++k) {
        ASSERT_EQ(t50.ticks[k], 8u * (k + 1u));
    }
    const mt_task_report_t r = h->report(1u);
    EXPECT_EQ(r.runs, 500u);
    EXPECT_EQ(r.interval, 8u);
    EXPECT_EQ(r.slips, 0u);
    EXPECT_EQ(r.pending, 0u);
    EXPECT_EQ(r.min_us, 100u);
    EXPECT_EQ(r.max_us, 100u);
    EXPECT_EQ(r.mean_us, 100u);
    EXPECT_EQ(r.overruns, 0u);
    EXPECT_STREQ(r.name, "task");
    // 4000 samples 2500 us apart
    EXPECT_EQ(h->s.last_sample_us, t0 + 4000u * 2500u);
}

TEST_F(SchedSim, TenthOfAHertzTask)
{
    Ctx &slow = h->add(100u, 500u, 10u, 5u); // 0.1 Hz
    ASSERT_EQ(h->init(400u), MT_OK);
    EXPECT_EQ(h->s.st[0].interval, 4000u);
    h->loops(3999u);
    EXPECT_TRUE(slow.ticks.empty());
    h->loops(8001u);
    EXPECT_EQ(slow.ticks, (std::vector<uint64_t>{4000u, 8000u, 12000u}));
}

// S-4 regression: with ArduPilot's 16-bit dt an interval above 65535 ticks never
// came due. 0.005 Hz at 400 Hz is an interval of 80000 ticks.
TEST_F(SchedSim, S4IntervalAbove65535Ticks)
{
    Ctx &t = h->add(5u, 100u, 3u, 1u);
    ASSERT_EQ(h->init(400u), MT_OK);
    EXPECT_EQ(h->s.st[0].interval, 80000u);
    h->loops(79999u);
    EXPECT_TRUE(t.ticks.empty());
    EXPECT_EQ(h->report(0u).pending, 0u);
    h->loop();
    EXPECT_EQ(t.ticks, (std::vector<uint64_t>{80000u}));
    h->loops(80000u);
    EXPECT_EQ(t.ticks, (std::vector<uint64_t>{80000u, 160000u}));
    EXPECT_EQ(h->report(0u).slips, 0u);
}

TEST_F(SchedSim, S4IntervalAbove65535TicksAt2000Hz)
{
    Ctx &t = h->add(20u, 100u, 3u, 1u); // 0.02 Hz at 2000 Hz: 100000 ticks
    ASSERT_EQ(h->init(2000u), MT_OK);
    EXPECT_EQ(h->s.st[0].interval, 100000u);
    h->loops(100000u);
    EXPECT_EQ(t.ticks, (std::vector<uint64_t>{100000u}));
}

TEST_F(SchedSim, IntervalIsFloorOfLoopRateOverTaskRate)
{
    Ctx &a = h->add(MT_HZ(150), 100u, 3u, 1u); // 400/150 = 2.67 -> 2
    Ctx &b = h->add(MT_HZ(400), 100u, 3u, 1u); // 1
    Ctx &c = h->add(MT_HZ(300), 100u, 3u, 1u); // 1.33 -> 1
    Ctx &d = h->add(MT_HZ(7), 100u, 3u, 1u);   // 57.1 -> 57
    Ctx &e = h->add(333333u, 100u, 3u, 1u);    // 400/333.333 -> 1
    ASSERT_EQ(h->init(400u), MT_OK);
    const uint32_t iv[] = {2u, 1u, 1u, 57u, 1u};
    for (uint32_t i = 0; i < 5u; ++i) {
        EXPECT_EQ(h->s.st[i].interval, iv[i]);
    }
    h->loops(400u);
    EXPECT_EQ(a.ticks.size(), 200u);
    EXPECT_EQ(b.ticks.size(), 400u);
    EXPECT_EQ(c.ticks.size(), 400u);
    EXPECT_EQ(d.ticks.size(), 7u);
    EXPECT_EQ(e.ticks.size(), 400u);
}

// S-3 regression: ArduPilot computed intervals from the live loop-rate parameter
// while the loop period stayed latched. Here the rate given to init fixes both
// the period and every interval; two schedulers with different rates over the
// same table do not influence each other.
TEST_F(SchedSim, S3LoopRateLatchedAtInit)
{
    Ctx &t = h->add(MT_HZ(10), 100u, 3u, 1u);
    ASSERT_EQ(h->init(50u), MT_OK);
    EXPECT_EQ(h->s.period_us, 20000u);
    EXPECT_EQ(h->s.st[0].interval, 5u);

    auto other = std::make_unique<mt_sched_t>();
    uint32_t bad = 0u;
    ASSERT_EQ(mt_sched_init(other.get(), h->tasks.data(), 1u, 400u, &bad), MT_OK);
    EXPECT_EQ(other->st[0].interval, 40u);
    EXPECT_EQ(other->period_us, 2500u);

    const uint64_t t0 = mt_port_now_us();
    h->loops(100u);
    EXPECT_EQ(h->s.loop_rate_hz, 50u);
    EXPECT_EQ(h->s.st[0].interval, 5u);
    EXPECT_EQ(t.ticks.size(), 20u);                     // 10 Hz in a 50 Hz loop
    EXPECT_EQ(h->s.last_sample_us, t0 + 100u * 20000u); // samples 20 ms apart
    EXPECT_EQ(h->loop_report().mean_us, 20000u);
}

TEST_F(SchedSim, FastTasksRunEveryTickEvenWhenBudgetExhausted)
{
    Ctx &hog = h->add(0u, 0u, 0u, 3000u);  // fast, longer than the period
    Ctx &fast = h->add(0u, 100u, 2u, 10u); // fast, runs after the budget is gone
    Ctx &norm = h->add(MT_HZ(400), 100u, 3u, 10u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(100u);
    EXPECT_EQ(hog.ticks.size(), 100u);
    EXPECT_EQ(fast.ticks.size(), 100u);
    EXPECT_EQ(norm.ticks.size(), 0u); // never fits after the hog
    const mt_task_report_t r = h->report(2u);
    EXPECT_EQ(r.budget_skips, 100u);
    EXPECT_EQ(r.pending, 100u);
    EXPECT_EQ(h->report(0u).overruns, 100u); // 3000 > allowance of one period
    EXPECT_EQ(h->report(1u).overruns, 0u);
}

TEST_F(SchedSim, FastTasksRunWhenTheSampleArrivesLate)
{
    Ctx &fast = h->add(0u, 0u, 1u, 10u);
    Ctx &norm = h->add(MT_HZ(400), 100u, 3u, 10u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->late_us = 2600u; // no time left in the period at all
    h->loops(10u);
    EXPECT_EQ(fast.ticks.size(), 10u);
    EXPECT_EQ(fast.avail_inside, 2500u); // budget 0: the allowance is the period
    EXPECT_TRUE(norm.ticks.empty());
    EXPECT_EQ(h->report(1u).budget_skips, 10u);
    h->late_us = 0u;
    h->loop();
    EXPECT_EQ(norm.ticks, (std::vector<uint64_t>{11u}));
    EXPECT_EQ(h->report(1u).slips, 10u);       // 11 releases, one served
    EXPECT_EQ(h->report(1u).not_achieved, 1u); // 11 >= 4 intervals late
}

// ---- budget, overruns, slips ------------------------------------------------------------

TEST_F(SchedSim, BudgetSkipStaysDueAndCheaperLaterTaskRuns)
{
    Ctx &a = h->add(MT_HZ(200), 2000u, 10u, 2000u); // every 2nd tick, eats 2000 of 2500
    Ctx &b = h->add(MT_HZ(400), 1000u, 20u, 100u);  // does not fit after a
    Ctx &c = h->add(MT_HZ(400), 300u, 30u, 50u);    // fits after a
    ASSERT_EQ(h->init(400u), MT_OK);
    for (uint64_t t = 1u; t <= 100u; ++t) {
        h->loop();
        if (t % 2u == 0u) {
            ASSERT_EQ(h->this_tick, (std::vector<int>{0, 2})) << "tick " << t;
        } else {
            ASSERT_EQ(h->this_tick, (std::vector<int>{1, 2})) << "tick " << t;
        }
    }
    EXPECT_EQ(a.ticks.size(), 50u);
    EXPECT_EQ(b.ticks.size(), 50u);
    EXPECT_EQ(c.ticks.size(), 100u);
    const mt_task_report_t rb = h->report(1u);
    EXPECT_EQ(rb.budget_skips, 50u);
    EXPECT_EQ(rb.slips, 49u); // every skipped release (the one at tick 100 is pending)
    EXPECT_EQ(rb.pending, 1u);
    EXPECT_EQ(rb.runs + rb.slips + rb.pending, 100u);
    EXPECT_EQ(rb.not_achieved, 0u);
    EXPECT_EQ(rb.overruns, 0u);
    EXPECT_EQ(h->report(0u).overruns, 0u); // taking exactly the budget is not an overrun
    EXPECT_EQ(h->report(2u).budget_skips, 0u);
}

// S-1 regression: ArduPilot counted slips in the overrun counter.
TEST_F(SchedSim, S1OverrunsAndSlipsAreSeparateCounters)
{
    h->add(MT_HZ(200), 2000u, 10u, 2000u); // crowds out the next task every 2nd tick
    Ctx &slipper = h->add(MT_HZ(400), 1000u, 20u, 100u);
    Ctx &overrunner = h->add(MT_HZ(400), 100u, 30u, 150u); // always 50 us over
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(100u);
    const mt_task_report_t rs = h->report(1u);
    const mt_task_report_t ro = h->report(2u);
    EXPECT_EQ(slipper.ticks.size(), 50u);
    EXPECT_EQ(rs.slips, 49u);
    EXPECT_EQ(rs.overruns, 0u);
    EXPECT_EQ(overrunner.ticks.size(), 100u);
    EXPECT_EQ(ro.overruns, 100u);
    EXPECT_EQ(ro.slips, 0u);
}

// A task kept from running for k intervals gets k - 1 slips when it runs, and
// "not achieved" from 4 intervals on.
TEST_F(SchedSim, SlipsExactAfterKIntervals)
{
    for (uint64_t k = 1u; k <= 7u; ++k) {
        mt_posix_sim_enable(mt_test::kSimStartUs);
        h = std::make_unique<Harness>();
        Ctx &t = h->add(MT_HZ(50), 1000u, 3u, 10u); // interval 8 at 400 Hz
        ASSERT_EQ(h->init(400u), MT_OK);
        h->loops(8u);
        ASSERT_EQ(t.ticks, (std::vector<uint64_t>{8u}));
        h->late_us = 3000u; // blocked: no budget left in these loops
        h->loops(8u * k - 1u);
        EXPECT_EQ(t.ticks.size(), 1u);
        EXPECT_EQ(h->report(0u).pending, k - 1u);
        h->late_us = 0u;
        h->loop();
        ASSERT_EQ(t.ticks.size(), 2u) << "k " << k;
        EXPECT_EQ(t.ticks[1], 8u + 8u * k);
        const mt_task_report_t r = h->report(0u);
        EXPECT_EQ(r.slips, k - 1u) << "k " << k;
        EXPECT_EQ(r.not_achieved, k >= 4u ? 1u : 0u) << "k " << k;
        EXPECT_EQ(r.budget_skips, 8u * (k - 1u)) << "k " << k;
        EXPECT_EQ(r.pending, 0u);
        EXPECT_EQ(r.runs + r.slips + r.pending, k + 1u); // releases at 8, 16, ..., 8 + 8k
        EXPECT_EQ(h->s.extra_us, k >= 4u ? 100u : 0u);
    }
}

// ---- adaptive extra time -------------------------------------------------------------------

TEST_F(SchedSim, ExtraTimeRisesOnLateLoopsAndDecaysAfterCleanOnes)
{
    Ctx &t = h->add(MT_HZ(400), 1000u, 3u, 10u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loop(); // tick 1
    h->late_us = 3000u;
    h->loops(3u); // ticks 2..4 blocked
    h->late_us = 0u;
    h->loop(); // tick 5: dt = 4 intervals: not achieved
    EXPECT_EQ(t.ticks, (std::vector<uint64_t>{1u, 5u}));
    EXPECT_EQ(h->report(0u).not_achieved, 1u);
    EXPECT_EQ(h->s.extra_us, 100u);
    EXPECT_EQ(h->loop_report().extra_us, 100u);
    h->loops(50u); // 50 clean loops: no change yet
    EXPECT_EQ(h->s.extra_us, 100u);
    h->loop(); // the 51st
    EXPECT_EQ(h->s.extra_us, 50u);
    h->loops(50u);
    EXPECT_EQ(h->s.extra_us, 50u);
    h->loop();
    EXPECT_EQ(h->s.extra_us, 0u);
    h->loops(200u);
    EXPECT_EQ(h->s.extra_us, 0u);
}

TEST_F(SchedSim, ExtraTimeStepsAndCap)
{
    h->add(MT_HZ(400), 100u, 3u, 1u);
    ASSERT_EQ(h->init(400u), MT_OK);
    for (uint32_t k = 1u; k <= 60u; ++k) {
        h->s.late_in_loop = 1u;
        mt_sched_end_loop(&h->s, 0u);
        ASSERT_EQ(h->s.extra_us, std::min(100u * k, 5000u)) << k;
        ASSERT_EQ(h->s.late_in_loop, 0u);
    }
    for (uint32_t k = 1u; k <= 50u; ++k) {
        mt_sched_end_loop(&h->s, 0u);
    }
    EXPECT_EQ(h->s.extra_us, 5000u);
    mt_sched_end_loop(&h->s, 0u);
    EXPECT_EQ(h->s.extra_us, 4950u);
    for (uint32_t k = 1u; k <= 30u; ++k) {
        mt_sched_end_loop(&h->s, 0u);
    }
    h->s.late_in_loop = 3u; // a late loop (several late tasks: still one step)
    mt_sched_end_loop(&h->s, 0u);
    EXPECT_EQ(h->s.extra_us, 5000u);
    for (uint32_t k = 1u; k <= 50u; ++k) { // the clean count started again
        mt_sched_end_loop(&h->s, 0u);
    }
    EXPECT_EQ(h->s.extra_us, 5000u);
    mt_sched_end_loop(&h->s, 0u);
    EXPECT_EQ(h->s.extra_us, 4950u);
}

TEST_F(SchedSim, ExtraTimeIsAddedToTheLoopBudget)
{
    Ctx &t = h->add(MT_HZ(400), 1000u, 3u, 10u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->s.extra_us = 1200u;
    h->late_us = 2400u; // 100 us of the period left, + 1200 extra: the 1000 us budget fits
    h->loop();
    EXPECT_EQ(t.ticks.size(), 1u);
    h->s.extra_us = 800u; // 900 us: it does not
    h->loop();
    EXPECT_EQ(t.ticks.size(), 1u);
    EXPECT_EQ(h->report(0u).budget_skips, 1u);
}

// ---- statistics -------------------------------------------------------------------------------

// S-7 regression: ArduPilot stored task times in 16 bits (70 ms became 4464 us)
// and divided by zero for the mean right after a reset.
TEST_F(SchedSim, S7LongTaskTimeNotTruncatedAndMeanGuarded)
{
    Ctx &t = h->add(MT_HZ(50), 20000u, 3u, 70000u);
    h->add(MT_HZ(1), 100u, 4u, 0u);
    ASSERT_EQ(h->init(50u), MT_OK);
    mt_task_report_t r = h->report(0u);
    EXPECT_EQ(r.runs, 0u);
    EXPECT_EQ(r.mean_us, 0u);
    EXPECT_EQ(r.min_us, 0u);
    EXPECT_EQ(h->loop_report().mean_us, 0u);
    EXPECT_EQ(h->loop_report().loops, 0u);

    h->loops(3u);
    ASSERT_EQ(t.ticks.size(), 3u);
    r = h->report(0u);
    EXPECT_EQ(r.max_us, 70000u);
    EXPECT_EQ(r.min_us, 70000u);
    EXPECT_EQ(r.mean_us, 70000u);
    EXPECT_EQ(r.overruns, 3u);
    EXPECT_EQ(h->s.st[0].total_us, 210000u);
    EXPECT_EQ(h->report(1u).mean_us, 0u); // never ran: still guarded

    mt_sched_reset_stats(&h->s);
    r = h->report(0u);
    EXPECT_EQ(r.runs, 0u);
    EXPECT_EQ(r.mean_us, 0u);
    EXPECT_EQ(h->loop_report().mean_us, 0u);
}

TEST_F(SchedSim, MinMaxMeanOfVaryingRunTimes)
{
    Ctx &t = h->add(MT_HZ(400), 2000u, 3u, 0u);
    const uint64_t costs[] = {300u, 100u, 500u, 200u};
    t.cost_of_run = [&](uint64_t n) { return costs[n % 4u]; };
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(8u);
    const mt_task_report_t r = h->report(0u);
    EXPECT_EQ(r.min_us, 100u);
    EXPECT_EQ(r.max_us, 500u);
    EXPECT_EQ(r.mean_us, 275u);
    EXPECT_EQ(h->s.st[0].total_us, 2200u);
}

TEST_F(SchedSim, LoopStatisticsFromSamples)
{
    h->add(MT_HZ(1), 100u, 3u, 0u);
    ASSERT_EQ(h->init(400u), MT_OK); // period 2500, long loop > 3000
    mt_sched_note_sample(&h->s, 1000000u);
    EXPECT_EQ(h->s.loops, 0u); // first sample: no loop yet
    EXPECT_EQ(h->s.loop_min_us, 0u);
    mt_sched_note_sample(&h->s, 1002500u);
    mt_sched_note_sample(&h->s, 1005000u);
    mt_sched_note_sample(&h->s, 1009000u); // 4000: long
    mt_sched_note_sample(&h->s, 1011000u); // 2000
    mt_loop_report_t lr = h->loop_report();
    EXPECT_EQ(lr.loops, 4u);
    EXPECT_EQ(lr.min_us, 2000u);
    EXPECT_EQ(lr.max_us, 4000u);
    EXPECT_EQ(lr.mean_us, 2750u);
    EXPECT_EQ(lr.long_loops, 1u);
    EXPECT_GE(lr.filtered_us, 2500u);
    EXPECT_LE(lr.filtered_us, 2600u);
    const uint32_t f = h->s.filtered_loop_q8;
    mt_sched_note_sample(&h->s, 1011000u + 20000u); // an outlier (> 1.2 periods + 10 ms)
    EXPECT_EQ(h->s.filtered_loop_q8, f);            // kept out of the filter
    lr = h->loop_report();
    EXPECT_EQ(lr.max_us, 20000u);
    EXPECT_EQ(lr.long_loops, 2u);
    EXPECT_EQ(lr.loops, 5u);
}

// S-8 regression: with more spare time than the period (extra time added) ArduPilot
// wrapped an unsigned subtraction and reported 100% load on an idle CPU.
TEST_F(SchedSim, S8LoadIsZeroWhenSpareExceedsPeriod)
{
    h->add(MT_HZ(400), 100u, 3u, 0u);
    ASSERT_EQ(h->init(400u), MT_OK);
    EXPECT_EQ(mt_sched_load_permille(&h->s), 0u); // before the first loop
    h->s.extra_us = 5000u;
    h->loops(40u); // idle tasks, 7500 us spare per loop
    EXPECT_GT(h->s.extra_us, 0u);
    EXPECT_GE(h->s.spare_us / h->s.spare_ticks, 2500u);
    EXPECT_EQ(mt_sched_load_permille(&h->s), 0u);
    EXPECT_EQ(h->loop_report().load_permille, 0u);
}

TEST_F(SchedSim, LoadFromSpareTime)
{
    h->add(MT_HZ(400), 100u, 3u, 0u);
    ASSERT_EQ(h->init(400u), MT_OK);
    for (int k = 0; k < 40; ++k) {
        mt_sched_end_loop(&h->s, 1250u);
    }
    EXPECT_EQ(mt_sched_load_permille(&h->s), 500u);
    for (int k = 0; k < 200; ++k) {
        mt_sched_end_loop(&h->s, 0u);
    }
    EXPECT_EQ(mt_sched_load_permille(&h->s), 1000u);
    EXPECT_LT(h->s.spare_ticks, MT_SCHED_SPARE_WINDOW);
}

TEST_F(SchedSim, LoadNearZeroAtIdle)
{
    h->add(0u, 0u, 0u, 0u);
    h->add(MT_HZ(50), 100u, 3u, 0u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(200u);
    EXPECT_EQ(h->loop_report().load_permille, 0u);
    EXPECT_EQ(h->loop_report().long_loops, 0u);
}

TEST_F(SchedSim, LoadNearFullAtFullLoad)
{
    h->add(MT_HZ(400), 2500u, 3u, 2499u); // uses all but 1 us of every period
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(200u);
    const mt_loop_report_t lr = h->loop_report();
    EXPECT_GE(lr.load_permille, 995u);
    EXPECT_LE(lr.load_permille, 1000u);
    EXPECT_EQ(lr.long_loops, 0u); // busy, not late
}

TEST_F(SchedSim, LoadHalf)
{
    h->add(MT_HZ(400), 2500u, 3u, 1250u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(200u);
    EXPECT_EQ(h->loop_report().load_permille, 500u);
}

TEST_F(SchedSim, LoadFullWhenOverloaded)
{
    h->add(MT_HZ(400), 2500u, 3u, 4000u); // every loop overruns the period
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(200u);
    const mt_loop_report_t lr = h->loop_report();
    EXPECT_EQ(lr.load_permille, 1000u);
    EXPECT_GT(lr.long_loops, 0u);
    EXPECT_GT(lr.filtered_us, 2500u * 100u / 95u); // the filtered loop rate is below 95%
}

// ---- per-tick rules ----------------------------------------------------------------------------

TEST_F(SchedSim, SecondRunInTheSameTickRunsNothing)
{
    Ctx &fast = h->add(0u, 0u, 0u, 10u);
    Ctx &norm = h->add(MT_HZ(400), 100u, 3u, 10u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loop();
    ASSERT_EQ(fast.ticks.size(), 1u);
    ASSERT_EQ(norm.ticks.size(), 1u);
    EXPECT_EQ(mt_sched_run(&h->s, 5000u), 5000u); // the whole allowance comes back
    EXPECT_EQ(fast.ticks.size(), 1u);
    EXPECT_EQ(norm.ticks.size(), 1u);
    mt_sched_tick(&h->s);
    EXPECT_EQ(mt_sched_run(&h->s, 5000u), 5000u - 20u);
    EXPECT_EQ(fast.ticks.size(), 2u);
    EXPECT_EQ(norm.ticks.size(), 2u);
    EXPECT_EQ(h->s.run_tick, h->s.tick);
    EXPECT_EQ(mt_sched_run(&h->s, 5000u), 5000u);
    EXPECT_EQ(fast.ticks.size(), 2u);
}

TEST_F(SchedSim, RunReturnsTimeLeftSaturatingAtZero)
{
    h->add(0u, 0u, 0u, 700u);
    h->add(MT_HZ(400), 100u, 3u, 60u);
    ASSERT_EQ(h->init(400u), MT_OK);
    mt_sched_tick(&h->s);
    EXPECT_EQ(mt_sched_run(&h->s, 1000u), 240u);
    mt_sched_tick(&h->s);
    EXPECT_EQ(mt_sched_run(&h->s, 500u), 0u); // the fast task alone exceeds it
    EXPECT_EQ(h->report(1u).budget_skips, 1u);
}

TEST_F(SchedSim, BreadcrumbsInTaskIdleAndWaitingForSample)
{
    Ctx &a = h->add(0u, 0u, 0u, 1u);
    Ctx &b = h->add(MT_HZ(400), 100u, 3u, 1u);
    Ctx &c = h->add(MT_HZ(400), 100u, 7u, 1u);
    ASSERT_EQ(h->init(400u), MT_OK);
    EXPECT_EQ(h->s.current, MT_SCHED_IDLE);
    h->crumb_in_wait = 12345;
    h->loop();
    EXPECT_EQ(h->crumb_in_wait, MT_SCHED_WAIT_SAMPLE);
    EXPECT_EQ(a.crumb, 0);
    EXPECT_EQ(b.crumb, 1);
    EXPECT_EQ(c.crumb, 2);
    EXPECT_EQ(h->s.current, MT_SCHED_IDLE);
    EXPECT_EQ(mt_sched_time_available_us(&h->s), 0u); // idle: no allowance
}

TEST_F(SchedSim, TimeAvailableInsideATask)
{
    Ctx &t = h->add(MT_HZ(400), 1000u, 3u, 0u);
    std::vector<uint32_t> seen;
    t.body = [&](Ctx &c) {
        seen.push_back(mt_sched_time_available_us(&c.h->s));
        mt_posix_sim_advance(300u);
        seen.push_back(mt_sched_time_available_us(&c.h->s));
        mt_posix_sim_advance(699u);
        seen.push_back(mt_sched_time_available_us(&c.h->s));
        mt_posix_sim_advance(1u);
        seen.push_back(mt_sched_time_available_us(&c.h->s));
        mt_posix_sim_advance(500u);
        seen.push_back(mt_sched_time_available_us(&c.h->s));
    };
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loop();
    EXPECT_EQ(seen, (std::vector<uint32_t>{1000u, 700u, 1u, 0u, 0u}));
    EXPECT_EQ(h->report(0u).overruns, 1u); // 1500 us against 1000
}

TEST_F(SchedSim, ResetStatsKeepsTheDueState)
{
    Ctx &t = h->add(MT_HZ(50), 100u, 3u, 10u);
    h->add(MT_HZ(400), 100u, 4u, 200u);
    ASSERT_EQ(h->init(400u), MT_OK);
    h->loops(20u);
    ASSERT_EQ(t.ticks.size(), 2u);
    mt_sched_reset_stats(&h->s);
    for (uint32_t i = 0; i < 2u; ++i) {
        const mt_task_report_t r = h->report(i);
        EXPECT_EQ(r.runs, 0u);
        EXPECT_EQ(r.min_us, 0u);
        EXPECT_EQ(r.max_us, 0u);
        EXPECT_EQ(r.overruns, 0u);
        EXPECT_EQ(r.slips, 0u);
        EXPECT_EQ(r.not_achieved, 0u);
        EXPECT_EQ(r.budget_skips, 0u);
        EXPECT_EQ(h->s.st[i].total_us, 0u);
    }
    const mt_loop_report_t lr = h->loop_report();
    EXPECT_EQ(lr.loops, 0u);
    EXPECT_EQ(lr.min_us, 0u);
    EXPECT_EQ(lr.max_us, 0u);
    EXPECT_EQ(lr.long_loops, 0u);
    EXPECT_EQ(lr.ticks, 20u); // not a statistic
    EXPECT_EQ(h->s.st[0].last_run, 16u);
    EXPECT_EQ(h->s.st[0].interval, 8u);
    h->loops(4u);
    EXPECT_EQ(t.ticks.back(), 24u); // the schedule goes on from the last run
    EXPECT_EQ(h->report(0u).runs, 1u);
    EXPECT_EQ(h->report(0u).min_us, 10u);
}

// ---- long runs and the tick counter ------------------------------------------------------------

TEST_F(SchedSim, VeryLongRunMillionTicks)
{
    // 10^6 ticks (41.7 simulated minutes at 400 Hz); this test has one thread, so
    // ThreadSanitizer adds nothing but time: it runs 240000 ticks there (still
    // three periods of the 80000-tick task).
    const uint64_t n = mt_test::kTsan ? 240000u : 1000000u;
    Ctx &fast = h->add(0u, 0u, 0u, 100u);
    Ctx &t50 = h->add(MT_HZ(50), 300u, 3u, 200u);
    Ctx &slow = h->add(100u, 600u, 4u, 500u);
    Ctx &vslow = h->add(5u, 100u, 5u, 10u);
    ASSERT_EQ(h->init(400u), MT_OK);
    const uint64_t t0 = mt_port_now_us();
    h->loops(n);
    EXPECT_EQ(h->s.tick, n);
    EXPECT_EQ(h->s.last_sample_us, t0 + n * 2500u);
    EXPECT_EQ(fast.ticks.size(), n);
    EXPECT_EQ(t50.ticks.size(), n / 8u);
    EXPECT_EQ(slow.ticks.size(), n / 4000u);
    EXPECT_EQ(vslow.ticks.size(), n / 80000u);
    const uint64_t want_runs[] = {n, n / 8u, n / 4000u, n / 80000u};
    const uint64_t cost[] = {100u, 200u, 500u, 10u};
    for (uint32_t i = 0; i < 4u; ++i) {
        const mt_task_report_t r = h->report(i);
        EXPECT_EQ(r.runs, want_runs[i]) << i;
        EXPECT_EQ(r.slips, 0u) << i;
        EXPECT_EQ(r.overruns, 0u) << i;
        EXPECT_EQ(r.budget_skips, 0u) << i;
        EXPECT_EQ(r.not_achieved, 0u) << i;
        EXPECT_EQ(r.mean_us, cost[i]) << i;
        EXPECT_EQ(h->s.st[i].total_us, want_runs[i] * cost[i]) << i;
    }
    EXPECT_EQ(h->report(3u).pending, (n % 80000u) / 80000u);
    const mt_loop_report_t lr = h->loop_report();
    EXPECT_EQ(lr.ticks, n);
    EXPECT_EQ(lr.loops, n - 1u);
    EXPECT_EQ(lr.min_us, 2500u);
    EXPECT_EQ(lr.max_us, 2500u);
    EXPECT_EQ(lr.mean_us, 2500u);
    EXPECT_EQ(lr.long_loops, 0u);
    EXPECT_EQ(lr.filtered_us, 2500u);
    EXPECT_EQ(lr.extra_us, 0u);
    EXPECT_LT(lr.load_permille, 1000u);
}

void run_across(Harness &hh, uint64_t start)
{
    hh.s.tick = start;
    hh.s.run_tick = start;
    for (uint32_t i = 0; i < hh.s.ntasks; ++i) {
        hh.s.st[i].last_run = start;
    }
    hh.loops(1024u);
}

// The tick counter is 64-bit: passing 2^32 (or 2^63) changes nothing.
TEST_F(SchedSim, TickCounterNeverWraps)
{
    for (uint64_t start : {0xFFFFFF00ull, 0x7FFFFFFFFFFFFF00ull}) {
        mt_posix_sim_enable(mt_test::kSimStartUs);
        h = std::make_unique<Harness>();
        Ctx &fast = h->add(0u, 0u, 0u, 1u);
        Ctx &t = h->add(MT_HZ(50), 100u, 3u, 1u);
        ASSERT_EQ(h->init(400u), MT_OK);
        run_across(*h, start);
        EXPECT_EQ(h->s.tick, start + 1024u);
        EXPECT_GT(h->s.tick, start);
        EXPECT_EQ(fast.ticks.size(), 1024u);
        ASSERT_EQ(t.ticks.size(), 128u);
        for (size_t k = 0; k < t.ticks.size(); ++k) {
            ASSERT_EQ(t.ticks[k], start + 8u * (k + 1u));
        }
        EXPECT_EQ(h->report(1u).slips, 0u);
        EXPECT_EQ(h->report(1u).pending, 0u);
    }
}

// ---- hardware-counter wrap in the port ---------------------------------------------------------

// A board's free-running counter of hw_max + 1 values at ticks_per_us MHz,
// sampled from simulated time and extended by mt_time_extend; the extension is
// the port's only wrap-around handling.
struct HwCounter {
    uint32_t hw_max;
    uint64_t ticks_per_us;
    mt_time_ext_t ext{};
    uint64_t base_us = 0u;
    uint64_t reads = 0u;
    uint64_t wraps = 0u;
    uint32_t last = 0u;

    uint32_t read()
    {
        const uint64_t t = mt_port_now_us() * ticks_per_us;
        const uint32_t hw = static_cast<uint32_t>(t % (static_cast<uint64_t>(hw_max) + 1u));
        wraps += (reads > 0u && hw < last) ? 1u : 0u;
        last = hw;
        ++reads;
        return hw;
    }
    void start()
    {
        base_us = mt_port_now_us();
        ASSERT_EQ(mt_time_ext_init(&ext, hw_max, read()), MT_OK);
    }
    uint64_t now_us()
    {
        const uint64_t ticks = mt_time_extend(&ext, read());
        return base_us + mt_time_ticks_to_us(ticks, static_cast<uint32_t>(ticks_per_us * 1000000u));
    }
};

void run_on_counter(Harness &hh, HwCounter &hw, uint32_t rate, uint64_t loops, uint64_t min_wraps)
{
    Ctx &fast = hh.add(0u, 0u, 0u, 20u);
    Ctx &t50 = hh.add(MT_HZ(50), 100u, 3u, 40u);
    ASSERT_EQ(hh.init(rate), MT_OK);
    hw.start();
    hh.port_clock = [&hw] { return hw.now_us(); };
    hh.loops(loops);
    const uint32_t period = 1000000u / rate;
    EXPECT_GE(hw.wraps, min_wraps) << "the counter must wrap many times";
    EXPECT_EQ(hh.clock_mismatches, 0u) << "extended counter disagrees with the true time";
    const mt_loop_report_t lr = hh.loop_report();
    EXPECT_EQ(lr.loops, loops - 1u);
    EXPECT_EQ(lr.min_us, period); // a wrong extension shows up as a short or long loop
    EXPECT_EQ(lr.max_us, period);
    EXPECT_EQ(lr.long_loops, 0u);
    EXPECT_EQ(fast.ticks.size(), loops);
    EXPECT_EQ(t50.ticks.size(), loops / (rate / 50u));
    EXPECT_EQ(hh.report(1u).budget_skips, 0u); // no phantom elapsed time ate a budget
    EXPECT_EQ(hh.report(1u).slips, 0u);
}

TEST_F(SchedSim, HardwareCounterWrap16BitAt1MHz)
{
    HwCounter hw{0xFFFFu, 1u}; // wraps every 65.536 ms
    run_on_counter(*h, hw, 400u, 40000u, 1500u);
}

TEST_F(SchedSim, HardwareCounterWrap32BitAt168MHz)
{
    HwCounter hw{0xFFFFFFFFu, 168u}; // wraps every 25.6 s
    run_on_counter(*h, hw, 400u, 40000u, 3u);
}

TEST_F(SchedSim, HardwareCounterWrapOddMaximum)
{
    HwCounter hw{999u, 1u}; // counts 0..999 us: wraps every millisecond
    run_on_counter(*h, hw, 2000u, 20000u, 9000u);
}

// ---- differential test against a reference model of the scheduler -----------------------------

struct ModelTask {
    bool fast;
    uint32_t interval;
    uint32_t budget;
    uint64_t last_run = 0u, runs = 0u, slips = 0u, not_achieved = 0u, budget_skips = 0u;
    uint32_t overruns = 0u, min_us = 0u, max_us = 0u;
    uint64_t total = 0u;
};

uint64_t cost_for(uint32_t task, uint64_t run, uint32_t budget, uint32_t period)
{
    Rng r((static_cast<uint64_t>(task) << 40) ^ (run * 0x9E3779B97F4A7C15ull) ^ 0x1234u);
    const uint32_t lim = (budget == 0u) ? period / 4u : budget;
    switch (r.below(8u)) {
    case 0: return lim + r.below(lim / 2u + 1u); // overrun
    case 1: return lim;                          // exactly the allowance
    default: return r.below(lim + 1u);
    }
}

void differential(uint32_t rate, uint64_t seed, uint64_t ticks)
{
    Rng rng(seed);
    auto h = std::make_unique<Harness>();
    const uint32_t period = 1000000u / rate;
    std::vector<ModelTask> model;
    uint8_t prio = 0u;
    const uint32_t nfast = rng.below(3u);
    const uint32_t nnorm = rng.range(2u, 7u);
    for (uint32_t k = 0; k < nfast + nnorm; ++k) {
        const bool fast = k < nfast;
        prio = fast ? static_cast<uint8_t>(std::min<uint32_t>(2u, prio + rng.below(2u)))
                    : static_cast<uint8_t>(std::max<uint32_t>(prio, 3u) + rng.below(3u));
        uint32_t rate_mhz = 0u;
        uint32_t budget = fast ? (rng.below(2u) == 0u ? 0u : rng.range(1u, period / 4u))
                               : rng.range(1u, period / 2u);
        if (!fast) {
            switch (rng.below(4u)) {
            case 0: rate_mhz = rate * 1000u; break;
            case 1: rate_mhz = rng.range(rate * 100u, rate * 1000u); break;
            default: rate_mhz = rng.range(rate * 1000u / 40u, rate * 1000u / 2u); break;
            }
        }
        Ctx &c = h->add(rate_mhz, budget, prio, 0u);
        const uint32_t idx = k;
        c.cost_of_run = [idx, budget, period](uint64_t run) {
            return cost_for(idx, run, budget, period);
        };
        model.push_back(ModelTask{fast, fast ? 1u : (rate * 1000u) / rate_mhz, budget});
    }
    ASSERT_EQ(h->init(rate), MT_OK);
    for (uint32_t i = 0; i < model.size(); ++i) {
        ASSERT_EQ(h->s.st[i].interval, model[i].interval);
    }

    uint32_t extra = 0u, clean = 0u;
    for (uint64_t tick = 1u; tick <= ticks; ++tick) {
        // late samples now and then, sometimes in bursts
        const uint32_t late = (rng.below(10u) == 0u) ? rng.below(2u * period) : 0u;
        h->late_us = late;
        h->loop();
        // model of this tick
        uint32_t avail = ((late >= period) ? 0u : period - late) + extra;
        uint32_t late_tasks = 0u;
        std::vector<int> ran;
        for (uint32_t i = 0; i < model.size(); ++i) {
            ModelTask &m = model[i];
            uint32_t allowed;
            if (m.fast) {
                allowed = (m.budget != 0u) ? m.budget : period;
            } else {
                const uint64_t dt = tick - m.last_run;
                if (dt < m.interval) {
                    continue;
                }
                if (m.budget > avail) {
                    ++m.budget_skips;
                    continue;
                }
                if (dt >= 2u * m.interval) {
                    m.slips += dt / m.interval - 1u;
                }
                if (dt >= 4u * m.interval) {
                    ++m.not_achieved;
                    ++late_tasks;
                }
                allowed = m.budget;
            }
            const uint64_t c = cost_for(i, m.runs, m.budget, period);
            const uint32_t c32 = static_cast<uint32_t>(c);
            if (m.runs == 0u || c32 < m.min_us) {
                m.min_us = c32;
            }
            m.max_us = std::max(m.max_us, c32);
            m.total += c;
            if (c > allowed) {
                ++m.overruns;
            }
            ++m.runs;
            m.last_run = tick;
            avail = (c >= avail) ? 0u : avail - c32;
            ran.push_back(static_cast<int>(i));
        }
        if (late_tasks > 0u) {
            extra = std::min(extra + 100u, 5000u);
            clean = 0u;
        } else if (extra > 0u) {
            if (++clean > 50u) {
                clean = 0u;
                extra = (extra > 50u) ? extra - 50u : 0u;
            }
        } else {
            clean = 0u;
        }
        ASSERT_EQ(h->this_tick, ran) << "tick " << tick << " seed " << seed;
        ASSERT_EQ(h->s.extra_us, extra) << "tick " << tick << " seed " << seed;
    }
    for (uint32_t i = 0; i < model.size(); ++i) {
        const ModelTask &m = model[i];
        const mt_task_report_t r = h->report(i);
        EXPECT_EQ(r.runs, m.runs) << i;
        EXPECT_EQ(r.slips, m.slips) << i;
        EXPECT_EQ(r.not_achieved, m.not_achieved) << i;
        EXPECT_EQ(r.budget_skips, m.budget_skips) << i;
        EXPECT_EQ(r.overruns, m.overruns) << i;
        EXPECT_EQ(r.min_us, m.min_us) << i;
        EXPECT_EQ(r.max_us, m.max_us) << i;
        EXPECT_EQ(h->s.st[i].total_us, m.total) << i;
        // every release is a run, a counted slip or pending, computed from the run
        // ticks the task itself recorded
        const std::vector<uint64_t> &rt = h->ctx[i].ticks;
        uint64_t releases = 0u;
        uint64_t prev = 0u;
        for (uint64_t t : rt) {
            EXPECT_GE(t - prev, m.fast ? 1u : m.interval) << "ran early";
            releases += (t - prev) / m.interval;
            prev = t;
        }
        releases += (ticks - prev) / m.interval;
        EXPECT_EQ(releases, r.runs + r.slips + r.pending) << i;
        if (m.fast) {
            EXPECT_EQ(r.runs, ticks);
        }
    }
}

TEST_F(SchedSim, DifferentialAgainstReferenceModel)
{
    const uint32_t rates[] = {400u, 50u, 1000u, 2000u, 400u, 333u};
    for (uint32_t k = 0; k < 6u; ++k) {
        mt_posix_sim_enable(mt_test::kSimStartUs);
        differential(rates[k], 100u + k, 20000u);
        if (HasFatalFailure()) {
            return;
        }
    }
}

// ---- the POSIX metronome in simulated time ----------------------------------------------------

TEST_F(SchedSim, MetronomeKeepsAbsoluteDeadlines)
{
    mt_posix_metronome_t m;
    mt_posix_metronome_init(&m, 2500u);
    const uint64_t t1 = mt_posix_metronome_wait(&m);
    EXPECT_EQ(t1, mt_test::kSimStartUs + 2500u);
    EXPECT_EQ(mt_port_now_us(), t1);
    mt_posix_sim_advance(1000u);
    EXPECT_EQ(mt_posix_metronome_wait(&m), t1 + 2500u); // no drift from the work done
    mt_posix_sim_advance(2600u);                        // a late loop
    EXPECT_EQ(mt_posix_metronome_wait(&m), t1 + 7500u); // skips to the next boundary
    mt_posix_sim_advance(9000u);                        // several periods late
    EXPECT_EQ(mt_posix_metronome_wait(&m), t1 + 17500u);
    EXPECT_EQ(m.samples, 4u);
}

// A loop that ends exactly on the next sample boundary must get that sample
// (it is due now), not lose a whole period.
TEST_F(SchedSim, MetronomeLoopEndingOnTheBoundaryGetsThatSample)
{
    mt_posix_metronome_t m;
    mt_posix_metronome_init(&m, 2500u);
    const uint64_t t1 = mt_posix_metronome_wait(&m);
    mt_posix_sim_advance(2500u);
    EXPECT_EQ(mt_posix_metronome_wait(&m), t1 + 2500u);
}

} // namespace
