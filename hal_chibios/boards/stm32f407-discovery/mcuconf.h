/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - ChibiOS STM32F4xx HAL settings for the STM32F4-Discovery
 * (STM32F407VG, 8 MHz crystal): 168 MHz SYSCLK from the PLL, APB1 42 MHz,
 * APB2 84 MHz, 48 MHz for USB/SDIO. Only the drivers that are built (PAL,
 * ST system tick, DMA/EXTI/ISR platform parts) are configured; every other
 * driver setting keeps its HAL default and is disabled in halconf.h.
 */
#ifndef MCUCONF_H
#define MCUCONF_H

#define STM32F4xx_MCUCONF
#define STM32F407_MCUCONF

/* ---- Clock tree. STM32_NO_INIT TRUE leaves clocks as reset set them
 *      (needed under QEMU, which has no RCC model). ------------------ */
#if !defined(STM32_NO_INIT)
#define STM32_NO_INIT                       FALSE
#endif
#define STM32_PVD_ENABLE                    FALSE
#define STM32_PLS                           STM32_PLS_LEV0
#define STM32_BKPRAM_ENABLE                 FALSE
#define STM32_HSI_ENABLED                   TRUE
#define STM32_LSI_ENABLED                   TRUE
#define STM32_HSE_ENABLED                   TRUE
#define STM32_LSE_ENABLED                   FALSE
#define STM32_CLOCK48_REQUIRED              TRUE
#define STM32_SW                            STM32_SW_PLL
#define STM32_PLLSRC                        STM32_PLLSRC_HSE
#define STM32_PLLM_VALUE                    8       /* 8 MHz / 8 = 1 MHz  */
#define STM32_PLLN_VALUE                    336     /* VCO 336 MHz        */
#define STM32_PLLP_VALUE                    2       /* SYSCLK 168 MHz     */
#define STM32_PLLQ_VALUE                    7       /* 48 MHz             */
#define STM32_HPRE                          STM32_HPRE_DIV1
#define STM32_PPRE1                         STM32_PPRE1_DIV4
#define STM32_PPRE2                         STM32_PPRE2_DIV2
#define STM32_RTCSEL                        STM32_RTCSEL_LSI
#define STM32_RTCPRE_VALUE                  8
#define STM32_MCO1SEL                       STM32_MCO1SEL_HSI
#define STM32_MCO1PRE                       STM32_MCO1PRE_DIV1
#define STM32_MCO2SEL                       STM32_MCO2SEL_SYSCLK
#define STM32_MCO2PRE                       STM32_MCO2PRE_DIV5
#define STM32_I2SSRC                        STM32_I2SSRC_CKIN
#define STM32_PLLI2SN_VALUE                 192
#define STM32_PLLI2SR_VALUE                 5

/* ---- Shared interrupt priorities (4 priority bits, 0 = highest). -- */
#define STM32_IRQ_EXTI0_PRIORITY            6
#define STM32_IRQ_EXTI1_PRIORITY            6
#define STM32_IRQ_EXTI2_PRIORITY            6
#define STM32_IRQ_EXTI3_PRIORITY            6
#define STM32_IRQ_EXTI4_PRIORITY            6
#define STM32_IRQ_EXTI5_9_PRIORITY          6
#define STM32_IRQ_EXTI10_15_PRIORITY        6
#define STM32_IRQ_EXTI16_PRIORITY           6
#define STM32_IRQ_EXTI17_PRIORITY           15
#define STM32_IRQ_EXTI18_PRIORITY           6
#define STM32_IRQ_EXTI19_PRIORITY           6
#define STM32_IRQ_EXTI20_PRIORITY           6
#define STM32_IRQ_EXTI21_PRIORITY           15
#define STM32_IRQ_EXTI22_PRIORITY           15

/* The shared ISR module (stm32_isr.c) checks the timer and USART priorities
 * even when their drivers are off. */
#define STM32_IRQ_TIM1_BRK_TIM9_PRIORITY    7
#define STM32_IRQ_TIM1_UP_TIM10_PRIORITY    7
#define STM32_IRQ_TIM1_TRGCO_TIM11_PRIORITY 7
#define STM32_IRQ_TIM1_CC_PRIORITY          7
#define STM32_IRQ_TIM2_PRIORITY             7
#define STM32_IRQ_TIM3_PRIORITY             7
#define STM32_IRQ_TIM4_PRIORITY             7
#define STM32_IRQ_TIM5_PRIORITY             7
#define STM32_IRQ_TIM6_PRIORITY             7
#define STM32_IRQ_TIM7_PRIORITY             7
#define STM32_IRQ_TIM8_BRK_TIM12_PRIORITY   7
#define STM32_IRQ_TIM8_UP_TIM13_PRIORITY    7
#define STM32_IRQ_TIM8_TRGCO_TIM14_PRIORITY 7
#define STM32_IRQ_TIM8_CC_PRIORITY          7

#define STM32_IRQ_USART1_PRIORITY           12
#define STM32_IRQ_USART2_PRIORITY           12
#define STM32_IRQ_USART3_PRIORITY           12
#define STM32_IRQ_UART4_PRIORITY            12
#define STM32_IRQ_UART5_PRIORITY            12
#define STM32_IRQ_USART6_PRIORITY           12

/* ---- System tick (ST driver): SysTick in periodic mode, as chconf.h
 *      selects CH_CFG_ST_TIMEDELTA 0; the timer number only matters for
 *      tickless mode. --------------------------------------------------- */
#define STM32_ST_IRQ_PRIORITY               8
#define STM32_ST_USE_TIMER                  2

#endif /* MCUCONF_H */
