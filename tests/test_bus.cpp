// SPDX-License-Identifier: Apache-2.0
// Topic bus (mt/bus.h): every status and edge (queue length 1 and N, missed and
// skipped accounting, generation wrap, interval subscriptions, notifier gates and
// bound, reliable topics, poll), plus a concurrency stress test with a task
// publisher, an "ISR" publisher thread and lock-free subscribers (run under
// ThreadSanitizer by `make test`).
#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::RealTime;
using mt_test::Rng;
using mt_test::sem_has_waiter;
using mt_test::SimTime;
using mt_test::wait_until;

struct Msg {
    uint32_t seq;
    uint32_t tag;
    uint8_t body[24];
};

Msg make_msg(uint32_t seq)
{
    Msg m{};
    m.seq = seq;
    m.tag = seq * 2654435761u;
    for (size_t k = 0; k < sizeof m.body; ++k) {
        m.body[k] = static_cast<uint8_t>(seq + k);
    }
    return m;
}

bool msg_whole(const Msg &m)
{
    if (m.tag != m.seq * 2654435761u) {
        return false;
    }
    for (size_t k = 0; k < sizeof m.body; ++k) {
        if (m.body[k] != static_cast<uint8_t>(m.seq + k)) {
            return false;
        }
    }
    return true;
}

// A topic of Msg with its own storage.
struct Topic {
    std::vector<uint8_t> mem;
    mt_topic_t t{};
    mt_status_t init(uint32_t qlen, uint32_t flags = 0u, uint32_t first_gen = 0u)
    {
        mem.assign(MT_BUS_STORAGE_BYTES(sizeof(Msg), qlen), 0u);
        mt_topic_desc_t d = MT_TOPIC_DESC("test", Msg, qlen, flags);
        d.first_gen = first_gen;
        return mt_topic_init(&t, &d, mem.data(), static_cast<uint32_t>(mem.size()));
    }
    mt_status_t pub(uint32_t seq)
    {
        const Msg m = make_msg(seq);
        return mt_topic_publish(&t, &m, sizeof m);
    }
};

uint32_t pending(const mt_sub_t &s)
{
    const uint32_t g = s.topic->gen;
    return g - s.gen; // test-side modular arithmetic (the kernel splits cases instead)
}

// ---------------------------------------------------------------------------------- init

TEST(BusInit, EveryStatus)
{
    uint8_t mem[64];
    mt_topic_t t;
    mt_topic_desc_t d = {"t", 4u, 4u, 0u, 0u};

    d.name = nullptr;
    EXPECT_EQ(mt_topic_init(&t, &d, mem, sizeof mem), MT_E_INVALID);
    EXPECT_EQ(t.size, 0u);
    d.name = "t";
    d.flags = 2u;
    EXPECT_EQ(mt_topic_init(&t, &d, mem, sizeof mem), MT_E_INVALID);
    d.flags = MT_TOPIC_RELIABLE | 2u;
    EXPECT_EQ(mt_topic_init(&t, &d, mem, sizeof mem), MT_E_INVALID);
    d.flags = 0u;
    d.msg_size = 0u;
    EXPECT_EQ(mt_topic_init(&t, &d, mem, sizeof mem), MT_E_BUS_MSG_SIZE);
    EXPECT_EQ(t.size, 0u);
    d.msg_size = MT_CFG_BUS_MAX_MSG + 1u;
    EXPECT_EQ(mt_topic_init(&t, &d, mem, sizeof mem), MT_E_BUS_MSG_SIZE);
    d.msg_size = 4u;
    d.queue_len = 0u;
    EXPECT_EQ(mt_topic_init(&t, &d, mem, sizeof mem), MT_E_BUS_QUEUE_LEN);
    EXPECT_EQ(t.size, 0u);
    d.queue_len = MT_CFG_BUS_MAX_QUEUE + 1u;
    EXPECT_EQ(mt_topic_init(&t, &d, mem, sizeof mem), MT_E_BUS_QUEUE_LEN);
    d.queue_len = 4u;
    EXPECT_EQ(mt_topic_init(&t, &d, nullptr, sizeof mem), MT_E_BUS_STORAGE);
    EXPECT_EQ(t.size, 0u);
    EXPECT_EQ(mt_topic_init(&t, &d, mem, MT_BUS_STORAGE_BYTES(4u, 4u) - 1u), MT_E_BUS_STORAGE);
    EXPECT_EQ(t.size, 0u);
    // checks run in the documented order: the first bad field decides
    d.msg_size = 0u;
    EXPECT_EQ(mt_topic_init(&t, &d, nullptr, 0u), MT_E_BUS_MSG_SIZE);
    d.msg_size = 4u;

    EXPECT_EQ(mt_topic_init(&t, &d, mem, MT_BUS_STORAGE_BYTES(4u, 4u)), MT_OK);
    EXPECT_EQ(t.size, 4u);
    EXPECT_EQ(t.qlen, 4u);
    EXPECT_EQ(t.reliable, 0u);
    EXPECT_EQ(t.published, 0u);
    EXPECT_EQ(t.gen, 0u);
    EXPECT_EQ(t.nnotify, 0u);
    EXPECT_EQ(t.publishes + t.rejected + t.notified, 0u);
    EXPECT_STREQ(t.name, "t");

    d.flags = MT_TOPIC_RELIABLE;
    d.msg_size = MT_CFG_BUS_MAX_MSG;
    d.queue_len = 1u;
    std::vector<uint8_t> big(MT_CFG_BUS_MAX_MSG);
    EXPECT_EQ(mt_topic_init(&t, &d, big.data(), MT_CFG_BUS_MAX_MSG), MT_OK);
    EXPECT_EQ(t.reliable, 1u);
    d.msg_size = 1u;
    d.queue_len = MT_CFG_BUS_MAX_QUEUE;
    EXPECT_EQ(mt_topic_init(&t, &d, big.data(), MT_CFG_BUS_MAX_QUEUE), MT_OK);
}

TEST(BusInit, DescMacroAndStorageMacro)
{
    const mt_topic_desc_t d = MT_TOPIC_DESC("m", Msg, 3u, MT_TOPIC_RELIABLE);
    EXPECT_EQ(d.msg_size, sizeof(Msg));
    EXPECT_EQ(d.queue_len, 3u);
    EXPECT_EQ(d.flags, MT_TOPIC_RELIABLE);
    EXPECT_EQ(d.first_gen, 0u);
    EXPECT_EQ(MT_BUS_STORAGE_BYTES(sizeof(Msg), 3u), 3u * sizeof(Msg));
}

// ------------------------------------------------------------------------ publish, copy

TEST(Bus, PublishSizeMismatchIsRefusedAndCounted)
{
    Topic tp;
    ASSERT_EQ(tp.init(2u), MT_OK);
    const Msg m = make_msg(1u);
    EXPECT_EQ(mt_topic_publish(&tp.t, &m, sizeof m - 1u), MT_E_BUS_MSG_SIZE);
    EXPECT_EQ(mt_topic_publish_isr(&tp.t, &m, sizeof m + 1u), MT_E_BUS_MSG_SIZE);
    EXPECT_EQ(tp.t.rejected, 2u);
    EXPECT_EQ(tp.t.publishes, 0u);
    EXPECT_EQ(tp.t.gen, 0u);
    EXPECT_EQ(tp.t.published, 0u);
    mt_port_lock();
    EXPECT_EQ(mt_topic_publish_i(&tp.t, &m, sizeof m), MT_OK);
    mt_port_unlock();
    EXPECT_EQ(tp.t.publishes, 1u);
    EXPECT_EQ(tp.t.gen, 1u);
}

TEST(Bus, CopySizeMismatchTouchesNothing)
{
    Topic tp;
    ASSERT_EQ(tp.init(2u), MT_OK);
    ASSERT_EQ(tp.pub(1u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    Msg out{};
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out - 1u, 0u), MT_E_BUS_MSG_SIZE);
    EXPECT_EQ(mt_sub_copy_latest(&s, &out, 3u, 0u), MT_E_BUS_MSG_SIZE);
    EXPECT_EQ(out.seq, 0u);
    EXPECT_EQ(pending(s), 1u);
}

TEST(Bus, QueueLengthOneKeepsTheNewest)
{
    Topic tp;
    ASSERT_EQ(tp.init(1u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    Msg out{};
    EXPECT_FALSE(mt_sub_updated(&s, 0u));
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_E_EMPTY);
    EXPECT_EQ(mt_sub_copy_latest(&s, &out, sizeof out, 0u), MT_E_EMPTY);

    ASSERT_EQ(tp.pub(7u), MT_OK);
    EXPECT_TRUE(mt_sub_updated(&s, 0u));
    EXPECT_TRUE(mt_sub_updated(&s, 0u)); // pure: asking twice changes nothing
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 7u);
    EXPECT_TRUE(msg_whole(out));
    EXPECT_FALSE(mt_sub_updated(&s, 0u));
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_E_EMPTY);

    for (uint32_t k = 8u; k <= 12u; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
    }
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_W_BUS_MISSED);
    EXPECT_EQ(out.seq, 12u);
    EXPECT_EQ(s.missed, 4u); // 8..11 were overwritten before the subscriber looked
    EXPECT_EQ(s.received, 2u);
    EXPECT_EQ(s.skipped, 0u);
    // copy_latest re-reads the newest message without consuming anything new
    EXPECT_EQ(mt_sub_copy_latest(&s, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 12u);
    EXPECT_EQ(s.received, 2u);
    EXPECT_EQ(s.missed + s.skipped, 4u);
}

TEST(Bus, QueueOfNDeliversInOrderThenJumpsToTheOldest)
{
    constexpr uint32_t kQ = 4u;
    Topic tp;
    ASSERT_EQ(tp.init(kQ), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    Msg out{};
    for (uint32_t k = 1u; k <= kQ; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
    }
    for (uint32_t k = 1u; k <= kQ; ++k) {
        ASSERT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
        EXPECT_EQ(out.seq, k);
    }
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_E_EMPTY);
    EXPECT_EQ(s.missed, 0u);

    // 11 more: messages 5..11 are gone, 12..15 retained
    for (uint32_t k = kQ + 1u; k <= kQ + 11u; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
    }
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_W_BUS_MISSED);
    EXPECT_EQ(out.seq, 12u);
    EXPECT_EQ(s.missed, 7u);
    for (uint32_t k = 13u; k <= 15u; ++k) {
        ASSERT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
        EXPECT_EQ(out.seq, k);
    }
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_E_EMPTY);
    EXPECT_EQ(s.received, 8u);
    EXPECT_EQ(s.missed, 7u);
    EXPECT_EQ(tp.t.publishes, 15u);
}

TEST(Bus, CopyLatestSkipsRetainedAndMissesOverwritten)
{
    constexpr uint32_t kQ = 3u;
    Topic tp;
    ASSERT_EQ(tp.init(kQ), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    Msg out{};
    ASSERT_EQ(tp.pub(1u), MT_OK);
    ASSERT_EQ(tp.pub(2u), MT_OK);
    EXPECT_EQ(mt_sub_copy_latest(&s, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 2u);
    EXPECT_EQ(s.skipped, 1u); // message 1 was still retained: skipped, not missed
    EXPECT_EQ(s.missed, 0u);
    for (uint32_t k = 3u; k <= 9u; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
    }
    // 7 pending, 3 retained (7, 8, 9): 3..6 missed, 7 and 8 skipped
    EXPECT_EQ(mt_sub_copy_latest(&s, &out, sizeof out, 0u), MT_W_BUS_MISSED);
    EXPECT_EQ(out.seq, 9u);
    EXPECT_EQ(s.missed, 4u);
    EXPECT_EQ(s.skipped, 3u);
    EXPECT_EQ(s.received, 2u);
    EXPECT_EQ(s.received + s.missed + s.skipped + pending(s), tp.t.publishes);
}

TEST(Bus, LateSubscriberSeesTheNewestAsPending)
{
    Topic tp;
    ASSERT_EQ(tp.init(4u), MT_OK);
    ASSERT_EQ(tp.pub(1u), MT_OK);
    ASSERT_EQ(tp.pub(2u), MT_OK);
    ASSERT_EQ(tp.pub(3u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    EXPECT_EQ(pending(s), 1u);
    Msg out{};
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 3u);
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_E_EMPTY);
}

// Random operations: every message published after init is received, missed,
// skipped or pending, exactly once (the accounting the contracts state per call).
TEST(Bus, AccountingIsExactUnderRandomOperations)
{
    for (uint32_t q : {1u, 2u, 5u}) {
        Topic tp;
        ASSERT_EQ(tp.init(q, 0u, 0xFFFFFF00u), MT_OK); // crosses the wrap on the way
        mt_sub_t s;
        mt_sub_init(&s, &tp.t, 0u);
        Rng rng(q);
        uint32_t published = 0u;
        uint32_t last_seen = 0u;
        for (int step = 0; step < 3000; ++step) {
            const uint32_t op = rng.below(10u);
            Msg out{};
            if (op < 5u) {
                ASSERT_EQ(tp.pub(++published), MT_OK);
            } else if (op < 8u) {
                const mt_status_t st = mt_sub_copy_next(&s, &out, sizeof out, 0u);
                ASSERT_TRUE(st == MT_OK || st == MT_W_BUS_MISSED || st == MT_E_EMPTY);
                if (st != MT_E_EMPTY) {
                    ASSERT_TRUE(msg_whole(out));
                    ASSERT_GT(out.seq, last_seen);
                    if (st == MT_OK) {
                        ASSERT_EQ(out.seq, last_seen + 1u); // the next one, nothing lost
                    }
                    last_seen = out.seq;
                }
            } else {
                const mt_status_t st = mt_sub_copy_latest(&s, &out, sizeof out, 0u);
                if (published == 0u) {
                    ASSERT_EQ(st, MT_E_EMPTY);
                } else {
                    ASSERT_TRUE(st == MT_OK || st == MT_W_BUS_MISSED);
                    ASSERT_EQ(out.seq, published);
                    last_seen = published;
                }
            }
            ASSERT_EQ(s.received + s.missed + s.skipped + pending(s), published) << "step " << step;
            ASSERT_LE(pending(s), published);
        }
        EXPECT_GT(s.missed, 0u);
        EXPECT_EQ(s.torn, 0u);
    }
}

// ------------------------------------------------------------------------ generation wrap

TEST(Bus, GenerationWrapsAndDistancesStayExact)
{
    constexpr uint32_t kQ = 3u;
    Topic tp;
    ASSERT_EQ(tp.init(kQ, 0u, UINT32_MAX - 1u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    EXPECT_EQ(s.gen, UINT32_MAX - 1u);
    ASSERT_EQ(tp.pub(1u), MT_OK);
    EXPECT_EQ(tp.t.gen, UINT32_MAX);
    ASSERT_EQ(tp.pub(2u), MT_OK);
    EXPECT_EQ(tp.t.gen, 0u); // 0xFFFFFFFF is followed by 0
    ASSERT_EQ(tp.pub(3u), MT_OK);
    EXPECT_EQ(tp.t.gen, 1u);
    EXPECT_TRUE(mt_sub_updated(&s, 0u));
    Msg out{};
    for (uint32_t k = 1u; k <= 3u; ++k) {
        ASSERT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
        EXPECT_EQ(out.seq, k);
    }
    EXPECT_EQ(s.gen, 1u);
    EXPECT_FALSE(mt_sub_updated(&s, 0u));
    // a lap across the wrap: the subscriber at generation 1, the topic 6 later
    mt_sub_t w;
    ASSERT_EQ(tp.init(kQ, 0u, UINT32_MAX - 2u), MT_OK);
    mt_sub_init(&w, &tp.t, 0u);
    for (uint32_t k = 1u; k <= 8u; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
    }
    EXPECT_EQ(tp.t.gen, 5u);
    EXPECT_EQ(mt_sub_copy_next(&w, &out, sizeof out, 0u), MT_W_BUS_MISSED);
    EXPECT_EQ(out.seq, 6u);
    EXPECT_EQ(w.missed, 5u);
    EXPECT_EQ(w.gen, 3u);
    // copy_latest across the wrap
    mt_sub_t l;
    ASSERT_EQ(tp.init(kQ, 0u, UINT32_MAX), MT_OK);
    mt_sub_init(&l, &tp.t, 0u);
    for (uint32_t k = 1u; k <= 2u; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
    }
    EXPECT_EQ(mt_sub_copy_latest(&l, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 2u);
    EXPECT_EQ(l.skipped, 1u);
    EXPECT_EQ(l.gen, 1u);
}

// ------------------------------------------------------------------------ torn copies

// The give-up path of the lock-free copy: a slot whose stamp does not match the
// generation the subscriber wants (as while a publisher overwrites it) is never
// returned; after MT_CFG_BUS_COPY_TRIES attempts the copy reports MT_E_BUS_TORN,
// counts it and consumes nothing. (The race itself: Stress test, tla/Bus.tla.)
TEST(Bus, StampMismatchGivesUpWithTornAndConsumesNothing)
{
    Topic tp;
    ASSERT_EQ(tp.init(2u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    ASSERT_EQ(tp.pub(1u), MT_OK);
    const uint32_t slot = tp.t.head;
    const uint32_t good = tp.t.stamp[slot];
    tp.t.stamp[slot] = good + 2u; // "being overwritten by the message two later"
    Msg out{};
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_E_BUS_TORN);
    EXPECT_EQ(mt_sub_copy_latest(&s, &out, sizeof out, 0u), MT_E_BUS_TORN);
    EXPECT_EQ(s.torn, 2u);
    EXPECT_EQ(s.received + s.missed + s.skipped, 0u);
    EXPECT_EQ(pending(s), 1u);
    tp.t.stamp[slot] = good;
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 1u);
}

// ------------------------------------------------------------------------ interval

TEST(Bus, IntervalSubscriptionFollowsUorbSemantics)
{
    constexpr uint32_t kIv = 1000u;
    Topic tp;
    ASSERT_EQ(tp.init(1u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, kIv);
    Msg out{};
    ASSERT_EQ(tp.pub(1u), MT_OK);
    EXPECT_FALSE(mt_sub_updated(&s, 999u)); // interval not yet elapsed since 0
    EXPECT_TRUE(mt_sub_updated(&s, 1000u));
    ASSERT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 1000u), MT_OK);
    EXPECT_EQ(s.last_us, 1000u); // now <= interval: last = now
    ASSERT_EQ(tp.pub(2u), MT_OK);
    EXPECT_FALSE(mt_sub_updated(&s, 1999u));
    EXPECT_TRUE(mt_sub_updated(&s, 2000u));
    ASSERT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 2300u), MT_OK);
    EXPECT_EQ(s.last_us, 2000u); // moved by one interval (no drift)
    ASSERT_EQ(tp.pub(3u), MT_OK);
    ASSERT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 9000u), MT_OK);
    EXPECT_EQ(s.last_us, 8000u); // clamped to now - interval: no backlog
    ASSERT_EQ(tp.pub(4u), MT_OK);
    EXPECT_TRUE(mt_sub_updated(&s, 9000u)); // one catch-up update is due at once
    ASSERT_EQ(mt_sub_copy_latest(&s, &out, sizeof out, 9500u), MT_OK);
    EXPECT_EQ(s.last_us, 9000u); // last + interval, inside the window
    ASSERT_EQ(tp.pub(5u), MT_OK);
    EXPECT_FALSE(mt_sub_updated(&s, 9999u));
    ASSERT_EQ(mt_sub_copy_latest(&s, &out, sizeof out, 9600u), MT_OK);
    EXPECT_EQ(s.last_us, 9600u); // clamped to now (copied before the interval)
    // a time before the last update never opens the gate
    ASSERT_EQ(tp.pub(6u), MT_OK);
    EXPECT_FALSE(mt_sub_updated(&s, 100u));
    // interval 0: every new message is an update
    mt_sub_t z;
    mt_sub_init(&z, &tp.t, 0u);
    EXPECT_TRUE(mt_sub_updated(&z, 0u));
}

// ------------------------------------------------------------------------ notifiers

struct Counter {
    std::atomic<int> calls{0};
};

void count_call(void *arg)
{
    static_cast<Counter *>(arg)->calls.fetch_add(1);
}

void other_call(void *arg)
{
    static_cast<Counter *>(arg)->calls.fetch_add(100);
}

TEST(BusNotify, RegistrationStatusesAndBound)
{
    Topic tp;
    ASSERT_EQ(tp.init(2u), MT_OK);
    Counter c[MT_CFG_BUS_MAX_NOTIFY + 1u];
    EXPECT_EQ(mt_topic_notify_add(&tp.t, nullptr, &c[0], 1u, 0u), MT_E_INVALID);
    EXPECT_EQ(mt_topic_notify_add(&tp.t, count_call, &c[0], 0u, 0u), MT_E_INVALID);
    for (uint32_t k = 0u; k < MT_CFG_BUS_MAX_NOTIFY; ++k) {
        EXPECT_EQ(mt_topic_notify_add(&tp.t, count_call, &c[k], 1u, 0u), MT_OK);
    }
    EXPECT_EQ(mt_topic_notify_add(&tp.t, count_call, &c[0], 1u, 0u), MT_E_DUPLICATE);
    EXPECT_EQ(mt_topic_notify_add(&tp.t, other_call, &c[MT_CFG_BUS_MAX_NOTIFY], 1u, 0u), MT_E_FULL);
    EXPECT_EQ(tp.t.nnotify, MT_CFG_BUS_MAX_NOTIFY);
    ASSERT_EQ(tp.pub(1u), MT_OK);
    for (uint32_t k = 0u; k < MT_CFG_BUS_MAX_NOTIFY; ++k) {
        EXPECT_EQ(c[k].calls.load(), 1);
        EXPECT_EQ(tp.t.notify_calls[k], 1u);
    }
    EXPECT_EQ(c[MT_CFG_BUS_MAX_NOTIFY].calls.load(), 0);
    EXPECT_EQ(tp.t.notified, MT_CFG_BUS_MAX_NOTIFY);
    // a refused publish calls nobody
    const Msg m = make_msg(2u);
    EXPECT_EQ(mt_topic_publish(&tp.t, &m, 1u), MT_E_BUS_MSG_SIZE);
    EXPECT_EQ(c[0].calls.load(), 1);
}

TEST(BusNotify, CountGateCallsEveryNthPublish)
{
    Topic tp;
    ASSERT_EQ(tp.init(1u), MT_OK);
    Counter c;
    ASSERT_EQ(mt_topic_notify_add(&tp.t, count_call, &c, 3u, 0u), MT_OK);
    for (uint32_t k = 1u; k <= 10u; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
        EXPECT_EQ(c.calls.load(), static_cast<int>(k / 3u)) << k;
    }
    EXPECT_EQ(tp.t.notify_calls[0], 3u);
    EXPECT_EQ(tp.t.notify_gated[0], 7u); // every publish that did not call is counted
    EXPECT_EQ(tp.t.notify_calls[0] + tp.t.notify_gated[0], tp.t.publishes);
}

using BusNotifySim = SimTime;

TEST_F(BusNotifySim, IntervalGateHoldsBackUntilTheIntervalPassed)
{
    constexpr uint32_t kIv = 10000u;
    Topic tp;
    ASSERT_EQ(tp.init(1u), MT_OK);
    Counter c;
    ASSERT_EQ(mt_topic_notify_add(&tp.t, count_call, &c, 1u, kIv), MT_OK);
    ASSERT_EQ(tp.pub(1u), MT_OK); // sim time 1 s: long after last_us 0
    EXPECT_EQ(c.calls.load(), 1);
    const uint64_t t0 = mt_port_now_us();
    EXPECT_EQ(tp.t.notify_last_us[0], t0 - kIv); // clamped to now - interval
    mt_posix_sim_advance(1u);
    ASSERT_EQ(tp.pub(2u), MT_OK); // the one catch-up call uORB's rule allows
    EXPECT_EQ(c.calls.load(), 2);
    EXPECT_EQ(tp.t.notify_last_us[0], t0);
    mt_posix_sim_advance(kIv - 2u);
    ASSERT_EQ(tp.pub(3u), MT_OK); // kIv - 1 after the last update: held back
    EXPECT_EQ(c.calls.load(), 2);
    EXPECT_EQ(tp.t.notify_gated[0], 1u);
    mt_posix_sim_advance(1u);
    ASSERT_EQ(tp.pub(4u), MT_OK);
    EXPECT_EQ(c.calls.load(), 3);
    EXPECT_EQ(tp.t.notify_last_us[0], t0 + kIv);
    EXPECT_EQ(tp.t.notify_calls[0] + tp.t.notify_gated[0], 4u);
}

// ------------------------------------------------------------------------ reliable

TEST(BusReliable, RegistrationStatuses)
{
    Topic plain;
    ASSERT_EQ(plain.init(2u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &plain.t, 0u);
    EXPECT_EQ(mt_sub_reliable(&s), MT_E_STATE);

    Topic tp;
    ASSERT_EQ(tp.init(2u, MT_TOPIC_RELIABLE), MT_OK);
    mt_sub_t r[MT_CFG_BUS_MAX_RELIABLE + 1u];
    for (uint32_t k = 0u; k < MT_CFG_BUS_MAX_RELIABLE; ++k) {
        mt_sub_init(&r[k], &tp.t, 0u);
        EXPECT_EQ(mt_sub_reliable(&r[k]), MT_OK);
        EXPECT_EQ(r[k].rel, k + 1u);
    }
    EXPECT_EQ(mt_sub_reliable(&r[0]), MT_E_DUPLICATE);
    mt_sub_init(&r[MT_CFG_BUS_MAX_RELIABLE], &tp.t, 0u);
    EXPECT_EQ(mt_sub_reliable(&r[MT_CFG_BUS_MAX_RELIABLE]), MT_E_FULL);
    EXPECT_EQ(tp.t.nrel, MT_CFG_BUS_MAX_RELIABLE);
}

TEST(BusReliable, PublishIsRefusedWhileAReliableSubscriberLags)
{
    constexpr uint32_t kQ = 3u;
    Topic tp;
    ASSERT_EQ(tp.init(kQ, MT_TOPIC_RELIABLE), MT_OK);
    mt_sub_t r;
    mt_sub_t casual;
    mt_sub_init(&r, &tp.t, 0u);
    mt_sub_init(&casual, &tp.t, 0u);
    ASSERT_EQ(mt_sub_reliable(&r), MT_OK);
    for (uint32_t k = 1u; k <= kQ; ++k) {
        ASSERT_EQ(tp.pub(k), MT_OK);
    }
    // the queue holds 3 messages r has not consumed: a fourth would overwrite message 1
    EXPECT_EQ(tp.pub(4u), MT_E_BUS_BEHIND);
    const Msg m = make_msg(4u);
    EXPECT_EQ(mt_topic_publish_isr(&tp.t, &m, sizeof m), MT_E_BUS_BEHIND);
    EXPECT_EQ(tp.t.rejected, 2u);
    EXPECT_EQ(tp.t.publishes, kQ);
    Msg out{};
    ASSERT_EQ(mt_sub_copy_next(&r, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 1u);
    EXPECT_EQ(tp.t.rel_gen[0], r.gen);
    EXPECT_EQ(tp.pub(4u), MT_OK); // room for exactly one
    EXPECT_EQ(tp.pub(5u), MT_E_BUS_BEHIND);
    for (uint32_t k = 2u; k <= 4u; ++k) {
        ASSERT_EQ(mt_sub_copy_next(&r, &out, sizeof out, 0u), MT_OK);
        EXPECT_EQ(out.seq, k);
    }
    EXPECT_EQ(r.missed, 0u); // a reliable subscriber never misses
    EXPECT_EQ(tp.pub(5u), MT_OK);
    // copy_latest moves the reliable mark too
    ASSERT_EQ(tp.pub(6u), MT_OK);
    ASSERT_EQ(mt_sub_copy_latest(&r, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 6u);
    EXPECT_EQ(tp.t.rel_gen[0], tp.t.gen);
    // a casual subscriber on the same topic is not protected: it just lags
    EXPECT_EQ(mt_sub_copy_next(&casual, &out, sizeof out, 0u), MT_W_BUS_MISSED);
    EXPECT_EQ(out.seq, 4u);
    EXPECT_EQ(casual.missed, 3u);
}

// ------------------------------------------------------------------------ poll

using BusPollSim = SimTime;

TEST_F(BusPollSim, StatusesWithoutBlocking)
{
    Topic tp;
    ASSERT_EQ(tp.init(1u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    EXPECT_EQ(mt_sub_poll(&s, 0u), MT_E_STATE);
    ASSERT_EQ(mt_sub_poll_enable(&s), MT_OK);
    EXPECT_EQ(s.notify, 1u);
    EXPECT_EQ(mt_sub_poll_enable(&s), MT_E_DUPLICATE);
    EXPECT_EQ(mt_sub_poll(&s, 0u), MT_E_TIMEOUT);
    const uint64_t t0 = mt_port_now_us();
    EXPECT_EQ(mt_sub_poll(&s, 5000u), MT_E_TIMEOUT); // simulated: the timeout elapses
    EXPECT_EQ(mt_port_now_us(), t0 + 5000u);
    ASSERT_EQ(tp.pub(1u), MT_OK);
    EXPECT_EQ(s.sem.token, 1u);            // the publish signalled
    EXPECT_EQ(mt_sub_poll(&s, 0u), MT_OK); // pending: no wait
    Msg out{};
    ASSERT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
    // the token left by the consumed publish does not make the next poll succeed
    EXPECT_EQ(mt_sub_poll(&s, 0u), MT_E_TIMEOUT);
    EXPECT_EQ(s.sem.token, 0u);
}

TEST(BusPoll, NotifierBoundAppliesToPoll)
{
    Topic tp;
    ASSERT_EQ(tp.init(1u), MT_OK);
    Counter c[MT_CFG_BUS_MAX_NOTIFY];
    for (uint32_t k = 0u; k < MT_CFG_BUS_MAX_NOTIFY; ++k) {
        ASSERT_EQ(mt_topic_notify_add(&tp.t, count_call, &c[k], 1u, 0u), MT_OK);
    }
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    EXPECT_EQ(mt_sub_poll_enable(&s), MT_E_FULL);
    EXPECT_EQ(s.notify, 0u);
    EXPECT_EQ(mt_sub_poll(&s, 0u), MT_E_STATE);
}

using BusPollReal = RealTime;

TEST_F(BusPollReal, WakesOnPublishAndReportsBusyForASecondPoller)
{
    Topic tp;
    ASSERT_EQ(tp.init(2u), MT_OK);
    mt_sub_t s;
    mt_sub_init(&s, &tp.t, 0u);
    ASSERT_EQ(mt_sub_poll_enable(&s), MT_OK);
    std::atomic<int> result{-1};
    std::thread waiter([&] { result.store(mt_sub_poll(&s, MT_WAIT_FOREVER)); });
    ASSERT_TRUE(wait_until([&] { return sem_has_waiter(&s.sem); }));
    EXPECT_EQ(mt_sub_poll(&s, 1000u), MT_E_BUSY); // one poller per subscriber
    const Msg m = make_msg(1u);
    ASSERT_EQ(mt_topic_publish_isr(&tp.t, &m, sizeof m), MT_OK);
    waiter.join();
    EXPECT_EQ(result.load(), MT_OK);
    Msg out{};
    EXPECT_EQ(mt_sub_copy_next(&s, &out, sizeof out, 0u), MT_OK);
    EXPECT_EQ(out.seq, 1u);
    EXPECT_EQ(mt_sub_poll(&s, 2000u), MT_E_TIMEOUT); // real time: nothing published
}

// ------------------------------------------------------------------------ stress

using BusStress = RealTime;

// A task publisher and an "ISR" publisher thread race three lock-free subscribers
// (copy_next, copy_latest, a poller). No subscriber ever gets a mixed message; each
// subscriber's accounting is exact at the end.
TEST_F(BusStress, PublishersRaceLockFreeSubscribers)
{
    constexpr uint32_t kQ = 4u;
    const uint32_t per_publisher = mt_test::kTsan ? 20000u : 200000u;
    Topic tp;
    ASSERT_EQ(tp.init(kQ), MT_OK);
    mt_sub_t next;
    mt_sub_t latest;
    mt_sub_t poller;
    mt_sub_init(&next, &tp.t, 0u);
    mt_sub_init(&latest, &tp.t, 0u);
    mt_sub_init(&poller, &tp.t, 0u);
    ASSERT_EQ(mt_sub_poll_enable(&poller), MT_OK);
    std::atomic<int> publishers_done{0};
    std::atomic<uint32_t> bad{0};

    // sequence numbers: task publisher odd, ISR publisher even; each increasing
    auto publisher = [&](bool isr) {
        for (uint32_t k = 0u; k < per_publisher; ++k) {
            const Msg m = make_msg(2u * k + (isr ? 2u : 1u));
            const mt_status_t st = isr ? mt_topic_publish_isr(&tp.t, &m, sizeof m)
                                       : mt_topic_publish(&tp.t, &m, sizeof m);
            if (st != MT_OK) {
                bad.fetch_add(1u);
            }
        }
        publishers_done.fetch_add(1);
    };
    auto check = [&](mt_status_t st, const Msg &out, uint32_t last[2]) {
        if (st == MT_OK || st == MT_W_BUS_MISSED) {
            if (!msg_whole(out)) {
                bad.fetch_add(1u);
                return;
            }
            const uint32_t side = out.seq & 1u;
            if (out.seq < last[side]) { // each publisher's messages arrive in order
                bad.fetch_add(1u);
            }
            last[side] = out.seq;
        } else if (st != MT_E_EMPTY && st != MT_E_BUS_TORN) {
            bad.fetch_add(1u);
        }
    };
    std::thread sub_next([&] {
        uint32_t last[2] = {0u, 0u};
        while (publishers_done.load() < 2) {
            Msg out{};
            check(mt_sub_copy_next(&next, &out, sizeof out, 0u), out, last);
        }
    });
    std::thread sub_latest([&] {
        uint32_t last[2] = {0u, 0u};
        while (publishers_done.load() < 2) {
            Msg out{};
            check(mt_sub_copy_latest(&latest, &out, sizeof out, 0u), out, last);
        }
    });
    std::thread sub_poll([&] {
        uint32_t last[2] = {0u, 0u};
        while (publishers_done.load() < 2) {
            const mt_status_t st = mt_sub_poll(&poller, 2000u);
            if (st != MT_OK && st != MT_E_TIMEOUT) {
                bad.fetch_add(1u);
            }
            Msg out{};
            check(mt_sub_copy_next(&poller, &out, sizeof out, 0u), out, last);
        }
    });
    std::thread task_pub(publisher, false);
    std::thread isr_pub(publisher, true);
    task_pub.join();
    isr_pub.join();
    sub_next.join();
    sub_latest.join();
    sub_poll.join();

    EXPECT_EQ(bad.load(), 0u);
    const uint32_t total = 2u * per_publisher;
    EXPECT_EQ(tp.t.publishes, total);
    for (const mt_sub_t *s : {&next, &latest, &poller}) {
        EXPECT_EQ(s->received + s->missed + s->skipped + pending(*s), total);
    }
    EXPECT_EQ(next.skipped, 0u);
    EXPECT_EQ(poller.skipped, 0u);
}

// A reliable subscriber under the same race never misses a message, and the
// publisher's refusals are all counted.
TEST_F(BusStress, ReliableSubscriberNeverMisses)
{
    constexpr uint32_t kQ = 3u;
    const uint32_t target = mt_test::kTsan ? 5000u : 50000u;
    Topic tp;
    ASSERT_EQ(tp.init(kQ, MT_TOPIC_RELIABLE), MT_OK);
    mt_sub_t r;
    mt_sub_init(&r, &tp.t, 0u);
    ASSERT_EQ(mt_sub_reliable(&r), MT_OK);
    std::atomic<bool> stop{false};
    std::atomic<uint32_t> refused{0};
    std::atomic<uint32_t> bad{0};
    std::thread isr_pub([&] {
        uint32_t seq = 1u;
        while (seq <= target && !stop.load()) {
            const Msg m = make_msg(seq);
            const mt_status_t st = mt_topic_publish_isr(&tp.t, &m, sizeof m);
            if (st == MT_OK) {
                ++seq;
            } else if (st == MT_E_BUS_BEHIND) {
                refused.fetch_add(1u);
                std::this_thread::yield();
            } else {
                bad.fetch_add(1u);
            }
        }
    });
    uint32_t expect = 1u;
    mt_test::Rng rng(7u);
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (expect <= target && std::chrono::steady_clock::now() < end) {
        Msg out{};
        const mt_status_t st = mt_sub_copy_next(&r, &out, sizeof out, 0u);
        if (st == MT_OK) {
            if (!msg_whole(out) || out.seq != expect) {
                bad.fetch_add(1u);
            }
            ++expect;
        } else if (st != MT_E_EMPTY && st != MT_E_BUS_TORN) {
            bad.fetch_add(1u);
        }
        if (rng.below(8u) == 0u) {
            std::this_thread::yield();
        }
    }
    stop.store(true);
    isr_pub.join();
    EXPECT_EQ(bad.load(), 0u);
    EXPECT_EQ(expect, target + 1u);
    EXPECT_EQ(r.missed, 0u);
    EXPECT_EQ(tp.t.rejected, refused.load());
    EXPECT_EQ(tp.t.publishes, target);
}

} // namespace
