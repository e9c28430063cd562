/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_request_stop against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_request_stop_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_request_stop_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_request_stop(q));
    mtc_snapshot();
    mt_wq_request_stop(q);
    mtc_post_mt_wq_request_stop(q);

    MTC_REACH(MTC_OLDV(q->wake.waiter) != (mt_port_tref_t)0 && q->wake.waiter == (mt_port_tref_t)0);
    MTC_REACH(q->wake.merged == 0xFFFFFFFFu && MTC_OLDV(q->stop) == 1u);
}
