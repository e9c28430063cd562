/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mtc.h
 * @brief Support for the CBMC harnesses: nondeterministic values, the snapshot registry
 *        that gives the generated contracts their pre-state (\old), and the location
 *        helpers used by \separated and assigns. See proofs/cbmc/README.md.
 *
 * Every object a harness hands to the kernel is allocated with mtc_alloc() (directly or by a
 * constructor in mtc_objects.h); mtc_snapshot() then copies all of them (buffers included:
 * they are objects of their own) and the ghost variables. The generated mtc_post_<F>() reads
 * the pre-state through MTC_OLD() and walks every registered object for the assigns check.
 */
#ifndef MTC_H
#define MTC_H

#include <stdbool.h>
#include <stdint.h>

/* Largest number of objects one harness registers (the generated frame check visits each). */
#define MTC_MAX_OBJS 6

typedef struct {
    void *orig;               /* the object the kernel sees */
    void *copy;               /* its copy at mtc_snapshot() */
    __CPROVER_size_t size;    /* bytes */
    __CPROVER_size_t count;   /* elements */
    int kind;                 /* MTC_K_* (generated in mtc_logic.h) */
} mtc_obj_t;

extern mtc_obj_t mtc_objs[MTC_MAX_OBJS];
extern int mtc_nobjs;
extern int mtc_snapshot_taken;

/* nondeterministic values */
uint8_t mtc_nondet_u8(void);
uint16_t mtc_nondet_u16(void);
uint32_t mtc_nondet_u32(void);
uint64_t mtc_nondet_u64(void);
int32_t mtc_nondet_i32(void);
bool mtc_nondet_bool(void);
__CPROVER_size_t mtc_nondet_size(void);
__int128 mtc_nondet_i128(void);

/* A fresh object of count elements of elem_size bytes with nondeterministic contents,
 * registered for the snapshot (kind: MTC_K_BYTES or MTC_K_<type>). */
void *mtc_alloc(__CPROVER_size_t elem_size, __CPROVER_size_t count, int kind);
#define MTC_NEW(T, n) ((T *)mtc_alloc(sizeof(T), (n), MTC_K_##T))

/* Copy every registered object and the ghost variables (call after assuming the pre). */
void mtc_snapshot(void);

/* ghost.c: nondeterministic ghost state, and its copy taken by mtc_snapshot(). */
void mtc_ghosts_nondet(void);
void mtc_snapshot_ghosts(void);

/* Address in the snapshot of the byte that p points to now (p must point into a registered
 * object; anything else is reported as a failed assertion, never silently read live). */
void *mtc_old_ptr(const void *p);
#define MTC_OLD(p) ((__typeof__(p))mtc_old_ptr((const void *)(p)))
#define MTC_AT(st, p) ((st) ? MTC_OLD(p) : (p))
/* Value of the lvalue x in the snapshot (for harness witnesses). */
#define MTC_OLDV(x) (*MTC_OLD(&(x)))

/* Is the cell [a, a + n) inside an assigns location? Three shapes, chosen by the generator:
 * one object of `width` bytes at base; count contiguous elements of `width` bytes from base;
 * count elements `stride` bytes apart, of which the first `width` bytes are assigned (a
 * field of each element of an array of structs). 64-bit arithmetic: object offsets and
 * sizes are below 2^62 in every harness. */
static inline long long mtc_rel(const void *a, const void *base)
{
    return (long long)__CPROVER_POINTER_OFFSET(a) - (long long)__CPROVER_POINTER_OFFSET(base);
}

static inline int mtc_in_one(const void *a, __CPROVER_size_t n, const void *base,
                             __CPROVER_size_t width)
{
    long long rel;
    if (!__CPROVER_same_object(a, base)) {
        return 0;
    }
    rel = mtc_rel(a, base);
    return rel >= 0 && rel + (long long)n <= (long long)width;
}

static inline int mtc_in_range(const void *a, __CPROVER_size_t n, const void *base, __int128 count,
                               __CPROVER_size_t width)
{
    long long rel;
    if (count <= 0 || !__CPROVER_same_object(a, base)) {
        return 0;
    }
    rel = mtc_rel(a, base);
    return rel >= 0 && (__int128)rel + (__int128)n <= count * (__int128)width;
}

static inline int mtc_in_strided(const void *a, __CPROVER_size_t n, const void *base,
                                 __CPROVER_size_t stride, __int128 count, __CPROVER_size_t width)
{
    long long rel;
    if (count <= 0 || !__CPROVER_same_object(a, base)) {
        return 0;
    }
    rel = mtc_rel(a, base);
    return rel >= 0 && (__int128)(rel / (long long)stride) < count &&
           rel % (long long)stride + (long long)n <= (long long)width;
}

/* \separated of two locations p + (lo .. hi), elements of esz bytes (byte ranges). */
static inline int mtc_separated(const void *p, __int128 plo, __int128 phi, __int128 pesz,
                                const void *q, __int128 qlo, __int128 qhi, __int128 qesz)
{
    __int128 ps;
    __int128 qs;
    if (plo > phi || qlo > qhi || !__CPROVER_same_object(p, q)) {
        return 1;
    }
    ps = (__int128)__CPROVER_POINTER_OFFSET(p) + plo * pesz;
    qs = (__int128)__CPROVER_POINTER_OFFSET(q) + qlo * qesz;
    return ps + (phi - plo + 1) * pesz <= qs || qs + (qhi - qlo + 1) * qesz <= ps;
}

/* ACSL a / b and a % b at 64 bits (tools/acsl2cbmc, Translator.divide), for operands whose
 * range the translator cannot bound: exact when the operands are in the asserted range (ACSL
 * truncates toward zero, as C does); an operand outside it is a failed check of the harness.
 * A zero divisor is reported by CBMC's division-by-zero check, as for any other division.
 * udiv: a dividend that is a difference of 64-bit values, over a non-negative 64-bit divisor. */
#define MTC_U64_MAX ((__int128)0xFFFFFFFFFFFFFFFFull)
#define MTC_I64_MIN (-(__int128)0x8000000000000000ull)
#define MTC_I64_MAX ((__int128)0x7FFFFFFFFFFFFFFFull)
/* Unsigned division and wide products of the contracts (mtc_udiv64, mtc_umod64, and the
 * translator's MTC_UDIV128, MTC_UMOD128, MTC_UMUL128). A proof built with -DMTC_DIV_MODEL
 * computes them with the models of mtc.c (assumption B11), the ones its Makefile puts in place
 * of the kernel's mt_udiv_u64, mt_umod_u64 and mt_umul_u64 (REPLACE_CALLS): a quotient or
 * product of the kernel and one of the contract with equal operands are then one value.
 * Without it they are the C operators. */
#if defined(MTC_DIV_MODEL)
uint64_t mtc_udiv_u64(uint64_t n, uint64_t d);
uint64_t mtc_umod_u64(uint64_t n, uint64_t d);
uint64_t mtc_umul_u64(uint64_t n, uint64_t m);
__int128 mtc_udiv128(__int128 n, __int128 d);
__int128 mtc_umod128(__int128 n, __int128 d);
__int128 mtc_umul128(__int128 a, __int128 b);
#define MTC_UDIV_U64(a, b) mtc_udiv_u64((a), (b))
#define MTC_UMOD_U64(a, b) mtc_umod_u64((a), (b))
#define MTC_UDIV128(a, b) mtc_udiv128((a), (b))
#define MTC_UMOD128(a, b) mtc_umod128((a), (b))
#define MTC_UMUL128(a, b) mtc_umul128((a), (b))
#else
#define MTC_UDIV_U64(a, b) ((a) / (b))
#define MTC_UMOD_U64(a, b) ((a) % (b))
#define MTC_UDIV128(a, b) ((a) / (b))
#define MTC_UMOD128(a, b) ((a) % (b))
#define MTC_UMUL128(a, b) ((a) * (b))
#endif

static inline __int128 mtc_udiv64(__int128 a, __int128 b)
{
    __CPROVER_assert(a >= 0 && a <= MTC_U64_MAX && b >= 0 && b <= MTC_U64_MAX,
                     "spec division: operands in [0, 2^64)");
    return (__int128)MTC_UDIV_U64((unsigned long long)a, (unsigned long long)b);
}

static inline __int128 mtc_umod64(__int128 a, __int128 b)
{
    __CPROVER_assert(a >= 0 && a <= MTC_U64_MAX && b >= 0 && b <= MTC_U64_MAX,
                     "spec division: operands in [0, 2^64)");
    return (__int128)MTC_UMOD_U64((unsigned long long)a, (unsigned long long)b);
}

static inline __int128 mtc_sdiv64(__int128 a, __int128 b)
{
    __CPROVER_assert(a >= MTC_I64_MIN && a <= MTC_I64_MAX && b >= MTC_I64_MIN && b <= MTC_I64_MAX,
                     "spec division: operands in [-2^63, 2^63)");
    return (__int128)((long long)a / (long long)b);
}

static inline __int128 mtc_smod64(__int128 a, __int128 b)
{
    __CPROVER_assert(a >= MTC_I64_MIN && a <= MTC_I64_MAX && b >= MTC_I64_MIN && b <= MTC_I64_MAX,
                     "spec division: operands in [-2^63, 2^63)");
    return (__int128)((long long)a % (long long)b);
}

static inline __int128 mtc_min(__int128 a, __int128 b)
{
    return a < b ? a : b;
}

static inline __int128 mtc_max(__int128 a, __int128 b)
{
    return a > b ? a : b;
}

/* Reachability witness: the block is a coverage goal of the harness, covered only if the
 * harness admits a state with cond (e.g. a capacity at its maximum). The coverage report
 * (proofs/cbmc/run.py) lists each MTC_REACH line as reached or not. */
extern int mtc_reached;
#define MTC_REACH(cond)                                                                         \
    if (cond) {                                                                                 \
        mtc_reached = __LINE__;                                                                 \
    }

#endif /* MTC_H */
