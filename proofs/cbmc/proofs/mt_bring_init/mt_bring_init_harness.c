/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_bring_init against its ACSL contract (kernel/include/mt/ring.h), translated by
 * tools/acsl2cbmc into mt_bring_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_bring_init_contract.h"

void harness(void)
{
    mt_bring_t *r = MTC_NEW(mt_bring_t, 1u);
    uint32_t cap = mtc_nondet_u32();                  /* any value: 0, 1, MAX, MAX + 1, UINT32_MAX */
    int fits = cap >= 1u && cap <= MT_BRING_CAP_MAX;
    uint8_t *storage = mtc_bytes(fits ? cap : 1u);     /* no loop in init: storage of any size */
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_bring_init(r, storage, cap));
    mtc_snapshot();
    mt_status_t res = mt_bring_init(r, storage, cap);
    mtc_post_mt_bring_init(r, storage, cap, res);

    MTC_REACH(cap == MT_BRING_CAP_MAX && res == MT_OK);
    MTC_REACH(cap == MT_BRING_CAP_MAX + 1u);
    MTC_REACH(cap == 0xFFFFFFFFu);
}
