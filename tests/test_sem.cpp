// SPDX-License-Identifier: Apache-2.0
// Binary semaphore (mt/sem.h): every status, the one-token rule, timeouts in
// simulated time, and blocking/waking on real threads (no timing assertions:
// a blocked thread is detected through the semaphore's own waiter field, read
// under the kernel lock).
#include <atomic>
#include <thread>

#include "mt_test_util.h"

namespace
{

using mt_test::RealTime;
using mt_test::sem_has_waiter;
using mt_test::sem_snapshot;
using mt_test::SimTime;
using mt_test::wait_until;

constexpr uint64_t kThreeHoursUs = 3ull * 3600ull * 1000000ull;

// mt_sem_valid is the C twin of MtSemInv (equivalence proved by WP and CBMC).
TEST(SemValid, TokenAndWaiterRule)
{
    mt_sem_t s;
    int parked = 0;
    mt_sem_init(&s, true);
    EXPECT_TRUE(mt_sem_valid(&s));
    s.waiter = static_cast<mt_port_tref_t>(static_cast<void *>(&parked));
    EXPECT_FALSE(mt_sem_valid(&s)) << "a token and a parked waiter";
    s.token = 0u;
    EXPECT_TRUE(mt_sem_valid(&s));
    s.token = 2u;
    s.waiter = nullptr;
    EXPECT_FALSE(mt_sem_valid(&s)) << "token above 1";
}

TEST(Sem, InitAvailableAndTaken)
{
    mt_sem_t s;
    mt_sem_init(&s, true);
    EXPECT_EQ(s.token, 1u);
    EXPECT_EQ(s.waiter, nullptr);
    EXPECT_EQ(s.merged, 0u);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_OK);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_E_TIMEOUT);

    mt_sem_init(&s, false);
    EXPECT_EQ(s.token, 0u);
    EXPECT_EQ(s.waiter, nullptr);
    EXPECT_EQ(s.merged, 0u);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_E_TIMEOUT);
}

using SemSim = SimTime;

TEST_F(SemSim, PollNeverBlocks)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    const uint64_t t0 = mt_port_now_us();
    for (int k = 0; k < 10; ++k) {
        EXPECT_EQ(mt_sem_wait(&s, 0u), MT_E_TIMEOUT);
    }
    // a poll never reaches the port's suspend (which would move simulated time)
    EXPECT_EQ(mt_port_now_us(), t0);
    EXPECT_EQ(s.token, 0u);
    EXPECT_EQ(s.waiter, nullptr);
}

TEST_F(SemSim, SignalThenWait)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    mt_sem_signal(&s);
    EXPECT_EQ(s.token, 1u);
    const uint64_t t0 = mt_port_now_us();
    EXPECT_EQ(mt_sem_wait(&s, 1000u), MT_OK); // token present: no wait
    EXPECT_EQ(mt_port_now_us(), t0);
    EXPECT_EQ(s.token, 0u);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_E_TIMEOUT);
}

TEST_F(SemSim, DoubleSignalLeavesOneTokenAndCountsTheMerge)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    mt_sem_signal(&s);
    mt_sem_signal(&s);
    EXPECT_EQ(s.token, 1u);
    EXPECT_EQ(s.merged, 1u);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_OK);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_E_TIMEOUT); // one token, not two

    mt_sem_init(&s, true); // an initial token merges too
    mt_sem_signal_isr(&s);
    EXPECT_EQ(s.merged, 1u);
    EXPECT_EQ(s.token, 1u);
}

TEST_F(SemSim, MergedSaturates)
{
    mt_sem_t s;
    mt_sem_init(&s, true);
    s.merged = 0xFFFFFFFEu;
    mt_sem_signal(&s);
    EXPECT_EQ(s.merged, 0xFFFFFFFFu);
    mt_sem_signal(&s);
    EXPECT_EQ(s.merged, 0xFFFFFFFFu);
    EXPECT_EQ(s.token, 1u);
}

TEST_F(SemSim, TimeoutAdvancesSimulatedTimeByTheTimeout)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    const uint64_t t0 = mt_port_now_us();
    EXPECT_EQ(mt_sem_wait(&s, 2500u), MT_E_TIMEOUT);
    EXPECT_EQ(mt_port_now_us(), t0 + 2500u);
    EXPECT_EQ(s.waiter, nullptr); // the port cleared the reference
    EXPECT_EQ(s.token, 0u);
}

TEST_F(SemSim, ThreeHourTimeout)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    const uint64_t t0 = mt_port_now_us();
    EXPECT_EQ(mt_sem_wait(&s, kThreeHoursUs), MT_E_TIMEOUT);
    EXPECT_EQ(mt_port_now_us(), t0 + kThreeHoursUs);
    // and a wait longer than 2^32 us (71.6 min, ArduPilot M-2) is not truncated
    EXPECT_EQ(mt_sem_wait(&s, 0x100000001ull), MT_E_TIMEOUT);
    EXPECT_EQ(mt_port_now_us(), t0 + kThreeHoursUs + 0x100000001ull);
}

TEST_F(SemSim, TimedOutWaitConsumesNoToken)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    EXPECT_EQ(mt_sem_wait(&s, 1000u), MT_E_TIMEOUT);
    mt_sem_signal(&s);
    EXPECT_EQ(s.token, 1u); // the signal after the timeout left the token
    EXPECT_EQ(s.merged, 0u);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_OK);
}

TEST_F(SemSim, LockHeldVariants)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    mt_port_lock();
    EXPECT_EQ(mt_sem_wait_s(&s, 0u), MT_E_TIMEOUT);
    mt_sem_signal_i(&s);
    EXPECT_EQ(s.token, 1u);
    mt_sem_signal_i(&s);
    EXPECT_EQ(s.merged, 1u);
    EXPECT_EQ(mt_sem_wait_s(&s, 0u), MT_OK);
    EXPECT_EQ(mt_sem_wait_s(&s, 10u), MT_E_TIMEOUT);
    mt_port_unlock();
    EXPECT_EQ(s.token, 0u);
}

TEST(SemSimDeath, WaitForeverInSimulatedTimeHalts)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(
        {
            mt_posix_sim_enable(mt_test::kSimStartUs);
            mt_sem_t s;
            mt_sem_init(&s, false);
            (void)mt_sem_wait(&s, MT_WAIT_FOREVER);
        },
        "endless wait in simulated time");
}

// ---- real threads -------------------------------------------------------------

using SemReal = RealTime;

TEST_F(SemReal, RealTimeoutThenSignalLeavesToken)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    EXPECT_EQ(mt_sem_wait(&s, 2000u), MT_E_TIMEOUT);
    const mt_sem_t snap = sem_snapshot(&s);
    EXPECT_EQ(snap.waiter, nullptr);
    EXPECT_EQ(snap.token, 0u);
    mt_sem_signal(&s);
    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_OK);
}

TEST_F(SemReal, SecondConcurrentWaiterIsBusy)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    std::atomic<int> first{-1};
    std::thread waiter([&] { first = mt_sem_wait(&s, MT_WAIT_FOREVER); });
    const bool parked = wait_until([&] { return sem_has_waiter(&s); });
    EXPECT_TRUE(parked);
    if (!parked) { // fail without hanging
        mt_sem_signal(&s);
        waiter.join();
        return;
    }

    EXPECT_EQ(mt_sem_wait(&s, 0u), MT_E_BUSY);      // this thread, polling
    EXPECT_EQ(mt_sem_wait(&s, 100000u), MT_E_BUSY); // this thread, with a timeout
    std::atomic<int> second{-1};
    std::thread other([&] { second = mt_sem_wait(&s, MT_WAIT_FOREVER); });
    other.join();
    EXPECT_EQ(second.load(), MT_E_BUSY); // another thread
    EXPECT_EQ(first.load(), -1);         // the first waiter is still parked

    mt_sem_signal(&s);
    waiter.join();
    EXPECT_EQ(first.load(), MT_OK);
    const mt_sem_t snap = sem_snapshot(&s);
    EXPECT_EQ(snap.token, 0u); // handed over directly, not left in the semaphore
    EXPECT_EQ(snap.waiter, nullptr);
    EXPECT_EQ(snap.merged, 0u);
}

void wake_blocked_waiter(void (*signal)(mt_sem_t *), uint64_t timeout_us)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    std::thread signaller([&] {
        EXPECT_TRUE(wait_until([&] { return sem_has_waiter(&s); }));
        signal(&s); // signal even on failure: the test fails, it does not hang
    });
    EXPECT_EQ(mt_sem_wait(&s, timeout_us), MT_OK);
    signaller.join();
    const mt_sem_t snap = sem_snapshot(&s);
    EXPECT_EQ(snap.token, 0u);
    EXPECT_EQ(snap.waiter, nullptr);
    EXPECT_EQ(snap.merged, 0u);
}

TEST_F(SemReal, SignalFromAnotherThreadWakesForeverWaiter)
{
    wake_blocked_waiter(mt_sem_signal, MT_WAIT_FOREVER);
}

TEST_F(SemReal, SignalIsrFromAnotherThreadWakesForeverWaiter)
{
    wake_blocked_waiter(mt_sem_signal_isr, MT_WAIT_FOREVER);
}

// A real three-hour timeout is longer than the port's one-hour chunk: the wait
// must still be woken by a signal (and not time out early).
TEST_F(SemReal, SignalWakesThreeHourWaiter)
{
    wake_blocked_waiter(mt_sem_signal, kThreeHoursUs);
}

TEST_F(SemReal, SignalBeforeWaitIsNotLost)
{
    mt_sem_t s;
    mt_sem_init(&s, false);
    std::thread t([&] { mt_sem_signal_isr(&s); });
    t.join();
    EXPECT_EQ(mt_sem_wait(&s, MT_WAIT_FOREVER), MT_OK);
}

} // namespace
