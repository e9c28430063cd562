/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - the link UART: a second serial port for a byte stream (the
 * vehicle's MAVLink ground-station link), and polled input on the console.
 * Implemented by boards that have one (BOARD_LINK_CSRC in their board.mk:
 * qemu-mps2-an386); an app that uses it adds $(BOARD_LINK_CSRC) to its
 * sources. No ChibiOS type in this header.
 *
 * Operating rules
 * - Receive is interrupt driven: the UART's receive ISR is the single
 *   producer of the byte ring given to fw_link_start (mt/ring.h allows an ISR
 *   as one side). Its consumer is one thread of the caller's. A byte that
 *   does not fit in the ring is read from the UART (so reception goes on),
 *   dropped and counted in rx_dropped: never silently.
 * - Transmit is polled: fw_link_send is the transmit ring's single consumer
 *   (one thread, e.g. an IO proc). It writes bytes while the transmitter has
 *   room and stops at the first byte it cannot write (left in the ring for
 *   the next call, counted in tx_busy): it never waits for the UART.
 * - Counters are written by the ISR and fw_link_send; fw_link_counters
 *   copies them under the kernel lock, from any thread.
 * - fw_console_rx_start / fw_console_getc: polled console input, one
 *   thread; the console's output (fw_putc) is unchanged.
 */
#ifndef FW_LINK_H
#define FW_LINK_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/ring.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What crossed the link UART. */
typedef struct {
  uint64_t rx_bytes;    /**< bytes received and put in the receive ring */
  uint32_t rx_dropped;  /**< bytes received that did not fit in the ring */
  uint32_t rx_overruns; /**< receive overruns the UART reported (bytes it lost) */
  uint32_t rx_irqs;     /**< receive interrupts served */
  uint64_t tx_bytes;    /**< bytes written to the transmitter */
  uint32_t tx_busy;     /**< sends that stopped at a full transmitter */
} fw_link_counters_t;

/*
 * Start the link UART at baud (8N1) with its receive interrupt; received
 * bytes go to rx (initialised, and not written by anyone else from now on).
 * Thread context, once, after chSysInit (mt_chibios_init).
 */
void fw_link_start(mt_bring_t *rx, uint32_t baud);

/* Stop the receive interrupt (thread context): no byte enters the ring any more. */
void fw_link_stop(void);

/*
 * Write up to max bytes of tx (its consumer) to the transmitter, stopping at
 * the first one that does not fit; returns the number written (and taken from
 * the ring). Thread context; requires fw_link_start.
 */
uint32_t fw_link_send(mt_bring_t *tx, uint32_t max);

/* A copy of the counters (thread context). */
void fw_link_counters(fw_link_counters_t *out);

/* Enable the console's receiver (thread context, once). */
void fw_console_rx_start(void);

/* A byte received on the console, or -1 when there is none (polled). */
int fw_console_getc(void);

#ifdef __cplusplus
}
#endif

#endif /* FW_LINK_H */
