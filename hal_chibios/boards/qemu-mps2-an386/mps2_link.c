/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - the link UART of QEMU mps2-an386 (fw_link.h): CMSDK UART1 at
 * 0x40005000, receive interrupt (IRQ 2) into a byte ring, polled transmit;
 * and polled console input on UART0 (the console's output stays fw_putc).
 *
 * Under QEMU, UART1 is QEMU's second -serial option (a TCP socket for the
 * ground station); without one, what is written goes nowhere and nothing
 * arrives. The CMSDK UART holds one received byte; QEMU hands it the next
 * only once that one has been read, so a slow reader slows the sender (the
 * socket's flow control) and the UART itself never overruns there. On a
 * real part it would: its overrun flag is counted.
 */
#include "ch.h"
#include "fw_link.h"

/* The receive interrupt: above SysTick (a byte every 87 us at 115200 baud),
   inside the kernel-masked range (CH_IRQ_PROLOGUE/EPILOGUE). */
#define LINK_RX_PRIORITY    (CORTEX_MINIMUM_PRIORITY - 2U)
/* Bytes taken per interrupt at most (the UART holds one; bounded anyway). */
#define LINK_RX_BURST       16U

#if !PORT_IRQ_IS_VALID_KERNEL_PRIORITY(LINK_RX_PRIORITY)
#error "link UART priority outside the kernel range"
#endif

/* The handler name is the vector's offset: IRQ 2 is exception 18, 0x48. */
#define LINK_RX_HANDLER     Vector48
#define LINK_RX_IRQN        UART1RX_IRQn
_Static_assert(UART1RX_IRQn == 2, "Vector48 is IRQ 2");

static mt_bring_t *link_rx;     /* set before the interrupt is enabled */
static fw_link_counters_t link_cnt;

/*
 * Receive ISR: the ring's only producer. The interrupt flag is cleared
 * before the data is read: a byte that arrives meanwhile sets it again and
 * raises a new interrupt (cleared after, it would be lost with its byte).
 */
static void link_rx_isr(void) {
  uint8_t buf[LINK_RX_BURST];
  uint32_t n = 0U;
  uint32_t put;

  CMSDK_UART1->INTSTATUS = CMSDK_UART_INT_RX;
  while ((n < LINK_RX_BURST) &&
         ((CMSDK_UART1->STATE & CMSDK_UART_STATE_RXFULL) != 0U)) {
    buf[n] = (uint8_t)CMSDK_UART1->DATA;
    n++;
  }
  if ((CMSDK_UART1->STATE & CMSDK_UART_STATE_RXOVR) != 0U) {
    CMSDK_UART1->STATE = CMSDK_UART_STATE_RXOVR; /* write 1 to clear */
    link_cnt.rx_overruns++;
  }
  put = (n > 0U) ? mt_bring_write(link_rx, buf, n) : 0U;
  link_cnt.rx_bytes += put;
  link_cnt.rx_dropped += n - put;
  link_cnt.rx_irqs++;
}

CH_IRQ_HANDLER(LINK_RX_HANDLER) {

  CH_IRQ_PROLOGUE();

  link_rx_isr();

  CH_IRQ_EPILOGUE();
}

void fw_link_start(mt_bring_t *rx, uint32_t baud) {

  link_rx = rx;
  CMSDK_UART1->BAUDDIV = MPS2_SYSTEM_CLOCK / baud;
  CMSDK_UART1->INTSTATUS = CMSDK_UART_INT_TX | CMSDK_UART_INT_RX;
  NVIC_SetPriority(LINK_RX_IRQN, LINK_RX_PRIORITY);
  NVIC_ClearPendingIRQ(LINK_RX_IRQN);
  NVIC_EnableIRQ(LINK_RX_IRQN);
  CMSDK_UART1->CTRL = CMSDK_UART_CTRL_TXEN | CMSDK_UART_CTRL_RXEN |
                      CMSDK_UART_CTRL_RXIE;
}

void fw_link_stop(void) {

  CMSDK_UART1->CTRL &= ~CMSDK_UART_CTRL_RXIE;
  NVIC_DisableIRQ(LINK_RX_IRQN);
}

uint32_t fw_link_send(mt_bring_t *tx, uint32_t max) {
  mt_iovec_t vec[2];
  uint32_t segs = mt_bring_peek_vec(tx, vec);
  uint32_t first = (segs > 0U) ? vec[0].len : 0U;
  uint32_t avail = first + ((segs > 1U) ? vec[1].len : 0U);
  uint32_t n = 0U;
  bool busy = false;

  while ((n < avail) && (n < max)) {
    if ((CMSDK_UART1->STATE & CMSDK_UART_STATE_TXFULL) != 0U) {
      busy = true; /* the rest waits for the next call */
      break;
    }
    CMSDK_UART1->DATA = (uint32_t)((n < first) ? vec[0].base[n] :
                                                 vec[1].base[n - first]);
    n++;
  }
  if (n > 0U) {
    (void)mt_bring_advance(tx, n);
  }
  chSysLock();
  link_cnt.tx_bytes += n;
  if (busy) {
    link_cnt.tx_busy++;
  }
  chSysUnlock();
  return n;
}

void fw_link_counters(fw_link_counters_t *out) {

  chSysLock();
  *out = link_cnt;
  chSysUnlock();
}

void fw_console_rx_start(void) {

  CMSDK_UART0->CTRL |= CMSDK_UART_CTRL_RXEN;
}

int fw_console_getc(void) {

  if ((CMSDK_UART0->STATE & CMSDK_UART_STATE_RXFULL) == 0U) {
    return -1;
  }
  return (int)(CMSDK_UART0->DATA & 0xFFU);
}
