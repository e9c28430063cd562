/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_bus.h
 * @brief ACSL logic for the topic bus (mt/bus.h): the wrap-free arithmetic, the topic and
 *        subscriber predicates, the clauses the publish forms share, and the bus's lemmas.
 *
 * Generations are uint32 values that wrap from 0xFFFFFFFF to 0. Every
 * distance is computed by a case split, never by a wrapping subtraction, so
 * each formula below is also the C expression (kernel/src/bus.c, bus_sub.c) and no
 * intermediate value leaves [0, 2^32).
 *
 * Only ACSL lives here: to a C compiler this header is empty. mt/bus.h includes it after
 * its types (the predicates read mt_topic_t and mt_sub_t); the ghost lemmas are proved by WP
 * in each file that includes it (bus.c, bus_sub.c) and called from bus.c's annotations.
 */
#ifndef MT_SPEC_BUS_H
#define MT_SPEC_BUS_H

/* MtGenDist(a, b)     messages published after generation b up to a (a - b mod 2^32)
 * MtGenNext(g)        the generation after g
 * MtGenBack(g, d)     the generation d messages before g (g - d mod 2^32, 0 <= d < 2^32)
 * MtSlotNext(h, q)    the queue slot after h in a queue of q slots
 * MtSlotBack(h, d, q) the queue slot d places before h (0 <= d < q)
 * MtSatInc, MtSatAdd  saturating 32-bit counters
 * MtNextDist(p, q)            how many messages before the newest the next message to copy
 *                              lies, for a subscriber p behind in a queue of q (p >= 1): the
 *                              oldest retained one (q - 1) when more than q behind
 * MtDue(last, iv, now)         an interval gate is open: iv is 0, or at least iv
 *                              microseconds passed since last (uORB SubscriptionInterval)
 * MtClampNext(last, iv, now)   the gate's new last time after an update: last + iv,
 *                              clamped to [now - iv, now] (now itself when now <= iv) */
/*@ logic integer MtGenDist(integer a, integer b) =
        a >= b ? a - b : (a + 4294967296) - b;

    logic integer MtGenNext(integer g) = g < 4294967295 ? g + 1 : 0;

    logic integer MtGenBack(integer g, integer d) =
        g >= d ? g - d : (g + 4294967296) - d;

    logic integer MtSlotNext(integer h, integer q) = h + 1 < q ? h + 1 : 0;

    logic integer MtSlotBack(integer h, integer d, integer q) = h >= d ? h - d : (h + q) - d;

    logic integer MtSatInc(integer x) = x < 4294967295 ? x + 1 : x;

    logic integer MtSatAdd(integer x, integer k) = x + k <= 4294967295 ? x + k : 4294967295;

    logic integer MtNextDist(integer p, integer q) = p > q ? q - 1 : p - 1;

    predicate MtDue(integer last, integer iv, integer now) =
        iv == 0 || (now >= last && now - last >= iv);

    logic integer MtClampNext(integer last, integer iv, integer now) =
        now <= iv ? now :
        (last + iv > now ? now : (last + iv < now - iv ? now - iv : last + iv));
*/

/* MtTopicBehind: some registered reliable subscriber has not consumed the oldest queued
 * message. */
/*@ predicate MtTopicInv(mt_topic_t *t) =
        \valid(t) &&
        1 <= t->size <= MT_CFG_BUS_MAX_MSG && 1 <= t->qlen <= MT_CFG_BUS_MAX_QUEUE &&
        t->head < t->qlen && t->published <= 1 && t->reliable <= 1 &&
        t->nnotify <= MT_CFG_BUS_MAX_NOTIFY && t->nrel <= MT_CFG_BUS_MAX_RELIABLE &&
        (t->reliable == 0 ==> t->nrel == 0) &&
        \valid(t->buf + (0 .. t->size * t->qlen - 1)) &&
        \separated(t, t->buf + (0 .. t->size * t->qlen - 1));

    predicate MtSubInv(mt_sub_t *s) =
        \valid(s) && MtTopicInv(s->topic) && \separated(s, s->topic) &&
        \separated(s, s->topic->buf + (0 .. s->topic->size * s->topic->qlen - 1)) &&
        s->rel <= s->topic->nrel && s->notify <= s->topic->nnotify &&
        MtSemInv(&s->sem);

    predicate MtTopicBehind(mt_topic_t *t) =
        \exists integer i; 0 <= i < t->nrel && MtGenDist(t->gen, t->rel_gen[i]) >= t->qlen;

    predicate MtNotifyRegistered(mt_topic_t *t, mt_bus_notify_fn_t fn, void *arg) =
        \exists integer i; 0 <= i < t->nnotify && t->notify_fn[i] == fn && t->notify_arg[i] == arg;

    logic integer MtSubPending(mt_sub_t *s) = MtGenDist(s->topic->gen, s->gen);

*/

/* Clauses that mt_topic_publish_i, mt_topic_publish and mt_topic_publish_isr state alike
 * (requires msg: MtPublishMsg; the task and ISR forms' status, generation and refused
 * postconditions: MtPublishStatus, MtPublishGeneration, MtPublishRefused, with L1 the state
 * before the call and L2 the state after it). */
/*@ predicate MtPublishMsg(mt_topic_t *t, uint8_t *msg, integer size) =
        size == t->size ==> \valid_read(msg + (0 .. size - 1)) &&
        \separated(msg + (0 .. size - 1), t, t->buf + (0 .. t->size * t->qlen - 1));

    predicate MtPublishStatus(integer r) =
        r == MT_OK || r == MT_E_BUS_MSG_SIZE || r == MT_E_BUS_BEHIND;

    predicate MtPublishGeneration{L1, L2}(mt_topic_t *t, integer r) =
        r == MT_OK ==> \at(t->gen, L2) == MtGenNext(\at(t->gen, L1));

    predicate MtPublishRefused{L1, L2}(mt_topic_t *t, integer r) =
        r != MT_OK ==> \at(t->gen, L2) == \at(t->gen, L1) &&
                       \at(t->rejected, L2) == MtSatInc(\at(t->rejected, L1));
*/

/* Lemma (ghost function, proved by WP, called only from annotations). */
/*@ ghost
  /@ requires 0 <= a <= b;
     requires h >= 1;
     assigns \nothing;
     ensures a * h <= b * h;
  @/
  static void mul_mono_lemma(uint32_t a, uint32_t b, uint32_t h) { }
*/

/* Lemma (ghost function, proved by WP): the topic invariant from its parts, in a small
 * context (the parts are discharged at the call site after the chain of stores). */
/*@ ghost
  /@ requires \valid(t);
     requires 1 <= t->size <= MT_CFG_BUS_MAX_MSG && 1 <= t->qlen <= MT_CFG_BUS_MAX_QUEUE;
     requires t->head < t->qlen && t->published <= 1 && t->reliable <= 1;
     requires t->nnotify == 0 && t->nrel == 0;
     requires \valid(t->buf + (0 .. t->size * t->qlen - 1));
     requires \separated(t, t->buf + (0 .. t->size * t->qlen - 1));
     assigns \nothing;
     ensures MtTopicInv(t);
  @/
  static void topic_inv_intro(mt_topic_t *t) { }
*/

#endif /* MT_SPEC_BUS_H */
