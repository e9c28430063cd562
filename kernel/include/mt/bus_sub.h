/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/bus_sub.h
 * @brief Topic bus, the subscriber side: attach, the update test, the lock-free copies
 *        (kernel/src/bus_sub.c), reliable registration and poll (kernel/src/bus_reg.c). The
 *        operating rules, the types and the publishers are in mt/bus.h.
 */
#ifndef MT_BUS_SUB_H
#define MT_BUS_SUB_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/bus.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Attach subscriber s to topic t with a minimum update interval (0: none). The
 *  newest message published before the call, if any, is pending (uORB's initial
 *  generation). [subscriber thread; no lock] */
/*@ requires valid: \valid(s);
    requires inv: MtTopicInv(t);
    requires sep: \separated(s, t) && \separated(s, t->buf + (0 .. t->size * t->qlen - 1));
    assigns *s;
    ensures inv: MtSubInv(s);
    ensures attached: s->topic == t && s->interval_us == interval_us && s->last_us == 0;
    ensures pending: s->gen == (t->published == 1 ? MtGenBack(t->gen, 1) : t->gen);
    ensures fresh: s->received == 0 && s->missed == 0 && s->skipped == 0 && s->torn == 0 &&
                   s->rel == 0 && s->notify == 0;
    ensures sem: s->sem.token == 0 && s->sem.waiter == \null;
*/
void mt_sub_init(mt_sub_t *s, mt_topic_t *t, uint32_t interval_us);

/** Register s as a reliable subscriber of its topic (task context; takes the lock).
 *  @retval MT_OK
 *  @retval MT_E_STATE the topic was not declared MT_TOPIC_RELIABLE.
 *  @retval MT_E_DUPLICATE s is already registered.
 *  @retval MT_E_FULL MT_CFG_BUS_MAX_RELIABLE subscribers are registered. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSubInv(s);
    assigns s->rel, s->topic->rel_gen[s->topic->nrel], s->topic->nrel, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSubInv(s);
    behavior state:
      assumes s->topic->reliable == 0;
      ensures status: \result == MT_E_STATE;
      ensures unchanged: s->rel == \old(s->rel) && s->topic->nrel == \old(s->topic->nrel);
    behavior duplicate:
      assumes s->topic->reliable == 1 && s->rel != 0;
      ensures status: \result == MT_E_DUPLICATE;
      ensures unchanged: s->rel == \old(s->rel) && s->topic->nrel == \old(s->topic->nrel);
    behavior full:
      assumes s->topic->reliable == 1 && s->rel == 0 && s->topic->nrel == MT_CFG_BUS_MAX_RELIABLE;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: s->rel == \old(s->rel) && s->topic->nrel == \old(s->topic->nrel);
    behavior ok:
      assumes s->topic->reliable == 1 && s->rel == 0 && s->topic->nrel < MT_CFG_BUS_MAX_RELIABLE;
      ensures status: \result == MT_OK;
      ensures registered: s->topic->nrel == \old(s->topic->nrel) + 1 &&
                          s->rel == s->topic->nrel && s->topic->rel_gen[s->rel - 1] == s->gen;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sub_reliable(mt_sub_t *s);

/** Let mt_sub_poll() wait for s: registers a notifier that signals s->sem on every
 *  publish (task context; takes the lock).
 *  @retval MT_OK
 *  @retval MT_E_DUPLICATE poll is already enabled for s.
 *  @retval MT_E_FULL the topic has MT_CFG_BUS_MAX_NOTIFY notifiers. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSubInv(s);
    assigns s->notify, s->topic->notify_fn[s->topic->nnotify], s->topic->notify_arg[s->topic->nnotify], s->topic->notify_min_updates[s->topic->nnotify], s->topic->notify_interval_us[s->topic->nnotify], s->topic->notify_last_gen[s->topic->nnotify], s->topic->notify_last_us[s->topic->nnotify], s->topic->notify_calls[s->topic->nnotify], s->topic->notify_gated[s->topic->nnotify],
            s->topic->nnotify, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSubInv(s);
    behavior duplicate:
      assumes s->notify != 0;
      ensures status: \result == MT_E_DUPLICATE;
      ensures unchanged: s->notify == \old(s->notify) && s->topic->nnotify == \old(s->topic->nnotify);
    behavior full:
      assumes s->notify == 0 && s->topic->nnotify == MT_CFG_BUS_MAX_NOTIFY;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: s->notify == 0 && s->topic->nnotify == \old(s->topic->nnotify);
    behavior ok:
      assumes s->notify == 0 && s->topic->nnotify < MT_CFG_BUS_MAX_NOTIFY;
      ensures status: \result == MT_OK;
      ensures registered: s->topic->nnotify == \old(s->topic->nnotify) + 1 &&
          s->notify == s->topic->nnotify && s->topic->notify_arg[s->notify - 1] != \null &&
          s->topic->notify_min_updates[s->notify - 1] == 1 &&
          s->topic->notify_interval_us[s->notify - 1] == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sub_poll_enable(mt_sub_t *s);

/** Has a message been published since s last consumed one, and is the interval gate
 *  open at now_us (MtDue)? Pure. [subscriber thread; no lock] */
/*@ requires inv: MtSubInv(s);
    assigns \nothing;
    ensures updated: \result == \true <==>
        (MtSubPending(s) != 0 && MtDue(s->last_us, s->interval_us, now_us));
*/
bool mt_sub_updated(const mt_sub_t *s, uint64_t now_us);

/** Copy the next queued message into out (size bytes) and consume it; a subscriber more
 *  than queue_len messages behind first jumps to the oldest retained message. now_us
 *  feeds the interval gate (MtClampNext). [subscriber thread; no lock]
 *  @retval MT_OK             the message after the last consumed one was copied.
 *  @retval MT_W_BUS_MISSED   copied the oldest retained message; the messages before it
 *                            that left the queue were added to `missed`.
 *  @retval MT_E_EMPTY        nothing new (out untouched).
 *  @retval MT_E_BUS_MSG_SIZE size is not the topic's message size (out untouched).
 *  @retval MT_E_BUS_TORN     every attempt was overwritten during the copy (decided by the
 *                            concurrent publisher, hence in both copying behaviours; counted
 *                            in `torn`; nothing consumed; out holds no valid message). */
/*@ requires inv: MtSubInv(s);
    requires out: size == s->topic->size ==>
        \valid((uint8_t *)out + (0 .. size - 1)) &&
        \separated((uint8_t *)out + (0 .. size - 1), s, s->topic,
                   s->topic->buf + (0 .. s->topic->size * s->topic->qlen - 1));
    assigns s->gen, s->last_us, s->received, s->missed, s->skipped, s->torn,
            s->topic->rel_gen[0 .. MT_CFG_BUS_MAX_RELIABLE - 1], ((uint8_t *)out)[0 .. size - 1];
    ensures inv: MtSubInv(s);
    ensures topic_kept: s->topic->gen == \old(s->topic->gen) && s->topic->head == \old(s->topic->head);
    ensures skipped_kept: s->skipped == \old(s->skipped);
    behavior msg_size:
      assumes size != s->topic->size;
      ensures status: \result == MT_E_BUS_MSG_SIZE;
      ensures unchanged: s->gen == \old(s->gen) && s->torn == \old(s->torn);
    behavior empty:
      assumes size == s->topic->size && MtSubPending(s) == 0;
      ensures status: \result == MT_E_EMPTY;
      ensures unchanged: s->gen == \old(s->gen) && s->torn == \old(s->torn);
    behavior next:
      assumes size == s->topic->size && 1 <= MtSubPending(s) <= s->topic->qlen;
      ensures status: \result == MT_OK || \result == MT_E_BUS_TORN;
      ensures consumed: \result == MT_OK ==> s->gen == MtGenNext(\old(s->gen)) &&
          s->missed == \old(s->missed) && s->received == MtSatInc(\old(s->received)) &&
          s->last_us == MtClampNext(\old(s->last_us), s->interval_us, now_us) &&
          (s->rel != 0 ==> s->topic->rel_gen[s->rel - 1] == s->gen);
      ensures data: \result == MT_OK ==> \forall integer k; 0 <= k < s->topic->size ==>
          ((uint8_t *)out)[k] == \old(s->topic->buf[MtSlotBack(s->topic->head,
              MtNextDist(MtGenDist(s->topic->gen, s->gen), s->topic->qlen), s->topic->qlen) *
              s->topic->size + k]);
      ensures torn: \result == MT_E_BUS_TORN ==> s->gen == \old(s->gen) &&
          s->missed == \old(s->missed) && s->torn == MtSatInc(\old(s->torn));
      ensures quiet: !MtSeqRacing ==> \result == MT_OK;
    behavior lapped:
      assumes size == s->topic->size && MtSubPending(s) > s->topic->qlen;
      ensures status: \result == MT_W_BUS_MISSED || \result == MT_E_BUS_TORN;
      ensures quiet: !MtSeqRacing ==> \result == MT_W_BUS_MISSED;
      ensures oldest: \result == MT_W_BUS_MISSED ==>
          s->gen == MtGenBack(s->topic->gen, s->topic->qlen - 1) &&
          s->received == MtSatInc(\old(s->received)) &&
          s->last_us == MtClampNext(\old(s->last_us), s->interval_us, now_us) &&
          (s->rel != 0 ==> s->topic->rel_gen[s->rel - 1] == s->gen);
      ensures missed_exact: \result == MT_W_BUS_MISSED ==>
          s->missed == MtSatAdd(\old(s->missed), \old(MtSubPending(s)) - s->topic->qlen);
      ensures data: \result == MT_W_BUS_MISSED ==> \forall integer k; 0 <= k < s->topic->size ==>
          ((uint8_t *)out)[k] == \old(s->topic->buf[MtSlotBack(s->topic->head,
              MtNextDist(MtGenDist(s->topic->gen, s->gen), s->topic->qlen), s->topic->qlen) *
              s->topic->size + k]);
      ensures torn: \result == MT_E_BUS_TORN ==> s->gen == \old(s->gen) &&
          s->missed == \old(s->missed) && s->torn == MtSatInc(\old(s->torn));
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sub_copy_next(mt_sub_t *s, void *out, uint32_t size, uint64_t now_us);

/** Copy the newest message into out (size bytes) and consume everything up to it,
 *  whether or not it is new (uORB's copy). Retained messages passed over are added to
 *  `skipped`, overwritten ones to `missed`. [subscriber thread; no lock]
 *  @retval MT_OK             the newest message was copied.
 *  @retval MT_W_BUS_MISSED   copied the newest message; messages between the last
 *                            consumed one and it had left the queue (added to `missed`).
 *  @retval MT_E_EMPTY        nothing was ever published (out untouched).
 *  @retval MT_E_BUS_MSG_SIZE size is not the topic's message size (out untouched).
 *  @retval MT_E_BUS_TORN     as mt_sub_copy_next (counted in `torn`). */
/*@ requires inv: MtSubInv(s);
    requires out: size == s->topic->size ==>
        \valid((uint8_t *)out + (0 .. size - 1)) &&
        \separated((uint8_t *)out + (0 .. size - 1), s, s->topic,
                   s->topic->buf + (0 .. s->topic->size * s->topic->qlen - 1));
    assigns s->gen, s->last_us, s->received, s->missed, s->skipped, s->torn,
            s->topic->rel_gen[0 .. MT_CFG_BUS_MAX_RELIABLE - 1], ((uint8_t *)out)[0 .. size - 1];
    ensures inv: MtSubInv(s);
    ensures topic_kept: s->topic->gen == \old(s->topic->gen) && s->topic->head == \old(s->topic->head);
    behavior msg_size:
      assumes size != s->topic->size;
      ensures status: \result == MT_E_BUS_MSG_SIZE;
      ensures unchanged: s->gen == \old(s->gen) && s->torn == \old(s->torn);
    behavior empty:
      assumes size == s->topic->size && s->topic->published == 0;
      ensures status: \result == MT_E_EMPTY;
      ensures unchanged: s->gen == \old(s->gen) && s->torn == \old(s->torn);
    behavior latest:
      assumes size == s->topic->size && s->topic->published == 1 &&
              MtSubPending(s) <= s->topic->qlen;
      ensures status: \result == MT_OK || \result == MT_E_BUS_TORN;
      ensures consumed: \result == MT_OK ==> s->gen == s->topic->gen &&
          s->missed == \old(s->missed) &&
          s->skipped == MtSatAdd(\old(s->skipped), \old(MtSubPending(s)) == 0 ? 0 : \old(MtSubPending(s)) - 1) &&
          s->received == (\old(MtSubPending(s)) == 0 ? \old(s->received) : MtSatInc(\old(s->received))) &&
          s->last_us == MtClampNext(\old(s->last_us), s->interval_us, now_us) &&
          (s->rel != 0 ==> s->topic->rel_gen[s->rel - 1] == s->gen);
      ensures data: \result == MT_OK ==> \forall integer k; 0 <= k < s->topic->size ==>
          ((uint8_t *)out)[k] == \old(s->topic->buf[MtSlotBack(s->topic->head, 0, s->topic->qlen) *
                                                     s->topic->size + k]);
      ensures torn: \result == MT_E_BUS_TORN ==> s->gen == \old(s->gen) &&
          s->missed == \old(s->missed) && s->torn == MtSatInc(\old(s->torn));
      ensures quiet: !MtSeqRacing ==> \result == MT_OK;
    behavior lapped:
      assumes size == s->topic->size && s->topic->published == 1 &&
              MtSubPending(s) > s->topic->qlen;
      ensures status: \result == MT_W_BUS_MISSED || \result == MT_E_BUS_TORN;
      ensures quiet: !MtSeqRacing ==> \result == MT_W_BUS_MISSED;
      ensures newest: \result == MT_W_BUS_MISSED ==> s->gen == s->topic->gen &&
          s->skipped == MtSatAdd(\old(s->skipped), s->topic->qlen - 1) &&
          s->received == MtSatInc(\old(s->received)) &&
          s->last_us == MtClampNext(\old(s->last_us), s->interval_us, now_us) &&
          (s->rel != 0 ==> s->topic->rel_gen[s->rel - 1] == s->gen);
      ensures missed_exact: \result == MT_W_BUS_MISSED ==>
          s->missed == MtSatAdd(\old(s->missed), \old(MtSubPending(s)) - s->topic->qlen);
      ensures data: \result == MT_W_BUS_MISSED ==> \forall integer k; 0 <= k < s->topic->size ==>
          ((uint8_t *)out)[k] == \old(s->topic->buf[MtSlotBack(s->topic->head, 0, s->topic->qlen) *
                                                     s->topic->size + k]);
      ensures torn: \result == MT_E_BUS_TORN ==> s->gen == \old(s->gen) &&
          s->missed == \old(s->missed) && s->torn == MtSatInc(\old(s->torn));
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sub_copy_latest(mt_sub_t *s, void *out, uint32_t size, uint64_t now_us);

/** Wait up to timeout_us for a message s has not consumed (0: do not wait). The
 *  interval gate is not applied (check mt_sub_updated() after a wake-up). Task
 *  context (takes the lock; parks on s->sem).
 *  @retval MT_OK        a message is pending, or a publish signalled s->sem while waiting.
 *  @retval MT_E_TIMEOUT nothing pending within the timeout.
 *  @retval MT_E_STATE   poll is not enabled for s (mt_sub_poll_enable).
 *  @retval MT_E_BUSY    another thread is already polling s. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSubInv(s);
    assigns s->sem.token, s->sem.waiter, MtPortNow, MtPortHandoffs, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSubInv(s);
    behavior state:
      assumes s->notify == 0;
      ensures status: \result == MT_E_STATE;
    behavior pending:
      assumes s->notify != 0 && MtSubPending(s) != 0;
      ensures status: \result == MT_OK;
    behavior busy:
      assumes s->notify != 0 && MtSubPending(s) == 0 && s->sem.waiter != \null;
      ensures status: \result == MT_E_BUSY;
    behavior no_wait:
      assumes s->notify != 0 && MtSubPending(s) == 0 && s->sem.waiter == \null &&
              timeout_us == 0;
      ensures status: \result == MT_E_TIMEOUT;
    behavior wait:
      assumes s->notify != 0 && MtSubPending(s) == 0 && s->sem.waiter == \null &&
              timeout_us > 0;
      ensures status: \result == MT_OK || \result == MT_E_TIMEOUT;
      ensures handed: \result == MT_OK <==> MtPortHandoffs != \old(MtPortHandoffs);
      ensures no_token_left: s->sem.token == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sub_poll(mt_sub_t *s, uint64_t timeout_us);

#ifdef __cplusplus
}
#endif

#endif /* MT_BUS_SUB_H */
