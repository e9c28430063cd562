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
 * access before it. Only naturally aligned 32-bit values and single bytes are
 * accessed, which is single-copy atomic on every supported target.
 *
 * The seqlock accessors (mt_seq_stamp_u32, mt_seq_recheck_u32, the relaxed byte
 * accessors) serve the topic bus (mt/bus.h): a publisher stamps a slot, then
 * writes the message bytes; a subscriber copies the bytes without the lock and
 * re-reads the stamp to detect an overwrite during its copy.
 */
#ifndef MT_ATOMIC_H
#define MT_ATOMIC_H

#include <stdint.h>
#include "mt_spec.h" /* MtSeqRacing (ACSL only; no line added: CBMC keys, B10) */
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

/*@ requires \valid_read(p);
    assigns \nothing;
    ensures \result == *p;
*/
static inline uint8_t mt_load_relaxed_u8(const uint8_t *p)
{
    return *p;
}

/*@ requires \valid(p);
    assigns *p;
    ensures *p == v;
*/
static inline void mt_store_relaxed_u8(uint8_t *p, uint8_t v)
{
    *p = v;
}

/*@ requires \valid(p);
    assigns *p;
    ensures *p == v;
*/
static inline void mt_seq_stamp_u32(uint32_t *p, uint32_t v)
{
    *p = v;
}

/* No body in proof builds: with a concurrent writer (MtSeqRacing, mt_spec.h) the stamp may
 * have changed since the caller's last read; without one it is the stamp the slot holds
 * (assumption C3). CBMC uses the stub that tools/acsl2cbmc generates from this contract. */
/*@ requires \valid_read(p);
    assigns \nothing;
    ensures quiet: !MtSeqRacing ==> \result == *p;
*/
uint32_t mt_seq_recheck_u32(const uint32_t *p);

#else

static inline uint32_t mt_load_acquire_u32(const uint32_t *p)
{
    return __atomic_load_n(p, __ATOMIC_ACQUIRE);
}

static inline void mt_store_release_u32(uint32_t *p, uint32_t v) // NOLINT(readability-non-const-parameter): D-101 the builtin writes *p
{
    __atomic_store_n(p, v, __ATOMIC_RELEASE);
}

/* Message bytes shared under a seqlock (mt/bus.h): relaxed atomic accesses, so that a copy
 * racing with a publisher is not a data race; the stamps order them. */
static inline uint8_t mt_load_relaxed_u8(const uint8_t *p)
{
    return __atomic_load_n(p, __ATOMIC_RELAXED);
}

static inline void mt_store_relaxed_u8(uint8_t *p, uint8_t v) // NOLINT(readability-non-const-parameter): D-101 the builtin writes *p
{
    __atomic_store_n(p, v, __ATOMIC_RELAXED);
}

/* Seqlock writer: store the slot's stamp, then a release fence, so every later store (the
 * message bytes) is ordered after the stamp. */
static inline void mt_seq_stamp_u32(uint32_t *p, uint32_t v) // NOLINT(readability-non-const-parameter): D-101 the builtin writes *p
{
    __atomic_store_n(p, v, __ATOMIC_RELAXED);
    __atomic_thread_fence(__ATOMIC_RELEASE);
}

/* Seqlock reader: an acquire fence (every earlier load, the message bytes, is ordered
 * before it), then the stamp again. If a copied byte came from a later publish, this load
 * sees that publish's stamp (the writer's release fence synchronises with this one). */
static inline uint32_t mt_seq_recheck_u32(const uint32_t *p)
{
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    return __atomic_load_n(p, __ATOMIC_RELAXED);
}

#endif

#endif /* MT_ATOMIC_H */
