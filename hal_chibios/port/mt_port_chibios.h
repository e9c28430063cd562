/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - ChibiOS/RT port: extras beyond the contract in
 * kernel/port/mt_port.h.
 */
#ifndef MT_PORT_CHIBIOS_H
#define MT_PORT_CHIBIOS_H

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Call once after chSysInit(). Arms a virtual timer that samples the system
 * tick often enough for the 64-bit time extension to see every wrap of the
 * 16/32-bit tick counter even when nobody calls mt_port_now_us() for a long
 * time (32-bit counter at 1 kHz: wraps every 49.7 days).
 */
void mt_port_chibios_start(void);

#ifdef __cplusplus
}
#endif

#endif /* MT_PORT_CHIBIOS_H */
