/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/time.h
 * @brief Extension of a wrapping hardware counter to 64 bits, and tick to
 *        microsecond conversion: the only wrap-around handling in Metronome.
 *
 * A port samples its hardware counter (16 or 32 bits, any maximum value) and
 * calls mt_time_extend() at least once per counter period; the extended count
 * never wraps in practice (2^64 ticks) and saturates rather than wrap.
 */
#ifndef MT_TIME_H
#define MT_TIME_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint64_t ticks;   /**< extended count */
    uint32_t last_hw; /**< raw counter value at the last call */
    uint32_t hw_max;  /**< largest raw counter value (0xFFFF, 0xFFFFFFFF, ...) */
} mt_time_ext_t;

/*@ predicate MtTimeExtInv(mt_time_ext_t *t) =
        \valid(t) && t->hw_max >= 1 && t->last_hw <= t->hw_max;

    logic integer MtHwDelta(integer now, integer last, integer max) =
        now >= last ? now - last : (max - last) + now + 1;
*/

/** Start extending a counter whose largest value is hw_max, now reading hw_now.
 *  @retval MT_OK
 *  @retval MT_E_INVALID hw_max is 0 or hw_now > hw_max. */
/*@ requires valid: \valid(t);
    assigns *t;
    behavior ok:
      assumes hw_max >= 1 && hw_now <= hw_max;
      ensures status: \result == MT_OK;
      ensures inv: MtTimeExtInv(t);
      ensures zero: t->ticks == 0 && t->last_hw == hw_now && t->hw_max == hw_max;
    behavior bad:
      assumes hw_max < 1 || hw_now > hw_max;
      ensures status: \result == MT_E_INVALID;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_time_ext_init(mt_time_ext_t *t, uint32_t hw_max, uint32_t hw_now);

/** Account the counter's progress since the last call (at most one wrap) and
 *  return the extended count. */
/*@ requires inv: MtTimeExtInv(t);
    requires in_range: hw_now <= t->hw_max;
    assigns t->ticks, t->last_hw;
    ensures inv: MtTimeExtInv(t);
    ensures last: t->last_hw == hw_now;
    ensures monotonic: t->ticks >= \old(t->ticks);
    ensures exact: \old(t->ticks) + MtHwDelta(hw_now, \old(t->last_hw), t->hw_max) <= 0xFFFFFFFFFFFFFFFF ==>
        t->ticks == \old(t->ticks) + MtHwDelta(hw_now, \old(t->last_hw), t->hw_max);
    ensures saturated: \old(t->ticks) + MtHwDelta(hw_now, \old(t->last_hw), t->hw_max) > 0xFFFFFFFFFFFFFFFF ==>
        t->ticks == 0xFFFFFFFFFFFFFFFF;
    ensures result: \result == t->ticks;
*/
uint64_t mt_time_extend(mt_time_ext_t *t, uint32_t hw_now);

/** Convert a tick count at hz ticks per second to microseconds (rounded
 *  down, saturating at UINT64_MAX). */
/*@ requires rate: hz >= 1;
    assigns \nothing;
    ensures exact: (ticks * 1000000) / hz <= 0xFFFFFFFFFFFFFFFF ==> \result == (ticks * 1000000) / hz;
    ensures saturated: (ticks * 1000000) / hz > 0xFFFFFFFFFFFFFFFF ==> \result == 0xFFFFFFFFFFFFFFFF;
*/
uint64_t mt_time_ticks_to_us(uint64_t ticks, uint32_t hz);

/** Constant-time validity check, the C twin of MtTimeExtInv (the object itself must be
 *  valid memory: its precondition). For debug assertions and tests. [owner context, pure] */
/*@ requires obj: \valid(t);
    assigns \nothing;
    ensures twin: \result != 0 <==> MtTimeExtInv(t);
*/
bool mt_time_ext_valid(const mt_time_ext_t *t);

#ifdef __cplusplus
}
#endif

#endif /* MT_TIME_H */
