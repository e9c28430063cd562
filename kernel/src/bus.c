/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file bus.c
 * @brief Topic bus (see mt/bus.h), the side under the kernel lock: topic set-up, publishers
 *        and the notifier calls. The registrations (notifiers, reliable subscribers, poll) are
 *        in bus_reg.c; the lock-free subscriber copies, checked by per-slot stamps (seqlock),
 *        in bus_sub.c.
 */
#include "mt/bus.h"

#include "mt_atomic.h"
#include "mt_bus_int.h"
#include "mt_bus_invoke.h"
#include "mt_sat.h"

/* ------------------------------------------------------------------------------------------
 * Wrap-free arithmetic: each helper is its logic twin in mt_spec_bus.h, by case split
 * (the mt_bus_ ones: contracts in mt_bus_int.h). */

uint32_t mt_bus_gen_dist(uint32_t a, uint32_t b)
{
    /* a < b: the distance crosses the wrap, a + 2^32 - b, computed without leaving 32 bits */
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (a >= b) ? (a - b) : (((0xFFFFFFFFu - b) + a) + 1u);
}

/*@ assigns \nothing;
    ensures \result == MtGenNext(g);
*/
static uint32_t gen_next(uint32_t g)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (g < 0xFFFFFFFFu) ? (g + 1u) : 0u;
}

/*@ requires h < q <= MT_CFG_BUS_MAX_QUEUE;
    assigns \nothing;
    ensures \result == MtSlotNext(h, q);
    ensures \result < q;
*/
static uint32_t slot_next(uint32_t h, uint32_t q)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return ((h + 1u) < q) ? (h + 1u) : 0u;
}

bool mt_bus_interval_due(uint64_t last, uint32_t iv, uint64_t now)
{
    return (iv == 0u) || ((now >= last) && ((now - last) >= iv));
}

uint64_t mt_bus_clamp_next(uint64_t last, uint32_t iv, uint64_t now)
{
    uint64_t r;

    if ((now <= iv) || (last > (now - iv))) {
        r = now;
    } else if ((last + iv) < (now - iv)) {
        r = now - iv;
    } else {
        r = last + iv;
    }
    return r;
}

/* ------------------------------------------------------------------------------------------
 * Slots and bytes */

uint8_t *mt_bus_slot_ptr(const mt_topic_t *t, uint32_t slot)
{
    //@ ghost mul_mono_lemma(slot + 1u, t->qlen, t->size);
    return t->buf + ((uint64_t)slot * t->size);
}

/* Copy n message bytes into a slot (publisher, lock held): relaxed stores, ordered after
 * the slot's stamp by mt_seq_stamp_u32's release fence. */
/*@ requires \valid(dst + (0 .. n - 1)) && \valid_read(src + (0 .. n - 1));
    requires \separated(dst + (0 .. n - 1), src + (0 .. n - 1));
    assigns dst[0 .. n - 1];
    ensures \forall integer k; 0 <= k < n ==> dst[k] == src[k];
*/
static void write_bytes(uint8_t *dst, const uint8_t *src, uint32_t n)
{
    uint32_t k;

    /*@ loop invariant 0 <= k <= n;
        loop invariant \forall integer j; 0 <= j < k ==> dst[j] == src[j];
        loop assigns k, dst[0 .. n - 1];
        loop variant n - k;
    */
    for (k = 0u; k < n; k++) {
        mt_store_relaxed_u8(&dst[k], src[k]);
    }
}

/* ------------------------------------------------------------------------------------------
 * Topic */

/* Validation of a topic description (check-then-act: no write). */
/*@ requires \valid_read(d);
    assigns \nothing;
    behavior invalid:
      assumes d->name == \null || (d->flags != 0 && d->flags != MT_TOPIC_RELIABLE);
      ensures \result == MT_E_INVALID;
    behavior msg_size:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes d->msg_size < 1 || d->msg_size > MT_CFG_BUS_MAX_MSG;
      ensures \result == MT_E_BUS_MSG_SIZE;
    behavior queue_len:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes 1 <= d->msg_size <= MT_CFG_BUS_MAX_MSG;
      assumes d->queue_len < 1 || d->queue_len > MT_CFG_BUS_MAX_QUEUE;
      ensures \result == MT_E_BUS_QUEUE_LEN;
    behavior storage:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes 1 <= d->msg_size <= MT_CFG_BUS_MAX_MSG;
      assumes 1 <= d->queue_len <= MT_CFG_BUS_MAX_QUEUE;
      assumes storage == \null || storage_bytes < d->msg_size * d->queue_len;
      ensures \result == MT_E_BUS_STORAGE;
    behavior ok:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes 1 <= d->msg_size <= MT_CFG_BUS_MAX_MSG;
      assumes 1 <= d->queue_len <= MT_CFG_BUS_MAX_QUEUE;
      assumes storage != \null && storage_bytes >= d->msg_size * d->queue_len;
      ensures \result == MT_OK;
    complete behaviors;
    disjoint behaviors;
*/
static mt_status_t check_desc(const mt_topic_desc_t *d, const void *storage,
                              uint32_t storage_bytes)
{
    mt_status_t st = MT_OK;

    // cppcheck-suppress misra-c2012-11.4 ; D-104 null pointer constant of the pointer's type
    if ((d->name == (const char *)0) || ((d->flags != 0u) && (d->flags != MT_TOPIC_RELIABLE))) {
        st = MT_E_INVALID;
    } else if ((d->msg_size < 1u) || (d->msg_size > MT_CFG_BUS_MAX_MSG)) {
        st = MT_E_BUS_MSG_SIZE;
    } else if ((d->queue_len < 1u) || (d->queue_len > MT_CFG_BUS_MAX_QUEUE)) {
        st = MT_E_BUS_QUEUE_LEN;
    } else {
        //@ ghost mul_mono_lemma(d->queue_len, MT_CFG_BUS_MAX_QUEUE, d->msg_size);
        if ((storage == (const void *)0) || (storage_bytes < (d->msg_size * d->queue_len))) {
            st = MT_E_BUS_STORAGE;
        }
    }
    return st;
}

/* Fill in a validated topic (scalar arguments: no read of the description after a store
 * into the topic, so no frame goal between the two objects). */
/*@ requires \valid(t);
    requires 1 <= size <= MT_CFG_BUS_MAX_MSG && 1 <= qlen <= MT_CFG_BUS_MAX_QUEUE;
    requires reliable <= 1;
    requires \valid(buf + (0 .. size * qlen - 1));
    requires \separated(t, buf + (0 .. size * qlen - 1));
    assigns *t;
    ensures MtTopicInv(t);
    ensures t->size == size && t->qlen == qlen && t->buf == buf && t->reliable == reliable &&
            t->name == name;
    ensures t->gen == first_gen && t->published == 0 && t->nnotify == 0 && t->nrel == 0;
    ensures t->publishes == 0 && t->rejected == 0 && t->notified == 0;
*/
static void setup(mt_topic_t *t, const char *name, uint8_t *buf, uint32_t size, uint32_t qlen,
                  uint32_t reliable, uint32_t first_gen)
{
    uint32_t i;

    /* A slot never written keeps the stamp first_gen, which no copy targets before 2^32
     * publications (a copy targets a published generation, first_gen + 1 or later). */
    /*@ loop invariant 0 <= i <= MT_CFG_BUS_MAX_QUEUE;
        loop assigns i, t->stamp[0 .. MT_CFG_BUS_MAX_QUEUE - 1];
        loop variant MT_CFG_BUS_MAX_QUEUE - i;
    */
    for (i = 0u; i < MT_CFG_BUS_MAX_QUEUE; i++) {
        t->stamp[i] = first_gen;
    }
    t->gen = first_gen;
    t->head = qlen - 1u; /* the first message goes to slot 0 */
    t->published = 0u;
    t->publishes = 0u;
    t->rejected = 0u;
    t->notified = 0u;
    t->nnotify = 0u;
    t->nrel = 0u;
    t->name = name;
    t->buf = buf;
    t->size = size;
    t->qlen = qlen;
    t->reliable = reliable;
    //@ ghost topic_inv_intro(t);
}

mt_status_t mt_topic_init(mt_topic_t *t, const mt_topic_desc_t *d, void *storage,
                          uint32_t storage_bytes)
{
    mt_status_t st = check_desc(d, storage, storage_bytes);

    if (st != MT_OK) {
        t->size = 0u; /* unusable */
        return st;
    }
    setup(t, d->name, (uint8_t *)storage, d->msg_size, d->queue_len,
          (d->flags == MT_TOPIC_RELIABLE) ? 1u : 0u, d->first_gen);
    return MT_OK;
}

/* Does a registered reliable subscriber still need the oldest queued message? Its
 * generation is written by that subscriber (release) and read here with acquire. */
/*@ requires MtTopicInv(t);
    assigns \nothing;
    ensures \result == 1 <==> MtTopicBehind(t);
    ensures \result == 0 || \result == 1;
*/
static uint32_t any_behind(const mt_topic_t *t)
{
    uint32_t i;

    /*@ loop invariant 0 <= i <= t->nrel;
        loop invariant \forall integer j; 0 <= j < i ==>
            MtGenDist(t->gen, t->rel_gen[j]) < t->qlen;
        loop assigns i;
        loop variant t->nrel - i;
    */
    for (i = 0u; i < t->nrel; i++) {
        if (mt_bus_gen_dist(t->gen, mt_load_acquire_u32(&t->rel_gen[i])) >= t->qlen) {
            return 1u;
        }
    }
    return 0u;
}

/*@ requires MtTopicInv(t);
    assigns t->rejected;
    ensures MtTopicInv(t);
    ensures t->rejected == MtSatInc(\old(t->rejected));
*/
// cppcheck-suppress misra-c2012-5.9 ; D-106 module-local helper, one per translation unit
static void note_rejected(mt_topic_t *t)
{
    t->rejected = mt_inc_sat_u32(t->rejected);
}

/* Write msg into the slot after head and publish it: stamp (then a release fence),
 * bytes, head, published, generation (release stores, in this order: a subscriber loads
 * the generation first, so the head it loads next is never older). */
/*@ requires MtTopicInv(t);
    requires \valid_read(msg + (0 .. t->size - 1));
    requires \separated(msg + (0 .. t->size - 1), t, t->buf + (0 .. t->size * t->qlen - 1));
    assigns t->gen, t->head, t->published, t->stamp[0 .. MT_CFG_BUS_MAX_QUEUE - 1],
            t->buf[0 .. t->size * t->qlen - 1], t->publishes;
    ensures MtTopicInv(t);
    ensures t->publishes == MtSatInc(\old(t->publishes));
    ensures notify_kept: \forall integer i; 0 <= i < MT_CFG_BUS_MAX_NOTIFY ==>
        t->notify_last_gen[i] == \old(t->notify_last_gen[i]) &&
        t->notify_min_updates[i] == \old(t->notify_min_updates[i]) &&
        t->notify_calls[i] == \old(t->notify_calls[i]) &&
        t->notify_gated[i] == \old(t->notify_gated[i]);
    ensures t->gen == MtGenNext(\old(t->gen));
    ensures t->head == MtSlotNext(\old(t->head), t->qlen);
    ensures t->published == 1;
    ensures t->stamp[t->head] == t->gen;
    ensures \forall integer k; 0 <= k < t->size ==> t->buf[t->head * t->size + k] == msg[k];
    ensures \forall integer k; 0 <= k < t->size * t->qlen ==>
        (k < t->head * t->size || k >= t->head * t->size + t->size) ==>
        t->buf[k] == \old(t->buf[k]);
*/
// cppcheck-suppress misra-c2012-5.9 ; D-106 module-local helper, one per translation unit
static void put(mt_topic_t *t, const uint8_t *msg)
{
    uint32_t ng = gen_next(t->gen);
    uint32_t nh = slot_next(t->head, t->qlen);
    uint8_t *dst = mt_bus_slot_ptr(t, nh);

    mt_seq_stamp_u32(&t->stamp[nh], ng);
    write_bytes(dst, msg, t->size);
    mt_store_release_u32(&t->head, nh);
    mt_store_release_u32(&t->published, 1u);
    mt_store_release_u32(&t->gen, ng);
    t->publishes = mt_inc_sat_u32(t->publishes);
}

/* Notifier i: pass its gates or count the hold-back (MtNotifyStep of mt_spec_bus.h with
 * each read spelled out: the provers then see memory reads, which Qed simplifies, rather
 * than a predicate of two memory states). */
/*@ requires held: MtLocked == 1;
    requires MtTopicInv(t);
    requires i < t->nnotify;
    assigns t->notify_last_gen[i], t->notify_last_us[i], t->notify_calls[i],
            t->notify_gated[i], t->notified, MtPortNow, MtPortWakes, MtCalls[MT_CALL_NOTIFY(i)];
    ensures MtTopicInv(t);
    ensures step:
        (t->notify_calls[i] == MtSatInc(\old(t->notify_calls[i])) &&
         t->notify_gated[i] == \old(t->notify_gated[i]) &&
         t->notify_last_gen[i] == t->gen &&
         MtCalls[MT_CALL_NOTIFY(i)] == MtCount64(\old(MtCalls[MT_CALL_NOTIFY(i)]), 1) &&
         MtGenDist(t->gen, \old(t->notify_last_gen[i])) >= t->notify_min_updates[i] &&
         MtDue(\old(t->notify_last_us[i]), t->notify_interval_us[i], MtPortNow)) ||
        (t->notify_calls[i] == \old(t->notify_calls[i]) &&
         t->notify_gated[i] == MtSatInc(\old(t->notify_gated[i])) &&
         t->notify_last_gen[i] == \old(t->notify_last_gen[i]) &&
         MtCalls[MT_CALL_NOTIFY(i)] == \old(MtCalls[MT_CALL_NOTIFY(i)]) &&
         (MtGenDist(t->gen, \old(t->notify_last_gen[i])) < t->notify_min_updates[i] ||
          !MtDue(\old(t->notify_last_us[i]), t->notify_interval_us[i], \old(MtPortNow)) ||
          t->notify_fn[i] == \null));
    ensures time: MtPortNow >= \old(MtPortNow);
    ensures gen_kept: t->gen == \old(t->gen);
    ensures settings_kept: \forall integer j; 0 <= j < MT_CFG_BUS_MAX_NOTIFY ==>
        t->notify_min_updates[j] == \old(t->notify_min_updates[j]) &&
        t->notify_interval_us[j] == \old(t->notify_interval_us[j]) &&
        t->notify_fn[j] == \old(t->notify_fn[j]);
    ensures others: \forall integer j; 0 <= j < MT_CFG_BUS_MAX_NOTIFY && j != i ==>
        t->notify_calls[j] == \old(t->notify_calls[j]) &&
        t->notify_gated[j] == \old(t->notify_gated[j]) &&
        t->notify_last_gen[j] == \old(t->notify_last_gen[j]) &&
        t->notify_last_us[j] == \old(t->notify_last_us[j]) &&
        MtCalls[MT_CALL_NOTIFY(j)] == \old(MtCalls[MT_CALL_NOTIFY(j)]);
*/
static void notify_one(mt_topic_t *t, uint32_t i)
{
    bool fire = false;

    if (mt_bus_gen_dist(t->gen, t->notify_last_gen[i]) >= t->notify_min_updates[i]) {
        if (t->notify_interval_us[i] == 0u) {
            fire = true;
        } else {
            uint64_t now = mt_port_now_us();
            if (mt_bus_interval_due(t->notify_last_us[i], t->notify_interval_us[i], now)) {
                t->notify_last_us[i] =
                    mt_bus_clamp_next(t->notify_last_us[i], t->notify_interval_us[i], now);
                fire = true;
            }
        }
    }
    /* a registered notifier never has a NULL fn (mt_topic_notify_add refuses it); the
     * test keeps the dispatcher's requires local instead of in the topic invariant */
    if (fire && (t->notify_fn[i] != (mt_bus_notify_fn_t)0)) {
        t->notify_last_gen[i] = t->gen;
        t->notify_calls[i] = mt_inc_sat_u32(t->notify_calls[i]);
        t->notified = mt_inc_sat_u32(t->notified);
        mt_bus_invoke_notify(t->notify_fn[i], t->notify_arg[i], MT_CALL_NOTIFY(i));
    } else {
        t->notify_gated[i] = mt_inc_sat_u32(t->notify_gated[i]);
    }
}

/* Every registered notifier, in registration order. */
/*@ requires held: MtLocked == 1;
    requires MtTopicInv(t);
    assigns t->notify_last_gen[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_last_us[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_calls[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_gated[0 .. MT_CFG_BUS_MAX_NOTIFY - 1], t->notified, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_NOTIFY(0) .. MT_CALL_NOTIFY(MT_CFG_BUS_MAX_NOTIFY - 1)];
    ensures MtTopicInv(t);
    ensures notified: \forall integer i; 0 <= i < t->nnotify ==>
        (t->notify_calls[i] == MtSatInc(\old(t->notify_calls[i])) &&
         t->notify_gated[i] == \old(t->notify_gated[i]) &&
         t->notify_last_gen[i] == t->gen &&
         MtCalls[MT_CALL_NOTIFY(i)] == MtCount64(\old(MtCalls[MT_CALL_NOTIFY(i)]), 1) &&
         MtGenDist(t->gen, \old(t->notify_last_gen[i])) >= t->notify_min_updates[i] &&
         MtDue(\old(t->notify_last_us[i]), t->notify_interval_us[i], MtPortNow)) ||
        (t->notify_calls[i] == \old(t->notify_calls[i]) &&
         t->notify_gated[i] == MtSatInc(\old(t->notify_gated[i])) &&
         t->notify_last_gen[i] == \old(t->notify_last_gen[i]) &&
         MtCalls[MT_CALL_NOTIFY(i)] == \old(MtCalls[MT_CALL_NOTIFY(i)]) &&
         (MtGenDist(t->gen, \old(t->notify_last_gen[i])) < t->notify_min_updates[i] ||
          !MtDue(\old(t->notify_last_us[i]), t->notify_interval_us[i], \old(MtPortNow)) ||
          t->notify_fn[i] == \null));
    ensures unused_kept: \forall integer i; t->nnotify <= i < MT_CFG_BUS_MAX_NOTIFY ==>
        t->notify_calls[i] == \old(t->notify_calls[i]) &&
        t->notify_gated[i] == \old(t->notify_gated[i]) &&
        t->notify_last_gen[i] == \old(t->notify_last_gen[i]) &&
        t->notify_last_us[i] == \old(t->notify_last_us[i]) &&
        MtCalls[MT_CALL_NOTIFY(i)] == \old(MtCalls[MT_CALL_NOTIFY(i)]);
    ensures time: MtPortNow >= \old(MtPortNow);
    ensures kept: t->gen == \old(t->gen) && t->nnotify == \old(t->nnotify) &&
          (\forall integer i; 0 <= i < MT_CFG_BUS_MAX_NOTIFY ==>
              t->notify_min_updates[i] == \old(t->notify_min_updates[i]) &&
              t->notify_interval_us[i] == \old(t->notify_interval_us[i]) &&
              t->notify_fn[i] == \old(t->notify_fn[i]));
*/
static void notify_all(mt_topic_t *t)
{
    uint32_t n = t->nnotify;
    uint32_t i;

    /*@ loop invariant 0 <= i <= n && n == t->nnotify && n <= MT_CFG_BUS_MAX_NOTIFY;
        loop invariant MtTopicInv(t);
        loop invariant done_fired: \forall integer j; 0 <= j < i ==>
        MtCalls[MT_CALL_NOTIFY(j)] != \at(MtCalls[MT_CALL_NOTIFY(j)], LoopEntry) ==>
        t->notify_calls[j] == MtSatInc(\at(t->notify_calls[j], LoopEntry)) &&
        t->notify_gated[j] == \at(t->notify_gated[j], LoopEntry) &&
        t->notify_last_gen[j] == t->gen &&
        MtCalls[MT_CALL_NOTIFY(j)] == MtCount64(\at(MtCalls[MT_CALL_NOTIFY(j)], LoopEntry), 1) &&
        MtGenDist(t->gen, \at(t->notify_last_gen[j], LoopEntry)) >= t->notify_min_updates[j];
        loop invariant done_held: \forall integer j; 0 <= j < i ==>
        MtCalls[MT_CALL_NOTIFY(j)] == \at(MtCalls[MT_CALL_NOTIFY(j)], LoopEntry) ==>
        t->notify_calls[j] == \at(t->notify_calls[j], LoopEntry) &&
        t->notify_gated[j] == MtSatInc(\at(t->notify_gated[j], LoopEntry)) &&
        t->notify_last_gen[j] == \at(t->notify_last_gen[j], LoopEntry) &&
        (MtGenDist(t->gen, \at(t->notify_last_gen[j], LoopEntry)) < t->notify_min_updates[j] ||
         !MtDue(\at(t->notify_last_us[j], LoopEntry), t->notify_interval_us[j],
                \at(MtPortNow, LoopEntry)) ||
         t->notify_fn[j] == \null);
        loop invariant done_due: \forall integer j; 0 <= j < i ==>
        MtCalls[MT_CALL_NOTIFY(j)] != \at(MtCalls[MT_CALL_NOTIFY(j)], LoopEntry) ==>
        MtDue(\at(t->notify_last_us[j], LoopEntry), t->notify_interval_us[j], MtPortNow);
        loop invariant rest: \forall integer j; i <= j < MT_CFG_BUS_MAX_NOTIFY ==>
        t->notify_calls[j] == \at(t->notify_calls[j], LoopEntry) &&
        t->notify_gated[j] == \at(t->notify_gated[j], LoopEntry) &&
        t->notify_last_gen[j] == \at(t->notify_last_gen[j], LoopEntry) &&
        t->notify_last_us[j] == \at(t->notify_last_us[j], LoopEntry) &&
        MtCalls[MT_CALL_NOTIFY(j)] == \at(MtCalls[MT_CALL_NOTIFY(j)], LoopEntry);
        loop invariant time: MtPortNow >= \at(MtPortNow, LoopEntry);
        loop invariant settings_kept: \forall integer j; 0 <= j < MT_CFG_BUS_MAX_NOTIFY ==>
        t->notify_min_updates[j] == \at(t->notify_min_updates[j], LoopEntry) &&
        t->notify_interval_us[j] == \at(t->notify_interval_us[j], LoopEntry) &&
        t->notify_fn[j] == \at(t->notify_fn[j], LoopEntry);
        loop assigns i, t->notify_last_gen[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_last_us[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_calls[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_gated[0 .. MT_CFG_BUS_MAX_NOTIFY - 1], t->notified, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_NOTIFY(0) .. MT_CALL_NOTIFY(MT_CFG_BUS_MAX_NOTIFY - 1)];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        notify_one(t, i);
        /*@ assert this_one: \let k = i;
        (t->notify_calls[k] == MtSatInc(\at(t->notify_calls[k], LoopEntry)) &&
         t->notify_gated[k] == \at(t->notify_gated[k], LoopEntry) &&
         t->notify_last_gen[k] == t->gen &&
         MtCalls[MT_CALL_NOTIFY(k)] == MtCount64(\at(MtCalls[MT_CALL_NOTIFY(k)], LoopEntry), 1) &&
         MtGenDist(t->gen, \at(t->notify_last_gen[k], LoopEntry)) >= t->notify_min_updates[k]) ||
        (t->notify_calls[k] == \at(t->notify_calls[k], LoopEntry) &&
         t->notify_gated[k] == MtSatInc(\at(t->notify_gated[k], LoopEntry)) &&
         t->notify_last_gen[k] == \at(t->notify_last_gen[k], LoopEntry) &&
         MtCalls[MT_CALL_NOTIFY(k)] == \at(MtCalls[MT_CALL_NOTIFY(k)], LoopEntry) &&
         (MtGenDist(t->gen, \at(t->notify_last_gen[k], LoopEntry)) < t->notify_min_updates[k] ||
          !MtDue(\at(t->notify_last_us[k], LoopEntry), t->notify_interval_us[k], \at(MtPortNow, LoopEntry)) ||
          t->notify_fn[k] == \null)); */
        /*@ assert this_due: \let k = i;
              MtCalls[MT_CALL_NOTIFY(k)] != \at(MtCalls[MT_CALL_NOTIFY(k)], LoopEntry) ==>
              MtDue(\at(t->notify_last_us[k], LoopEntry), t->notify_interval_us[k], MtPortNow); */
    }
}

mt_status_t mt_topic_publish_i(mt_topic_t *t, const void *msg, uint32_t size)
{
    if (size != t->size) {
        note_rejected(t);
        return MT_E_BUS_MSG_SIZE;
    }
    if (any_behind(t) != 0u) {
        note_rejected(t);
        return MT_E_BUS_BEHIND;
    }
    put(t, (const uint8_t *)msg);
    /*@ assert notify_kept: \forall integer i; 0 <= i < MT_CFG_BUS_MAX_NOTIFY ==>
            t->notify_last_gen[i] == \at(t->notify_last_gen[i], Pre) &&
            t->notify_last_us[i] == \at(t->notify_last_us[i], Pre) &&
            t->notify_calls[i] == \at(t->notify_calls[i], Pre) &&
            t->notify_gated[i] == \at(t->notify_gated[i], Pre) &&
            MtCalls[MT_CALL_NOTIFY(i)] == \at(MtCalls[MT_CALL_NOTIFY(i)], Pre); */
    notify_all(t);
    return MT_OK;
}

mt_status_t mt_topic_publish(mt_topic_t *t, const void *msg, uint32_t size)
{
    mt_status_t st;

    mt_port_lock();
    st = mt_topic_publish_i(t, msg, size);
    mt_port_unlock();
    return st;
}

mt_status_t mt_topic_publish_isr(mt_topic_t *t, const void *msg, uint32_t size)
{
    mt_status_t st;

    mt_port_lock_isr();
    st = mt_topic_publish_i(t, msg, size);
    mt_port_unlock_isr();
    return st;
}
