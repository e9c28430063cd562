// SPDX-License-Identifier: Apache-2.0
// Hardware-counter extension and tick conversion (mt/time.h): the port's only
// wrap-around handling, checked against a 64-bit reference count and 128-bit
// arithmetic.
#include <vector>

#include "mt_test_util.h"

namespace
{

using mt_test::Rng;
using u128 = unsigned __int128;

TEST(TimeExtInit, Statuses)
{
    mt_time_ext_t t;
    EXPECT_EQ(mt_time_ext_init(&t, 0u, 0u), MT_E_INVALID);      // hw_max 0
    EXPECT_EQ(mt_time_ext_init(&t, 999u, 1000u), MT_E_INVALID); // now > max
    EXPECT_EQ(mt_time_ext_init(&t, 0xFFFFu, 0x10000u), MT_E_INVALID);
    EXPECT_EQ(mt_time_ext_init(&t, 0u, 5u), MT_E_INVALID);

    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFu, 0x1234u), MT_OK);
    EXPECT_EQ(t.ticks, 0u);
    EXPECT_EQ(t.last_hw, 0x1234u);
    EXPECT_EQ(t.hw_max, 0xFFFFu);

    ASSERT_EQ(mt_time_ext_init(&t, 1u, 1u), MT_OK); // smallest counter, at its max
    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFFFFFu, 0xFFFFFFFFu), MT_OK);
    EXPECT_EQ(t.last_hw, 0xFFFFFFFFu);
}

// mt_time_ext_valid is the C twin of MtTimeExtInv (equivalence proved by WP and CBMC).
TEST(TimeExtValid, MaximumAndLastReading)
{
    mt_time_ext_t t;
    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFu, 0xFFFFu), MT_OK);
    EXPECT_TRUE(mt_time_ext_valid(&t));
    t.last_hw = 0x10000u;
    EXPECT_FALSE(mt_time_ext_valid(&t)) << "last reading above the maximum";
    t.hw_max = 0u;
    t.last_hw = 0u;
    EXPECT_FALSE(mt_time_ext_valid(&t)) << "maximum 0";
}

TEST(TimeExtend, NoWrap)
{
    mt_time_ext_t t;
    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFu, 100u), MT_OK);
    EXPECT_EQ(mt_time_extend(&t, 100u), 0u); // no progress
    EXPECT_EQ(mt_time_extend(&t, 150u), 50u);
    EXPECT_EQ(mt_time_extend(&t, 0xFFFFu), 0xFFFFu - 100u);
    EXPECT_EQ(t.last_hw, 0xFFFFu);
}

TEST(TimeExtend, SingleWrap16And32Bit)
{
    mt_time_ext_t t;
    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFu, 0xFFF0u), MT_OK);
    EXPECT_EQ(mt_time_extend(&t, 0x0010u), 0x20u); // 0xFFF0 -> 0xFFFF -> 0 -> 0x10
    EXPECT_EQ(mt_time_extend(&t, 0x000Fu),
              0x20u + 0xFFFFu); // a reading just below: almost a full period

    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFFFFFu, 0xFFFFFFFEu), MT_OK);
    EXPECT_EQ(mt_time_extend(&t, 1u), 3u);
    EXPECT_EQ(mt_time_extend(&t, 0u), 3u + 0xFFFFFFFFull); // full period minus one tick
    EXPECT_EQ(mt_time_extend(&t, 0xFFFFFFFFu), 3u + 0xFFFFFFFFull + 0xFFFFFFFFull);
    EXPECT_EQ(mt_time_extend(&t, 0u), 3u + 2u * 0xFFFFFFFFull + 1u);

    ASSERT_EQ(mt_time_ext_init(&t, 999u, 998u), MT_OK); // odd maximum (0..999)
    EXPECT_EQ(mt_time_extend(&t, 999u), 1u);
    EXPECT_EQ(mt_time_extend(&t, 0u), 2u);
    EXPECT_EQ(mt_time_extend(&t, 998u), 1000u);
}

// Drive a simulated counter of period hw_max + 1 forward in random steps of less
// than one period (the port's calling rule) and compare with the true count.
void many_wraps(uint32_t hw_max, uint32_t start, uint64_t seed, uint32_t steps, uint64_t min_wraps)
{
    mt_time_ext_t t;
    const uint64_t period = static_cast<uint64_t>(hw_max) + 1u;
    Rng rng(seed);
    uint64_t truth = 0u;
    uint64_t wraps = 0u;
    uint32_t hw = start;

    ASSERT_EQ(mt_time_ext_init(&t, hw_max, start), MT_OK);
    for (uint32_t k = 0; k < steps; ++k) {
        uint64_t step;
        switch (rng.below(4u)) {
        case 0: step = 0u; break;
        case 1: step = period - 1u; break; // the longest legal step
        case 2: step = rng.next() % period; break;
        default: step = rng.next() % (period / 16u + 1u); break;
        }
        const uint64_t pos = static_cast<uint64_t>(hw) + step;
        if (pos > hw_max) {
            ++wraps;
        }
        hw = static_cast<uint32_t>(pos % period);
        truth += step;
        const uint64_t got = mt_time_extend(&t, hw);
        ASSERT_EQ(got, truth) << "hw_max " << hw_max << " step " << k;
        ASSERT_EQ(t.ticks, truth);
        ASSERT_EQ(t.last_hw, hw);
    }
    EXPECT_GE(wraps, min_wraps) << "the run must cross the wrap point many times";
}

TEST(TimeExtend, ManyWraps16Bit)
{
    many_wraps(0xFFFFu, 0u, 1u, 20000u, 1000u);
}
TEST(TimeExtend, ManyWraps32Bit)
{
    many_wraps(0xFFFFFFFFu, 0xFFFFFF00u, 2u, 20000u, 1000u);
}
TEST(TimeExtend, ManyWrapsOddMax999)
{
    many_wraps(999u, 500u, 3u, 20000u, 1000u);
}
TEST(TimeExtend, ManyWrapsTinyCounters)
{
    many_wraps(1u, 0u, 4u, 5000u, 500u);
    many_wraps(2u, 2u, 5u, 5000u, 500u);
    many_wraps(0x7FFFu, 0x7FFFu, 6u, 5000u, 500u);
}

TEST(TimeExtend, SaturatesAtUint64Max)
{
    mt_time_ext_t t;
    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFu, 0u), MT_OK);
    t.ticks = UINT64_MAX - 10u;
    EXPECT_EQ(mt_time_extend(&t, 10u), UINT64_MAX); // lands exactly on the maximum
    EXPECT_EQ(mt_time_extend(&t, 10u), UINT64_MAX);
    EXPECT_EQ(mt_time_extend(&t, 0xFFFFu), UINT64_MAX); // would pass it: saturates
    EXPECT_EQ(mt_time_extend(&t, 3u), UINT64_MAX);      // and a wrap on top of that
    EXPECT_EQ(t.last_hw, 3u);

    ASSERT_EQ(mt_time_ext_init(&t, 0xFFFFFFFFu, 0xFFFFFFF0u), MT_OK);
    t.ticks = UINT64_MAX - 0x1Fu;
    EXPECT_EQ(mt_time_extend(&t, 0x0Fu), UINT64_MAX - 0x1Fu + 0x1Fu); // exact: 0x1F ticks
    t.ticks = UINT64_MAX - 0x1Eu;
    t.last_hw = 0xFFFFFFF0u;
    EXPECT_EQ(mt_time_extend(&t, 0x0Fu), UINT64_MAX); // one tick too many: saturated
}

uint64_t ref_ticks_to_us(uint64_t ticks, uint32_t hz)
{
    const u128 us = (static_cast<u128>(ticks) * 1000000u) / hz;
    return (us > UINT64_MAX) ? UINT64_MAX : static_cast<uint64_t>(us);
}

TEST(TimeTicksToUs, ExactAgainst128BitArithmetic)
{
    const uint32_t rates[] = {1u,         2u,          3u,         7u,       999u,
                              1000u,      32768u,      1000000u,   1000001u, 8000000u,
                              168000000u, 0x7FFFFFFFu, 0xFFFFFFFFu};
    const uint64_t ticks[] = {0u,
                              1u,
                              2u,
                              999u,
                              1000u,
                              1000001u,
                              0xFFFFFFFFull,
                              0x100000000ull,
                              18446744073709ull,
                              18446744073709551ull,
                              18446744073709552ull,
                              UINT64_MAX / 1000000u,
                              UINT64_MAX / 1000000u + 1u,
                              UINT64_MAX - 1u,
                              UINT64_MAX};
    for (uint32_t hz : rates) {
        for (uint64_t tk : ticks) {
            EXPECT_EQ(mt_time_ticks_to_us(tk, hz), ref_ticks_to_us(tk, hz))
                << "ticks " << tk << " hz " << hz;
        }
    }
    Rng rng(42u);
    for (int k = 0; k < 200000; ++k) {
        const uint32_t hz = static_cast<uint32_t>(rng.next() >> (32u + rng.below(32u))) | 1u;
        const uint64_t tk = rng.next() >> rng.below(64u);
        ASSERT_EQ(mt_time_ticks_to_us(tk, hz), ref_ticks_to_us(tk, hz))
            << "ticks " << tk << " hz " << hz;
    }
}

TEST(TimeTicksToUs, RoundsDownAndSaturates)
{
    EXPECT_EQ(mt_time_ticks_to_us(1u, 3u), 333333u); // 333333.33 rounded down
    EXPECT_EQ(mt_time_ticks_to_us(2u, 3u), 666666u);
    EXPECT_EQ(mt_time_ticks_to_us(1000u, 1000u), 1000000u);
    EXPECT_EQ(mt_time_ticks_to_us(1u, 1000000u), 1u);
    EXPECT_EQ(mt_time_ticks_to_us(999999u, 1000000u), 999999u);
    EXPECT_EQ(mt_time_ticks_to_us(1u, 2000000u), 0u);
    // at 1 MHz the conversion is the identity, up to UINT64_MAX
    EXPECT_EQ(mt_time_ticks_to_us(UINT64_MAX, 1000000u), UINT64_MAX);
    // at 1 Hz anything above UINT64_MAX / 1e6 saturates
    const uint64_t edge = UINT64_MAX / 1000000u;
    EXPECT_EQ(mt_time_ticks_to_us(edge, 1u), edge * 1000000u);
    EXPECT_EQ(mt_time_ticks_to_us(edge + 1u, 1u), UINT64_MAX);
    EXPECT_EQ(mt_time_ticks_to_us(UINT64_MAX, 1u), UINT64_MAX);
    EXPECT_EQ(mt_time_ticks_to_us(UINT64_MAX, 999999u), UINT64_MAX);
    // just below 1 MHz the result exceeds the tick count but may still fit
    EXPECT_EQ(mt_time_ticks_to_us(UINT64_MAX / 2u, 999999u),
              ref_ticks_to_us(UINT64_MAX / 2u, 999999u));
}

} // namespace
