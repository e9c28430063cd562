/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - board glue for the STM32F4-Discovery on the ChibiOS HAL:
 * halInit() (clocks, PAL, system tick), polled USART2 console on PA2
 * (AF7, 115200 8N1), exit through semihosting when a debugger is attached.
 */
#include "hal.h"
#include "fw_board.h"

#define CONSOLE_BAUD    115200U
#define CONSOLE_TX_PAD  2U          /* PA2 = USART2_TX */
#define CONSOLE_TX_AF   7U

void fw_board_init(void) {
  halInit();

  rccEnableUSART2(true);
  palSetPadMode(GPIOA, CONSOLE_TX_PAD, PAL_MODE_ALTERNATE(CONSOLE_TX_AF));
  USART2->CR1 = 0U;
  USART2->BRR = (uint32_t)((STM32_PCLK1 + (CONSOLE_BAUD / 2U)) / CONSOLE_BAUD);
  USART2->CR2 = 0U;
  USART2->CR3 = 0U;
  USART2->CR1 = USART_CR1_UE | USART_CR1_TE;
}

void fw_putc(char c) {
  while ((USART2->SR & USART_SR_TXE) == 0U) {
  }
  USART2->DR = (uint32_t)(uint8_t)c;
}

void fw_exit(int status) {
  /* Drain the console before stopping. */
  while ((USART2->SR & USART_SR_TC) == 0U) {
  }
  if ((CoreDebug->DHCSR & CoreDebug_DHCSR_C_DEBUGEN_Msk) != 0U) {
    fw_semihost_exit(status);
  }
  /* Standalone: a semihosting BKPT would fault, so just stop here. */
  __disable_irq();
  for (;;) {
  }
}
