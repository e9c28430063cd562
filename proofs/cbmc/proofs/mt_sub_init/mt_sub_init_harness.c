/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sub_init against its ACSL contract (kernel/include/mt/bus_sub.h), translated by
 * tools/acsl2cbmc into mt_sub_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_sub_init_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    mt_sub_t *s = MTC_NEW(mt_sub_t, 1u);
    uint32_t interval_us = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sub_init(s, t, interval_us));
    mtc_snapshot();
    mt_sub_init(s, t, interval_us);
    mtc_post_mt_sub_init(s, t, interval_us);

    MTC_REACH(t->published == 1u && t->gen == 0u && s->gen == 0xFFFFFFFFu);  /* newest pending, wrap */
    MTC_REACH(t->published == 0u && s->gen == t->gen && interval_us == 0xFFFFFFFFu);
}
