/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_oring_init against its ACSL contract (kernel/include/mt/objring.h), translated by
 * tools/acsl2cbmc into mt_oring_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_oring_init_contract.h"

void harness(void)
{
    mt_oring_t *r = MTC_NEW(mt_oring_t, 1u);
    /* cap: any value; elem: small sizes, the largest that fit, and values whose product with
     * cap + 1 overflows 32 bits (B15: one operand of the product from a set) */
    static const uint32_t elems[] = {0u, 1u, 2u, 3u, 4u, 24u, 0x1000u, MT_ORING_BYTES_MAX / 2u,
                                     MT_ORING_BYTES_MAX, MT_ORING_BYTES_MAX + 1u, 0xFFFFFFFFu};
    uint32_t elem = MTC_PICK(elems);
    uint32_t cap = mtc_nondet_u32();
    uint64_t bytes = (uint64_t)elem * ((uint64_t)cap + 1u);
    int fits = elem >= 1u && cap >= 1u && bytes <= MT_ORING_BYTES_MAX;
    void *storage = mtc_bytes(fits ? (uint32_t)bytes : 1u);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_oring_init(r, storage, elem, cap));
    mtc_snapshot();
    mt_status_t res = mt_oring_init(r, storage, elem, cap);
    mtc_post_mt_oring_init(r, storage, elem, cap, res);

    MTC_REACH(res == MT_OK && cap == MT_ORING_BYTES_MAX - 1u);
    MTC_REACH(res == MT_OK && elem == MT_ORING_BYTES_MAX / 2u && cap == 1u);
    MTC_REACH(res == MT_E_INVALID && elem == 4u && cap == MT_ORING_BYTES_MAX / 4u);
    MTC_REACH(cap == 0xFFFFFFFFu && elem == 0xFFFFFFFFu);
}
