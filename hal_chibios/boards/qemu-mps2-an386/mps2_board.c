/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - board support for QEMU mps2-an386 without the ChibiOS HAL:
 * polled CMSDK UART0 console, SysTick as the RT system tick, semihosting
 * exit.
 */
#include "ch.h"
#include "fw_board.h"

#define CONSOLE_BAUD        115200U

/* SysTick priority: inside the kernel-masked range (numerically above
   CORTEX_MAX_KERNEL_PRIORITY), below nothing else on this board. */
#define SYSTICK_PRIORITY    (CORTEX_MINIMUM_PRIORITY - 1U)

#if SYSTICK_PRIORITY < CORTEX_MAX_KERNEL_PRIORITY
#error "SysTick priority outside the kernel range"
#endif

/* RT system tick: one call of the system-timer handler per SysTick. */
CH_IRQ_HANDLER(SysTick_Handler) {

  CH_IRQ_PROLOGUE();

  chSysLockFromISR();
  chSysTimerHandlerI();
  chSysUnlockFromISR();

  CH_IRQ_EPILOGUE();
}

void fw_board_init(void) {
  /* Console: CMSDK UART0, transmitter only. */
  CMSDK_UART0->BAUDDIV = MPS2_SYSTEM_CLOCK / CONSOLE_BAUD;
  CMSDK_UART0->CTRL = CMSDK_UART_CTRL_TXEN;

  /* System tick at CH_CFG_ST_FREQUENCY from the core clock. Interrupts stay
     masked (startup code) until chSysInit() enables them. */
  SysTick->LOAD = (MPS2_SYSTEM_CLOCK / CH_CFG_ST_FREQUENCY) - 1U;
  SysTick->VAL = 0U;
  NVIC_SetPriority(SysTick_IRQn, SYSTICK_PRIORITY);
  SysTick->CTRL = SysTick_CTRL_CLKSOURCE_Msk | SysTick_CTRL_TICKINT_Msk |
                  SysTick_CTRL_ENABLE_Msk;
}

void fw_putc(char c) {
  while ((CMSDK_UART0->STATE & CMSDK_UART_STATE_TXFULL) != 0U) {
  }
  CMSDK_UART0->DATA = (uint32_t)(uint8_t)c;
}

void fw_exit(int status) {
  /* QEMU runs with semihosting enabled: this ends the process. */
  fw_semihost_exit(status);
}
