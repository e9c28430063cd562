// SPDX-License-Identifier: Apache-2.0
/**
 * @file mt_test_util.h
 * @brief Shared helpers of the googletest suite: simulated-time fixture,
 *        bounded polling, sanitizer detection, a small deterministic RNG.
 *
 * Polling helpers never assert on elapsed time: they wait for a condition and
 * fail only when a generous bound (seconds) passes, which on a loaded 2-core
 * machine means the condition never became true.
 */
#ifndef MT_TEST_UTIL_H
#define MT_TEST_UTIL_H

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>

extern "C" {
#include "mt/mt.h"
#include "mt_posix.h"
}

namespace mt_test
{

#if defined(__SANITIZE_THREAD__)
constexpr bool kTsan = true;
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
constexpr bool kTsan = true;
#else
constexpr bool kTsan = false;
#endif
#else
constexpr bool kTsan = false;
#endif

/** Start of simulated time in every simulated test (non-zero on purpose: the
 *  scheduler treats sample time 0 as "no sample yet"). */
constexpr uint64_t kSimStartUs = 1000000u;

/** Fixture: simulated time for the duration of one test. */
class SimTime : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        mt_posix_sim_enable(kSimStartUs);
    }
    void TearDown() override
    {
        mt_posix_sim_disable();
    }
};

/** Fixture: real time (undoes a simulated test that failed half-way). */
class RealTime : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        mt_posix_sim_disable();
    }
};

/** Poll pred until it holds or limit passes; true when it held. */
inline bool wait_until(const std::function<bool()> &pred,
                       std::chrono::milliseconds limit = std::chrono::milliseconds(20000))
{
    const auto end = std::chrono::steady_clock::now() + limit;
    while (!pred()) {
        if (std::chrono::steady_clock::now() > end) {
            return false;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    return true;
}

/** True when a thread is parked on s (read under the kernel lock). */
inline bool sem_has_waiter(mt_sem_t *s)
{
    mt_port_lock();
    const bool parked = s->waiter != nullptr;
    mt_port_unlock();
    return parked;
}

/** Snapshot of the semaphore fields (read under the kernel lock). */
inline mt_sem_t sem_snapshot(mt_sem_t *s)
{
    mt_port_lock();
    const mt_sem_t copy = *s;
    mt_port_unlock();
    return copy;
}

/** xorshift64*: small, deterministic, seedable. */
class Rng
{
  public:
    explicit Rng(uint64_t seed) : x_(seed != 0u ? seed : 0x9E3779B97F4A7C15ull)
    {
    }
    uint64_t next()
    {
        x_ ^= x_ >> 12;
        x_ ^= x_ << 25;
        x_ ^= x_ >> 27;
        return x_ * 2685821657736338717ull;
    }
    /** Uniform in [0, n) (n >= 1). */
    uint32_t below(uint32_t n)
    {
        return static_cast<uint32_t>(next() % n);
    }
    /** Uniform in [lo, hi]. */
    uint32_t range(uint32_t lo, uint32_t hi)
    {
        return lo + below(hi - lo + 1u);
    }

  private:
    uint64_t x_;
};

} // namespace mt_test

#endif // MT_TEST_UTIL_H
