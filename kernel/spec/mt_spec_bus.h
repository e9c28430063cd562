/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_bus.h
 * @brief ACSL logic for the topic bus (mt/bus.h).
 *
 * Generations are uint32 values that wrap from 0xFFFFFFFF to 0. Every
 * distance is computed by a case split, never by a wrapping subtraction, so
 * each formula below is also the C expression (kernel/src/bus.c) and no
 * intermediate value leaves [0, 2^32).
 *
 * Only ACSL lives here: to a C compiler this header is empty.
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

#endif /* MT_SPEC_BUS_H */
