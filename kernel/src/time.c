/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file time.c
 * @brief Hardware-counter extension and tick conversion (see mt/time.h).
 */
#include "mt/time.h"

#include "mt_arith.h"
#include "mt_spec_arith.h"

mt_status_t mt_time_ext_init(mt_time_ext_t *t, uint32_t hw_max, uint32_t hw_now)
{
    t->ticks = 0u;
    t->last_hw = 0u;
    t->hw_max = 1u;
    if ((hw_max < 1u) || (hw_now > hw_max)) {
        return MT_E_INVALID;
    }
    t->last_hw = hw_now;
    t->hw_max = hw_max;
    return MT_OK;
}

uint64_t mt_time_extend(mt_time_ext_t *t, uint32_t hw_now)
{
    uint64_t delta;

    /* The one wrap-around in Metronome: a reading below the last one means the
     * counter passed hw_max once; computed in 64 bits without any C wrap. */
    if (hw_now >= t->last_hw) {
        delta = (uint64_t)hw_now - (uint64_t)t->last_hw;
    } else {
        delta = (((uint64_t)t->hw_max - (uint64_t)t->last_hw) + (uint64_t)hw_now) + 1u;
    }
    t->ticks = (t->ticks <= (UINT64_MAX - delta)) ? (t->ticks + delta) : UINT64_MAX;
    t->last_hw = hw_now;
    return t->ticks;
}

uint64_t mt_time_ticks_to_us(uint64_t ticks, uint32_t hz)
{
    uint64_t whole = mt_udiv_u64(ticks, hz);
    /* < 10^6, and no overflow: (hz - 1) * 10^6 < 2^52 */
    uint64_t part = mt_udiv_u64(mt_umul_u64(mt_umod_u64(ticks, hz), 1000000u), hz);

    /* floor(ticks * 1e6 / hz) == whole * 1e6 + part, by uniqueness of the quotient */
    //@ assert split: ticks == whole * hz + ticks % hz && 0 <= ticks % hz < hz;
    //@ assert part_lo: part * hz <= (ticks % hz) * 1000000;
    //@ assert part_hi: (ticks % hz) * 1000000 < (part + 1) * hz;
    //@ assert q_lo: (whole * 1000000 + part) * hz <= ticks * 1000000;
    //@ assert q_hi: ticks * 1000000 < (whole * 1000000 + part + 1) * hz;
    //@ assert quot: (ticks * 1000000) / hz == whole * 1000000 + part;

    /* saturate when whole * 10^6 + part > UINT64_MAX: first whole * 10^6 alone, then the sum */
    if (whole > (UINT64_MAX / 1000000u)) {
        return UINT64_MAX;
    }
    whole = mt_umul_u64(whole, 1000000u);
    if (part > (UINT64_MAX - whole)) {
        return UINT64_MAX;
    }
    return whole + part;
}

bool mt_time_ext_valid(const mt_time_ext_t *t)
{
    return (t->hw_max >= 1u) && (t->last_hw <= t->hw_max);
}
