/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_bus_int.h
 * @brief Topic bus helpers shared by its two files (kernel-internal): the publisher side
 *        (bus.c, which defines them) and the lock-free subscriber side (bus_sub.c).
 *
 * Each is pure or reads the topic's constant fields only; the contracts below are the ones
 * both files' proofs use (WP proves the definitions against them in module bus).
 */
#ifndef MT_BUS_INT_H
#define MT_BUS_INT_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/bus.h"

/* ------------------------------------------------------------------------------------------
 * Wrap-free arithmetic: each helper is its logic twin in mt_spec_bus.h, by case split. */

/*@ assigns \nothing;
    ensures \result == MtGenDist(a, b);
*/
uint32_t mt_bus_gen_dist(uint32_t a, uint32_t b);

/*@ assigns \nothing;
    ensures \result == \true <==> MtDue(last, iv, now);
*/
bool mt_bus_interval_due(uint64_t last, uint32_t iv, uint64_t now);

/* uORB SubscriptionInterval: last + iv, clamped to [now - iv, now]; now itself while
 * now <= iv (now - iv would wrap). No sum leaves 64 bits: last + iv is formed only
 * when last <= now - iv. */
/*@ assigns \nothing;
    ensures \result == MtClampNext(last, iv, now);
*/
uint64_t mt_bus_clamp_next(uint64_t last, uint32_t iv, uint64_t now);

/* ------------------------------------------------------------------------------------------
 * Slots */

/* Address of slot `slot`. */
/*@ requires MtTopicInv(t);
    requires slot < t->qlen;
    assigns \nothing;
    ensures \result == t->buf + slot * t->size;
    ensures in_storage: slot * t->size + t->size <= t->size * t->qlen;
    ensures \valid(\result + (0 .. t->size - 1));
*/
uint8_t *mt_bus_slot_ptr(const mt_topic_t *t, uint32_t slot);

#endif /* MT_BUS_INT_H */
