// SPDX-License-Identifier: Apache-2.0
// SPSC byte ring (mt/ring.h), single-threaded: every status, the two-segment
// cases at the wrap point, and a randomized differential test against a
// std::deque reference model.
#include <cstring>
#include <deque>
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::Rng;

// A ring over its own storage, with guard bytes on both sides of the storage.
struct Ring {
    static constexpr uint32_t kGuard = 16u;
    static constexpr uint8_t kGuardByte = 0xC3u;
    std::vector<uint8_t> mem;
    mt_bring_t r;

    explicit Ring(uint32_t cap) : mem(cap + 2u * kGuard, kGuardByte)
    {
        EXPECT_EQ(mt_bring_init(&r, mem.data() + kGuard, cap), MT_OK);
    }
    uint8_t *storage()
    {
        return mem.data() + kGuard;
    }
    bool guards_intact() const
    {
        for (uint32_t k = 0; k < kGuard; ++k) {
            if (mem[k] != kGuardByte || mem[mem.size() - 1u - k] != kGuardByte) {
                return false;
            }
        }
        return true;
    }
    uint32_t write(const std::vector<uint8_t> &v)
    {
        return mt_bring_write(&r, v.data(), static_cast<uint32_t>(v.size()));
    }
    std::vector<uint8_t> read(uint32_t n)
    {
        std::vector<uint8_t> out(n + 1u, 0xEEu);
        const uint32_t got = mt_bring_read(&r, out.data(), n);
        out.resize(got);
        return out;
    }
};

std::vector<uint8_t> seq(uint8_t first, uint32_t n)
{
    std::vector<uint8_t> v(n);
    for (uint32_t k = 0; k < n; ++k) {
        v[k] = static_cast<uint8_t>(first + k);
    }
    return v;
}

TEST(ByteRingInit, Statuses)
{
    uint8_t buf[8];
    mt_bring_t r;

    std::memset(&r, 0x5A, sizeof(r));
    EXPECT_EQ(mt_bring_init(&r, buf, 0u), MT_E_INVALID);
    EXPECT_EQ(r.cap, 0u); // left unusable

    std::memset(&r, 0x5A, sizeof(r));
    EXPECT_EQ(mt_bring_init(&r, buf, MT_BRING_CAP_MAX + 1u), MT_E_INVALID);
    EXPECT_EQ(r.cap, 0u);
    EXPECT_EQ(mt_bring_init(&r, buf, 0xFFFFFFFFu), MT_E_INVALID);
    EXPECT_EQ(r.cap, 0u);

    std::memset(&r, 0x5A, sizeof(r));
    ASSERT_EQ(mt_bring_init(&r, buf, 1u), MT_OK);
    EXPECT_EQ(r.cap, 1u);
    EXPECT_EQ(r.buf, buf);
    EXPECT_EQ(r.head, 0u);
    EXPECT_EQ(r.tail, 0u);
    EXPECT_EQ(r.reserved, 0u);
    EXPECT_EQ(mt_bring_available(&r), 0u);
    EXPECT_EQ(mt_bring_space(&r), 1u);

    for (uint32_t cap : {3u, 5u, 7u, 8u}) { // non-powers of two and a power of two
        ASSERT_EQ(mt_bring_init(&r, buf, cap), MT_OK) << cap;
        EXPECT_EQ(r.cap, cap);
        EXPECT_EQ(mt_bring_space(&r), cap);
    }
}

// R-2 regression: ArduPilot's zero-size ByteBuffer divided by zero on the first
// commit/advance/write. Here a zero capacity is refused at init.
TEST(ByteRingInit, R2ZeroCapacityRejectedAtInit)
{
    mt_bring_t r;
    EXPECT_EQ(mt_bring_init(&r, nullptr, 0u), MT_E_INVALID);
    EXPECT_EQ(r.cap, 0u);
}

TEST(ByteRing, CapacityOneHoldsOneByte)
{
    Ring g(1u);
    for (int round = 0; round < 5; ++round) { // crosses the mirror wrap (2*cap) twice
        EXPECT_EQ(g.write(seq(static_cast<uint8_t>(10 * round), 3u)), 1u);
        EXPECT_EQ(mt_bring_space(&g.r), 0u);
        EXPECT_EQ(mt_bring_available(&g.r), 1u);
        EXPECT_EQ(g.write(seq(99u, 1u)), 0u); // full: nothing written
        EXPECT_EQ(g.read(4u), seq(static_cast<uint8_t>(10 * round), 1u));
        EXPECT_EQ(mt_bring_available(&g.r), 0u);
    }
    EXPECT_TRUE(g.guards_intact());
}

TEST(ByteRing, PartialWriteAndRead)
{
    Ring g(5u);
    EXPECT_EQ(g.write(seq(1u, 3u)), 3u);
    EXPECT_EQ(g.write(seq(4u, 4u)), 2u); // only 2 free: partial
    EXPECT_EQ(mt_bring_space(&g.r), 0u);
    EXPECT_EQ(g.read(2u), seq(1u, 2u));
    EXPECT_EQ(g.read(10u), seq(3u, 3u)); // partial read: only 3 left
    EXPECT_EQ(g.read(1u), std::vector<uint8_t>{});
    EXPECT_EQ(mt_bring_write(&g.r, nullptr, 0u), 0u);
    EXPECT_EQ(mt_bring_read(&g.r, nullptr, 0u), 0u);
    EXPECT_TRUE(g.guards_intact());
}

TEST(ByteRing, NeverOverwritesUnreadData)
{
    Ring g(4u);
    EXPECT_EQ(g.write(seq(1u, 4u)), 4u);
    EXPECT_EQ(g.write(seq(50u, 4u)), 0u);
    const std::vector<uint8_t> snapshot(g.storage(), g.storage() + 4);
    EXPECT_EQ(g.write(seq(60u, 1u)), 0u);
    EXPECT_EQ(std::vector<uint8_t>(g.storage(), g.storage() + 4), snapshot);
    EXPECT_EQ(g.read(4u), seq(1u, 4u));
}

TEST(ByteRing, PeekDoesNotConsume)
{
    Ring g(6u);
    EXPECT_EQ(g.write(seq(7u, 4u)), 4u);
    uint8_t out[8] = {};
    EXPECT_EQ(mt_bring_peek(&g.r, out, 2u), 2u);
    EXPECT_EQ(out[0], 7u);
    EXPECT_EQ(out[1], 8u);
    EXPECT_EQ(mt_bring_peek(&g.r, out, 8u), 4u);
    EXPECT_EQ(std::vector<uint8_t>(out, out + 4), seq(7u, 4u));
    EXPECT_EQ(mt_bring_available(&g.r), 4u);
    EXPECT_EQ(g.read(4u), seq(7u, 4u));
    EXPECT_EQ(mt_bring_peek(&g.r, out, 8u), 0u);
}

// Put head and tail at storage slot `at` (empty ring), so the next bytes wrap.
void move_to(Ring &g, uint32_t at)
{
    std::vector<uint8_t> fill(at, 0u);
    ASSERT_EQ(g.write(fill), at);
    ASSERT_EQ(g.read(at).size(), at);
}

TEST(ByteRing, PeekVecSegments)
{
    Ring g(8u);
    mt_iovec_t v[2];

    EXPECT_EQ(mt_bring_peek_vec(&g.r, v), 0u); // empty
    EXPECT_EQ(v[0].len, 0u);
    EXPECT_EQ(v[1].len, 0u);

    EXPECT_EQ(g.write(seq(1u, 5u)), 5u); // one segment from slot 0
    EXPECT_EQ(mt_bring_peek_vec(&g.r, v), 1u);
    EXPECT_EQ(v[0].base, g.storage());
    EXPECT_EQ(v[0].len, 5u);
    EXPECT_EQ(v[1].len, 0u);
    EXPECT_EQ(g.read(5u), seq(1u, 5u));

    // head at slot 5: 3 bytes fit before the end, exactly one segment
    EXPECT_EQ(g.write(seq(20u, 3u)), 3u);
    EXPECT_EQ(mt_bring_peek_vec(&g.r, v), 1u);
    EXPECT_EQ(v[0].base, g.storage() + 5);
    EXPECT_EQ(v[0].len, 3u);
    // a fourth byte goes to slot 0: two segments
    EXPECT_EQ(g.write(seq(23u, 3u)), 3u);
    EXPECT_EQ(mt_bring_peek_vec(&g.r, v), 2u);
    EXPECT_EQ(v[0].base, g.storage() + 5);
    EXPECT_EQ(v[0].len, 3u);
    EXPECT_EQ(v[1].base, g.storage());
    EXPECT_EQ(v[1].len, 3u);
    std::vector<uint8_t> joined(v[0].base, v[0].base + v[0].len);
    joined.insert(joined.end(), v[1].base, v[1].base + v[1].len);
    EXPECT_EQ(joined, seq(20u, 6u));
    // peek_vec does not consume
    EXPECT_EQ(mt_bring_available(&g.r), 6u);
    EXPECT_EQ(mt_bring_advance(&g.r, 3u), MT_OK); // drop the first segment
    EXPECT_EQ(mt_bring_peek_vec(&g.r, v), 1u);
    EXPECT_EQ(v[0].base, g.storage());
    EXPECT_EQ(v[0].len, 3u);
    EXPECT_EQ(g.read(8u), seq(23u, 3u));
}

TEST(ByteRing, PeekVecFullRingAtWrap)
{
    Ring g(7u);
    move_to(g, 4u);
    EXPECT_EQ(g.write(seq(1u, 7u)), 7u); // full, starting at slot 4
    mt_iovec_t v[2];
    EXPECT_EQ(mt_bring_peek_vec(&g.r, v), 2u);
    EXPECT_EQ(v[0].base, g.storage() + 4);
    EXPECT_EQ(v[0].len, 3u);
    EXPECT_EQ(v[1].base, g.storage());
    EXPECT_EQ(v[1].len, 4u);
    EXPECT_EQ(g.read(7u), seq(1u, 7u));
}

TEST(ByteRing, ReserveCommitSegments)
{
    Ring g(8u);
    mt_iovec_t v[2];

    EXPECT_EQ(mt_bring_reserve(&g.r, v, 0u), 0u);
    EXPECT_EQ(g.r.reserved, 0u);

    EXPECT_EQ(mt_bring_reserve(&g.r, v, 5u), 1u);
    EXPECT_EQ(v[0].base, g.storage());
    EXPECT_EQ(v[0].len, 5u);
    EXPECT_EQ(v[1].len, 0u);
    EXPECT_EQ(mt_bring_space(&g.r), 3u);     // reserved bytes are not free
    EXPECT_EQ(mt_bring_available(&g.r), 0u); // nor readable before commit
    std::memcpy(v[0].base, seq(1u, 5u).data(), 5u);
    EXPECT_EQ(mt_bring_commit(&g.r, 5u), MT_OK);
    EXPECT_EQ(g.r.reserved, 0u);
    EXPECT_EQ(g.read(5u), seq(1u, 5u));

    // tail at slot 5: a reservation of 6 is split 3 + 3
    EXPECT_EQ(mt_bring_reserve(&g.r, v, 6u), 2u);
    EXPECT_EQ(v[0].base, g.storage() + 5);
    EXPECT_EQ(v[0].len, 3u);
    EXPECT_EQ(v[1].base, g.storage());
    EXPECT_EQ(v[1].len, 3u);
    std::memcpy(v[0].base, seq(30u, 3u).data(), 3u);
    std::memcpy(v[1].base, seq(33u, 3u).data(), 3u);
    EXPECT_EQ(mt_bring_commit(&g.r, 6u), MT_OK);
    EXPECT_EQ(g.read(6u), seq(30u, 6u));

    // more than free: the reservation is cut to the free space
    EXPECT_EQ(g.write(seq(0u, 5u)), 5u);
    EXPECT_EQ(mt_bring_reserve(&g.r, v, 100u), 1u);
    EXPECT_EQ(g.r.reserved, 3u);
    EXPECT_EQ(v[0].len, 3u);
    EXPECT_EQ(mt_bring_space(&g.r), 0u);
    EXPECT_EQ(mt_bring_commit(&g.r, 0u), MT_OK); // commit nothing: releases the reservation
    EXPECT_EQ(g.r.reserved, 0u);
    EXPECT_EQ(mt_bring_space(&g.r), 3u);
    EXPECT_EQ(mt_bring_available(&g.r), 5u);

    // full ring: no segment
    EXPECT_EQ(g.write(seq(0u, 3u)), 3u);
    EXPECT_EQ(mt_bring_reserve(&g.r, v, 4u), 0u);
    EXPECT_EQ(g.r.reserved, 0u);
    EXPECT_TRUE(g.guards_intact());
}

TEST(ByteRing, PartialCommitPublishesOnlyCommittedBytes)
{
    Ring g(8u);
    mt_iovec_t v[2];
    ASSERT_EQ(mt_bring_reserve(&g.r, v, 6u), 1u);
    std::memcpy(v[0].base, seq(1u, 6u).data(), 6u);
    EXPECT_EQ(mt_bring_commit(&g.r, 4u), MT_OK);
    EXPECT_EQ(g.r.reserved, 0u);
    EXPECT_EQ(mt_bring_available(&g.r), 4u);
    EXPECT_EQ(g.read(8u), seq(1u, 4u));
}

TEST(ByteRing, CommitBeyondReservationIsRange)
{
    Ring g(8u);
    mt_iovec_t v[2];
    EXPECT_EQ(mt_bring_commit(&g.r, 1u), MT_E_RANGE); // nothing reserved
    EXPECT_EQ(mt_bring_available(&g.r), 0u);

    ASSERT_EQ(mt_bring_reserve(&g.r, v, 3u), 1u);
    const uint32_t tail = g.r.tail;
    EXPECT_EQ(mt_bring_commit(&g.r, 4u), MT_E_RANGE);
    EXPECT_EQ(g.r.tail, tail);   // nothing published
    EXPECT_EQ(g.r.reserved, 3u); // reservation kept
    EXPECT_EQ(mt_bring_available(&g.r), 0u);
    EXPECT_EQ(mt_bring_commit(&g.r, 3u), MT_OK);
    EXPECT_EQ(mt_bring_available(&g.r), 3u);
}

TEST(ByteRing, AdvanceBeyondAvailableIsRange)
{
    Ring g(8u);
    EXPECT_EQ(mt_bring_advance(&g.r, 1u), MT_E_RANGE); // empty
    EXPECT_EQ(mt_bring_advance(&g.r, 0u), MT_OK);
    EXPECT_EQ(g.write(seq(1u, 5u)), 5u);
    const uint32_t head = g.r.head;
    EXPECT_EQ(mt_bring_advance(&g.r, 6u), MT_E_RANGE);
    EXPECT_EQ(g.r.head, head); // nothing dropped
    EXPECT_EQ(mt_bring_available(&g.r), 5u);
    EXPECT_EQ(mt_bring_advance(&g.r, 2u), MT_OK);
    EXPECT_EQ(g.read(8u), seq(3u, 3u));
    EXPECT_EQ(mt_bring_advance(&g.r, 0xFFFFFFFFu), MT_E_RANGE);
}

TEST(ByteRing, FlushDropsEverythingReadable)
{
    Ring g(5u);
    EXPECT_EQ(mt_bring_flush(&g.r), 0u);
    move_to(g, 3u);
    EXPECT_EQ(g.write(seq(1u, 4u)), 4u);
    const uint32_t tail = g.r.tail;
    EXPECT_EQ(mt_bring_flush(&g.r), 4u);
    EXPECT_EQ(g.r.tail, tail); // the consumer never writes the producer's index
    EXPECT_EQ(mt_bring_available(&g.r), 0u);
    EXPECT_EQ(mt_bring_space(&g.r), 5u);
    EXPECT_EQ(g.write(seq(40u, 5u)), 5u);
    EXPECT_EQ(g.read(5u), seq(40u, 5u));
}

TEST(ByteRing, ConsumerNeverWritesProducerHalfAndViceVersa)
{
    Ring g(6u);
    mt_iovec_t v[2];
    uint8_t out[8];
    ASSERT_EQ(g.write(seq(1u, 4u)), 4u);
    const uint32_t tail = g.r.tail;
    const uint32_t head_cache = g.r.head_cache;
    (void)mt_bring_peek(&g.r, out, 2u);
    (void)mt_bring_read(&g.r, out, 1u);
    (void)mt_bring_peek_vec(&g.r, v);
    (void)mt_bring_advance(&g.r, 1u);
    (void)mt_bring_available(&g.r);
    (void)mt_bring_flush(&g.r);
    EXPECT_EQ(g.r.tail, tail);
    EXPECT_EQ(g.r.head_cache, head_cache);
    EXPECT_EQ(g.r.reserved, 0u);

    const uint32_t head = g.r.head;
    const uint32_t tail_cache = g.r.tail_cache;
    ASSERT_EQ(g.write(seq(1u, 2u)), 2u);
    ASSERT_EQ(mt_bring_reserve(&g.r, v, 2u), 1u);
    ASSERT_EQ(mt_bring_commit(&g.r, 2u), MT_OK);
    (void)mt_bring_space(&g.r);
    EXPECT_EQ(g.r.head, head);
    EXPECT_EQ(g.r.tail_cache, tail_cache);
}

// ---- randomized differential test ------------------------------------------

void differential(uint32_t cap, uint64_t seed, uint32_t ops)
{
    Ring g(cap);
    std::deque<uint8_t> model;
    Rng rng(seed);
    uint8_t next = 0u;
    uint32_t head_wraps = 0u;
    uint32_t tail_wraps = 0u;
    std::vector<uint8_t> buf(cap + 8u);

    auto expect_front = [&](const uint8_t *p, uint32_t n) {
        for (uint32_t k = 0; k < n; ++k) {
            ASSERT_EQ(p[k], model[k]) << "cap " << cap << " byte " << k;
        }
    };

    for (uint32_t op = 0; op < ops; ++op) {
        const uint32_t head0 = g.r.head;
        const uint32_t tail0 = g.r.tail;
        const uint32_t count = static_cast<uint32_t>(model.size());
        const uint32_t len = rng.below(cap + 3u);
        switch (rng.below(10u)) {
        case 0:
        case 1: { // write
            std::vector<uint8_t> src(len);
            for (auto &b : src) {
                b = next++;
            }
            const uint32_t n = mt_bring_write(&g.r, src.data(), len);
            ASSERT_EQ(n, std::min(len, cap - count));
            model.insert(model.end(), src.begin(), src.begin() + n);
            next = static_cast<uint8_t>(next - (len - n));
            break;
        }
        case 2: { // reserve + commit (sometimes too much first)
            mt_iovec_t v[2];
            const uint32_t segs = mt_bring_reserve(&g.r, v, len);
            const uint32_t want = std::min(len, cap - count);
            ASSERT_EQ(g.r.reserved, want);
            ASSERT_EQ(segs, want == 0u ? 0u : (v[1].len > 0u ? 2u : 1u));
            ASSERT_EQ(v[0].len + v[1].len, want);
            if (segs >= 1u) {
                ASSERT_EQ(v[0].base, g.storage() + (g.r.tail % cap));
            }
            if (segs == 2u) {
                ASSERT_EQ(v[1].base, g.storage());
                ASSERT_EQ(g.r.tail % cap + v[0].len, cap); // the first segment ends at the end
            }
            ASSERT_EQ(mt_bring_space(&g.r), cap - count - want);
            const uint32_t commit = (want == 0u) ? 0u : rng.below(want + 1u);
            uint32_t k = 0;
            for (uint32_t s = 0; s < 2u; ++s) {
                for (uint32_t j = 0; j < v[s].len; ++j, ++k) {
                    v[s].base[j] = static_cast<uint8_t>(next + k);
                }
            }
            if (rng.below(3u) == 0u) {
                ASSERT_EQ(mt_bring_commit(&g.r, want + 1u), MT_E_RANGE);
                ASSERT_EQ(g.r.tail, tail0);
                ASSERT_EQ(g.r.reserved, want);
            }
            ASSERT_EQ(mt_bring_commit(&g.r, commit), MT_OK);
            ASSERT_EQ(g.r.reserved, 0u);
            for (uint32_t j = 0; j < commit; ++j) {
                model.push_back(next++);
            }
            break;
        }
        case 3:
        case 4: { // read
            const uint32_t n = mt_bring_read(&g.r, buf.data(), std::min(len, cap + 8u));
            ASSERT_EQ(n, std::min(std::min(len, cap + 8u), count));
            expect_front(buf.data(), n);
            model.erase(model.begin(), model.begin() + n);
            break;
        }
        case 5: { // peek
            const uint32_t n = mt_bring_peek(&g.r, buf.data(), std::min(len, cap + 8u));
            ASSERT_EQ(n, std::min(std::min(len, cap + 8u), count));
            expect_front(buf.data(), n);
            ASSERT_EQ(g.r.head, head0);
            break;
        }
        case 6: { // peek_vec + advance
            mt_iovec_t v[2];
            const uint32_t segs = mt_bring_peek_vec(&g.r, v);
            ASSERT_EQ(v[0].len + v[1].len, count);
            ASSERT_EQ(segs, count == 0u ? 0u : (v[1].len > 0u ? 2u : 1u));
            if (segs >= 1u) {
                ASSERT_EQ(v[0].base, g.storage() + (head0 % cap));
                expect_front(v[0].base, v[0].len);
            }
            if (segs == 2u) {
                ASSERT_EQ(v[1].base, g.storage());
                for (uint32_t j = 0; j < v[1].len; ++j) {
                    ASSERT_EQ(v[1].base[j], model[v[0].len + j]);
                }
            }
            const uint32_t n = rng.below(count + 2u);
            if (n > count) {
                ASSERT_EQ(mt_bring_advance(&g.r, n), MT_E_RANGE);
                ASSERT_EQ(g.r.head, head0);
            } else {
                ASSERT_EQ(mt_bring_advance(&g.r, n), MT_OK);
                model.erase(model.begin(), model.begin() + n);
            }
            break;
        }
        case 7: { // available / space
            ASSERT_EQ(mt_bring_available(&g.r), count);
            ASSERT_EQ(mt_bring_space(&g.r), cap - count);
            break;
        }
        case 8: { // flush (rarely, so the ring also runs full)
            if (rng.below(8u) == 0u) {
                ASSERT_EQ(mt_bring_flush(&g.r), count);
                model.clear();
            }
            break;
        }
        default: { // fill to the brim, then check full behaviour
            std::vector<uint8_t> src(cap);
            for (auto &b : src) {
                b = next++;
            }
            const uint32_t n = mt_bring_write(&g.r, src.data(), cap);
            ASSERT_EQ(n, cap - count);
            model.insert(model.end(), src.begin(), src.begin() + n);
            next = static_cast<uint8_t>(next - (cap - n));
            ASSERT_EQ(mt_bring_space(&g.r), 0u);
            uint8_t extra = 0xABu;
            ASSERT_EQ(mt_bring_write(&g.r, &extra, 1u), 0u);
            break;
        }
        }
        if (::testing::Test::HasFatalFailure()) {
            return;
        }
        // invariants of the mirror indices, and the C twin of MtBRingInv agrees
        ASSERT_TRUE(mt_bring_valid(&g.r));
        ASSERT_LT(g.r.head, 2u * cap);
        ASSERT_LT(g.r.tail, 2u * cap);
        ASSERT_EQ((g.r.tail + 2u * cap - g.r.head) % (2u * cap), model.size());
        head_wraps += (g.r.head < head0) ? 1u : 0u;
        tail_wraps += (g.r.tail < tail0) ? 1u : 0u;
    }
    EXPECT_TRUE(g.guards_intact()) << "cap " << cap;
    EXPECT_GE(head_wraps, 3u) << "cap " << cap;
    EXPECT_GE(tail_wraps, 3u) << "cap " << cap;
}

// mt_bring_valid is the C twin of MtBRingInv (equivalence proved by WP and CBMC): each broken
// relation of the invariant is reported, and a fresh ring is valid.
TEST(ByteRingValid, EachBrokenRelationIsReported)
{
    uint8_t storage[8];
    mt_bring_t r;
    ASSERT_EQ(mt_bring_init(&r, storage, 8u), MT_OK);
    EXPECT_TRUE(mt_bring_valid(&r));
    const mt_bring_t good = r;
    r.cap = 0u;
    EXPECT_FALSE(mt_bring_valid(&r)) << "capacity 0";
    r = good;
    r.cap = MT_BRING_CAP_MAX + 1u;
    EXPECT_FALSE(mt_bring_valid(&r)) << "capacity above the maximum";
    r = good;
    r.tail = 16u;
    EXPECT_FALSE(mt_bring_valid(&r)) << "tail outside [0, 2 cap)";
    r = good;
    r.head_cache = 16u;
    EXPECT_FALSE(mt_bring_valid(&r)) << "head cache outside [0, 2 cap)";
    r = good;
    r.tail = 3u;
    r.head = 12u; // 7 readable bytes (mirror indices), 1 free
    r.head_cache = 12u;
    r.tail_cache = 3u;
    EXPECT_TRUE(mt_bring_valid(&r));
    r.reserved = 2u; // only 1 byte free
    EXPECT_FALSE(mt_bring_valid(&r)) << "reservation larger than the free space";
    r = good;
    r.tail = 5u;
    r.head_cache = 6u; // cached head ahead of the tail: the producer would see 15 bytes
    EXPECT_FALSE(mt_bring_valid(&r)) << "producer's cached head ahead of the data";
}

TEST(ByteRingDifferential, Capacities1To17)
{
    for (uint32_t cap = 1u; cap <= 17u; ++cap) {
        differential(cap, 1000u + cap, 20000u);
        if (HasFatalFailure()) {
            return;
        }
    }
}

TEST(ByteRingDifferential, LargerNonPowerOfTwo)
{
    differential(1000u, 77u, 20000u);
}

} // namespace
