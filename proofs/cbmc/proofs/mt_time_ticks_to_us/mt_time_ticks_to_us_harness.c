/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_time_ticks_to_us against its ACSL contract (kernel/include/mt/time.h), translated by
 * tools/acsl2cbmc into mt_time_ticks_to_us_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_time_ticks_to_us_contract.h"

void harness(void)
{
    uint64_t ticks = mtc_nondet_u64();
    /* ticks: any value up to 2^64 - 1; the rate from a set (B14) */
    static const uint32_t rates[] = {0u, 1u, 3u, 1000u, 32768u, 1000000u, 16000000u,
                                     0xFFFFFFFFu};
    uint32_t hz = MTC_PICK(rates);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_time_ticks_to_us(ticks, hz));
    /* Assumed facts (B12), all proved by WP for every ticks and every hz >= 1: the split
     * quotient, assertion `quot` of mt_time_ticks_to_us (kernel/src/time.c),
     * floor(ticks * 10^6 / hz) == (ticks / hz) * 10^6 + ((ticks % hz) * 10^6) / hz, here with
     * the product computed in 64 bits where it fits, and lemma MtUsAbove
     * (kernel/spec/mt_spec_div.h) where it does not. */
    if (hz >= 1u) {
        uint64_t w = mtc_udiv_u64(ticks, hz);
        uint64_t p = mtc_udiv_u64(mtc_umul_u64(mtc_umod_u64(ticks, hz), 1000000u), hz);
        __int128 q = mtc_udiv128(mtc_umul128((__int128)ticks, (__int128)1000000), (__int128)hz);
        if (w <= (UINT64_MAX / 1000000u)) {
            __CPROVER_assume(q == ((__int128)mtc_umul_u64(w, 1000000u) + (__int128)p));
        } else {
            __CPROVER_assume(q > (__int128)UINT64_MAX);
        }
    }
    mtc_snapshot();
    uint64_t res = mt_time_ticks_to_us(ticks, hz);
    mtc_post_mt_time_ticks_to_us(ticks, hz, res);

    MTC_REACH(res == UINT64_MAX && hz == 1u);                 /* saturated */
    MTC_REACH(res > 0xFFFFFFFFull && hz == 0xFFFFFFFFu);
    MTC_REACH(res < UINT64_MAX && ticks > 0xFFFFFFFF00000000ull);
}
