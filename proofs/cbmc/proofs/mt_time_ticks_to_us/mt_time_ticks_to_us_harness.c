/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_time_ticks_to_us against its ACSL contract (kernel/include/mt/time.h), translated by
 * tools/acsl2cbmc.py into mt_time_ticks_to_us_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_time_ticks_to_us_contract.h"

void harness(void)
{
    uint64_t ticks = mtc_nondet_u64();
    /* ticks: any value up to 2^64 - 1; the rate from a set (B3) */
    static const uint32_t rates[] = {0u, 1u, 3u, 1000u, 32768u, 1000000u, 16000000u,
                                     0xFFFFFFFFu};
    uint32_t hz = MTC_PICK(rates);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_time_ticks_to_us(ticks, hz));
    mtc_snapshot();
    uint64_t res = mt_time_ticks_to_us(ticks, hz);
    mtc_post_mt_time_ticks_to_us(ticks, hz, res);

    MTC_REACH(res == UINT64_MAX && hz == 1u);                 /* saturated */
    MTC_REACH(res > 0xFFFFFFFFull && hz == 0xFFFFFFFFu);
    MTC_REACH(res < UINT64_MAX && ticks > 0xFFFFFFFF00000000ull);
}
