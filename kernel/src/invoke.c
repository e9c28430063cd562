/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file invoke.c
 * @brief Indirect calls (assumption A1, see mt_invoke.h). Not analysed by WP.
 */
#include "mt_invoke.h"

/* The slot only names the call for the proofs (the ghost MtCalls). */
void mt_invoke(void (*fn)(void *), void *arg, uint32_t slot)
{
    (void)slot;
    fn(arg);
}

uint64_t mt_invoke_u64(uint64_t (*fn)(void *), void *arg, uint32_t slot)
{
    (void)slot;
    return fn(arg);
}
