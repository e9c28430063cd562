/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_bring_commit against its ACSL contract (kernel/include/mt/ring.h), translated by
 * tools/acsl2cbmc into mt_bring_commit_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_bring_commit_contract.h"

void harness(void)
{
    mt_bring_t *r = mtc_bring();
    uint32_t n = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_bring_commit(r, n));
    mtc_snapshot();
    mt_status_t res = mt_bring_commit(r, n);
    mtc_post_mt_bring_commit(r, n, res);

    MTC_REACH(res == MT_OK && n == r->cap);
    MTC_REACH(n == 0xFFFFFFFFu);
}
