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
/* The model of unsigned 64-bit division (assumption B11). q = n / d and r = n % d are the
 * values of two uninterpreted functions of (n, d), constrained by C's definition of unsigned
 * division (C11 6.5.5): q * d + r == n and r < d. For d >= 1 exactly one pair satisfies
 * it, the operators' values, so the assumption excludes no execution. What it adds is
 * congruence: CBMC gives two applications to equal operands equal results, which for two
 * division circuits the solver would have to prove. A zero divisor fails the assertion, as
 * the operator fails --div-by-zero-check. */
uint64_t __CPROVER_uninterpreted_mtc_udiv(uint64_t, uint64_t);
uint64_t __CPROVER_uninterpreted_mtc_umod(uint64_t, uint64_t);

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
#endif
