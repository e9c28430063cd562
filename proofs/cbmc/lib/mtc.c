/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mtc.c
 * @brief Snapshot registry of the CBMC harnesses (see mtc.h).
 *
 * The loops over the registry are written out (MTC_MAX_OBJS cases) so that no unwinding
 * bound depends on them.
 */
#include <stdlib.h>

#include "mtc_logic.h"

mtc_obj_t mtc_objs[MTC_MAX_OBJS];
int mtc_nobjs;
int mtc_snapshot_taken;
int mtc_reached;

void *mtc_alloc(__CPROVER_size_t elem_size, __CPROVER_size_t count, int kind)
{
    __CPROVER_size_t size = elem_size * count;
    void *p;

    __CPROVER_assert(mtc_nobjs < MTC_MAX_OBJS, "harness: too many objects (raise MTC_MAX_OBJS)");
    __CPROVER_assert(!mtc_snapshot_taken, "harness: object allocated after the snapshot");
    /* A zero-size request still yields a distinct object (a valid empty range). */
    p = malloc(size == 0u ? 1u : size);
    mtc_objs[mtc_nobjs].orig = p;
    mtc_objs[mtc_nobjs].copy = p;
    mtc_objs[mtc_nobjs].size = size;
    mtc_objs[mtc_nobjs].count = count;
    mtc_objs[mtc_nobjs].kind = kind;
    mtc_nobjs++;
    return p;
}

static void snap_one(int i)
{
    if (i < mtc_nobjs) {
        mtc_obj_t *o = &mtc_objs[i];
        char *c = malloc(o->size == 0u ? 1u : o->size);
        __CPROVER_array_copy(c, (char *)o->orig);
        o->copy = c;
    }
}

void mtc_snapshot(void)
{
    __CPROVER_assert(!mtc_snapshot_taken, "harness: second snapshot");
    snap_one(0);
    snap_one(1);
    snap_one(2);
    snap_one(3);
    snap_one(4);
    snap_one(5);
    mtc_snapshot_ghosts();
    mtc_snapshot_taken = 1;
}

#define MTC_TRY(i)                                                                              \
    if ((i) < mtc_nobjs && __CPROVER_same_object(p, mtc_objs[i].orig)) {                       \
        return (char *)mtc_objs[i].copy + __CPROVER_POINTER_OFFSET(p);                         \
    }

void *mtc_old_ptr(const void *p)
{
    __CPROVER_assert(mtc_snapshot_taken, "contract: \\old read before the snapshot");
    MTC_TRY(0)
    MTC_TRY(1)
    MTC_TRY(2)
    MTC_TRY(3)
    MTC_TRY(4)
    MTC_TRY(5)
    __CPROVER_assert(0, "contract: \\old read of an object that is not in the snapshot");
    return (void *)p;
}

/* Nondeterministic values: a local that is never written holds any value in CBMC. */
#define MTC_NONDET(T, fn)                                                                       \
    T fn(void)                                                                                  \
    {                                                                                           \
        T v;                                                                                    \
        __CPROVER_havoc_object(&v);                                                             \
        return v;                                                                               \
    }
MTC_NONDET(uint8_t, mtc_nondet_u8)
MTC_NONDET(uint16_t, mtc_nondet_u16)
MTC_NONDET(uint32_t, mtc_nondet_u32)
MTC_NONDET(uint64_t, mtc_nondet_u64)
MTC_NONDET(int32_t, mtc_nondet_i32)
MTC_NONDET(__CPROVER_size_t, mtc_nondet_size)
MTC_NONDET(__int128, mtc_nondet_i128)

bool mtc_nondet_bool(void)
{
    uint8_t v = mtc_nondet_u8();
    return v != 0u;
}

#if defined(MTC_DIV_MODEL)
/* Models of unsigned division and multiplication (assumption B11). Each result is the value
 * of an uninterpreted function of the operands, constrained by the operation's definition:
 * for division q * d + r == n and r < d (C11 6.5.5), for a product p == n * m without
 * overflow. Each constraint has exactly one solution, the operator's value, so the
 * assumptions exclude no execution. What they add is congruence: CBMC gives two applications
 * to equal operands equal results, which for two division or multiplication circuits the
 * solver would have to prove. A zero divisor or an overflowing product fails an assertion,
 * as the operator fails --div-by-zero-check or --unsigned-overflow-check. */
uint64_t __CPROVER_uninterpreted_mtc_udiv(uint64_t, uint64_t);
uint64_t __CPROVER_uninterpreted_mtc_umod(uint64_t, uint64_t);
uint64_t __CPROVER_uninterpreted_mtc_umul(uint64_t, uint64_t);
__int128 __CPROVER_uninterpreted_mtc_udiv128(__int128, __int128);
__int128 __CPROVER_uninterpreted_mtc_umod128(__int128, __int128);
__int128 __CPROVER_uninterpreted_mtc_umul128(__int128, __int128);

static void mtc_div_model(uint64_t n, uint64_t d, uint64_t q, uint64_t r)
{
    __CPROVER_assert(d != 0u, "division by zero (model of unsigned division)");
    __CPROVER_assume((r < d) && ((((unsigned __int128)q * d) + r) == n));
}

uint64_t mtc_udiv_u64(uint64_t n, uint64_t d)
{
    uint64_t q = __CPROVER_uninterpreted_mtc_udiv(n, d);
    mtc_div_model(n, d, q, __CPROVER_uninterpreted_mtc_umod(n, d));
    return q;
}

uint64_t mtc_umod_u64(uint64_t n, uint64_t d)
{
    uint64_t r = __CPROVER_uninterpreted_mtc_umod(n, d);
    mtc_div_model(n, d, __CPROVER_uninterpreted_mtc_udiv(n, d), r);
    return r;
}

uint64_t mtc_umul_u64(uint64_t n, uint64_t m)
{
    uint64_t p = __CPROVER_uninterpreted_mtc_umul(n, m);
    __CPROVER_assert(!__CPROVER_overflow_mult(n, m), "product overflow (model of multiplication)");
    __CPROVER_assume(!__CPROVER_overflow_mult(n, m) && (p == (n * m)));
    return p;
}

/* The contracts' wide arithmetic: operands the translator knows to be non-negative. */
static void mtc_div128_model(__int128 n, __int128 d, __int128 q, __int128 r)
{
    __CPROVER_assert((n >= 0) && (d >= 1), "spec division: dividend >= 0, divisor >= 1 (model)");
    __CPROVER_assume((q >= 0) && (r >= 0) && (r < d) && !__CPROVER_overflow_mult(q, d) &&
                     ((q * d) == (n - r)));
}

__int128 mtc_udiv128(__int128 n, __int128 d)
{
    __int128 q = __CPROVER_uninterpreted_mtc_udiv128(n, d);
    mtc_div128_model(n, d, q, __CPROVER_uninterpreted_mtc_umod128(n, d));
    return q;
}

__int128 mtc_umod128(__int128 n, __int128 d)
{
    __int128 r = __CPROVER_uninterpreted_mtc_umod128(n, d);
    mtc_div128_model(n, d, __CPROVER_uninterpreted_mtc_udiv128(n, d), r);
    return r;
}

__int128 mtc_umul128(__int128 a, __int128 b)
{
    __int128 p = __CPROVER_uninterpreted_mtc_umul128(a, b);
    __CPROVER_assert(!__CPROVER_overflow_mult(a, b), "spec product within 128 bits (model)");
    __CPROVER_assume(!__CPROVER_overflow_mult(a, b) && (p == (a * b)));
    return p;
}
#endif
