// SPDX-License-Identifier: Apache-2.0
// SPSC word ring (mt/wordring.h): every status, the full and empty edges at the compile-time
// capacity, the wrap of the slot indices, the saturating refusal counter, a randomized
// differential test against std::deque, and a two-thread run (the producer and the consumer
// on their own threads, every word checked in order).
#include <deque>
#include <thread>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::Rng;

constexpr uint32_t kCap = MT_CFG_WRING_CAP;

TEST(WordRing, InitIsEmpty)
{
    mt_wring_t r;
    r.tail = 7u;
    r.head = 3u;
    r.rejected = 9u;
    mt_wring_init(&r);
    EXPECT_EQ(mt_wring_available(&r), 0u);
    EXPECT_EQ(r.rejected, 0u);
    uint32_t out = 0xDEADBEEFu;
    EXPECT_EQ(mt_wring_pop(&r, &out), MT_E_EMPTY);
    EXPECT_EQ(out, 0xDEADBEEFu); // untouched
}

TEST(WordRing, FillsToCapacityThenRefusesAndCounts)
{
    mt_wring_t r;
    mt_wring_init(&r);
    for (uint32_t i = 0; i < kCap; i++) {
        ASSERT_EQ(mt_wring_push(&r, i * 3u), MT_OK) << i;
    }
    EXPECT_EQ(mt_wring_available(&r), kCap);
    EXPECT_EQ(mt_wring_push(&r, 12345u), MT_E_FULL);
    EXPECT_EQ(mt_wring_push(&r, 12346u), MT_E_FULL);
    EXPECT_EQ(r.rejected, 2u);
    EXPECT_EQ(mt_wring_available(&r), kCap); // nothing overwritten
    for (uint32_t i = 0; i < kCap; i++) {
        uint32_t v = 0;
        ASSERT_EQ(mt_wring_pop(&r, &v), MT_OK);
        EXPECT_EQ(v, i * 3u);
    }
    uint32_t v = 77u;
    EXPECT_EQ(mt_wring_pop(&r, &v), MT_E_EMPTY);
    EXPECT_EQ(v, 77u);
    // room again after the pops
    EXPECT_EQ(mt_wring_push(&r, 1u), MT_OK);
    EXPECT_EQ(r.rejected, 2u);
}

TEST(WordRing, RejectedSaturates)
{
    mt_wring_t r;
    mt_wring_init(&r);
    for (uint32_t i = 0; i < kCap; i++) {
        ASSERT_EQ(mt_wring_push(&r, i), MT_OK);
    }
    r.rejected = 0xFFFFFFFEu;
    EXPECT_EQ(mt_wring_push(&r, 0u), MT_E_FULL);
    EXPECT_EQ(r.rejected, 0xFFFFFFFFu);
    EXPECT_EQ(mt_wring_push(&r, 0u), MT_E_FULL);
    EXPECT_EQ(r.rejected, 0xFFFFFFFFu);
}

TEST(WordRing, IndicesWrapAtTheLastSlot)
{
    mt_wring_t r;
    mt_wring_init(&r);
    // walk both indices across the end of the slots several times, one word in flight
    for (uint32_t i = 0; i < 3u * MT_WRING_SLOTS + 5u; i++) {
        ASSERT_EQ(mt_wring_push(&r, i), MT_OK);
        ASSERT_LT(r.tail, MT_WRING_SLOTS);
        uint32_t v = 0;
        ASSERT_EQ(mt_wring_pop(&r, &v), MT_OK);
        ASSERT_EQ(v, i);
        ASSERT_EQ(r.head, r.tail);
    }
    // full with the indices wrapped: the free slot sits just before head
    for (uint32_t i = 0; i < kCap; i++) {
        ASSERT_EQ(mt_wring_push(&r, i), MT_OK);
    }
    EXPECT_EQ(mt_wring_push(&r, 0u), MT_E_FULL);
    EXPECT_EQ((r.tail + 1u) % MT_WRING_SLOTS, r.head);
}

TEST(WordRing, RandomizedAgainstDeque)
{
    Rng rng(0x5157u);
    mt_wring_t r;
    mt_wring_init(&r);
    std::deque<uint32_t> model;
    uint32_t rejected = 0;
    uint32_t empties = 0;
    for (int step = 0; step < 200000; step++) {
        uint32_t op = (uint32_t)(rng.next() % 3u);
        if (op != 0u) { // push twice as often as pop, so the full edge is reached
            uint32_t v = (uint32_t)rng.next();
            mt_status_t st = mt_wring_push(&r, v);
            if (model.size() < kCap) {
                ASSERT_EQ(st, MT_OK);
                model.push_back(v);
            } else {
                ASSERT_EQ(st, MT_E_FULL);
                rejected++;
            }
        } else {
            // phases of 5000 steps: short pop bursts fill the ring, long ones drain it
            uint32_t burst = ((step / 5000) % 2 == 0) ? 3u : 64u;
            uint32_t n = (uint32_t)(rng.next() % (burst + 1u));
            for (uint32_t k = 0; k < n; k++) {
                uint32_t v = 0;
                mt_status_t st = mt_wring_pop(&r, &v);
                if (model.empty()) {
                    ASSERT_EQ(st, MT_E_EMPTY);
                    empties++;
                } else {
                    ASSERT_EQ(st, MT_OK);
                    ASSERT_EQ(v, model.front());
                    model.pop_front();
                }
            }
        }
        ASSERT_EQ(mt_wring_available(&r), model.size());
    }
    EXPECT_EQ(r.rejected, rejected);
    EXPECT_GT(rejected, 0u); // the full edge was reached
    EXPECT_GT(empties, 0u);  // and the empty one
}

TEST(WordRing, TwoThreadsEveryWordInOrder)
{
    static mt_wring_t r;
    mt_wring_init(&r);
    constexpr uint32_t kItems = 2000000u;
    uint32_t bad = 0;
    std::thread consumer([&] {
        uint32_t want = 0;
        while (want < kItems) {
            uint32_t v = 0;
            if (mt_wring_pop(&r, &v) == MT_OK) {
                bad += (v != want);
                want++;
            }
        }
    });
    for (uint32_t i = 0; i < kItems; i++) {
        while (mt_wring_push(&r, i) != MT_OK) {
        }
    }
    consumer.join();
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(mt_wring_available(&r), 0u);
}

} // namespace
