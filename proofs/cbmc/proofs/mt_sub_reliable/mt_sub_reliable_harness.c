/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sub_reliable against its ACSL contract (kernel/include/mt/bus_sub.h), translated by
 * tools/acsl2cbmc into mt_sub_reliable_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_sub_reliable_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    mt_sub_t *s = mtc_sub(t);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sub_reliable(s));
    mtc_snapshot();
    mt_status_t res = mt_sub_reliable(s);
    mtc_post_mt_sub_reliable(s, res);

    MTC_REACH(res == MT_OK && t->nrel == MT_CFG_BUS_MAX_RELIABLE && s->gen == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_STATE);
    MTC_REACH(res == MT_E_DUPLICATE);
    MTC_REACH(res == MT_E_FULL);
}
