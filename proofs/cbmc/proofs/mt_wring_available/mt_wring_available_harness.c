/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wring_available against its ACSL contract (kernel/include/mt/wordring.h), translated by
 * tools/acsl2cbmc into mt_wring_available_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. The ring is the default
 * configuration (MT_CFG_WRING_CAP 256: 257 slots), every index and counter nondeterministic. */
#include "mtc_objects.h"
#include "mt_wring_available_contract.h"

void harness(void)
{
    mt_wring_t *r = MTC_NEW(mt_wring_t, 1u);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wring_available(r));
    mtc_snapshot();
    uint32_t res = mt_wring_available(r);
    mtc_post_mt_wring_available(r, res);

    MTC_REACH(res == MT_CFG_WRING_CAP && r->tail < r->head);
    MTC_REACH(res == 0u && r->tail == MT_WRING_SLOTS - 1u);
}
