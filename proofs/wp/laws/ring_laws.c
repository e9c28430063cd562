/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ring_laws.c
 * @brief Data-type laws of the SPSC byte ring (ardupilot.md §4.4), proved by WP from the
 *        public contracts of mt/ring.h only (ACSL-by-Example style: each law is a tiny
 *        function whose contract is the law). Sequential: one thread plays both sides.
 */
#include "mt/ring.h"

/* Representation: readable + free == capacity (no reservation outstanding). */
/*@ requires inv: MtBRingInv(r);
    requires no_reservation: r->reserved == 0;
    assigns r->tail_cache, r->head_cache;
    ensures count_plus_space: \result == r->cap;
*/
uint32_t law_bring_count_plus_space(mt_bring_t *r)
{
    uint32_t avail = mt_bring_available(r);
    uint32_t space = mt_bring_space(r);
    return avail + space;
}

/* FIFO: a byte written into an empty ring is the byte read back. */
/*@ requires inv: MtBRingInv(r);
    requires empty: MtBRingCount(r) == 0 && r->reserved == 0;
    assigns r->tail, r->head, r->head_cache, r->tail_cache, r->buf[0 .. r->cap - 1];
    ensures round_trip: \result == v;
    ensures empty_again: MtBRingCount(r) == 0;
*/
uint8_t law_bring_write_then_read(mt_bring_t *r, uint8_t v)
{
    uint8_t in = v;
    uint8_t out = 0u;
    uint32_t w = mt_bring_write(r, &in, 1u);
    uint32_t n = mt_bring_read(r, &out, 1u);
    //@ assert one_each: w == 1 && n == 1;
    return out;
}

/* FIFO order: two bytes come out in the order they went in (the result packs the bytes read,
 * first one in the high byte). */
/*@ requires inv: MtBRingInv(r);
    requires room: MtBRingCount(r) == 0 && r->reserved == 0 && r->cap >= 2;
    assigns r->tail, r->head, r->head_cache, r->tail_cache, r->buf[0 .. r->cap - 1];
    ensures fifo: \result == a * 256 + b;
*/
uint32_t law_bring_fifo_order(mt_bring_t *r, uint8_t a, uint8_t b)
{
    uint8_t in[2];
    uint8_t out[2] = {0u, 0u};
    uint32_t w;
    uint32_t n;

    in[0] = a;
    in[1] = b;
    w = mt_bring_write(r, in, 2u);
    n = mt_bring_read(r, out, 2u);
    //@ assert two_each: w == 2 && n == 2;
    //@ assert in_order: out[0] == a && out[1] == b;
    return ((uint32_t)out[0] * 256u) + (uint32_t)out[1];
}

/* No overwrite: a write into a full ring writes nothing and changes no unread byte. */
/*@ requires inv: MtBRingInv(r);
    requires full: MtBRingCount(r) == r->cap && r->reserved == 0;
    assigns r->tail, r->head_cache, r->buf[0 .. r->cap - 1];
    ensures nothing_written: \result == 0 && r->tail == \old(r->tail);
    ensures unread_kept: \forall integer k; 0 <= k < r->cap ==> MtBRingByte(r, k) == \old(MtBRingByte(r, k));
*/
uint32_t law_bring_full_no_overwrite(mt_bring_t *r, uint8_t v)
{
    uint8_t in = v;
    return mt_bring_write(r, &in, 1u);
}
