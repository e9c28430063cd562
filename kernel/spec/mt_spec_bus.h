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

/* MtTopicStamped: each of the newest messages still in the queue (as many as were
 * published, at most qlen) lies in its slot under its generation's stamp, so a copy of it
 * that no concurrent writer disturbs passes both stamp checks (mt_sub_copy_next).
 * MtTopicInv: the topic's shape and MtTopicStamped.
 * MtSubInv: the subscriber's topic is sound and the subscriber is no further behind than
 * the topic has publications (a saturated count, 2^32 - 1, bounds every distance).
 * MtTopicBehind: some registered reliable subscriber has not consumed the oldest queued
 * message. */
/*@ predicate MtTopicStamped(mt_topic_t *t) =
        \forall integer d; 0 <= d < t->qlen && d < t->publishes ==>
            t->stamp[MtSlotBack(t->head, d, t->qlen)] == MtGenBack(t->gen, d);

    predicate MtTopicInv(mt_topic_t *t) =
        \valid(t) &&
        1 <= t->size <= MT_CFG_BUS_MAX_MSG && 1 <= t->qlen <= MT_CFG_BUS_MAX_QUEUE &&
        t->head < t->qlen && t->published <= 1 && t->reliable <= 1 &&
        (t->published == 0 <==> t->publishes == 0) &&
        t->nnotify <= MT_CFG_BUS_MAX_NOTIFY && t->nrel <= MT_CFG_BUS_MAX_RELIABLE &&
        (t->reliable == 0 ==> t->nrel == 0) &&
        \valid(t->buf + (0 .. t->size * t->qlen - 1)) &&
        \separated(t, t->buf + (0 .. t->size * t->qlen - 1)) &&
        MtTopicStamped(t);

    predicate MtSubInv(mt_sub_t *s) =
        \valid(s) && MtTopicInv(s->topic) && \separated(s, s->topic) &&
        \separated(s, s->topic->buf + (0 .. s->topic->size * s->topic->qlen - 1)) &&
        s->rel <= s->topic->nrel && s->notify <= s->topic->nnotify &&
        MtGenDist(s->topic->gen, s->gen) <= s->topic->publishes &&
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

/* The per-outcome clauses that the three forms state alike (their behaviors msg_size, behind
 * and ok use these under the same labels), from state L1 before the call to L2 after it.
 * The scalar arguments are read by the clause, so that the prover sees the same terms in the
 * lock-held form's proof and in the task and ISR forms' (through predicates that read the
 * topic's fields themselves, five goals of mt_topic_publish_i timed out in both provers):
 * MtPublishKept            a refusal: generation, head and publish count unchanged;
 * MtPublishNothingWritten  a refusal: no byte of the storage changed;
 * MtPublishData            the n bytes at buf + off are the message's (read at L2);
 * MtPublishOthersKept      every byte of the len at buf outside [off, off + n) is unchanged;
 * MtPublishNotified        the step of every registered notifier (n of them), MtNotifyStep;
 * MtPublishUnusedKept      no notifier slot from n on was called. */
/*@ predicate MtPublishKept{L1, L2}(mt_topic_t *t) =
        \at(t->gen, L2) == \at(t->gen, L1) && \at(t->head, L2) == \at(t->head, L1) &&
        \at(t->publishes, L2) == \at(t->publishes, L1);

    predicate MtPublishNothingWritten{L1, L2}(mt_topic_t *t) =
        \forall integer k; 0 <= k < \at(t->size * t->qlen, L2) ==>
            \at(t->buf[k], L2) == \at(t->buf[k], L1);

    predicate MtPublishData(uint8_t *buf, integer off, uint8_t *msg, integer n) =
        \forall integer k; 0 <= k < n ==> buf[off + k] == msg[k];

    predicate MtPublishOthersKept{L1, L2}(uint8_t *buf, integer len, integer off, integer n) =
        \forall integer k; 0 <= k < len ==> (k < off || k >= off + n) ==>
            \at(buf[k], L2) == \at(buf[k], L1);
*/

/* A publish's step for registered notifier i, from state L1 to L2 (bus.h, "Notifiers"):
 * MtNotifyFired  it was called once through its trampoline (MtCalls slot MT_CALL_NOTIFY(i)),
 *                its call count went up and its last generation is the topic's;
 * MtNotifyHeld   it was not called and the hold-back was counted;
 * MtNotifyStep   fired only when its count gate was open and its interval gate open at a
 *                time no later than L2's clock; held only when the count gate was closed,
 *                the interval gate closed at L1's clock (so at every later reading), or it
 *                has no function (never, for one mt_topic_notify_add registered);
 * MtNotifyKept   untouched: neither called nor counted (its settings are outside every
 *                publish's assigns). */
/*@ predicate MtNotifyFired{L1, L2}(mt_topic_t *t, integer i) =
        \at(t->notify_calls[i], L2) == MtSatInc(\at(t->notify_calls[i], L1)) &&
        \at(t->notify_gated[i], L2) == \at(t->notify_gated[i], L1) &&
        \at(t->notify_last_gen[i], L2) == \at(t->gen, L2) &&
        \at(MtCalls[MT_CALL_NOTIFY(i)], L2) == MtCount64(\at(MtCalls[MT_CALL_NOTIFY(i)], L1), 1);

    predicate MtNotifyHeld{L1, L2}(mt_topic_t *t, integer i) =
        \at(t->notify_calls[i], L2) == \at(t->notify_calls[i], L1) &&
        \at(t->notify_gated[i], L2) == MtSatInc(\at(t->notify_gated[i], L1)) &&
        \at(t->notify_last_gen[i], L2) == \at(t->notify_last_gen[i], L1) &&
        \at(MtCalls[MT_CALL_NOTIFY(i)], L2) == \at(MtCalls[MT_CALL_NOTIFY(i)], L1);

    predicate MtNotifyStep{L1, L2}(mt_topic_t *t, integer i) =
        (MtNotifyFired{L1, L2}(t, i) &&
         MtGenDist(\at(t->gen, L2), \at(t->notify_last_gen[i], L1)) >=
             \at(t->notify_min_updates[i], L2) &&
         MtDue(\at(t->notify_last_us[i], L1), \at(t->notify_interval_us[i], L2),
               \at(MtPortNow, L2))) ||
        (MtNotifyHeld{L1, L2}(t, i) &&
         (MtGenDist(\at(t->gen, L2), \at(t->notify_last_gen[i], L1)) <
              \at(t->notify_min_updates[i], L2) ||
          !MtDue(\at(t->notify_last_us[i], L1), \at(t->notify_interval_us[i], L2),
                 \at(MtPortNow, L1)) ||
          \at(t->notify_fn[i], L2) == \null));

    predicate MtNotifyKept{L1, L2}(mt_topic_t *t, integer i) =
        \at(t->notify_calls[i], L2) == \at(t->notify_calls[i], L1) &&
        \at(t->notify_gated[i], L2) == \at(t->notify_gated[i], L1) &&
        \at(t->notify_last_gen[i], L2) == \at(t->notify_last_gen[i], L1) &&
        \at(t->notify_last_us[i], L2) == \at(t->notify_last_us[i], L1) &&
        \at(MtCalls[MT_CALL_NOTIFY(i)], L2) == \at(MtCalls[MT_CALL_NOTIFY(i)], L1);
*/

/* Lemma (proved by WP): an interval gate open at one time is open at every later time. */
/*@ lemma MtDueLater: \forall integer last, iv, a, b;
        a <= b ==> MtDue(last, iv, a) ==> MtDue(last, iv, b);
*/

/* A refused publish (every form, L1 before the call, L2 after it) calls no notifier and
 * changes none. (An accepted one takes each registered notifier's step, MtNotifyStep, and
 * calls no unregistered entry: clauses notified and unused_not_called.) */
/*@ predicate MtPublishNotifiedNone{L1, L2}(mt_topic_t *t) =
        \forall integer i; 0 <= i < MT_CFG_BUS_MAX_NOTIFY ==> MtNotifyKept{L1, L2}(t, i);

    predicate MtPublishNotified{L1, L2}(mt_topic_t *t, integer n) =
        \forall integer i; 0 <= i < n ==> MtNotifyStep{L1, L2}(t, i);

    predicate MtPublishUnusedKept{L1, L2}(integer n) =
        \forall integer i; n <= i < MT_CFG_BUS_MAX_NOTIFY ==>
            \at(MtCalls[MT_CALL_NOTIFY(i)], L2) == \at(MtCalls[MT_CALL_NOTIFY(i)], L1);
*/

/* Lemma (proved by WP): a publish shifts every retained message one place back, in slot
 * and in generation, and none of them lies in the slot it writes (MtTopicStamped kept). */
/*@ lemma MtSlotShift: \forall integer h, q, d;
        1 <= q ==> 0 <= h < q ==> 1 <= d < q ==>
        MtSlotBack(MtSlotNext(h, q), d, q) == MtSlotBack(h, d - 1, q);

    lemma MtSlotShiftOther: \forall integer h, q, d;
        1 <= q ==> 0 <= h < q ==> 1 <= d < q ==>
        MtSlotBack(h, d - 1, q) != MtSlotNext(h, q);

    lemma MtGenShift: \forall integer g, d;
        0 <= g <= 4294967295 ==> 1 <= d <= 4294967295 ==>
        MtGenBack(MtGenNext(g), d) == MtGenBack(g, d - 1);
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
     requires t->head < t->qlen && t->published == 0 && t->publishes == 0 && t->reliable <= 1;
     requires t->nnotify == 0 && t->nrel == 0;
     requires \valid(t->buf + (0 .. t->size * t->qlen - 1));
     requires \separated(t, t->buf + (0 .. t->size * t->qlen - 1));
     assigns \nothing;
     ensures MtTopicInv(t);
  @/
  static void topic_inv_intro(mt_topic_t *t) { }
*/

#endif /* MT_SPEC_BUS_H */
