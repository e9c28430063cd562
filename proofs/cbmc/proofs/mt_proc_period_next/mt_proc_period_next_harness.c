/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_proc_period_next against its ACSL contract (kernel/include/mt/proc.h), translated by
 * tools/acsl2cbmc into mt_proc_period_next_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_proc_period_next_contract.h"

void harness(void)
{
    uint64_t *deadline = (uint64_t *)mtc_alloc(1u, sizeof(uint64_t), MTC_K_BYTES);
    uint64_t now = mtc_nondet_u64();
    /* now and *deadline: any values (up to 2^64 - 1); the divisor from a set (B14) */
    static const uint32_t periods[] = {0u, 1u, 2u, 3u, 1000u, 2500u, 1000000u, 0x80000001u,
                                       0xFFFFFFFFu};
    uint32_t period_us = MTC_PICK(periods);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_proc_period_next(deadline, now, period_us));
    /* Lemma MtModStep (kernel/spec/mt_spec_div.h, proved by WP) at n = now - *deadline,
     * p = period_us: (n - n % p + p) % p == 0, the late deadline is on the grid. Assumed
     * (B12): a fact about a product and a quotient that the solver does not derive. */
    if (now >= *deadline) {
        uint64_t n = now - *deadline;
        uint64_t r = mtc_umod_u64(n, period_us);
        if ((r <= n) && ((n - r) <= (UINT64_MAX - period_us))) {
            __CPROVER_assume(mtc_umod_u64((n - r) + period_us, period_us) == 0u);
        }
    }
    mtc_snapshot();
    uint32_t res = mt_proc_period_next(deadline, now, period_us);
    mtc_post_mt_proc_period_next(deadline, now, period_us, res);

    MTC_REACH(now > 0xFFFFFFFF00000000ull && res > 0u);  /* times near 2^64 */
    MTC_REACH(res == 0xFFFFFFFFu);                       /* missed-period count saturated */
}
