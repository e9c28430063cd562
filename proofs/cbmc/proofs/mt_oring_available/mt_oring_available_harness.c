/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_oring_available against its ACSL contract (kernel/include/mt/objring.h), translated by
 * tools/acsl2cbmc into mt_oring_available_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_oring_available_contract.h"

void harness(void)
{
    mt_oring_t *r = mtc_oring(MTC_ELEM_MAX);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_oring_available(r));
    mtc_snapshot();
    uint32_t res = mt_oring_available(r);
    mtc_post_mt_oring_available(r, res);

    MTC_REACH(r->cap == MTC_ORING_CAP_TOP(r->elem) && res == r->cap);
}
