/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file bus_sub.c
 * @brief Topic bus (see mt/bus.h), the lock-free subscriber side: attach, the update test and
 *        the copies, checked by per-slot stamps (seqlock). Publishers are in bus.c, the
 *        subscriber calls that take the kernel lock in bus_reg.c.
 */
#include "mt/bus_sub.h"

#include "mt_atomic.h"
#include "mt_bus_int.h"
#include "mt_sat.h"

/* ------------------------------------------------------------------------------------------
 * Wrap-free arithmetic: each helper is its logic twin in mt_spec_bus.h, by case split. */

/*@ assigns \nothing;
    ensures \result == MtGenBack(g, d);
*/
static uint32_t gen_back(uint32_t g, uint32_t d)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (g >= d) ? (g - d) : (((0xFFFFFFFFu - d) + g) + 1u);
}

/*@ requires h < q <= MT_CFG_BUS_MAX_QUEUE;
    requires d < q;
    assigns \nothing;
    ensures \result == MtSlotBack(h, d, q);
    ensures \result < q;
*/
static uint32_t slot_back(uint32_t h, uint32_t d, uint32_t q)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (h >= d) ? (h - d) : ((h + q) - d);
}

/*@ requires 1 <= p && 1 <= q;
    assigns \nothing;
    ensures \result == MtNextDist(p, q);
*/
static uint32_t next_dist(uint32_t p, uint32_t q)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (p > q) ? (q - 1u) : (p - 1u);
}

/* ------------------------------------------------------------------------------------------
 * Bytes */

/* Copy n message bytes out of a slot (subscriber, no lock): relaxed loads, ordered
 * before the stamp re-check by mt_seq_recheck_u32's acquire fence. */
/*@ requires \valid(dst + (0 .. n - 1)) && \valid_read(src + (0 .. n - 1));
    requires \separated(dst + (0 .. n - 1), src + (0 .. n - 1));
    assigns dst[0 .. n - 1];
    ensures \forall integer k; 0 <= k < n ==> dst[k] == src[k];
*/
static void read_bytes(uint8_t *dst, const uint8_t *src, uint32_t n)
{
    uint32_t k;

    /*@ loop invariant 0 <= k <= n;
        loop invariant \forall integer j; 0 <= j < k ==> dst[j] == src[j];
        loop assigns k, dst[0 .. n - 1];
        loop variant n - k;
    */
    for (k = 0u; k < n; k++) {
        dst[k] = mt_load_relaxed_u8(&src[k]);
    }
}

/* ------------------------------------------------------------------------------------------
 * Subscribers */

void mt_sub_init(mt_sub_t *s, mt_topic_t *t, uint32_t interval_us)
{
    /* published before gen: a publish between the two loads leaves the new message not
     * pending (it was published while the subscriber attached), never a slot unwritten */
    uint32_t published = mt_load_acquire_u32(&t->published);
    uint32_t gen = mt_load_acquire_u32(&t->gen);

    s->topic = t;
    s->gen = (published != 0u) ? gen_back(gen, 1u) : gen;
    s->interval_us = interval_us;
    s->last_us = 0u;
    s->received = 0u;
    s->missed = 0u;
    s->skipped = 0u;
    s->torn = 0u;
    s->rel = 0u;
    s->notify = 0u;
    mt_sem_init(&s->sem, false);
}

bool mt_sub_updated(const mt_sub_t *s, uint64_t now_us)
{
    uint32_t gen = mt_load_acquire_u32(&s->topic->gen);

    return (gen != s->gen) && mt_bus_interval_due(s->last_us, s->interval_us, now_us);
}

/* One copy attempt of the message d before the newest (generation gen, slot head, as
 * loaded by the caller): check the slot's stamp, copy, re-check the stamp. 1: out holds
 * that message whole; 0: the slot held or received another message (retry). With no
 * concurrent writer, a retained message (d below the publication count) of the current
 * generation and head is always copied (MtTopicStamped). */
/*@ requires MtTopicInv(t);
    requires head < t->qlen && d < t->qlen;
    requires \valid(out + (0 .. t->size - 1));
    requires \separated(out + (0 .. t->size - 1), t, t->buf + (0 .. t->size * t->qlen - 1));
    assigns out[0 .. t->size - 1];
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> \forall integer k; 0 <= k < t->size ==>
        out[k] == t->buf[MtSlotBack(head, d, t->qlen) * t->size + k];
    ensures in_storage: MtSlotBack(head, d, t->qlen) * t->size + t->size <= t->size * t->qlen;
    ensures quiet: !MtSeqRacing && gen == t->gen && head == t->head && d < t->publishes ==>
        \result == 1;
*/
static uint32_t try_copy(const mt_topic_t *t, uint32_t gen, uint32_t head, uint32_t d,
                         uint8_t *out)
{
    uint32_t slot = slot_back(head, d, t->qlen);
    uint32_t want = gen_back(gen, d);

    if (mt_load_acquire_u32(&t->stamp[slot]) != want) {
        return 0u; /* already overwritten, or head and gen from different publishes */
    }
    read_bytes(out, mt_bus_slot_ptr(t, slot), t->size);
    /* a publisher that wrote any of these bytes stamped the slot before it */
    return (mt_seq_recheck_u32(&t->stamp[slot]) == want) ? 1u : 0u;
}

/* Consume up to generation g: lost messages missed, skipped ones skipped, one received
 * when fresh; a reliable subscriber publishes its progress (release). */
/*@ requires MtSubInv(s);
    requires fresh == 0 || fresh == 1;
    requires closer: MtGenDist(s->topic->gen, g) <= MtGenDist(s->topic->gen, s->gen);
    assigns s->gen, s->missed, s->skipped, s->received,
            s->topic->rel_gen[0 .. MT_CFG_BUS_MAX_RELIABLE - 1];
    ensures MtSubInv(s);
    ensures s->gen == g;
    ensures s->missed == MtSatAdd(\old(s->missed), lost);
    ensures s->skipped == MtSatAdd(\old(s->skipped), skipped);
    ensures s->received == (fresh == 1 ? MtSatInc(\old(s->received)) : \old(s->received));
    ensures s->rel != 0 ==> s->topic->rel_gen[s->rel - 1] == g;
    ensures topic_kept: s->topic == \old(s->topic) && s->topic->gen == \old(s->topic->gen) &&
        s->topic->head == \old(s->topic->head) && s->topic->size == \old(s->topic->size) &&
        s->topic->qlen == \old(s->topic->qlen) && s->topic->buf == \old(s->topic->buf);
*/
static void consume(mt_sub_t *s, uint32_t g, uint32_t lost, uint32_t skipped, uint32_t fresh)
{
    s->gen = g;
    if (s->rel != 0u) {
        mt_store_release_u32(&s->topic->rel_gen[s->rel - 1u], g);
    }
    s->missed = mt_add_sat_u32(s->missed, lost);
    s->skipped = mt_add_sat_u32(s->skipped, skipped);
    if (fresh != 0u) {
        s->received = mt_inc_sat_u32(s->received);
    }
}

/*@ requires MtSubInv(s);
    assigns s->last_us;
    ensures MtSubInv(s);
    ensures s->last_us == MtClampNext(\old(s->last_us), s->interval_us, now);
*/
static void note_update(mt_sub_t *s, uint64_t now)
{
    s->last_us = mt_bus_clamp_next(s->last_us, s->interval_us, now);
}

/*@ requires MtSubInv(s);
    assigns s->torn;
    ensures MtSubInv(s);
    ensures s->torn == MtSatInc(\old(s->torn));
*/
static void note_torn(mt_sub_t *s)
{
    s->torn = mt_inc_sat_u32(s->torn);
}

mt_status_t mt_sub_copy_next(mt_sub_t *s, void *out, uint32_t size, uint64_t now_us)
{
    const mt_topic_t *t = s->topic;
    uint32_t tries;

    if (size != t->size) {
        return MT_E_BUS_MSG_SIZE;
    }
    /*@ loop invariant 0 <= tries <= MT_CFG_BUS_COPY_TRIES;
        loop invariant MtSubInv(s);
        loop invariant s->gen == \at(s->gen, Pre) && s->torn == \at(s->torn, Pre);
        loop invariant buf_kept: \forall integer k; 0 <= k < s->topic->size * s->topic->qlen ==>
            s->topic->buf[k] == \at(s->topic->buf[k], Pre);
        loop invariant looked: tries != 0 ==> s->topic->gen != s->gen;
        loop invariant quiet: !MtSeqRacing ==> tries == 0;
        loop assigns tries, ((uint8_t *)out)[0 .. size - 1];
        loop variant MT_CFG_BUS_COPY_TRIES - tries;
    */
    for (tries = 0u; tries < MT_CFG_BUS_COPY_TRIES; tries++) {
        uint32_t gen = mt_load_acquire_u32(&t->gen);
        uint32_t head = mt_load_acquire_u32(&t->head);
        uint32_t pending = mt_bus_gen_dist(gen, s->gen);
        uint32_t d;

        if (pending == 0u) {
            return MT_E_EMPTY;
        }
        /* more than qlen behind: the oldest retained message, qlen - 1 before the newest */
        d = next_dist(pending, t->qlen);
        if (try_copy(t, gen, head, d, (uint8_t *)out) != 0u) {
            /*@ assert got: \forall integer k; 0 <= k < t->size ==>
                    \let o = MtSlotBack(head, d, t->qlen) * t->size + k;
                    ((uint8_t *)out)[k] == t->buf[o] && t->buf[o] == \at(s->topic->buf[o], Pre); */
            uint32_t lost = (pending > t->qlen) ? (pending - t->qlen) : 0u;
            consume(s, gen_back(gen, d), lost, 0u, 1u);
            note_update(s, now_us);
            return (lost != 0u) ? MT_W_BUS_MISSED : MT_OK;
        }
    }
    note_torn(s);
    return MT_E_BUS_TORN;
}

mt_status_t mt_sub_copy_latest(mt_sub_t *s, void *out, uint32_t size, uint64_t now_us)
{
    const mt_topic_t *t = s->topic;
    uint32_t tries;

    if (size != t->size) {
        return MT_E_BUS_MSG_SIZE;
    }
    if (mt_load_acquire_u32(&t->published) == 0u) {
        return MT_E_EMPTY;
    }
    /*@ loop invariant 0 <= tries <= MT_CFG_BUS_COPY_TRIES;
        loop invariant MtSubInv(s);
        loop invariant s->gen == \at(s->gen, Pre) && s->torn == \at(s->torn, Pre);
        loop invariant buf_kept: \forall integer k; 0 <= k < s->topic->size * s->topic->qlen ==>
            s->topic->buf[k] == \at(s->topic->buf[k], Pre);
        loop invariant quiet: !MtSeqRacing ==> tries == 0;
        loop assigns tries, ((uint8_t *)out)[0 .. size - 1];
        loop variant MT_CFG_BUS_COPY_TRIES - tries;
    */
    for (tries = 0u; tries < MT_CFG_BUS_COPY_TRIES; tries++) {
        uint32_t gen = mt_load_acquire_u32(&t->gen);
        uint32_t head = mt_load_acquire_u32(&t->head);
        uint32_t pending = mt_bus_gen_dist(gen, s->gen);

        if (try_copy(t, gen, head, 0u, (uint8_t *)out) != 0u) {
            /*@ assert got: \forall integer k; 0 <= k < t->size ==>
                    \let o = MtSlotBack(head, 0, t->qlen) * t->size + k;
                    ((uint8_t *)out)[k] == t->buf[o] && t->buf[o] == \at(s->topic->buf[o], Pre); */
            /* overwritten before this copy looked: missed; still retained: skipped */
            uint32_t lost = (pending > t->qlen) ? (pending - t->qlen) : 0u;
            uint32_t passed = (pending == 0u) ? 0u : ((pending - 1u) - lost);
            consume(s, gen, lost, passed, (pending != 0u) ? 1u : 0u);
            note_update(s, now_us);
            return (lost != 0u) ? MT_W_BUS_MISSED : MT_OK;
        }
    }
    note_torn(s);
    return MT_E_BUS_TORN;
}
