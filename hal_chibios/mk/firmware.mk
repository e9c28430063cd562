# SPDX-License-Identifier: Apache-2.0
#
# Metronome - ChibiOS firmware build.
#
#   make -f hal_chibios/mk/firmware.mk CHIBIOS=/path/to/ChibiOS \
#        [BOARD=qemu-mps2-an386|stm32f407-discovery] [APP=smoke|hello|port_smoke] [FAIL=1|2] \
#        [BUILD=build] [VARIANT=name] [EXTRA_DEFS=...] [all|run|clean]
#
# Builds $(APP) for $(BOARD) against an external ChibiOS tree (nothing of
# ChibiOS lives in this repository), using ChibiOS's own makefile fragments.
# Output: $(BUILD)/fw/$(BOARD)/$(VARIANT)/$(APP).elf, BUILD relative to the
# repository root unless absolute; VARIANT defaults to $(APP), $(APP)-fail
# (FAIL=1) or $(APP)-failN (FAIL=N). FAIL=N defines FW_FAIL=N: the app's
# seeded failure N (every app has 1). Without CHIBIOS the build is skipped
# with a message and success status.

HALDIR  := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
ROOTDIR := $(abspath $(HALDIR)/..)

BOARD ?= qemu-mps2-an386
APP   ?= smoke
FAIL  ?=
BUILD ?= build
FW_OUT := $(if $(filter /%,$(BUILD)),$(BUILD),$(ROOTDIR)/$(BUILD))/fw

BOARDDIR := $(HALDIR)/boards/$(BOARD)
APPDIR   ?= $(HALDIR)/apps/$(APP)

ifeq ($(strip $(CHIBIOS)),)

.PHONY: all run clean
all run:
	@echo "skipped: CHIBIOS not set (give CHIBIOS=/path/to/ChibiOS, tested with ver21.11.5)"
clean:
	@rm -rf $(FW_OUT)

else

CHIBIOS := $(abspath $(CHIBIOS))
ifeq ($(wildcard $(CHIBIOS)/os/rt/rt.mk),)
$(error CHIBIOS=$(CHIBIOS) does not look like a ChibiOS tree (no os/rt/rt.mk))
endif
ifeq ($(wildcard $(BOARDDIR)/board.mk),)
$(error unknown BOARD '$(BOARD)': no $(BOARDDIR)/board.mk)
endif

##############################################################################
# Global options (ChibiOS rules.mk conventions).

USE_OPT    ?= -O2 -ggdb -fomit-frame-pointer -falign-functions=16 -std=gnu11
USE_COPT   ?=
USE_CPPOPT ?= -fno-rtti
USE_LINK_GC ?= yes
USE_LDOPT  ?=
USE_LTO    ?= no
USE_VERBOSE_COMPILE ?= no
USE_SMART_BUILD ?= yes
USE_PROCESS_STACKSIZE    ?= 0x400
USE_EXCEPTIONS_STACKSIZE ?= 0x400

##############################################################################
# Project, sources, paths.

# Build-folder name; give a distinct VARIANT when changing EXTRA_DEFS.
VARIANT  ?= $(APP)$(if $(FAIL),-fail$(filter-out 1,$(FAIL)))
PROJECT  := $(APP)
BUILDDIR := $(FW_OUT)/$(BOARD)/$(VARIANT)
DEPDIR   := $(BUILDDIR)/.dep

# Configuration: RT (chconf.h) is shared; HAL configuration, when a board
# uses the HAL, lives in the board folder.
CHCONFDIR  := $(HALDIR)/cfg
HALCONFDIR := $(BOARDDIR)

include $(CHIBIOS)/os/license/license.mk
# Board: startup, RT, port (and HAL where used), LDSCRIPT, BOARD_CSRC,
# BOARD_INC, MCU.
include $(BOARDDIR)/board.mk

# Optional per-app fragment: may set APP_EXTRA_CSRC, APP_EXTRA_INC,
# APP_EXTRA_DEFS (e.g. to pull in the kernel and the port, see
# mk/kernel.mk) and APP_STRICT_CSRC (sources without ChibiOS headers, built
# with the kernel's strict warnings too).
APP_EXTRA_CSRC  :=
APP_EXTRA_INC   :=
APP_EXTRA_DEFS  :=
APP_STRICT_CSRC :=
-include $(APPDIR)/app.mk

# Our own C sources: compiled with -Werror on top of CWARN.
OWN_CSRC := $(BOARD_CSRC) \
            $(HALDIR)/common/fw_common.c \
            $(wildcard $(APPDIR)/*.c) \
            $(APP_EXTRA_CSRC) \
            $(EXTRA_CSRC)

CSRC    = $(ALLCSRC) $(OWN_CSRC)
CPPSRC  = $(ALLCPPSRC)
ASMSRC  = $(ALLASMSRC)
ASMXSRC = $(ALLXASMSRC)

INCDIR  = $(BOARD_INC) $(CHCONFDIR) $(HALDIR)/include $(APPDIR) \
          $(APP_EXTRA_INC) $(EXTRA_INC) $(ALLINC)

CWARN   = -Wall -Wextra -Wundef -Wstrict-prototypes
CPPWARN = -Wall -Wextra -Wundef

# -D options go to C (UDEFS) and to preprocessed assembler (UADEFS) alike:
# chconf.h is read by both, a mismatch breaks the link.
FW_DEFS := $(if $(FAIL),-DFW_FAIL=$(FAIL)) $(APP_EXTRA_DEFS) $(EXTRA_DEFS)
UDEFS   += $(FW_DEFS)
UADEFS  += $(FW_DEFS)
UINCDIR +=
ULIBDIR +=
ULIBS   +=

RULESPATH := $(CHIBIOS)/os/common/startup/ARMCMx/compilers/GCC/mk
include $(RULESPATH)/arm-none-eabi.mk
include $(RULESPATH)/rules.mk

OWN_OBJS := $(addprefix $(BUILDDIR)/obj/, $(notdir $(OWN_CSRC:.c=.o)))
$(OWN_OBJS): CWARN += -Werror
# The kernel's warning set (top-level Makefile) for sources that include no
# ChibiOS header (ChibiOS's inline functions would not pass -Wconversion).
STRICT_WARN := -Wpedantic -Wconversion -Wsign-conversion -Wshadow \
               -Wmissing-prototypes -Wcast-align -Wformat=2
STRICT_OBJS := $(addprefix $(BUILDDIR)/obj/, $(notdir $(APP_STRICT_CSRC:.c=.o)))
$(STRICT_OBJS): CWARN += $(STRICT_WARN)

# Size report after every build. The ChibiOS linker rules hand all RAM left
# over to a NOLOAD .heap section (core allocator), which "size" counts as
# bss; the second line leaves it out.
POST_MAKE_ALL_RULE_HOOK: $(BUILDDIR)/$(PROJECT).elf
	@echo "SIZE $(BOARD)/$(VARIANT):"
	@$(SZ) $(BUILDDIR)/$(PROJECT).elf
	@$(SZ) -A $(BUILDDIR)/$(PROJECT).elf | awk \
	  '$$1==".vectors"||$$1==".text"||$$1==".rodata"||$$1==".init_array"||$$1==".fini_array"||$$1==".ARM.exidx"{t+=$$2} \
	   $$1==".data"||$$1 ~ /^\.ram[0-7]_init$$/{d+=$$2} \
	   $$1==".bss"||$$1 ~ /^\.ram[0-7]$$/||$$1==".mstack"||$$1==".pstack"{b+=$$2} \
	   $$1==".heap"{h+=$$2} \
	   END{printf "  without .heap: text=%d data=%d bss=%d (incl. stacks); .heap=%d\n",t,d,b,h}'

##############################################################################
# Run under QEMU (boards that define QEMU_MACHINE).

QEMU ?= qemu-system-arm
QEMU_TIMEOUT ?= 60
QEMU_FLAGS = -M $(QEMU_MACHINE) -display none -monitor none -serial stdio \
             -semihosting-config enable=on,target=native -icount shift=5

.PHONY: run
run: all
ifeq ($(QEMU_MACHINE),)
	@echo "skipped: board $(BOARD) has no QEMU machine"
else
	timeout $(QEMU_TIMEOUT) $(QEMU) $(QEMU_FLAGS) -kernel $(BUILDDIR)/$(PROJECT).elf
endif

endif
