/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - minimal CMSIS-style device header for the Arm MPS2 AN386
 * image (Cortex-M4 with FPU) as modelled by QEMU's "mps2-an386" machine.
 * Only what the firmware uses is described: IRQ numbers, core parameters
 * and the CMSDK APB UART.
 */
#ifndef MPS2_AN386_H
#define MPS2_AN386_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Exception and interrupt numbers (CMSIS convention: core < 0). */
typedef enum IRQn {
  NonMaskableInt_IRQn   = -14,
  HardFault_IRQn        = -13,
  MemoryManagement_IRQn = -12,
  BusFault_IRQn         = -11,
  UsageFault_IRQn       = -10,
  SVCall_IRQn           = -5,
  DebugMonitor_IRQn     = -4,
  PendSV_IRQn           = -2,
  SysTick_IRQn          = -1,

  UART0RX_IRQn          = 0,
  UART0TX_IRQn          = 1,
  UART1RX_IRQn          = 2,
  UART1TX_IRQn          = 3,
  UART2RX_IRQn          = 4,
  UART2TX_IRQn          = 5,
  GPIO0ALL_IRQn         = 6,
  GPIO1ALL_IRQn         = 7,
  TIMER0_IRQn           = 8,
  TIMER1_IRQn           = 9,
  DUALTIMER_IRQn        = 10,
  SPI_0_1_IRQn          = 11,
  UART_OVF_IRQn         = 12,
  ETHERNET_IRQn         = 13,
  I2S_IRQn              = 14,
  TSC_IRQn              = 15,
  GPIO2_IRQn            = 16,
  GPIO3_IRQn            = 17,
  UART3RX_IRQn          = 18,
  UART3TX_IRQn          = 19,
  UART4RX_IRQn          = 20,
  UART4TX_IRQn          = 21,
  SPI_2_IRQn            = 22,
  SPI_3_4_IRQn          = 23,
  GPIO0_0_IRQn          = 24,
  GPIO0_1_IRQn          = 25,
  GPIO0_2_IRQn          = 26,
  GPIO0_3_IRQn          = 27,
  GPIO0_4_IRQn          = 28,
  GPIO0_5_IRQn          = 29,
  GPIO0_6_IRQn          = 30,
  GPIO0_7_IRQn          = 31
} IRQn_Type;

/* Core parameters consumed by core_cm4.h. */
#define __CM4_REV               0x0001U
#define __MPU_PRESENT           1U
#define __FPU_PRESENT           1U
#define __NVIC_PRIO_BITS        3U
#define __Vendor_SysTickConfig  0U

#include "core_cm4.h"

/* Core clock of the FPGA image (also the SysTick clock). */
#define MPS2_SYSTEM_CLOCK       25000000U

/* CMSDK APB UART. */
typedef struct {
  volatile uint32_t DATA;       /* +0x00 data                              */
  volatile uint32_t STATE;      /* +0x04 full and overrun flags (below)    */
  volatile uint32_t CTRL;       /* +0x08 enables (below)                   */
  volatile uint32_t INTSTATUS;  /* +0x0C interrupt status, write 1 to clear */
  volatile uint32_t BAUDDIV;    /* +0x10 baud divider (>= 16)              */
} CMSDK_UART_TypeDef;

/* STATE: bit0 TX full, bit1 RX full (a byte to read), bit2 TX overrun,
   bit3 RX overrun (write 1 to clear the overrun bits). */
#define CMSDK_UART_STATE_TXFULL 0x1U
#define CMSDK_UART_STATE_RXFULL 0x2U
#define CMSDK_UART_STATE_TXOVR  0x4U
#define CMSDK_UART_STATE_RXOVR  0x8U
/* CTRL: bit0 TX enable, bit1 RX enable, bit2 TX interrupt enable, bit3 RX
   interrupt enable. */
#define CMSDK_UART_CTRL_TXEN    0x1U
#define CMSDK_UART_CTRL_RXEN    0x2U
#define CMSDK_UART_CTRL_TXIE    0x4U
#define CMSDK_UART_CTRL_RXIE    0x8U
/* INTSTATUS: bit0 TX, bit1 RX, bit2 TX overrun, bit3 RX overrun. */
#define CMSDK_UART_INT_TX       0x1U
#define CMSDK_UART_INT_RX       0x2U

/* UART0 is the console; UART1 the link UART (fw_link.h). QEMU connects
   UARTn to its n-th -serial option. */
#define CMSDK_UART0_BASE        0x40004000UL
#define CMSDK_UART0             ((CMSDK_UART_TypeDef *)CMSDK_UART0_BASE)
#define CMSDK_UART1_BASE        0x40005000UL
#define CMSDK_UART1             ((CMSDK_UART_TypeDef *)CMSDK_UART1_BASE)

#ifdef __cplusplus
}
#endif

#endif /* MPS2_AN386_H */
