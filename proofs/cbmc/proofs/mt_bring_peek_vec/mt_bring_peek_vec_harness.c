/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_bring_peek_vec against its ACSL contract (kernel/include/mt/ring.h), translated by
 * tools/acsl2cbmc into mt_bring_peek_vec_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_bring_peek_vec_contract.h"

void harness(void)
{
    mt_bring_t *r = mtc_bring();
    mt_iovec_t *vec = MTC_NEW(mt_iovec_t, 2u);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_bring_peek_vec(r, vec));
    mtc_snapshot();
    uint32_t res = mt_bring_peek_vec(r, vec);
    mtc_post_mt_bring_peek_vec(r, vec, res);

    MTC_REACH(res == 2u && r->cap == MTC_CAP_TOP);
}
