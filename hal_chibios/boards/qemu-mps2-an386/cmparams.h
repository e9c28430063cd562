/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - Cortex-M parameters of the MPS2 AN386 image, in the form the
 * ChibiOS ARMv7-M port and ARMCMx startup expect. This file is also
 * included from assembler sources (_FROM_ASM_ defined there).
 */
#ifndef CMPARAMS_H
#define CMPARAMS_H

#define CORTEX_MODEL            4
#define CORTEX_HAS_FPU          1
#define CORTEX_PRIORITY_BITS    3U
/* External interrupts of the image (QEMU models 32); multiple of 8. */
#define CORTEX_NUM_VECTORS      32
#define CORTEX_MPU_REGIONS      8

#if !defined(_FROM_ASM_)
#include "mps2_an386.h"

/* The device header and these parameters must agree. */
#if CORTEX_MODEL != __CORTEX_M
#error "cmparams.h: CORTEX_MODEL does not match the device header"
#endif
#if CORTEX_HAS_FPU != __FPU_PRESENT
#error "cmparams.h: CORTEX_HAS_FPU does not match the device header"
#endif
#if CORTEX_PRIORITY_BITS != __NVIC_PRIO_BITS
#error "cmparams.h: CORTEX_PRIORITY_BITS does not match the device header"
#endif
#endif /* !_FROM_ASM_ */

#endif /* CMPARAMS_H */
