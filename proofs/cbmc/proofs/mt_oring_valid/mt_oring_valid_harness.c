/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_oring_valid (a C twin of an ACSL invariant) against its ACSL contract, translated by
 * tools/acsl2cbmc into mt_oring_valid_contract.h: the result is 1 exactly when the invariant holds.
 * Every field of the object is nondeterministic, corrupted values included; MTC_REACH lines
 * are coverage witnesses. */
#include "mtc_objects.h"
#include "mt_oring_valid_contract.h"

void harness(void)
{
    /* elem multiplies slots in the storage bound: a non-linear operand, hence a set (B15) */
    static const uint32_t elems[] = {0u, 1u, 3u, 64u, MT_ORING_BYTES_MAX, 0xFFFFFFFFu};
    mt_oring_t *r = MTC_NEW(mt_oring_t, 1u);
    r->elem = MTC_PICK(elems);
    uint64_t bytes = (uint64_t)r->slots * r->elem;
    r->buf = mtc_bytes(bytes <= MT_ORING_BYTES_MAX ? (uint32_t)bytes : 0u);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_oring_valid(r));
    mtc_snapshot();
    bool ok = mt_oring_valid(r);
    mtc_post_mt_oring_valid(r, ok);

    MTC_REACH(ok && r->slots == MT_ORING_BYTES_MAX && r->elem == 1u);
    MTC_REACH(!ok && r->cap == 0xFFFFFFFFu);
    MTC_REACH(!ok && r->cap == 5u && r->slots == 6u && r->elem == 0xFFFFFFFFu);
    MTC_REACH(ok && r->elem == 64u && r->cap >= 2u);
    MTC_REACH(!ok && r->cap == 3u && r->slots == 4u && r->elem == 1u && r->head_cache == 8u);
}
