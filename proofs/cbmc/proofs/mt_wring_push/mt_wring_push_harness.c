/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wring_push against its ACSL contract (kernel/include/mt/wordring.h), translated by
 * tools/acsl2cbmc into mt_wring_push_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. The ring is the default
 * configuration (MT_CFG_WRING_CAP 256: 257 slots), every index and counter nondeterministic. */
#include "mtc_objects.h"
#include "mt_wring_push_contract.h"

void harness(void)
{
    mt_wring_t *r = MTC_NEW(mt_wring_t, 1u);
    uint32_t v = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wring_push(r, v));
    mtc_snapshot();
    mt_status_t res = mt_wring_push(r, v);
    mtc_post_mt_wring_push(r, v, res);

    MTC_REACH(res == MT_OK && MTC_OLDV(r->tail) == MT_WRING_SLOTS - 1u && r->tail == 0u);
    MTC_REACH(res == MT_OK && MTC_OLDV(r->head_cache) != r->head_cache);
    MTC_REACH(res == MT_E_FULL && MTC_OLDV(r->rejected) == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_FULL && r->rejected == 1u);
}
