/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/bus.h
 * @brief Topic bus (uORB-style publish/subscribe): static topics with a queue of
 *        one or more messages, lock-free subscriber copies, exact loss accounting,
 *        rate-limited subscriptions, poll, gated notifiers and reliable topics. This
 *        header has the rules, the types, topic set-up, publish and notifiers; the
 *        subscriber functions are in mt/bus_sub.h (mt/mt.h includes both).
 *
 * Operating rules
 * - A topic is declared statically (mt_topic_desc_t, MT_TOPIC_DESC) with storage of
 *   MT_BUS_STORAGE_BYTES(msg_size, queue_len) bytes supplied by the application.
 * - Publishers: any number, in task (mt_topic_publish), interrupt (_isr) or lock-held
 *   (_i) context. Every publish runs under the kernel lock, so publishers are
 *   serialised; a publish never blocks and its time is bounded by one message copy
 *   plus the topic's notifiers.
 * - Generation: each publish moves the topic's 32-bit generation to the next value
 *   (0xFFFFFFFF is followed by 0). Every distance between generations is computed
 *   by a case split (MtGenDist), never by a wrapping subtraction. A subscriber
 *   must look at its topic (copy or updated) at least once per 2^32 - 1
 *   publications, or its distances alias (assumption G1).
 * - Torn reads (design decision): subscribers copy WITHOUT the kernel lock, seqlock
 *   style. The publisher stamps the slot with the new generation (store + release
 *   fence), writes the bytes (relaxed), then publishes head and generation (release).
 *   The subscriber loads the generation (acquire), checks the slot's stamp, copies
 *   (relaxed), and re-checks the stamp after an acquire fence (mt_seq_recheck_u32):
 *   a publisher that overwrote any byte of the slot during the copy has changed the
 *   stamp, and the attempt is discarded. After MT_CFG_BUS_COPY_TRIES discarded
 *   attempts the copy returns MT_E_BUS_TORN (counted in `torn`), never a mixed
 *   message. Why: the alternative (copy under the kernel lock) keeps interrupts
 *   masked for up to MT_CFG_BUS_MAX_MSG bytes per subscriber copy, which is the
 *   interrupt latency uORB pays; here only the publisher's own copy runs with the
 *   lock held. The interleavings are checked by tla/Bus.tla (NoTornRead). The
 *   contracts below are sequential (assumption C2) and name the concurrent writer:
 *   without one (MtSeqRacing false, assumption C3) a copy of a pending message is never
 *   torn (clauses `quiet`), because every retained message sits in its slot under its
 *   generation's stamp (MtTopicStamped, part of the topic invariant); with one, a copy may
 *   be torn at every attempt.
 * - Missed messages, defined: a message is missed by a subscriber when it had left
 *   the queue (was overwritten) before the subscriber read the generation in the
 *   copy that passed over it. copy_next on a subscriber more than queue_len
 *   messages behind jumps to the oldest retained message and adds the overwritten
 *   ones to `missed`. Messages that copy_latest passes over while they are still
 *   retained are counted in `skipped`, not in `missed`: the subscriber chose the
 *   newest. So every message published after a subscriber's init is exactly one of
 *   received, missed, skipped or pending (Bus.tla, AccountingExact).
 * - Rate-limited subscriptions (uORB SubscriptionInterval): with interval_us > 0,
 *   mt_sub_updated() reports an update only once interval_us passed since the last
 *   update; every successful copy moves the last-update time forward by one interval,
 *   clamped to [now - interval, now] (MtClampNext). Copies themselves are not gated.
 * - Notifiers: each topic calls up to MT_CFG_BUS_MAX_NOTIFY notifiers on publish,
 *   with the kernel lock held (I-class), through mt_bus_invoke_notify (assumption
 *   A1: a notifier returns, keeps the lock, and writes neither the topic nor another
 *   topic's publish path; it must not publish). A notifier has a count gate (called
 *   once at least min_updates publications happened since its last call) and an
 *   interval gate (interval_us, the rule above); a publish that a gate holds back is
 *   counted in `gated`. There is no timer: a held-back notifier is called by a later
 *   publish. Each call is counted in the ghost MtCalls[MT_CALL_NOTIFY(i)], so the publish
 *   contracts say which notifiers ran (MtNotifyStep, MtPublishNotifiedNone); a refused publish
 *   calls none. A work queue points fn at its schedule function (uORB's
 *   SubscriptionCallback); mt_sub_poll_enable registers the subscriber's semaphore.
 * - Reliable topics (MT_TOPIC_RELIABLE): a publish that would overwrite a message a
 *   registered reliable subscriber has not consumed is refused with MT_E_BUS_BEHIND
 *   and counted in `rejected` (PX4 #26217); a reliable subscriber never misses.
 * - Ownership: publishers own the topic fields above `rel_gen` (lock held);
 *   reliable subscriber i owns rel_gen[i] (release store, read by publishers with
 *   acquire); a subscriber object belongs to one thread, which alone calls the
 *   mt_sub_* functions on it.
 */
#ifndef MT_BUS_H
#define MT_BUS_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/config.h"
#include "mt/sem.h"
#include "mt/status.h"
#include "mt_port.h"
#include "mt_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Topic flag: publishes are refused while a reliable subscriber lags (see above). */
#define MT_TOPIC_RELIABLE 1u

/** Storage bytes of a topic: queue_len messages of msg_size bytes. */
#define MT_BUS_STORAGE_BYTES(msg_size, queue_len) ((uint32_t)(msg_size) * (uint32_t)(queue_len))

/** Static declaration of a topic: name, message type, queue length, flags. */
#define MT_TOPIC_DESC(name_, type_, queue_len_, flags_)                                         \
    {(name_), (uint32_t)sizeof(type_), (uint32_t)(queue_len_), (uint32_t)(flags_), 0u}

/** Notifier callback (called with the kernel lock held). */
typedef void (*mt_bus_notify_fn_t)(void *arg);

/** A topic's static description. */
typedef struct {
    const char *name;   /**< for reports (not copied) */
    uint32_t msg_size;  /**< bytes per message, 1..MT_CFG_BUS_MAX_MSG */
    uint32_t queue_len; /**< messages retained, 1..MT_CFG_BUS_MAX_QUEUE */
    uint32_t flags;     /**< 0 or MT_TOPIC_RELIABLE */
    uint32_t first_gen; /**< generation before the first publish (0; tests start near
                             UINT32_MAX to exercise the wrap) */
} mt_topic_desc_t;

typedef struct {
    /* publisher side: written with the kernel lock held */
    uint32_t gen;                          /**< generation of the newest message (release) */
    uint32_t head;                         /**< slot of the newest message, [0, qlen) */
    uint32_t published;                    /**< 0 before the first publish, then 1 (release) */
    uint32_t stamp[MT_CFG_BUS_MAX_QUEUE];  /**< generation whose bytes each slot holds or is
                                                being overwritten with (seqlock stamp) */
    uint32_t publishes;                    /**< accepted publishes (saturating) */
    uint32_t rejected;                     /**< refused publishes: size, behind (saturating) */
    uint32_t notified;                 /**< notifier calls made (saturating) */
    /* notifiers, one column per field (WP frames whole columns cheaply); entry i is
       registered when i < nnotify; fn, arg, min_updates, interval_us constant then */
    uint32_t nnotify;                                      /**< registered notifiers */
    mt_bus_notify_fn_t notify_fn[MT_CFG_BUS_MAX_NOTIFY];   /**< callback */
    void *notify_arg[MT_CFG_BUS_MAX_NOTIFY];               /**< its argument */
    uint32_t notify_min_updates[MT_CFG_BUS_MAX_NOTIFY];    /**< count gate, >= 1 */
    uint32_t notify_interval_us[MT_CFG_BUS_MAX_NOTIFY];    /**< interval gate, 0: none */
    uint32_t notify_last_gen[MT_CFG_BUS_MAX_NOTIFY];       /**< generation at the last call
                                                                (or registration) */
    uint64_t notify_last_us[MT_CFG_BUS_MAX_NOTIFY];        /**< interval gate's last update */
    uint32_t notify_calls[MT_CFG_BUS_MAX_NOTIFY];          /**< calls made (saturating) */
    uint32_t notify_gated[MT_CFG_BUS_MAX_NOTIFY];          /**< publishes a gate held back
                                                                (saturating) */
    uint32_t nrel;                         /**< registered reliable subscribers */
    /* subscriber side */
    uint32_t rel_gen[MT_CFG_BUS_MAX_RELIABLE]; /**< generation consumed by reliable
                                                    subscriber i (written by it, release) */
    /* constant after init */
    const char *name;
    uint8_t *buf;      /**< qlen slots of size bytes */
    uint32_t size;     /**< bytes per message */
    uint32_t qlen;     /**< slots */
    uint32_t reliable; /**< 1 for a MT_TOPIC_RELIABLE topic */
} mt_topic_t;

typedef struct {
    mt_topic_t *topic;    /**< constant after init */
    uint32_t gen;         /**< generation of the last message consumed (received, missed or
                               skipped) */
    uint32_t interval_us; /**< minimum interval between updates (0: none) */
    uint64_t last_us;     /**< last-update time of the interval gate */
    uint32_t received;    /**< new messages copied (saturating) */
    uint32_t missed;      /**< messages that left the queue before this subscriber reached
                               them (saturating; exact below saturation) */
    uint32_t skipped;     /**< retained messages copy_latest passed over (saturating) */
    uint32_t torn;        /**< copies given up with MT_E_BUS_TORN (saturating) */
    uint32_t rel;         /**< reliable slot + 1, 0: not reliable */
    uint32_t notify;      /**< poll notifier slot + 1, 0: poll not enabled */
    mt_sem_t sem;         /**< poll wake-up */
} mt_sub_t;

/* The bus's ACSL logic and predicates (empty to a C compiler), after the types they read. */
// cppcheck-suppress misra-c2012-20.1 ; D-107 ACSL only, included after the types it names
#include "mt_spec_bus.h"

/** Initialise a topic from its description over storage of storage_bytes bytes. [init]
 *  @retval MT_OK
 *  @retval MT_E_INVALID d->name is NULL or d->flags is not 0 or MT_TOPIC_RELIABLE.
 *  @retval MT_E_BUS_MSG_SIZE d->msg_size is 0 or above MT_CFG_BUS_MAX_MSG.
 *  @retval MT_E_BUS_QUEUE_LEN d->queue_len is 0 or above MT_CFG_BUS_MAX_QUEUE.
 *  @retval MT_E_BUS_STORAGE storage is NULL or storage_bytes is below
 *          MT_BUS_STORAGE_BYTES(msg_size, queue_len).
 *  On an error the topic is left unusable (size 0). */
/*@ requires valid: \valid(t) && \valid_read(d) && \separated(t, d);
    requires storage: storage != \null ==>
        \valid((uint8_t *)storage + (0 .. storage_bytes - 1)) &&
        \separated(t, (uint8_t *)storage + (0 .. storage_bytes - 1));
    assigns *t;
    behavior invalid:
      assumes d->name == \null || (d->flags != 0 && d->flags != MT_TOPIC_RELIABLE);
      ensures status: \result == MT_E_INVALID;
      ensures unusable: t->size == 0;
    behavior msg_size:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes d->msg_size < 1 || d->msg_size > MT_CFG_BUS_MAX_MSG;
      ensures status: \result == MT_E_BUS_MSG_SIZE;
      ensures unusable: t->size == 0;
    behavior queue_len:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes 1 <= d->msg_size <= MT_CFG_BUS_MAX_MSG;
      assumes d->queue_len < 1 || d->queue_len > MT_CFG_BUS_MAX_QUEUE;
      ensures status: \result == MT_E_BUS_QUEUE_LEN;
      ensures unusable: t->size == 0;
    behavior storage:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes 1 <= d->msg_size <= MT_CFG_BUS_MAX_MSG;
      assumes 1 <= d->queue_len <= MT_CFG_BUS_MAX_QUEUE;
      assumes storage == \null || storage_bytes < d->msg_size * d->queue_len;
      ensures status: \result == MT_E_BUS_STORAGE;
      ensures unusable: t->size == 0;
    behavior ok:
      assumes d->name != \null && (d->flags == 0 || d->flags == MT_TOPIC_RELIABLE);
      assumes 1 <= d->msg_size <= MT_CFG_BUS_MAX_MSG;
      assumes 1 <= d->queue_len <= MT_CFG_BUS_MAX_QUEUE;
      assumes storage != \null && storage_bytes >= d->msg_size * d->queue_len;
      ensures status: \result == MT_OK;
      ensures inv: MtTopicInv(t);
      ensures shape: t->size == d->msg_size && t->qlen == d->queue_len &&
                     t->reliable == (d->flags == MT_TOPIC_RELIABLE ? 1 : 0) && t->name == d->name;
      ensures empty: t->gen == d->first_gen && t->published == 0 && t->nnotify == 0 &&
                     t->nrel == 0;
      ensures stats: t->publishes == 0 && t->rejected == 0 && t->notified == 0;
      ensures storage: t->buf == (uint8_t *)storage;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_topic_init(mt_topic_t *t, const mt_topic_desc_t *d, void *storage,
                          uint32_t storage_bytes);

/** Publish a copy of msg (size bytes). I-class: kernel lock held; never blocks.
 *  Notifiers run before it returns.
 *  @retval MT_OK published: generation advanced, oldest slot overwritten.
 *  @retval MT_E_BUS_MSG_SIZE size is not the topic's message size (counted in rejected).
 *  @retval MT_E_BUS_BEHIND reliable topic, a reliable subscriber has not consumed the
 *          oldest queued message (counted in rejected; nothing written). */
/*@ requires held: MtLocked == 1;
    requires inv: MtTopicInv(t);
    requires msg: MtPublishMsg(t, (uint8_t *)msg, size);
    assigns t->gen, t->head, t->published, t->stamp[0 .. MT_CFG_BUS_MAX_QUEUE - 1],
            t->buf[0 .. t->size * t->qlen - 1], t->publishes, t->rejected, t->notified,
            t->notify_last_gen[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_last_us[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_calls[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_gated[0 .. MT_CFG_BUS_MAX_NOTIFY - 1], MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_NOTIFY(0) .. MT_CALL_NOTIFY(MT_CFG_BUS_MAX_NOTIFY - 1)];
    ensures held: MtLocked == 1;
    ensures inv: MtTopicInv(t);
    behavior msg_size:
      assumes size != t->size;
      ensures status: \result == MT_E_BUS_MSG_SIZE;
      ensures counted: t->rejected == MtSatInc(\old(t->rejected));
      ensures unchanged: MtPublishKept{Old, Here}(t);
      ensures nothing_written: MtPublishNothingWritten{Old, Here}(t);
      ensures none_notified: MtPublishNotifiedNone{Old, Here}(t);
    behavior behind:
      assumes size == t->size && MtTopicBehind(t);
      ensures status: \result == MT_E_BUS_BEHIND;
      ensures counted: t->rejected == MtSatInc(\old(t->rejected));
      ensures unchanged: MtPublishKept{Old, Here}(t);
      ensures nothing_written: MtPublishNothingWritten{Old, Here}(t);
      ensures none_notified: MtPublishNotifiedNone{Old, Here}(t);
    behavior ok:
      assumes size == t->size && !MtTopicBehind(t);
      ensures status: \result == MT_OK;
      ensures generation: t->gen == MtGenNext(\old(t->gen));
      ensures slot: t->head == MtSlotNext(\old(t->head), t->qlen);
      ensures stamped: t->stamp[t->head] == t->gen;
      ensures data: MtPublishData(t->buf, t->head * t->size, (uint8_t *)msg, t->size);
      ensures others_kept: MtPublishOthersKept{Old, Here}(t->buf, t->size * t->qlen,
                                                          t->head * t->size, t->size);
      ensures published: t->published == 1;
      ensures counted: t->publishes == MtSatInc(\old(t->publishes)) &&
                       t->rejected == \old(t->rejected);
      ensures notified: MtPublishNotified{Old, Here}(t, t->nnotify);
      ensures unused_not_called: MtPublishUnusedKept{Old, Here}(t->nnotify);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_topic_publish_i(mt_topic_t *t, const void *msg, uint32_t size);

/** mt_topic_publish_i() from task context (takes the kernel lock). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtTopicInv(t);
    requires msg: MtPublishMsg(t, (uint8_t *)msg, size);
    assigns t->gen, t->head, t->published, t->stamp[0 .. MT_CFG_BUS_MAX_QUEUE - 1],
            t->buf[0 .. t->size * t->qlen - 1], t->publishes, t->rejected, t->notified,
            t->notify_last_gen[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_last_us[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_calls[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_gated[0 .. MT_CFG_BUS_MAX_NOTIFY - 1], MtPortNow, MtPortWakes, MtLocked,
            MtCalls[MT_CALL_NOTIFY(0) .. MT_CALL_NOTIFY(MT_CFG_BUS_MAX_NOTIFY - 1)];
    ensures released: MtLocked == 0;
    ensures inv: MtTopicInv(t);
    ensures status: MtPublishStatus(\result);
    ensures generation: MtPublishGeneration{Old, Here}(t, \result);
    ensures refused: MtPublishRefused{Old, Here}(t, \result);
    ensures notified: \result == MT_OK ==> MtPublishNotified{Old, Here}(t, t->nnotify);
    ensures unused_not_called: \result == MT_OK ==> MtPublishUnusedKept{Old, Here}(t->nnotify);
    ensures none_notified: \result != MT_OK ==> MtPublishNotifiedNone{Old, Here}(t);
    behavior msg_size:
      assumes size != t->size;
      ensures status: \result == MT_E_BUS_MSG_SIZE;
      ensures unchanged: MtPublishKept{Old, Here}(t);
      ensures nothing_written: MtPublishNothingWritten{Old, Here}(t);
    behavior behind:
      assumes size == t->size && MtTopicBehind(t);
      ensures status: \result == MT_E_BUS_BEHIND;
      ensures unchanged: MtPublishKept{Old, Here}(t);
      ensures nothing_written: MtPublishNothingWritten{Old, Here}(t);
    behavior ok:
      assumes size == t->size && !MtTopicBehind(t);
      ensures status: \result == MT_OK;
      ensures slot: t->head == MtSlotNext(\old(t->head), t->qlen);
      ensures stamped: t->stamp[t->head] == t->gen;
      ensures data: MtPublishData(t->buf, t->head * t->size, (uint8_t *)msg, t->size);
      ensures others_kept: MtPublishOthersKept{Old, Here}(t->buf, t->size * t->qlen,
                                                          t->head * t->size, t->size);
      ensures published: t->published == 1;
      ensures counted: t->publishes == MtSatInc(\old(t->publishes)) &&
                       t->rejected == \old(t->rejected);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_topic_publish(mt_topic_t *t, const void *msg, uint32_t size);

/** mt_topic_publish_i() from an interrupt handler. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtTopicInv(t);
    requires msg: MtPublishMsg(t, (uint8_t *)msg, size);
    assigns t->gen, t->head, t->published, t->stamp[0 .. MT_CFG_BUS_MAX_QUEUE - 1],
            t->buf[0 .. t->size * t->qlen - 1], t->publishes, t->rejected, t->notified,
            t->notify_last_gen[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_last_us[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_calls[0 .. MT_CFG_BUS_MAX_NOTIFY - 1],
            t->notify_gated[0 .. MT_CFG_BUS_MAX_NOTIFY - 1], MtPortNow, MtPortWakes, MtLocked,
            MtCalls[MT_CALL_NOTIFY(0) .. MT_CALL_NOTIFY(MT_CFG_BUS_MAX_NOTIFY - 1)];
    ensures released: MtLocked == 0;
    ensures inv: MtTopicInv(t);
    ensures status: MtPublishStatus(\result);
    ensures generation: MtPublishGeneration{Old, Here}(t, \result);
    ensures refused: MtPublishRefused{Old, Here}(t, \result);
    ensures notified: \result == MT_OK ==> MtPublishNotified{Old, Here}(t, t->nnotify);
    ensures unused_not_called: \result == MT_OK ==> MtPublishUnusedKept{Old, Here}(t->nnotify);
    ensures none_notified: \result != MT_OK ==> MtPublishNotifiedNone{Old, Here}(t);
    behavior msg_size:
      assumes size != t->size;
      ensures status: \result == MT_E_BUS_MSG_SIZE;
      ensures unchanged: MtPublishKept{Old, Here}(t);
      ensures nothing_written: MtPublishNothingWritten{Old, Here}(t);
    behavior behind:
      assumes size == t->size && MtTopicBehind(t);
      ensures status: \result == MT_E_BUS_BEHIND;
      ensures unchanged: MtPublishKept{Old, Here}(t);
      ensures nothing_written: MtPublishNothingWritten{Old, Here}(t);
    behavior ok:
      assumes size == t->size && !MtTopicBehind(t);
      ensures status: \result == MT_OK;
      ensures slot: t->head == MtSlotNext(\old(t->head), t->qlen);
      ensures stamped: t->stamp[t->head] == t->gen;
      ensures data: MtPublishData(t->buf, t->head * t->size, (uint8_t *)msg, t->size);
      ensures others_kept: MtPublishOthersKept{Old, Here}(t->buf, t->size * t->qlen,
                                                          t->head * t->size, t->size);
      ensures published: t->published == 1;
      ensures counted: t->publishes == MtSatInc(\old(t->publishes)) &&
                       t->rejected == \old(t->rejected);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_topic_publish_isr(mt_topic_t *t, const void *msg, uint32_t size);

/** Register fn(arg) as a notifier of t (task context; takes the kernel lock). It is
 *  called, with the lock held, by a publish once min_updates publications happened
 *  since its last call (or its registration) and, when interval_us > 0, once the
 *  interval gate is open (MtDue; its last-update time then moves by MtClampNext).
 *  @retval MT_OK
 *  @retval MT_E_INVALID fn is NULL or min_updates is 0.
 *  @retval MT_E_DUPLICATE the same (fn, arg) is already registered on t.
 *  @retval MT_E_FULL MT_CFG_BUS_MAX_NOTIFY notifiers are registered. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtTopicInv(t);
    assigns t->notify_fn[t->nnotify], t->notify_arg[t->nnotify], t->notify_min_updates[t->nnotify], t->notify_interval_us[t->nnotify], t->notify_last_gen[t->nnotify], t->notify_last_us[t->nnotify], t->notify_calls[t->nnotify], t->notify_gated[t->nnotify],
            t->nnotify, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtTopicInv(t);
    behavior invalid:
      assumes fn == \null || min_updates == 0;
      ensures status: \result == MT_E_INVALID;
      ensures unchanged: t->nnotify == \old(t->nnotify);
    behavior duplicate:
      assumes fn != \null && min_updates != 0 && MtNotifyRegistered(t, fn, arg);
      ensures status: \result == MT_E_DUPLICATE;
      ensures unchanged: t->nnotify == \old(t->nnotify);
    behavior full:
      assumes fn != \null && min_updates != 0 && !MtNotifyRegistered(t, fn, arg);
      assumes t->nnotify == MT_CFG_BUS_MAX_NOTIFY;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: t->nnotify == \old(t->nnotify);
    behavior ok:
      assumes fn != \null && min_updates != 0 && !MtNotifyRegistered(t, fn, arg);
      assumes t->nnotify < MT_CFG_BUS_MAX_NOTIFY;
      ensures status: \result == MT_OK;
      ensures appended: t->nnotify == \old(t->nnotify) + 1;
      ensures entry: t->notify_fn[\old(t->nnotify)] == fn && t->notify_arg[\old(t->nnotify)] == arg &&
          t->notify_min_updates[\old(t->nnotify)] == min_updates &&
          t->notify_interval_us[\old(t->nnotify)] == interval_us &&
          t->notify_last_gen[\old(t->nnotify)] == t->gen;
      ensures fresh: t->notify_calls[\old(t->nnotify)] == 0 && t->notify_gated[\old(t->nnotify)] == 0 &&
          t->notify_last_us[\old(t->nnotify)] == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_topic_notify_add(mt_topic_t *t, mt_bus_notify_fn_t fn, void *arg,
                                uint32_t min_updates, uint32_t interval_us);

#ifdef __cplusplus
}
#endif

#endif /* MT_BUS_H */
