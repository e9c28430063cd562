/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sub_copy_next against its ACSL contract (kernel/include/mt/bus_sub.h), translated by
 * tools/acsl2cbmc into mt_sub_copy_next_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_sub_copy_next_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    mt_sub_t *s = mtc_sub(t);
    uint8_t *out = mtc_bytes(t->size);
    uint32_t size = mtc_nondet_u32();
    uint64_t now_us = mtc_nondet_u64();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sub_copy_next(s, out, size, now_us));
    mtc_snapshot();
    mt_status_t res = mt_sub_copy_next(s, out, size, now_us);
    mtc_post_mt_sub_copy_next(s, out, size, now_us, res);

    MTC_REACH(res == MT_OK && MTC_OLDV(s->gen) == 0xFFFFFFFFu && s->gen == 0u && s->rel != 0u);
    MTC_REACH(res == MT_OK && t->size == MT_CFG_BUS_MAX_MSG && t->qlen == MT_CFG_BUS_MAX_QUEUE &&
              s->received == 0xFFFFFFFFu && now_us == UINT64_MAX);
    MTC_REACH(res == MT_W_BUS_MISSED && s->missed == 0xFFFFFFFFu &&
              MTC_OLDV(s->missed) != 0xFFFFFFFFu);                      /* saturates */
    MTC_REACH(res == MT_W_BUS_MISSED && MTC_OLDV(s->gen) != 0u &&
              t->gen == MTC_OLDV(s->gen) - 1u);                           /* lapped by 2^32 - 1 */
    MTC_REACH(res == MT_E_BUS_TORN && s->torn == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_EMPTY);
    MTC_REACH(res == MT_E_BUS_MSG_SIZE);
}
