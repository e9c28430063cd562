/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_bring_read against its ACSL contract (kernel/include/mt/ring.h), translated by
 * tools/acsl2cbmc into mt_bring_read_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_bring_read_contract.h"

void harness(void)
{
    mt_bring_t *r = mtc_bring();
    uint32_t len = mtc_nondet_u32();
    __CPROVER_assume(len <= MTC_LEN_MAX);
    uint8_t *dst = mtc_bytes(len);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_bring_read(r, dst, len));
    mtc_snapshot();
    uint32_t res = mt_bring_read(r, dst, len);
    mtc_post_mt_bring_read(r, dst, len, res);

    MTC_REACH(r->cap == MTC_CAP_TOP && res == MTC_LEN_MAX);
    MTC_REACH(res >= 2u && mtc_MtIdxSlot(0, MTC_OLDV(r->head), r->cap) + res > r->cap); /* wraps */
}
