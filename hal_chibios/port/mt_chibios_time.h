/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_chibios_time.h
 * @brief Time arithmetic of the ChibiOS port that is not the kernel's
 *        (mt/time.h): microseconds to system ticks, wait chunks, sub-tick
 *        interpolation. Plain C, no ChibiOS header, proved by Frama-C/WP.
 *
 * Operating rules
 * - Every tick count here is the port's 64-bit extended count
 *   (mt_time_extend() of the RT system time): it never wraps, and every
 *   function saturates at UINT64_MAX instead.
 * - The only modular arithmetic is mt_chibios_counter_shift(), which
 *   reproduces a hardware counter's wrap without any C unsigned wrap.
 * - No function here has a side effect; all are callable from any context.
 */
#ifndef MT_CHIBIOS_TIME_H
#define MT_CHIBIOS_TIME_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/*@ logic integer MtCeilTicks(integer us, integer hz) = (us * hz + 999999) / 1000000;
    logic integer MtSat64(integer v) = v <= 0xFFFFFFFFFFFFFFFF ? v : 0xFFFFFFFFFFFFFFFF;
*/

/** Microseconds to ticks at hz, rounded up, saturating at UINT64_MAX.
 *  Rounding up makes a wait that ends on tick mt_chibios_us_to_ticks_ceil(d)
 *  end no earlier than d: mt_time_ticks_to_us() of that tick is >= d. */
/*@ requires rate: hz >= 1;
    assigns \nothing;
    ensures exact: MtCeilTicks(us, hz) <= 0xFFFFFFFFFFFFFFFF ==> \result == MtCeilTicks(us, hz);
    ensures saturated: MtCeilTicks(us, hz) > 0xFFFFFFFFFFFFFFFF ==> \result == 0xFFFFFFFFFFFFFFFF;
    ensures not_early: MtCeilTicks(us, hz) <= 0xFFFFFFFFFFFFFFFF ==> \result * 1000000 >= us * hz;
    ensures tight: \result >= 1 ==> (\result - 1) * 1000000 < us * hz;
*/
uint64_t mt_chibios_us_to_ticks_ceil(uint64_t us, uint32_t hz);

/** Deadline tick of a timeout of timeout_us that starts inside tick now:
 *  now + ceil(timeout_us at hz) + 1, saturating. On a periodic tick a wait
 *  ends on a tick edge and the first edge may come at once; the extra tick
 *  makes the wait last at least timeout_us. */
/*@ requires rate: hz >= 1;
    assigns \nothing;
    ensures deadline: \result == MtSat64(now + MtCeilTicks(timeout_us, hz) + 1);
    ensures after: \result > now || now == 0xFFFFFFFFFFFFFFFF;
*/
uint64_t mt_chibios_timeout_deadline(uint64_t now, uint64_t timeout_us, uint32_t hz);

/** Ticks to wait at tick now to reach tick target, in chunks of at most
 *  max_chunk (the longest single RT wait): 0 once target is reached. */
/*@ requires chunk: max_chunk >= 1;
    assigns \nothing;
    behavior reached:
      assumes target <= now;
      ensures none: \result == 0;
    behavior whole:
      assumes target > now && target - now <= max_chunk;
      ensures rest: \result == target - now;
    behavior split:
      assumes target > now && target - now > max_chunk;
      ensures chunk: \result == max_chunk;
    complete behaviors;
    disjoint behaviors;
*/
uint64_t mt_chibios_wait_chunk(uint64_t target, uint64_t now, uint64_t max_chunk);

/** A counter reading raw of a counter with largest value hw_max, moved on by
 *  offset counts with the counter's own wrap: (raw + offset) mod (hw_max + 1).
 *  The port uses it to start the RT system time anywhere in its range (wrap
 *  tests); with offset 0 it is the identity. */
/*@ requires range: raw <= hw_max && offset <= hw_max;
    assigns \nothing;
    ensures wrapped: \result == (raw + offset) % (hw_max + 1);
    ensures in_range: \result <= hw_max;
*/
uint32_t mt_chibios_counter_shift(uint32_t raw, uint32_t offset, uint32_t hw_max);

/** Microseconds elapsed inside the current tick, from the count of a tick
 *  timer that counts counts_per_tick per tick (elapsed counts since the
 *  tick edge) and a tick of tick_us whole microseconds: rounded down and
 *  always below tick_us, so that time stays monotonic across the edge. */
/*@ requires ticking: counts_per_tick >= 1 && elapsed < counts_per_tick;
    requires tick: tick_us >= 1;
    assigns \nothing;
    ensures value: \result == (elapsed * tick_us) / counts_per_tick;
    ensures below_tick: \result < tick_us;
*/
uint32_t mt_chibios_subtick_us(uint32_t elapsed, uint32_t counts_per_tick, uint32_t tick_us);

/** Time of the last tick edge plus the sub-tick part, saturating. */
/*@ assigns \nothing;
    ensures sum: \result == MtSat64(edge_us + sub_us);
    ensures not_before_edge: \result >= edge_us;
*/
uint64_t mt_chibios_time_add(uint64_t edge_us, uint32_t sub_us);

#ifdef __cplusplus
}
#endif

#endif /* MT_CHIBIOS_TIME_H */
