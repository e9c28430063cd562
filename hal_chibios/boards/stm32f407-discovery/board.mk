# SPDX-License-Identifier: Apache-2.0
# Metronome - STM32F4-Discovery (STM32F407VG), ChibiOS/RT + HAL (PAL only).
# Build only: there is no QEMU machine for it (see CHIBIOS_QEMU.md for the
# netduinoplus2 route). Included by hal_chibios/mk/firmware.mk.

MCU := cortex-m4
USE_FPU ?= no

# ChibiOS startup for STM32F4xx (crt0/crt1/vectors, CMSIS and ST headers).
include $(CHIBIOS)/os/common/startup/ARMCMx/compilers/GCC/mk/startup_stm32f4xx.mk
# HAL, STM32F4xx platform, the ChibiOS board files of the Discovery kit,
# OSAL over RT.
include $(CHIBIOS)/os/hal/hal.mk
include $(CHIBIOS)/os/hal/ports/STM32/STM32F4xx/platform.mk
include $(CHIBIOS)/os/hal/boards/ST_STM32F4_DISCOVERY/board.mk
include $(CHIBIOS)/os/hal/osal/rt-nil/osal.mk
# RT kernel and ARMv7-M port.
include $(CHIBIOS)/os/rt/rt.mk
include $(CHIBIOS)/os/common/ports/ARMv7-M/compilers/GCC/mk/port.mk

LDSCRIPT   := $(STARTUPLD)/STM32F407xG.ld
BOARD_CSRC := $(BOARDDIR)/f407_glue.c
BOARD_INC  := $(BOARDDIR)

QEMU_MACHINE :=
