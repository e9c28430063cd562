// SPDX-License-Identifier: Apache-2.0
// SPSC object ring (mt/objring.h), single-threaded: every status, the
// drop-oldest protocol (the consumer drops, the producer never writes the
// consumer's half), R-1/R-3 regressions and a randomized differential test.
#include <cstring>
#include <deque>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::Rng;

struct Obj {
    uint32_t seq;
    uint32_t check;
};

Obj mk(uint32_t seq)
{
    return Obj{seq, seq * 2654435761u + 7u};
}

struct ORing {
    std::vector<uint8_t> mem;
    mt_oring_t r;
    explicit ORing(uint32_t cap) : mem(MT_ORING_STORAGE_BYTES(sizeof(Obj), cap), 0u)
    {
        EXPECT_EQ(mt_oring_init(&r, mem.data(), sizeof(Obj), cap), MT_OK);
    }
    mt_status_t push(uint32_t seq)
    {
        const Obj o = mk(seq);
        return mt_oring_push(&r, &o);
    }
    mt_status_t push_drop(uint32_t seq)
    {
        const Obj o = mk(seq);
        return mt_oring_push_drop_oldest(&r, &o);
    }
    // pops everything, returning the sequence numbers (checks each object's body)
    std::vector<uint32_t> drain()
    {
        std::vector<uint32_t> got;
        Obj o;
        while (mt_oring_pop(&r, &o) == MT_OK) {
            EXPECT_EQ(o.check, mk(o.seq).check);
            got.push_back(o.seq);
        }
        return got;
    }
};

struct ConsumerHalf {
    uint32_t head, tail_cache, lost;
    explicit ConsumerHalf(const mt_oring_t &r)
        : head(r.head), tail_cache(r.tail_cache), lost(r.lost)
    {
    }
    bool operator==(const ConsumerHalf &o) const
    {
        return head == o.head && tail_cache == o.tail_cache && lost == o.lost;
    }
};

TEST(ObjRingInit, Statuses)
{
    uint8_t buf[64];
    mt_oring_t r;

    EXPECT_EQ(mt_oring_init(&r, buf, 0u, 4u), MT_E_INVALID); // elem 0
    EXPECT_EQ(r.cap, 0u);
    EXPECT_EQ(mt_oring_init(&r, buf, 4u, 0u), MT_E_INVALID); // cap 0
    EXPECT_EQ(r.cap, 0u);
    // (cap + 1) * elem above MT_ORING_BYTES_MAX
    EXPECT_EQ(mt_oring_init(&r, buf, 2u, 0x20000000u), MT_E_INVALID);
    EXPECT_EQ(r.cap, 0u);
    EXPECT_EQ(mt_oring_init(&r, buf, 0x10000u, 0x4000u), MT_E_INVALID);
    // products that wrap in 32 bits must not pass as small ones
    EXPECT_EQ(mt_oring_init(&r, buf, 0x10000u, 0xFFFFu), MT_E_INVALID); // 2^32 -> 0
    EXPECT_EQ(mt_oring_init(&r, buf, 1u, 0xFFFFFFFFu), MT_E_INVALID);   // cap + 1 -> 0
    EXPECT_EQ(mt_oring_init(&r, buf, 0x80000000u, 1u), MT_E_INVALID);   // 2^32 -> 0
    EXPECT_EQ(mt_oring_init(&r, buf, 0xFFFFFFFFu, 0xFFFFFFFFu), MT_E_INVALID);
    EXPECT_EQ(r.cap, 0u);

    ASSERT_EQ(mt_oring_init(&r, buf, 4u, 15u), MT_OK); // 64 bytes: exactly the storage
    EXPECT_EQ(r.cap, 15u);
    EXPECT_EQ(r.slots, 16u);
    EXPECT_EQ(r.elem, 4u);
    EXPECT_EQ(r.lost, 0u);
    EXPECT_EQ(r.rejected, 0u);
    EXPECT_EQ(mt_oring_available(&r), 0u);
    EXPECT_EQ(mt_oring_space(&r), 15u);
    EXPECT_EQ(MT_ORING_STORAGE_BYTES(4u, 15u), 64u);
    EXPECT_EQ(MT_ORING_STORAGE_BYTES(sizeof(Obj), 1u), 2u * sizeof(Obj));
}

TEST(ObjRing, PushPopFifoAndCounts)
{
    ORing g(3u);
    Obj o{};
    EXPECT_EQ(mt_oring_pop(&g.r, &o), MT_E_EMPTY);
    EXPECT_EQ(g.push(1u), MT_OK);
    EXPECT_EQ(mt_oring_available(&g.r), 1u);
    EXPECT_EQ(mt_oring_space(&g.r), 2u);
    EXPECT_EQ(g.push(2u), MT_OK);
    EXPECT_EQ(g.push(3u), MT_OK);
    EXPECT_EQ(mt_oring_available(&g.r), 3u);
    EXPECT_EQ(mt_oring_space(&g.r), 0u);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{1u, 2u, 3u}));
    EXPECT_EQ(mt_oring_space(&g.r), 3u);
    EXPECT_EQ(g.r.lost, 0u);
    EXPECT_EQ(g.r.rejected, 0u);
}

TEST(ObjRing, PopOnEmptyLeavesOutputUntouched)
{
    ORing g(2u);
    Obj o{0xDEADBEEFu, 0xFEEDFACEu};
    EXPECT_EQ(mt_oring_pop(&g.r, &o), MT_E_EMPTY);
    EXPECT_EQ(mt_oring_peek(&g.r, &o), MT_E_EMPTY);
    EXPECT_EQ(o.seq, 0xDEADBEEFu);
    EXPECT_EQ(o.check, 0xFEEDFACEu);
    const Obj n = mk(5u);
    EXPECT_EQ(mt_oring_update_front(&g.r, &n), MT_E_EMPTY);
    EXPECT_EQ(mt_oring_available(&g.r), 0u); // update_front on empty did not add anything
}

TEST(ObjRing, FullPushIsRejectedAndCounted)
{
    ORing g(2u);
    EXPECT_EQ(g.push(1u), MT_OK);
    EXPECT_EQ(g.push(2u), MT_OK);
    const std::vector<uint8_t> before = g.mem;
    const uint32_t tail = g.r.tail;
    EXPECT_EQ(g.push(3u), MT_E_FULL);
    EXPECT_EQ(g.push(4u), MT_E_FULL);
    EXPECT_EQ(g.r.rejected, 2u);
    EXPECT_EQ(g.r.tail, tail);
    EXPECT_EQ(g.mem, before); // nothing written, not even the spare slot
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{1u, 2u}));
    EXPECT_EQ(g.push(5u), MT_OK);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{5u}));
    EXPECT_EQ(g.r.lost, 0u);
}

TEST(ObjRing, RejectedSaturates)
{
    ORing g(1u);
    EXPECT_EQ(g.push(1u), MT_OK);
    g.r.rejected = 0xFFFFFFFEu;
    EXPECT_EQ(g.push(2u), MT_E_FULL);
    EXPECT_EQ(g.r.rejected, 0xFFFFFFFFu);
    EXPECT_EQ(g.push(3u), MT_E_FULL);
    EXPECT_EQ(g.r.rejected, 0xFFFFFFFFu);
}

TEST(ObjRing, PeekAndUpdateFront)
{
    ORing g(3u);
    Obj o{};
    EXPECT_EQ(g.push(10u), MT_OK);
    EXPECT_EQ(g.push(11u), MT_OK);
    EXPECT_EQ(mt_oring_peek(&g.r, &o), MT_OK);
    EXPECT_EQ(o.seq, 10u);
    EXPECT_EQ(mt_oring_available(&g.r), 2u); // peek does not consume
    const Obj repl = mk(99u);
    EXPECT_EQ(mt_oring_update_front(&g.r, &repl), MT_OK);
    EXPECT_EQ(mt_oring_peek(&g.r, &o), MT_OK);
    EXPECT_EQ(o.seq, 99u);
    EXPECT_EQ(mt_oring_available(&g.r), 2u);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{99u, 11u}));
}

TEST(ObjRing, Flush)
{
    ORing g(4u);
    EXPECT_EQ(mt_oring_flush(&g.r), 0u);
    EXPECT_EQ(g.push(1u), MT_OK);
    EXPECT_EQ(g.push(2u), MT_OK);
    EXPECT_EQ(g.push(3u), MT_OK);
    const uint32_t tail = g.r.tail;
    EXPECT_EQ(mt_oring_flush(&g.r), 3u);
    EXPECT_EQ(g.r.tail, tail); // consumer's clear: producer index untouched
    EXPECT_EQ(mt_oring_available(&g.r), 0u);
    EXPECT_EQ(mt_oring_space(&g.r), 4u);
    EXPECT_EQ(g.r.lost, 0u);
    EXPECT_EQ(g.push(4u), MT_OK);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{4u}));
}

TEST(ObjRing, FlushAfterDropCountsTheDropAsLost)
{
    ORing g(2u);
    EXPECT_EQ(g.push(1u), MT_OK);
    EXPECT_EQ(g.push(2u), MT_OK);
    EXPECT_EQ(g.push_drop(3u), MT_W_DROPPED_OLDEST);
    EXPECT_EQ(mt_oring_flush(&g.r), 2u); // the two retained objects
    EXPECT_EQ(g.r.lost, 1u);             // the dropped one
    EXPECT_EQ(mt_oring_available(&g.r), 0u);
}

TEST(ObjRingDropOldest, OnRoomBehavesLikePush)
{
    ORing g(3u);
    EXPECT_EQ(g.push_drop(1u), MT_OK);
    EXPECT_EQ(g.push_drop(2u), MT_OK);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{1u, 2u}));
    EXPECT_EQ(g.r.lost, 0u);
    EXPECT_EQ(g.r.rejected, 0u);
}

TEST(ObjRingDropOldest, ConsumerSeesNewestCapObjectsAndCountsOneLost)
{
    for (uint32_t cap = 1u; cap <= 6u; ++cap) {
        ORing g(cap);
        for (uint32_t k = 1u; k <= cap; ++k) {
            ASSERT_EQ(g.push(k), MT_OK);
        }
        EXPECT_EQ(g.push(cap + 1u), MT_E_FULL); // plain push never drops
        EXPECT_EQ(g.push_drop(cap + 1u), MT_W_DROPPED_OLDEST) << cap;
        EXPECT_EQ(mt_oring_available(&g.r), cap); // never reports more than cap
        EXPECT_EQ(mt_oring_space(&g.r), 0u);
        std::vector<uint32_t> want;
        for (uint32_t k = 2u; k <= cap + 1u; ++k) {
            want.push_back(k);
        }
        EXPECT_EQ(g.drain(), want) << cap;
        EXPECT_EQ(g.r.lost, 1u);
        EXPECT_EQ(g.r.rejected, 1u); // the plain push above
    }
}

TEST(ObjRingDropOldest, SecondDropBeforeConsumerRunsIsRejected)
{
    ORing g(3u);
    for (uint32_t k = 1u; k <= 3u; ++k) {
        ASSERT_EQ(g.push(k), MT_OK);
    }
    EXPECT_EQ(g.push_drop(4u), MT_W_DROPPED_OLDEST);
    const uint32_t tail = g.r.tail;
    EXPECT_EQ(g.push_drop(5u), MT_E_FULL);
    EXPECT_EQ(g.r.tail, tail);
    EXPECT_EQ(g.r.rejected, 1u);
    EXPECT_EQ(g.push(6u), MT_E_FULL);
    EXPECT_EQ(g.r.rejected, 2u);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{2u, 3u, 4u}));
    EXPECT_EQ(g.r.lost, 1u);
    // once the consumer has caught up, drop-oldest works again
    for (uint32_t k = 7u; k <= 9u; ++k) {
        ASSERT_EQ(g.push(k), MT_OK);
    }
    EXPECT_EQ(g.push_drop(10u), MT_W_DROPPED_OLDEST);
    Obj o{};
    EXPECT_EQ(mt_oring_pop(&g.r, &o), MT_OK); // the consumer drops 7 and delivers 8
    EXPECT_EQ(o.seq, 8u);
    EXPECT_EQ(g.r.lost, 2u);
    EXPECT_EQ(g.push_drop(11u), MT_OK); // one slot free again: no drop
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{9u, 10u, 11u}));
    EXPECT_EQ(g.r.lost, 2u);
}

TEST(ObjRingDropOldest, PeekAndUpdateFrontPerformThePendingDrop)
{
    ORing g(2u);
    Obj o{};
    ASSERT_EQ(g.push(1u), MT_OK);
    ASSERT_EQ(g.push(2u), MT_OK);
    ASSERT_EQ(g.push_drop(3u), MT_W_DROPPED_OLDEST);
    EXPECT_EQ(mt_oring_peek(&g.r, &o), MT_OK);
    EXPECT_EQ(o.seq, 2u); // 1 was the oldest: dropped
    EXPECT_EQ(g.r.lost, 1u);
    EXPECT_EQ(mt_oring_peek(&g.r, &o), MT_OK);
    EXPECT_EQ(o.seq, 2u);
    EXPECT_EQ(g.r.lost, 1u); // dropped once only

    ASSERT_EQ(g.push_drop(4u), MT_W_DROPPED_OLDEST);
    const Obj repl = mk(77u);
    EXPECT_EQ(mt_oring_update_front(&g.r, &repl), MT_OK); // drops 2, replaces 3
    EXPECT_EQ(g.r.lost, 2u);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{77u, 4u}));
}

// R-1 regression: ArduPilot's push_force(n = 2) mixed bytes and objects and never
// made room (with 1 free slot, or on a full buffer, it returned false with
// nothing dropped). Here two drop-oldest pushes in a row behave as documented.
TEST(ObjRingDropOldest, R1TwoForcedPushesMakeRoom)
{
    ORing g(4u);
    for (uint32_t k = 1u; k <= 3u; ++k) { // one free slot left
        ASSERT_EQ(g.push(k), MT_OK);
    }
    EXPECT_EQ(g.push_drop(4u), MT_OK);
    EXPECT_EQ(g.push_drop(5u), MT_W_DROPPED_OLDEST);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{2u, 3u, 4u, 5u}));
    EXPECT_EQ(g.r.lost, 1u);
    EXPECT_EQ(g.r.rejected, 0u);

    // full ring: the first forced push makes room; the second waits for the consumer
    for (uint32_t k = 6u; k <= 9u; ++k) {
        ASSERT_EQ(g.push(k), MT_OK);
    }
    EXPECT_EQ(g.push_drop(10u), MT_W_DROPPED_OLDEST);
    Obj o{};
    ASSERT_EQ(mt_oring_pop(&g.r, &o), MT_OK);
    EXPECT_EQ(o.seq, 7u);
    EXPECT_EQ(g.push_drop(11u), MT_OK);
    EXPECT_EQ(g.push_drop(12u), MT_W_DROPPED_OLDEST);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{9u, 10u, 11u, 12u}));
    EXPECT_EQ(g.r.lost, 3u); // 1, 6, 8
    EXPECT_EQ(g.r.rejected, 0u);
}

// R-3 regression: ArduPilot's push_force (producer) wrote the consumer's head.
// push_drop_oldest must not write head, tail_cache or lost on any path.
TEST(ObjRingDropOldest, R3ProducerNeverWritesConsumerHalf)
{
    ORing g(3u);
    Obj o{};
    ASSERT_EQ(g.push(1u), MT_OK);
    ASSERT_EQ(mt_oring_pop(&g.r, &o), MT_OK); // consumer fields now non-zero
    ASSERT_EQ(g.push(2u), MT_OK);
    (void)mt_oring_available(&g.r);

    ConsumerHalf before(g.r);
    EXPECT_EQ(g.push_drop(3u), MT_OK); // room path
    EXPECT_TRUE(ConsumerHalf(g.r) == before);
    EXPECT_EQ(g.push_drop(4u), MT_OK);
    EXPECT_TRUE(ConsumerHalf(g.r) == before);
    EXPECT_EQ(g.push_drop(5u), MT_W_DROPPED_OLDEST); // drop path
    EXPECT_TRUE(ConsumerHalf(g.r) == before);
    EXPECT_EQ(g.push_drop(6u), MT_E_FULL); // rejected path
    EXPECT_TRUE(ConsumerHalf(g.r) == before);
    (void)mt_oring_space(&g.r);
    EXPECT_EQ(g.push(7u), MT_E_FULL);
    EXPECT_TRUE(ConsumerHalf(g.r) == before);

    // and the consumer never writes the producer's half
    const uint32_t tail = g.r.tail;
    const uint32_t head_cache = g.r.head_cache;
    const uint32_t rejected = g.r.rejected;
    (void)mt_oring_peek(&g.r, &o);
    (void)g.drain();
    (void)mt_oring_flush(&g.r);
    EXPECT_EQ(g.r.tail, tail);
    EXPECT_EQ(g.r.head_cache, head_cache);
    EXPECT_EQ(g.r.rejected, rejected);
}

TEST(ObjRing, LostSaturates)
{
    ORing g(1u);
    ASSERT_EQ(g.push(1u), MT_OK);
    g.r.lost = 0xFFFFFFFFu;
    ASSERT_EQ(g.push_drop(2u), MT_W_DROPPED_OLDEST);
    EXPECT_EQ(g.drain(), (std::vector<uint32_t>{2u}));
    EXPECT_EQ(g.r.lost, 0xFFFFFFFFu);
}

// ---- randomized differential test ------------------------------------------

// Reference model: the published objects (up to cap + 1); the consumer's
// operations first drop the oldest when more than cap are published.
struct Model {
    uint32_t cap;
    std::deque<std::vector<uint8_t>> q;
    uint32_t lost = 0u;
    uint32_t rejected = 0u;
    void sync()
    {
        if (q.size() > cap) {
            q.pop_front();
            ++lost;
        }
    }
};

void differential(uint32_t cap, uint32_t elem, uint64_t seed, uint32_t ops)
{
    std::vector<uint8_t> mem(MT_ORING_STORAGE_BYTES(elem, cap) + 32u, 0x3Cu);
    mt_oring_t r;
    ASSERT_EQ(mt_oring_init(&r, mem.data() + 16, elem, cap), MT_OK);
    Model m{cap, {}, 0u, 0u};
    Rng rng(seed);
    uint32_t counter = 0u;
    uint32_t drops = 0u;
    uint32_t head_wraps = 0u;
    std::vector<uint8_t> out(elem);

    auto fresh = [&]() {
        std::vector<uint8_t> v(elem);
        for (uint32_t k = 0; k < elem; ++k) {
            v[k] = static_cast<uint8_t>(counter * 31u + k);
        }
        ++counter;
        return v;
    };

    for (uint32_t op = 0; op < ops; ++op) {
        const uint32_t head0 = r.head;
        switch (rng.below(9u)) {
        case 0:
        case 1: { // push
            const auto v = fresh();
            const mt_status_t st = mt_oring_push(&r, v.data());
            if (m.q.size() >= cap) {
                ASSERT_EQ(st, MT_E_FULL);
                ++m.rejected;
            } else {
                ASSERT_EQ(st, MT_OK);
                m.q.push_back(v);
            }
            break;
        }
        case 2:
        case 3: { // push_drop_oldest
            const auto v = fresh();
            const ConsumerHalf ch(r);
            const mt_status_t st = mt_oring_push_drop_oldest(&r, v.data());
            ASSERT_TRUE(ConsumerHalf(r) == ch);
            if (m.q.size() > cap) {
                ASSERT_EQ(st, MT_E_FULL);
                ++m.rejected;
            } else if (m.q.size() == cap) {
                ASSERT_EQ(st, MT_W_DROPPED_OLDEST);
                m.q.push_back(v);
                ++drops;
            } else {
                ASSERT_EQ(st, MT_OK);
                m.q.push_back(v);
            }
            break;
        }
        case 4:
        case 5: { // pop
            m.sync();
            const mt_status_t st = mt_oring_pop(&r, out.data());
            if (m.q.empty()) {
                ASSERT_EQ(st, MT_E_EMPTY);
            } else {
                ASSERT_EQ(st, MT_OK);
                ASSERT_EQ(out, m.q.front());
                m.q.pop_front();
            }
            break;
        }
        case 6: { // peek or update_front
            m.sync();
            if (rng.below(2u) == 0u) {
                const mt_status_t st = mt_oring_peek(&r, out.data());
                ASSERT_EQ(st, m.q.empty() ? MT_E_EMPTY : MT_OK);
                if (!m.q.empty()) {
                    ASSERT_EQ(out, m.q.front());
                }
            } else {
                const auto v = fresh();
                const mt_status_t st = mt_oring_update_front(&r, v.data());
                ASSERT_EQ(st, m.q.empty() ? MT_E_EMPTY : MT_OK);
                if (!m.q.empty()) {
                    m.q.front() = v;
                }
            }
            break;
        }
        case 7: { // available / space (no drop performed)
            const uint32_t n = static_cast<uint32_t>(m.q.size());
            ASSERT_EQ(mt_oring_available(&r), std::min(n, cap));
            ASSERT_EQ(mt_oring_space(&r), n >= cap ? 0u : cap - n);
            break;
        }
        default: { // flush, rarely
            if (rng.below(6u) == 0u) {
                m.sync();
                ASSERT_EQ(mt_oring_flush(&r), m.q.size());
                m.q.clear();
            }
            break;
        }
        }
        ASSERT_TRUE(mt_oring_valid(&r));
        ASSERT_EQ(r.lost, m.lost);
        ASSERT_EQ(r.rejected, m.rejected);
        ASSERT_LT(r.head, 2u * (cap + 1u));
        ASSERT_LT(r.tail, 2u * (cap + 1u));
        head_wraps += (r.head < head0) ? 1u : 0u;
    }
    for (uint32_t k = 0; k < 16u; ++k) {
        ASSERT_EQ(mem[k], 0x3Cu) << "write before the storage";
        ASSERT_EQ(mem[mem.size() - 1u - k], 0x3Cu) << "write after the storage";
    }
    EXPECT_GE(drops, 3u) << "cap " << cap;
    EXPECT_GE(m.lost, 1u) << "cap " << cap;
    EXPECT_GE(head_wraps, 3u) << "cap " << cap;
}

// mt_oring_valid is the C twin of MtORingInv (equivalence proved by WP and CBMC).
TEST(ObjRingValid, EachBrokenRelationIsReported)
{
    alignas(8) uint8_t storage[MT_ORING_STORAGE_BYTES(4u, 3u)];
    mt_oring_t r;
    ASSERT_EQ(mt_oring_init(&r, storage, 4u, 3u), MT_OK);
    EXPECT_TRUE(mt_oring_valid(&r));
    const mt_oring_t good = r;
    r.slots = r.cap;
    EXPECT_FALSE(mt_oring_valid(&r)) << "slots != cap + 1";
    r = good;
    r.elem = 0u;
    EXPECT_FALSE(mt_oring_valid(&r)) << "element size 0";
    r = good;
    r.elem = MT_ORING_BYTES_MAX;
    EXPECT_FALSE(mt_oring_valid(&r)) << "storage above MT_ORING_BYTES_MAX";
    r = good;
    r.cap = 0xFFFFFFFFu;
    r.slots = 0u;
    EXPECT_FALSE(mt_oring_valid(&r)) << "cap + 1 wraps";
    r = good;
    r.head = 2u * r.slots;
    EXPECT_FALSE(mt_oring_valid(&r)) << "head outside [0, 2 slots)";
    r = good;
    r.tail = 2u;
    r.tail_cache = 1u; // the consumer's cached tail may lag behind the real one
    r.head_cache = 0u;
    EXPECT_TRUE(mt_oring_valid(&r));
    r.tail_cache = 3u; // consumer's cached tail ahead of the real one
    EXPECT_FALSE(mt_oring_valid(&r)) << "consumer's cached tail ahead of the data";
}

TEST(ObjRingDifferential, AgainstReferenceModel)
{
    const uint32_t elems[] = {1u, 3u, 8u, 13u};
    for (uint32_t cap = 1u; cap <= 9u; ++cap) {
        for (uint32_t elem : elems) {
            differential(cap, elem, cap * 100u + elem, 8000u);
            if (HasFatalFailure()) {
                return;
            }
        }
    }
}

} // namespace
