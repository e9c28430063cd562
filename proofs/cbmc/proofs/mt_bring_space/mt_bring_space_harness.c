/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_bring_space against its ACSL contract (kernel/include/mt/ring.h), translated by
 * tools/acsl2cbmc into mt_bring_space_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_bring_space_contract.h"

void harness(void)
{
    mt_bring_t *r = mtc_bring();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_bring_space(r));
    mtc_snapshot();
    uint32_t res = mt_bring_space(r);
    mtc_post_mt_bring_space(r, res);

    MTC_REACH(r->cap == MTC_CAP_TOP && res == 0u);
    MTC_REACH(r->tail >= r->cap && r->head < r->cap); /* indices on both halves */
}
