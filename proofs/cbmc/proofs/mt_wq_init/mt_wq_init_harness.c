/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_init against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_init_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_init_contract.h"

void harness(void)
{
    mt_wq_t *q = MTC_NEW(mt_wq_t, 1u);
    const char *name = mtc_nondet_bool() ? (const char *)0 : (const char *)mtc_callback();
    mt_prio_base_t base = (mt_prio_base_t)mtc_nondet_u32();
    int32_t off = mtc_nondet_i32();
    __CPROVER_assume(off >= -128 && off <= 127);
    int8_t offset = (int8_t)off;
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_init(q, name, base, offset));
    mtc_snapshot();
    mt_wq_init(q, name, base, offset);
    mtc_post_mt_wq_init(q, name, base, offset);

    MTC_REACH(base == MT_PRIO_BOOST && offset == -128 && name != (const char *)0);
    MTC_REACH(MTC_OLDV(q->stats.runs) == UINT64_MAX && MTC_OLDV(q->slot[MT_CFG_WQ_MAX_ITEMS - 1u].stats.merged) == 0xFFFFFFFFu);
}
