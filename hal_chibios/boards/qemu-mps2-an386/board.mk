# SPDX-License-Identifier: Apache-2.0
# Metronome - QEMU mps2-an386 (Cortex-M4F), ChibiOS/RT without HAL.
# Included by hal_chibios/mk/firmware.mk with CHIBIOS and BOARDDIR set.

MCU := cortex-m4
# The core has an FPU; the firmware does not use it yet (soft float keeps
# the RT context switch free of FP state).
USE_FPU ?= no

# Device-neutral ARMCMx startup from the ChibiOS tree (the stock startup
# makefiles are per vendor family; this board needs none of their headers).
STARTUPSRC := $(CHIBIOS)/os/common/startup/ARMCMx/compilers/GCC/crt1.c
STARTUPASM := $(CHIBIOS)/os/common/startup/ARMCMx/compilers/GCC/crt0_v7m.S \
              $(CHIBIOS)/os/common/startup/ARMCMx/compilers/GCC/vectors.S
STARTUPINC := $(CHIBIOS)/os/common/portability/GCC \
              $(CHIBIOS)/os/common/startup/ARMCMx/compilers/GCC \
              $(CHIBIOS)/os/common/ext/ARM/CMSIS/Core/Include
STARTUPLD  := $(CHIBIOS)/os/common/startup/ARMCMx/compilers/GCC/ld
ALLXASMSRC += $(STARTUPASM)
ALLCSRC    += $(STARTUPSRC)
ALLINC     += $(STARTUPINC)

# RT kernel and ARMv7-M port.
include $(CHIBIOS)/os/rt/rt.mk
include $(CHIBIOS)/os/common/ports/ARMv7-M/compilers/GCC/mk/port.mk

LDSCRIPT  := $(BOARDDIR)/mps2_an386.ld
BOARD_CSRC := $(BOARDDIR)/mps2_board.c
BOARD_INC  := $(BOARDDIR)

# How to run it (used by the run target).
QEMU_MACHINE := mps2-an386

# The link UART (hal_chibios/include/fw_link.h: UART1, interrupt-driven
# receive into a kernel byte ring): an app that uses it adds this to its
# sources (it needs the kernel's headers, which not every app has).
BOARD_LINK_CSRC := $(BOARDDIR)/mps2_link.c
