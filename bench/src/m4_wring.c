/* SPDX-License-Identifier: Apache-2.0 */
/* The word ring's push and pop as the Cortex-M4 compiles them into a caller (they are inline in
 * mt/wordring.h): bench/run.py measures these two functions' size and barriers (P5). */
#include "mt/wordring.h"

mt_status_t bench_m4_wring_push(mt_wring_t *r, uint32_t v);
mt_status_t bench_m4_wring_pop(mt_wring_t *r, uint32_t *out);

mt_status_t bench_m4_wring_push(mt_wring_t *r, uint32_t v)
{
    return mt_wring_push(r, v);
}

mt_status_t bench_m4_wring_pop(mt_wring_t *r, uint32_t *out)
{
    return mt_wring_pop(r, out);
}
