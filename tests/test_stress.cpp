// SPDX-License-Identifier: Apache-2.0
// Concurrency stress on real threads (meaningful under ThreadSanitizer): SPSC
// rings with one producer and one consumer thread, semaphore ping-pong and an
// "ISR" thread signalling a waiter that uses timeouts. Assertions are about
// order and counts only; a generous deadline turns a hang into a failure.
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::RealTime;
using mt_test::Rng;

// Turns a lost item or wake-up into a test failure instead of a hang.
class Deadline
{
  public:
    Deadline() : end_(std::chrono::steady_clock::now() + std::chrono::seconds(60))
    {
    }
    bool passed() const
    {
        return std::chrono::steady_clock::now() > end_;
    }

  private:
    std::chrono::steady_clock::time_point end_;
};

uint8_t stream_byte(uint64_t k)
{
    return static_cast<uint8_t>((k * 2654435761u) >> 13);
}

void relax(uint32_t &spins)
{
    // spinning is cheap natively; under ThreadSanitizer every probe is costly
    if (++spins > (mt_test::kTsan ? 1u : 64u)) {
        std::this_thread::yield();
        spins = 0u;
    }
}

using Stress = RealTime;

constexpr uint64_t kBytes = 1000000u;

TEST_F(Stress, ByteRingWriteReadPeek)
{
    std::vector<uint8_t> mem(251u); // not a power of two: the wrap moves around
    mt_bring_t r;
    ASSERT_EQ(mt_bring_init(&r, mem.data(), 251u), MT_OK);
    std::atomic<bool> give_up{false};
    uint64_t produced = 0u;

    std::thread producer([&] {
        Rng rng(1u);
        Deadline dl;
        uint8_t chunk[300];
        uint32_t spins = 0u;
        while (produced < kBytes && !give_up.load(std::memory_order_relaxed)) {
            const uint32_t len =
                static_cast<uint32_t>(std::min<uint64_t>(rng.range(1u, 300u), kBytes - produced));
            for (uint32_t k = 0; k < len; ++k) {
                chunk[k] = stream_byte(produced + k);
            }
            const uint32_t n = mt_bring_write(&r, chunk, len); // partial writes allowed
            produced += n;
            if (n == 0u) {
                relax(spins);
                if (dl.passed()) {
                    give_up = true;
                }
            }
        }
    });

    Rng rng(2u);
    Deadline dl;
    uint64_t consumed = 0u;
    uint64_t mismatches = 0u;
    uint8_t buf[300];
    uint32_t spins = 0u;
    while (consumed < kBytes && !give_up.load(std::memory_order_relaxed)) {
        const uint32_t len = rng.range(1u, 300u);
        uint32_t n;
        if (rng.below(3u) == 0u) { // peek, then drop what was looked at
            n = mt_bring_peek(&r, buf, len);
            if (n > 0u && mt_bring_advance(&r, n) != MT_OK) {
                ++mismatches;
            }
        } else {
            n = mt_bring_read(&r, buf, len);
        }
        for (uint32_t k = 0; k < n; ++k) {
            mismatches += (buf[k] != stream_byte(consumed + k)) ? 1u : 0u;
        }
        consumed += n;
        if (n == 0u) {
            relax(spins);
            if (dl.passed()) {
                give_up = true;
            }
        }
    }
    producer.join();
    EXPECT_FALSE(give_up.load()) << "stalled: produced " << produced << " consumed " << consumed;
    EXPECT_EQ(produced, kBytes);
    EXPECT_EQ(consumed, kBytes);
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(mt_bring_available(&r), 0u);
}

TEST_F(Stress, ByteRingReserveCommitPeekVec)
{
    std::vector<uint8_t> mem(113u);
    mt_bring_t r;
    ASSERT_EQ(mt_bring_init(&r, mem.data(), 113u), MT_OK);
    std::atomic<bool> give_up{false};
    uint64_t produced = 0u;
    uint64_t producer_errors = 0u;

    std::thread producer([&] {
        Rng rng(3u);
        Deadline dl;
        uint32_t spins = 0u;
        while (produced < kBytes && !give_up.load(std::memory_order_relaxed)) {
            mt_iovec_t v[2];
            const uint32_t want =
                static_cast<uint32_t>(std::min<uint64_t>(rng.range(1u, 128u), kBytes - produced));
            const uint32_t segs = mt_bring_reserve(&r, v, want);
            const uint32_t got = v[0].len + v[1].len;
            producer_errors += (segs > 2u || got > want) ? 1u : 0u;
            if (got == 0u) {
                producer_errors += (mt_bring_commit(&r, 0u) != MT_OK) ? 1u : 0u;
                relax(spins);
                if (dl.passed()) {
                    give_up = true;
                }
                continue;
            }
            const uint32_t commit = rng.range(1u, got); // sometimes less than reserved
            uint32_t k = 0u;
            for (uint32_t s = 0; s < 2u; ++s) {
                for (uint32_t j = 0; j < v[s].len; ++j, ++k) {
                    v[s].base[j] = stream_byte(produced + k);
                }
            }
            producer_errors += (mt_bring_commit(&r, got + 1u) != MT_E_RANGE) ? 1u : 0u;
            producer_errors += (mt_bring_commit(&r, commit) != MT_OK) ? 1u : 0u;
            produced += commit;
        }
    });

    Rng rng(4u);
    Deadline dl;
    uint64_t consumed = 0u;
    uint64_t mismatches = 0u;
    uint32_t spins = 0u;
    while (consumed < kBytes && !give_up.load(std::memory_order_relaxed)) {
        mt_iovec_t v[2];
        const uint32_t segs = mt_bring_peek_vec(&r, v);
        const uint32_t avail = v[0].len + v[1].len;
        if (segs == 0u) {
            relax(spins);
            if (dl.passed()) {
                give_up = true;
            }
            continue;
        }
        const uint32_t take = rng.range(1u, avail);
        uint32_t k = 0u;
        for (uint32_t s = 0; s < 2u && k < take; ++s) {
            for (uint32_t j = 0; j < v[s].len && k < take; ++j, ++k) {
                mismatches += (v[s].base[j] != stream_byte(consumed + k)) ? 1u : 0u;
            }
        }
        // (advance beyond what peek_vec showed is no error here: the producer
        // may have published more meanwhile; MT_E_RANGE is covered in test_ring)
        mismatches += (mt_bring_advance(&r, take) != MT_OK) ? 1u : 0u;
        consumed += take;
    }
    producer.join();
    EXPECT_FALSE(give_up.load()) << "stalled: produced " << produced << " consumed " << consumed;
    EXPECT_EQ(produced, kBytes);
    EXPECT_EQ(consumed, kBytes);
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(producer_errors, 0u);
}

struct Item {
    uint64_t seq;
    uint64_t inv; // ~seq: a torn copy shows up as a mismatch
};

constexpr uint64_t kObjects = 1000000u;

TEST_F(Stress, ObjRingPushPop)
{
    // room for a burst: on a loaded machine a full or empty ring costs a
    // scheduler round-trip, so a tiny ring would measure the load, not the ring
    const uint32_t cap = 255u;
    std::vector<uint8_t> mem(MT_ORING_STORAGE_BYTES(sizeof(Item), cap));
    mt_oring_t r;
    ASSERT_EQ(mt_oring_init(&r, mem.data(), sizeof(Item), cap), MT_OK);
    std::atomic<bool> give_up{false};
    uint64_t sent = 0u;
    uint64_t full = 0u;

    std::thread producer([&] {
        Deadline dl;
        uint32_t spins = 0u;
        while (sent < kObjects && !give_up.load(std::memory_order_relaxed)) {
            const Item it{sent, ~sent};
            if (mt_oring_push(&r, &it) == MT_OK) {
                ++sent;
            } else {
                ++full;
                relax(spins);
                if (dl.passed()) {
                    give_up = true;
                }
            }
        }
    });

    Rng rng(5u);
    Deadline dl;
    uint64_t next = 0u;
    uint64_t bad = 0u;
    uint32_t spins = 0u;
    while (next < kObjects && !give_up.load(std::memory_order_relaxed)) {
        Item it{};
        if (rng.below(8u) == 0u) { // peek must show what the next pop returns
            Item pk{};
            if (mt_oring_peek(&r, &pk) == MT_OK) {
                bad += (mt_oring_pop(&r, &it) != MT_OK || it.seq != pk.seq) ? 1u : 0u;
                bad += (it.seq != next || it.inv != ~it.seq) ? 1u : 0u;
                ++next;
                continue;
            }
        }
        bad += (mt_oring_available(&r) > cap) ? 1u : 0u;
        if (mt_oring_pop(&r, &it) == MT_OK) {
            bad += (it.seq != next || it.inv != ~it.seq) ? 1u : 0u;
            ++next;
        } else {
            relax(spins);
            if (dl.passed()) {
                give_up = true;
            }
        }
    }
    producer.join();
    EXPECT_FALSE(give_up.load()) << "stalled: sent " << sent << " received " << next;
    EXPECT_EQ(sent, kObjects);
    EXPECT_EQ(next, kObjects);
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(r.rejected, full);
    EXPECT_EQ(r.lost, 0u);
}

TEST_F(Stress, ObjRingDropOldestAccountsForEveryObject)
{
    const uint32_t cap = 5u;
    const uint64_t n = kObjects;
    std::vector<uint8_t> mem(MT_ORING_STORAGE_BYTES(sizeof(Item), cap));
    mt_oring_t r;
    ASSERT_EQ(mt_oring_init(&r, mem.data(), sizeof(Item), cap), MT_OK);
    std::atomic<bool> done{false};
    uint64_t ok = 0u, dropped = 0u, full = 0u, other = 0u;

    std::thread producer([&] {
        Rng rng(6u);
        for (uint64_t seq = 0u; seq < n; ++seq) {
            const Item it{seq, ~seq};
            switch (mt_oring_push_drop_oldest(&r, &it)) {
            case MT_OK: ++ok; break;
            case MT_W_DROPPED_OLDEST: ++dropped; break;
            case MT_E_FULL: ++full; break;
            default: ++other; break;
            }
            if (rng.below(64u) == 0u) {
                std::this_thread::yield(); // let the consumer catch up now and then
            }
        }
        done.store(true, std::memory_order_release);
    });

    Rng rng(7u);
    Deadline dl;
    uint64_t received = 0u;
    int64_t last = -1;
    uint64_t bad = 0u;
    uint32_t spins = 0u;
    for (;;) {
        const bool finished = done.load(std::memory_order_acquire);
        Item it{};
        if (rng.below(16u) == 0u && mt_oring_peek(&r, &it) == MT_OK) {
            bad += (it.inv != ~it.seq || static_cast<int64_t>(it.seq) <= last) ? 1u : 0u;
        }
        if (mt_oring_pop(&r, &it) == MT_OK) {
            // strictly increasing sequence numbers, intact bodies
            bad += (it.inv != ~it.seq || static_cast<int64_t>(it.seq) <= last) ? 1u : 0u;
            last = static_cast<int64_t>(it.seq);
            ++received;
            if (rng.below(512u) == 0u) {
                for (int k = 0; k < 16; ++k) {
                    std::this_thread::yield(); // fall behind now and then: drops happen
                }
            }
            continue;
        }
        if (finished) {
            break; // empty after `done`: everything published has been taken
        }
        relax(spins);
        if (dl.passed()) {
            ++bad;
            break;
        }
    }
    producer.join();
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(other, 0u);
    EXPECT_EQ(ok + dropped + full, n);
    EXPECT_EQ(r.rejected, full);                  // every refusal counted by the producer
    EXPECT_LE(r.lost, dropped);                   // a drop only after a drop-oldest push said so
    EXPECT_EQ(received + r.lost + r.rejected, n); // no object lost uncounted
    EXPECT_EQ(mt_oring_available(&r), 0u);
}

// ---- semaphores --------------------------------------------------------------------

TEST_F(Stress, SemPingPongNoLostWakeUp)
{
    const uint32_t rounds = 100000u;
    const uint64_t limit_us = 30000000u; // a lost wake-up fails here instead of hanging
    mt_sem_t ping;
    mt_sem_t pong;
    mt_sem_init(&ping, false);
    mt_sem_init(&pong, false);
    uint32_t b_ok = 0u;
    uint32_t b_fail = 0u;

    std::thread b([&] {
        for (uint32_t k = 0; k < rounds; ++k) {
            if (mt_sem_wait(&ping, limit_us) != MT_OK) {
                ++b_fail;
                return;
            }
            ++b_ok;
            mt_sem_signal(&pong);
        }
    });
    uint32_t a_ok = 0u;
    for (uint32_t k = 0; k < rounds; ++k) {
        mt_sem_signal(&ping);
        if (mt_sem_wait(&pong, limit_us) != MT_OK) {
            break;
        }
        ++a_ok;
    }
    if (a_ok != rounds) {
        mt_sem_signal(&ping); // release b if it waits, then report
    }
    b.join();
    EXPECT_EQ(a_ok, rounds);
    EXPECT_EQ(b_ok, rounds);
    EXPECT_EQ(b_fail, 0u);
    const mt_sem_t sp = mt_test::sem_snapshot(&ping);
    const mt_sem_t so = mt_test::sem_snapshot(&pong);
    // strict alternation: no signal ever found a token already set
    EXPECT_EQ(sp.merged, 0u);
    EXPECT_EQ(so.merged, 0u);
    EXPECT_EQ(sp.token, 0u);
    EXPECT_EQ(so.token, 0u);
    EXPECT_EQ(sp.waiter, nullptr);
    EXPECT_EQ(so.waiter, nullptr);
}

// Every signal is consumed by a wait, merged into a pending token (counted), or
// is the token left at the end: signals == ok waits + merged + final token.
void isr_vs_timed_waiter(void (*signal)(mt_sem_t *), uint64_t seed)
{
    const uint32_t signals = mt_test::kTsan ? 5000u : 10000u;
    mt_sem_t s;
    mt_sem_init(&s, false);
    std::atomic<bool> stop{false};
    uint64_t ok = 0u;
    uint64_t timeouts = 0u;
    uint64_t other = 0u;

    std::thread waiter([&] {
        Rng rng(seed);
        while (!stop.load(std::memory_order_acquire)) {
            const uint64_t t = (rng.below(16u) == 0u) ? 0u : rng.range(1u, 300u);
            switch (mt_sem_wait(&s, t)) {
            case MT_OK: ++ok; break;
            case MT_E_TIMEOUT: ++timeouts; break;
            default: ++other; break;
            }
        }
    });
    std::thread isr([&] {
        Rng rng(seed + 1u);
        for (uint32_t k = 0; k < signals; ++k) {
            signal(&s);
            const uint32_t gap = rng.below(64u);
            if (gap < 8u) {
                std::this_thread::yield();
            } else if (gap == 8u) {
                std::this_thread::sleep_for(std::chrono::microseconds(50));
            }
        }
    });
    isr.join();
    stop.store(true, std::memory_order_release);
    waiter.join();
    const mt_sem_t snap = mt_test::sem_snapshot(&s);
    EXPECT_EQ(other, 0u); // one waiter: never MT_E_BUSY
    EXPECT_EQ(snap.waiter, nullptr);
    EXPECT_EQ(static_cast<uint64_t>(signals), ok + snap.merged + snap.token)
        << "ok " << ok << " merged " << snap.merged << " token " << snap.token << " timeouts "
        << timeouts;
    EXPECT_GT(ok, 0u);
}

TEST_F(Stress, SemIsrSignalsVersusTimedWaiter)
{
    isr_vs_timed_waiter(mt_sem_signal_isr, 21u);
}

TEST_F(Stress, SemTaskSignalsVersusTimedWaiter)
{
    isr_vs_timed_waiter(mt_sem_signal, 31u);
}

} // namespace
