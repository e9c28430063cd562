/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - board-neutral firmware services: console helpers, semihosting
 * exit, RT halt hook and fault handlers that turn every panic into a failed
 * run instead of a hang.
 */
#include "ch.h"
#include "fw_board.h"

/* ARM semihosting: operation number and ADP_Stopped_* reasons. */
#define SEMIHOST_SYS_EXIT               0x18U
#define ADP_STOPPED_APPLICATION_EXIT    0x20026U
#define ADP_STOPPED_RUNTIME_ERROR       0x20023U

void fw_puts(const char *s) {
  while (*s != '\0') {
    fw_putc(*s);
    s++;
  }
}

void fw_put_u32(uint32_t v) {
  char buf[10];
  unsigned n = 0U;

  do {
    buf[n++] = (char)('0' + (v % 10U));
    v /= 10U;
  } while (v != 0U);
  while (n > 0U) {
    fw_putc(buf[--n]);
  }
}

void fw_put_hex32(uint32_t v) {
  static const char digits[] = "0123456789abcdef";
  int shift;

  fw_puts("0x");
  for (shift = 28; shift >= 0; shift -= 4) {
    fw_putc(digits[(v >> (unsigned)shift) & 0xFU]);
  }
}

void fw_semihost_exit(int status) {
  /* On 32-bit ARM, SYS_EXIT takes the reason code itself in r1. */
  register uint32_t r0 __asm__("r0") = SEMIHOST_SYS_EXIT;
  register uint32_t r1 __asm__("r1") = (status == FW_EXIT_SUCCESS) ?
                                       ADP_STOPPED_APPLICATION_EXIT :
                                       ADP_STOPPED_RUNTIME_ERROR;

  __asm__ volatile ("bkpt 0xAB" : "+r" (r0) : "r" (r1) : "memory");
  /* Only reached when no semihosting host is attached. */
  __disable_irq();
  for (;;) {
  }
}

/* Called by chSysHalt() with interrupts disabled. */
void fw_halt_hook(const char *reason) {
  fw_puts("\r\nHALT: ");
  fw_puts((reason != NULL) ? reason : "(no reason)");
  fw_puts("\r\n");
  fw_exit(FW_EXIT_FAILURE);
}

static void fw_fault(const char *what) {
  __disable_irq();
  fw_puts("\r\nFAULT: ");
  fw_puts(what);
  fw_puts(" HFSR=");
  fw_put_hex32(SCB->HFSR);
  fw_puts(" CFSR=");
  fw_put_hex32(SCB->CFSR);
  fw_puts(" ICSR=");
  fw_put_hex32(SCB->ICSR);
  fw_puts("\r\n");
  fw_exit(FW_EXIT_FAILURE);
}

/* These replace weak symbols of the ChibiOS ARMCMx vector table. */
void HardFault_Handler(void);
void MemManage_Handler(void);
void BusFault_Handler(void);
void UsageFault_Handler(void);
void _unhandled_exception(void);

void HardFault_Handler(void) {
  fw_fault("HardFault");
}

void MemManage_Handler(void) {
  fw_fault("MemManage");
}

void BusFault_Handler(void) {
  fw_fault("BusFault");
}

void UsageFault_Handler(void) {
  fw_fault("UsageFault");
}

void _unhandled_exception(void) {
  fw_fault("unhandled exception");
}
