/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_chibios_time.c
 * @brief Time arithmetic of the ChibiOS port (see mt_chibios_time.h).
 */
#include "mt_chibios_time.h"

#define US_PER_S 1000000u

uint64_t mt_chibios_us_to_ticks_ceil(uint64_t us, uint32_t hz)
{
    /* us = whole * 1e6 + rest: us * hz never has to be formed in 64 bits. */
    uint64_t whole = us / US_PER_S;
    uint64_t rest = us % US_PER_S;
    /* rest * hz < 1e6 * 2^32 < 2^52: no overflow. */
    uint64_t part = ((rest * hz) + (US_PER_S - 1u)) / US_PER_S;

    /*@ assert split: us * hz + 999999 == (whole * hz) * 1000000 + (rest * hz + 999999); */
    /*@ assert ceil: MtCeilTicks(us, hz) == whole * hz + part; */
    if (whole > ((UINT64_MAX - part) / hz)) {
        return UINT64_MAX;
    }
    return (whole * hz) + part;
}

uint64_t mt_chibios_timeout_deadline(uint64_t now, uint64_t timeout_us, uint32_t hz)
{
    uint64_t ticks = mt_chibios_us_to_ticks_ceil(timeout_us, hz);

    if ((ticks == UINT64_MAX) || (now >= (UINT64_MAX - ticks - 1u))) {
        return UINT64_MAX;
    }
    return now + ticks + 1u;
}

uint64_t mt_chibios_wait_chunk(uint64_t target, uint64_t now, uint64_t max_chunk)
{
    uint64_t left;

    if (target <= now) {
        return 0u;
    }
    left = target - now;
    return (left > max_chunk) ? max_chunk : left;
}

uint32_t mt_chibios_counter_shift(uint32_t raw, uint32_t offset, uint32_t hw_max)
{
    /* Room above raw before the counter wraps: hw_max - raw (no C wrap). */
    if (offset <= (hw_max - raw)) {
        return raw + offset;
    }
    return offset - (hw_max - raw) - 1u;
}

uint32_t mt_chibios_subtick_us(uint32_t elapsed, uint32_t counts_per_tick, uint32_t tick_us)
{
    /* elapsed < counts_per_tick, so the quotient is below tick_us. */
    return (uint32_t)(((uint64_t)elapsed * tick_us) / counts_per_tick);
}

uint64_t mt_chibios_time_add(uint64_t edge_us, uint32_t sub_us)
{
    const uint64_t sub = (uint64_t)sub_us;

    if (edge_us > (UINT64_MAX - sub)) {
        return UINT64_MAX;
    }
    return edge_us + sub;
}
