/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_time_ext_init against its ACSL contract (kernel/include/mt/time.h), translated by
 * tools/acsl2cbmc into mt_time_ext_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_time_ext_init_contract.h"

void harness(void)
{
    mt_time_ext_t *t = mtc_time_ext();
    uint32_t hw_max = mtc_nondet_u32();
    uint32_t hw_now = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_time_ext_init(t, hw_max, hw_now));
    mtc_snapshot();
    mt_status_t res = mt_time_ext_init(t, hw_max, hw_now);
    mtc_post_mt_time_ext_init(t, hw_max, hw_now, res);

    MTC_REACH(res == MT_OK && hw_max == 0xFFFFFFFFu && hw_now == hw_max);
}
