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

/** One console line "[   s.mmm] text\n", the time since boot in front. */
void veh_say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#ifdef __cplusplus
}
#endif

#endif /* VEH_CONSOLE_H */
