/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_time_ext_valid (a C twin of an ACSL invariant) against its ACSL contract, translated by
 * tools/acsl2cbmc into mt_time_ext_valid_contract.h: the result is 1 exactly when the invariant holds.
 * Every field of the object is nondeterministic, corrupted values included; MTC_REACH lines
 * are coverage witnesses. */
#include "mtc_objects.h"
#include "mt_time_ext_valid_contract.h"

void harness(void)
{
    mt_time_ext_t *t = mtc_time_ext();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_time_ext_valid(t));
    mtc_snapshot();
    bool ok = mt_time_ext_valid(t);
    mtc_post_mt_time_ext_valid(t, ok);

    MTC_REACH(ok && t->hw_max == 0xFFFFFFFFu && t->last_hw == 0xFFFFFFFFu);
    MTC_REACH(!ok && t->hw_max == 0u);
    MTC_REACH(!ok && t->hw_max >= 1u && t->last_hw > t->hw_max);
}
