/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sub_poll_enable against its ACSL contract (kernel/include/mt/bus_sub.h), translated by
 * tools/acsl2cbmc into mt_sub_poll_enable_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_sub_poll_enable_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    mt_sub_t *s = mtc_sub(t);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sub_poll_enable(s));
    mtc_snapshot();
    mt_status_t res = mt_sub_poll_enable(s);
    mtc_post_mt_sub_poll_enable(s, res);

    MTC_REACH(res == MT_OK && t->nnotify == MT_CFG_BUS_MAX_NOTIFY && s->notify == MT_CFG_BUS_MAX_NOTIFY);
    MTC_REACH(res == MT_E_DUPLICATE);
    MTC_REACH(res == MT_E_FULL);
}
