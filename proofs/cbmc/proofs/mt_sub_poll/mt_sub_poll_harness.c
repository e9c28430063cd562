/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sub_poll against its ACSL contract (kernel/include/mt/bus_sub.h), translated by
 * tools/acsl2cbmc into mt_sub_poll_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_sub_poll_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    mt_sub_t *s = mtc_sub(t);
    uint64_t timeout_us = mtc_nondet_u64();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sub_poll(s, timeout_us));
    mtc_snapshot();
    mt_status_t res = mt_sub_poll(s, timeout_us);
    mtc_post_mt_sub_poll(s, timeout_us, res);

    MTC_REACH(res == MT_OK && timeout_us == MT_WAIT_FOREVER && MTC_OLDV(t->gen) == MTC_OLDV(s->gen));
    MTC_REACH(res == MT_OK && t->gen == 0u && s->gen == 0xFFFFFFFFu);          /* pending across the wrap */
    MTC_REACH(res == MT_E_TIMEOUT && timeout_us == 0u && MTC_OLDV(s->sem.token) == 1u);  /* stale token */
    MTC_REACH(res == MT_E_TIMEOUT && timeout_us != 0u);
    MTC_REACH(res == MT_E_BUSY);
    MTC_REACH(res == MT_E_STATE);
}
