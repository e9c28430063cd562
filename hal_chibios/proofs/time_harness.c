/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file time_harness.c
 * @brief CBMC harnesses for the ChibiOS port's time arithmetic
 *        (port/mt_chibios_time.c) together with the kernel's time extension
 *        (kernel/src/time.c), at the counters' maximum values.
 *
 * One entry point per property (cbmc --function NAME); the assertion
 * messages carry the same labels as the ACSL clauses in mt_chibios_time.h.
 * Run by hal_chibios/proofs/run_cbmc.sh.
 */
#include <stdint.h>

#include "mt/time.h"
#include "mt_chibios_time.h"

uint64_t nondet_u64(void);
uint32_t nondet_u32(void);

#define U64_MAX_ 0xFFFFFFFFFFFFFFFFull

/* A wait of n ticks (n <= one counter period) across a counter wrap: the
 * counter reading after the wait is the port's counter_shift of the reading
 * before it; the extension then advances by exactly n. Counter widths: the
 * RT system time's 16 and 32 bits, and any other. */
void harness_wrap(void)
{
    mt_time_ext_t t;
    uint32_t hw_max = nondet_u32();
    uint32_t before = nondet_u32();
    uint32_t n = nondet_u32();
    uint64_t start = nondet_u64();
    uint64_t now;
    uint32_t after;

    __CPROVER_assume(hw_max >= 1u);
    __CPROVER_assume(before <= hw_max && n <= hw_max);
    __CPROVER_assume(start <= U64_MAX_ - 0xFFFFFFFFull);
    __CPROVER_assert(mt_time_ext_init(&t, hw_max, before) == MT_OK, "init_ok");
    t.ticks = start;

    after = mt_chibios_counter_shift(before, n, hw_max);
    __CPROVER_assert(after <= hw_max, "in_range");
    __CPROVER_assert((uint64_t)after == ((uint64_t)before + n) % ((uint64_t)hw_max + 1u),
                     "wrapped");
    now = mt_time_extend(&t, after);
    __CPROVER_assert(now == start + n, "wait_across_wrap_exact");
}

/* Same at the exact maxima: 16- and 32-bit counters, reading hw_max, a
 * wait of a whole counter period minus one, and a 1-tick wait over the edge. */
void harness_wrap_maxima(void)
{
    mt_time_ext_t t;
    uint32_t hw_max = (nondet_u32() & 1u) ? 0xFFFFu : 0xFFFFFFFFu;
    uint32_t n = (nondet_u32() & 1u) ? 1u : hw_max;

    __CPROVER_assert(mt_time_ext_init(&t, hw_max, hw_max) == MT_OK, "init_ok");
    __CPROVER_assert(mt_chibios_counter_shift(hw_max, 1u, hw_max) == 0u, "edge_to_zero");
    __CPROVER_assert(mt_time_extend(&t, mt_chibios_counter_shift(hw_max, n, hw_max)) == n,
                     "wait_across_wrap_exact");
    /* The extension saturates instead of wrapping. */
    t.ticks = U64_MAX_ - 1u;
    __CPROVER_assert(mt_time_extend(&t, mt_chibios_counter_shift(t.last_hw, n, hw_max)) == U64_MAX_,
                     "saturated");
}

/* Extreme values for the arithmetic harnesses. Their properties (exact
 * rounding, no early wake-up, monotonic sub-tick time) are nonlinear: WP
 * proves them for every input (mt_chibios_time.h); a SAT solver does not
 * finish them over free 64-bit values here, so CBMC checks them at the
 * maxima and around every saturation and rounding boundary. */
static const uint64_t US[] = {0u,
                              1u,
                              999u,
                              1000u,
                              1001u,
                              999999u,
                              1000000u,
                              1000001u,
                              0x10C6F7A0B5EDull, /* ~2^64 / 1e6 */
                              0x7FFFFFFFFFFFFFFFull,
                              0x8000000000000000ull,
                              0x4189374BC6A7EFull, /* ~2^64 / 1000 */
                              0x4189374BC6A7F0ull,
                              U64_MAX_ / 1000000u,
                              (U64_MAX_ / 1000000u) + 1u,
                              U64_MAX_ - 1000000u,
                              U64_MAX_ - 1u,
                              U64_MAX_};
static const uint32_t HZ[] = {1u, 1000u, 1024u, 32768u, 1000000u, 0xFFFFFFFFu};
#define N_US (sizeof(US) / sizeof(US[0]))
#define N_HZ (sizeof(HZ) / sizeof(HZ[0]))

/* us -> ticks rounded up: exact or saturated, against 128-bit arithmetic;
 * a wake-up on that tick is not early by the kernel's own conversion. */
void harness_ticks_ceil(void)
{
    uint32_t i;
    uint32_t j;

    for (i = 0u; i < N_US; i++) {
        for (j = 0u; j < N_HZ; j++) {
            uint64_t us = US[i];
            uint32_t hz = HZ[j];
            uint64_t ticks = mt_chibios_us_to_ticks_ceil(us, hz);
            unsigned __int128 ref = ((unsigned __int128)us * hz + 999999u) / 1000000u;

            if (ref <= U64_MAX_) {
                __CPROVER_assert(ticks == (uint64_t)ref, "exact");
                __CPROVER_assert(mt_time_ticks_to_us(ticks, hz) >= us, "not_early");
            } else {
                __CPROVER_assert(ticks == U64_MAX_, "saturated");
            }
        }
    }
}

/* Sub-tick time never passes the next tick edge, so the port's time is
 * monotonic across the edge, including where the conversion saturates. */
void harness_subtick_monotonic(void)
{
    static const uint32_t RELOAD[] = {0u, 24999u, 167999u, 0xFFFFFFu};
    uint32_t i;
    uint32_t j;
    uint32_t r;

    for (i = 0u; i < N_US; i++) {
        for (j = 1u; j < 4u; j++) { /* rates up to 1 MHz */
            for (r = 0u; r < 4u; r++) {
                uint64_t k = (US[i] == U64_MAX_) ? (U64_MAX_ - 1u) : US[i];
                uint32_t hz = HZ[j];
                uint32_t reload = RELOAD[r];
                uint32_t sub = mt_chibios_subtick_us(reload, reload + 1u, 1000000u / hz);

                __CPROVER_assert(sub < 1000000u / hz, "below_tick");
                __CPROVER_assert(mt_chibios_time_add(mt_time_ticks_to_us(k, hz), sub) <=
                                     mt_time_ticks_to_us(k + 1u, hz),
                                 "monotonic_across_edge");
            }
        }
    }
}

/* Timeout deadlines and wait chunks at the top of the tick range. */
void harness_deadline_chunks(void)
{
    uint64_t now = nondet_u64();
    uint64_t timeout = nondet_u64();
    uint64_t chunk_max = (nondet_u32() & 1u) ? 0xFFFEull : 0xFFFFFFFEull;
    uint64_t target;
    uint64_t n;

    __CPROVER_assume(timeout >= 1u);
    target = mt_chibios_timeout_deadline(now, timeout, 1000u);
    __CPROVER_assert(target > now || now == U64_MAX_, "after");
    n = mt_chibios_wait_chunk(target, now, chunk_max);
    __CPROVER_assert(n <= chunk_max, "chunk");
    __CPROVER_assert((n == 0u) == (target <= now), "reached");
    __CPROVER_assert(n == 0u || now + n <= target, "never_past_target");
}
