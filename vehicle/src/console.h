/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file console.h
 * @brief The console component: the vehicle's time (veh_now, time since boot)
 *        and its text output (veh_say: a time-stamped line; veh_printf in
 *        veh.h: plain text), formatted by vprint.c and handed to the
 *        platform's console in one piece per line.
 *
 * Every other component may call it; it calls no other component (only the
 * formatter and the platform), so the vehicle's file-level call graph stays
 * acyclic. Rules: veh_console_init once, in veh_init, before any output;
 * output from the main-loop thread only (the deployment's own lines after the
 * threads have stopped).
 */
#ifndef VEH_CONSOLE_H
#define VEH_CONSOLE_H

#include <stdbool.h>
#include <stdint.h>

#include "veh.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Bind the console to the platform's text sink; boot time is now. */
void veh_console_init(const veh_platform_t *plat);

/** The port's time, us (mt_port_now_us). */
uint64_t veh_now(void);

/** Time the vehicle was set up (veh_console_init), us. */
uint64_t veh_boot_us(void);

/** One console line "[   s.mmm] text\n", the time since boot in front. The text (without
 *  the time) is also kept for the ground-station link (veh_console_said). */
void veh_say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/** Lines kept for the link, and the longest text kept of one (longer ones are cut). */
#define VEH_SAID_KEEP 8u
#define VEH_SAID_TEXT 96u

/** The text of line number seq (1 = the first veh_say since veh_console_init). true: copied
 *  into text (VEH_SAID_TEXT bytes, NUL-terminated); false: not said yet, or overwritten by
 *  newer lines (veh_console_said_count() - seq >= VEH_SAID_KEEP: the reader has lost it). */
bool veh_console_said(uint32_t seq, char text[VEH_SAID_TEXT]);

/** Lines said so far. */
uint32_t veh_console_said_count(void);

#ifdef __cplusplus
}
#endif

#endif /* VEH_CONSOLE_H */
