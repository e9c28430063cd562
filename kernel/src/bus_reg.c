/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file bus_reg.c
 * @brief Topic bus (see mt/bus.h), the registrations under the kernel lock: notifiers,
 *        reliable subscribers, a subscriber's poll notifier and the poll itself. Topic set-up
 *        and publish are in bus.c, the lock-free subscriber copies in bus_sub.c.
 */
#include "mt/bus_sub.h"

#include "mt_bus_invoke.h"

/* ------------------------------------------------------------------------------------------
 * Notifiers */

/*@ requires MtTopicInv(t);
    assigns \nothing;
    ensures \result == 1 <==> MtNotifyRegistered(t, fn, arg);
    ensures \result == 0 || \result == 1;
*/
static uint32_t notify_registered(const mt_topic_t *t, mt_bus_notify_fn_t fn, const void *arg)
{
    uint32_t i;

    /*@ loop invariant 0 <= i <= t->nnotify;
        loop invariant \forall integer j; 0 <= j < i ==>
            !(t->notify_fn[j] == fn && t->notify_arg[j] == arg);
        loop assigns i;
        loop variant t->nnotify - i;
    */
    for (i = 0u; i < t->nnotify; i++) {
        if ((t->notify_fn[i] == fn) && (t->notify_arg[i] == arg)) {
            return 1u;
        }
    }
    return 0u;
}

/* Append a notifier (lock held; the caller checked fn, min_updates and the room). */
/*@ requires MtTopicInv(t);
    requires fn != \null && min_updates >= 1;
    requires t->nnotify < MT_CFG_BUS_MAX_NOTIFY;
    assigns t->notify_fn[t->nnotify], t->notify_arg[t->nnotify], t->notify_min_updates[t->nnotify], t->notify_interval_us[t->nnotify], t->notify_last_gen[t->nnotify], t->notify_last_us[t->nnotify], t->notify_calls[t->nnotify], t->notify_gated[t->nnotify],
            t->nnotify;
    ensures MtTopicInv(t);
    ensures t->nnotify == \old(t->nnotify) + 1;
    ensures t->notify_fn[\old(t->nnotify)] == fn && t->notify_arg[\old(t->nnotify)] == arg &&
        t->notify_min_updates[\old(t->nnotify)] == min_updates &&
        t->notify_interval_us[\old(t->nnotify)] == interval_us &&
        t->notify_last_gen[\old(t->nnotify)] == t->gen &&
        t->notify_calls[\old(t->nnotify)] == 0 && t->notify_gated[\old(t->nnotify)] == 0 &&
        t->notify_last_us[\old(t->nnotify)] == 0;
*/
static void add_notifier(mt_topic_t *t, mt_bus_notify_fn_t fn, void *arg, uint32_t min_updates,
                         uint32_t interval_us)
{
    uint32_t n = t->nnotify;

    // cppcheck-suppress misra-c2012-11.1 ; D-105 no conversion: same function-pointer type
    t->notify_fn[n] = fn;
    t->notify_arg[n] = arg;
    t->notify_min_updates[n] = min_updates;
    t->notify_interval_us[n] = interval_us;
    t->notify_last_gen[n] = t->gen;
    t->notify_last_us[n] = 0u;
    t->notify_calls[n] = 0u;
    t->notify_gated[n] = 0u;
    t->nnotify++;
}

mt_status_t mt_topic_notify_add(mt_topic_t *t, mt_bus_notify_fn_t fn, void *arg,
                                uint32_t min_updates, uint32_t interval_us)
{
    mt_status_t st;

    mt_port_lock();
    if ((fn == (mt_bus_notify_fn_t)0) || (min_updates == 0u)) {
        st = MT_E_INVALID;
    } else if (notify_registered(t, fn, arg) != 0u) {
        st = MT_E_DUPLICATE;
    } else if (t->nnotify >= MT_CFG_BUS_MAX_NOTIFY) {
        st = MT_E_FULL;
    } else {
        add_notifier(t, fn, arg, min_updates, interval_us);
        st = MT_OK;
    }
    mt_port_unlock();
    return st;
}

/* ------------------------------------------------------------------------------------------
 * Subscribers: registrations and poll (lock held; the copies are in bus_sub.c) */

mt_status_t mt_sub_reliable(mt_sub_t *s)
{
    mt_topic_t *t = s->topic;
    mt_status_t st;

    mt_port_lock();
    if (t->reliable == 0u) {
        st = MT_E_STATE;
    } else if (s->rel != 0u) {
        st = MT_E_DUPLICATE;
    } else if (t->nrel >= MT_CFG_BUS_MAX_RELIABLE) {
        st = MT_E_FULL;
    } else {
        t->rel_gen[t->nrel] = s->gen;
        t->nrel++;
        s->rel = t->nrel;
        st = MT_OK;
    }
    mt_port_unlock();
    return st;
}

mt_status_t mt_sub_poll_enable(mt_sub_t *s)
{
    mt_topic_t *t = s->topic;
    mt_status_t st;

    /* (for WP: the subscriber's fields are not among the topic's pointer columns) */
    /*@ assert sep: \separated(&s->topic, &s->notify, &s->sem, &s->rel,
            t->notify_fn + (0 .. MT_CFG_BUS_MAX_NOTIFY - 1),
            t->notify_arg + (0 .. MT_CFG_BUS_MAX_NOTIFY - 1)); */
    mt_port_lock();
    if (s->notify != 0u) {
        st = MT_E_DUPLICATE;
    } else if (t->nnotify >= MT_CFG_BUS_MAX_NOTIFY) {
        st = MT_E_FULL;
    } else {
        void *arg = mt_bus_invoke_wake_arg(&s->sem);
        s->notify = t->nnotify + 1u; /* the slot add_notifier fills, + 1 */
        add_notifier(t, &mt_bus_invoke_wake, arg, 1u, 0u);
        st = MT_OK;
    }
    mt_port_unlock();
    return st;
}

mt_status_t mt_sub_poll(mt_sub_t *s, uint64_t timeout_us)
{
    mt_status_t st;

    mt_port_lock();
    if (s->notify == 0u) {
        st = MT_E_STATE;
    } else if (s->topic->gen != s->gen) {
        st = MT_OK;
    } else {
        /* Nothing pending: drop a token left by a publish this subscriber has already
         * consumed, then wait. The lock is held from the check to the park, so a
         * publish after the check hands its signal to the parked waiter. */
        st = mt_sem_wait_s(&s->sem, 0u);
        if (st == MT_E_BUSY) {
            /* another thread polls s */
        } else if (timeout_us == 0u) {
            st = MT_E_TIMEOUT;
        } else {
            st = mt_sem_wait_s(&s->sem, timeout_us);
        }
    }
    mt_port_unlock();
    return st;
}
