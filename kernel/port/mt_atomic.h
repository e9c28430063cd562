/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_atomic.h
 * @brief Acquire/release accessors for indices shared between two contexts.
 *
 * Proof builds (__FRAMAC__, CBMC) see plain reads and writes, as stated by the
 * contracts: Frama-C 25 cannot analyse <stdatomic.h>, and the ordering these
 * accessors give is the business of the TLA+ models (tla/). Target and host
 * builds use the GCC/Clang __atomic builtins (no OS header): an acquire load
 * orders every later access after it, a release store orders every earlier
 * access before it. Only naturally aligned 32-bit values are accessed, which
 * is single-copy atomic on every supported target.
 */
#ifndef MT_ATOMIC_H
#define MT_ATOMIC_H

#include <stdint.h>

#if defined(__FRAMAC__) || defined(CBMC)

/*@ requires \valid_read(p);
    assigns \nothing;
    ensures \result == *p;
*/
static inline uint32_t mt_load_acquire_u32(const uint32_t *p)
{
    return *p;
}

/*@ requires \valid(p);
    assigns *p;
    ensures *p == v;
*/
static inline void mt_store_release_u32(uint32_t *p, uint32_t v)
{
    *p = v;
}

#else

static inline uint32_t mt_load_acquire_u32(const uint32_t *p)
{
    return __atomic_load_n(p, __ATOMIC_ACQUIRE);
}

static inline void mt_store_release_u32(uint32_t *p, uint32_t v) // NOLINT(readability-non-const-parameter): D-101 the builtin writes *p
{
    __atomic_store_n(p, v, __ATOMIC_RELEASE);
}

#endif

#endif /* MT_ATOMIC_H */
