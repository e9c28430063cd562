// SPDX-License-Identifier: Apache-2.0
// The port contract (kernel/port/mt_port.h) as the POSIX port implements it:
// time, the kernel lock, suspend/resume, thread creation statuses, halting,
// and the simulated-time switch (hal_posix/mt_posix.h).
#include <atomic>
#include <thread>

#include "mt_test_util.h"

namespace
{

using mt_test::RealTime;
using mt_test::SimTime;

using PortReal = RealTime;
using PortSim = SimTime;

TEST_F(PortReal, TimeIsMonotonic)
{
    EXPECT_FALSE(mt_posix_sim_active());
    uint64_t prev = mt_port_now_us();
    EXPECT_GT(prev, 0u);
    for (int k = 0; k < 10000; ++k) {
        const uint64_t now = mt_port_now_us();
        ASSERT_GE(now, prev);
        prev = now;
    }
}

TEST_F(PortSim, SimulatedTimeMovesOnlyWhenMoved)
{
    EXPECT_TRUE(mt_posix_sim_active());
    EXPECT_EQ(mt_port_now_us(), mt_test::kSimStartUs);
    EXPECT_EQ(mt_port_now_us(), mt_test::kSimStartUs);
    mt_posix_sim_advance(0u);
    EXPECT_EQ(mt_port_now_us(), mt_test::kSimStartUs);
    mt_posix_sim_advance(123u);
    EXPECT_EQ(mt_port_now_us(), mt_test::kSimStartUs + 123u);
    mt_posix_sim_advance(UINT64_MAX); // saturates instead of wrapping
    EXPECT_EQ(mt_port_now_us(), UINT64_MAX);
    mt_posix_sim_enable(5u); // restart at another time
    EXPECT_EQ(mt_port_now_us(), 5u);
    mt_posix_sim_disable();
    EXPECT_FALSE(mt_posix_sim_active());
    EXPECT_NE(mt_port_now_us(), 5u); // real clock again (microseconds since boot)
}

TEST_F(PortSim, SuspendTimesOutAndAdvancesSimulatedTime)
{
    mt_port_tref_t ref = nullptr;
    mt_port_lock();
    EXPECT_EQ(mt_port_suspend_s(&ref, 700u), MT_PORT_TIMEOUT);
    EXPECT_EQ(ref, nullptr);
    mt_port_unlock();
    EXPECT_EQ(mt_port_now_us(), mt_test::kSimStartUs + 700u);
}

TEST_F(PortReal, ResumeWithoutWaiterReturnsFalse)
{
    mt_port_tref_t ref = nullptr;
    mt_port_lock();
    EXPECT_FALSE(mt_port_resume_i(&ref));
    EXPECT_EQ(ref, nullptr);
    mt_port_unlock();
}

TEST_F(PortReal, SuspendResumeOnRealThreads)
{
    mt_port_tref_t ref = nullptr;
    std::atomic<int> result{-1};
    std::thread t([&] {
        mt_port_lock();
        result = mt_port_suspend_s(&ref, MT_WAIT_FOREVER);
        mt_port_unlock();
    });
    bool parked = false;
    EXPECT_TRUE(mt_test::wait_until([&] {
        mt_port_lock();
        parked = ref != nullptr;
        if (parked) {
            EXPECT_TRUE(mt_port_resume_i(&ref));
            EXPECT_EQ(ref, nullptr); // cleared by the resume
        }
        mt_port_unlock();
        return parked;
    }));
    t.join();
    EXPECT_EQ(result.load(), MT_PORT_RESUMED);
}

TEST_F(PortReal, RealSuspendTimesOutAndClearsReference)
{
    mt_port_tref_t ref = nullptr;
    mt_port_lock();
    EXPECT_EQ(mt_port_suspend_s(&ref, 1000u), MT_PORT_TIMEOUT);
    EXPECT_EQ(ref, nullptr);
    EXPECT_FALSE(mt_port_resume_i(&ref)); // a later resume finds nobody
    mt_port_unlock();
}

// The task lock and the ISR lock are one critical section: a plain counter
// incremented under either from two threads loses no increment (and ThreadSanitizer
// sees the accesses ordered).
TEST_F(PortReal, TaskAndIsrLockAreOneCriticalSection)
{
    const uint32_t n = mt_test::kTsan ? 20000u : 100000u;
    uint64_t counter = 0u; // deliberately not atomic
    std::thread isr([&] {
        for (uint32_t k = 0; k < n; ++k) {
            mt_port_lock_isr();
            counter = counter + 1u;
            mt_port_unlock_isr();
        }
    });
    for (uint32_t k = 0; k < n; ++k) {
        mt_port_lock();
        counter = counter + 1u;
        mt_port_unlock();
    }
    isr.join();
    EXPECT_EQ(counter, 2u * n);
}

std::atomic<uint32_t> g_thread_runs{0u};

void thread_body(void *arg)
{
    g_thread_runs.fetch_add(1u);
    static_cast<std::atomic<uint32_t> *>(arg)->fetch_add(1u);
}

TEST_F(PortReal, ThreadCreateStatuses)
{
    std::atomic<uint32_t> mine{0u};
    uint8_t stack[256];
    EXPECT_EQ(mt_port_thread_create("x", nullptr, &mine, stack, sizeof(stack), MT_PRIO_IO, 0),
              MT_E_INVALID);
    EXPECT_EQ(
        mt_port_thread_create("x", thread_body, &mine, stack, sizeof(stack), MT_PRIO_BASE_COUNT, 0),
        MT_E_INVALID);
    EXPECT_EQ(mt_port_thread_create("x", thread_body, &mine, stack, sizeof(stack),
                                    static_cast<mt_prio_base_t>(100), 0),
              MT_E_INVALID);

    // the port has a bounded thread table: creation ends in MT_E_FULL, not a crash
    uint32_t created = 0u;
    mt_status_t st = MT_OK;
    while (created < 1000u) {
        st = mt_port_thread_create("worker-with-a-long-name", thread_body, &mine, nullptr, 0u,
                                   static_cast<mt_prio_base_t>(created % MT_PRIO_BASE_COUNT),
                                   static_cast<int8_t>(static_cast<int>(created % 5u) - 2));
        if (st != MT_OK) {
            break;
        }
        ++created;
    }
    EXPECT_EQ(st, MT_E_FULL);
    EXPECT_GE(created, 1u);
    EXPECT_LT(created, 1000u);
    mt_posix_join_all();
    EXPECT_EQ(mine.load(), created); // every created thread ran once
    (void)mt_posix_rt_priorities();  // environment-dependent: callable, no assertion

    // joining frees the table
    EXPECT_EQ(mt_port_thread_create(nullptr, thread_body, &mine, nullptr, 0u, MT_PRIO_MAIN, 0),
              MT_OK);
    mt_posix_join_all();
    EXPECT_EQ(mine.load(), created + 1u);
}

TEST(PortDeath, HaltStopsWithItsReason)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(mt_port_halt("contract violated here"), "halt: contract violated here");
}

TEST(PortDeath, NestedLockHalts)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(
        {
            mt_port_lock();
            mt_port_lock();
        },
        "already held|double lock");
}

TEST(PortDeath, UnlockWithoutLockHalts)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(
        {
            mt_port_lock();
            mt_port_unlock();
            mt_port_unlock();
        },
        "not held|unlock of an unlocked");
}

// The same violation as the first kernel-lock call of the process.
TEST(PortDeath, UnlockWithoutLockHaltsInAFreshProcess)
{
    // The mutex is statically initialised as error-checking, so even the first
    // kernel-lock call of the process is checked.
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(mt_port_unlock(), "not held|unlock of an unlocked");
}

} // namespace
