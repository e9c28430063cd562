/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_bring_valid (a C twin of an ACSL invariant) against its ACSL contract, translated by
 * tools/acsl2cbmc into mt_bring_valid_contract.h: the result is 1 exactly when the invariant holds.
 * Every field of the object is nondeterministic, corrupted values included; MTC_REACH lines
 * are coverage witnesses. */
#include "mtc_objects.h"
#include "mt_bring_valid_contract.h"

void harness(void)
{
    mt_bring_t *r = MTC_NEW(mt_bring_t, 1u);
    r->buf = mtc_bytes(r->cap);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_bring_valid(r));
    mtc_snapshot();
    bool ok = mt_bring_valid(r);
    mtc_post_mt_bring_valid(r, ok);

    MTC_REACH(ok && r->cap == MT_BRING_CAP_MAX && r->reserved > 0u);
    MTC_REACH(!ok && r->cap == MT_BRING_CAP_MAX + 1u);
    MTC_REACH(!ok && r->cap >= 1u && r->cap <= MT_BRING_CAP_MAX && r->tail == 2u * r->cap);
    MTC_REACH(!ok && r->cap >= 1u && r->cap <= MT_BRING_CAP_MAX && r->reserved == 0xFFFFFFFFu);
}
