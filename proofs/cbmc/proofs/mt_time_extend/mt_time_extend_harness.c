/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_time_extend against its ACSL contract (kernel/include/mt/time.h), translated by
 * tools/acsl2cbmc into mt_time_extend_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_time_extend_contract.h"

void harness(void)
{
    mt_time_ext_t *t = mtc_time_ext();
    uint32_t hw_now = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_time_extend(t, hw_now));
    mtc_snapshot();
    uint64_t res = mt_time_extend(t, hw_now);
    mtc_post_mt_time_extend(t, hw_now, res);

    MTC_REACH(res == UINT64_MAX && t->hw_max == 0xFFFFFFFFu);  /* saturated */
    MTC_REACH(hw_now < MTC_OLDV(t->last_hw));                    /* the counter wrapped */
}
