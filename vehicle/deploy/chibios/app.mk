# SPDX-License-Identifier: Apache-2.0
# The example vehicle as ChibiOS firmware (make firmware CHIBIOS=... APP=vehicle; the
# top-level hal_chibios/mk/targets.mk points APPDIR here). The vehicle's components, the
# simulated world (QEMU has no sensors) and the built-in mission, on the kernel and the
# port. None of these sources includes a ChibiOS header, so all get the kernel's strict
# warnings.
include $(HALDIR)/mk/kernel.mk
VEH_DIR        := $(ROOTDIR)/vehicle
VEH_FW_CSRC    := $(wildcard $(VEH_DIR)/src/*.c) $(wildcard $(VEH_DIR)/sim/*.c) \
                  $(VEH_DIR)/deploy/builtin_mission.c $(VEH_DIR)/deploy/startup.c
APP_EXTRA_CSRC  := $(MT_KERNEL_CSRC) $(MT_PORT_CSRC) $(VEH_FW_CSRC)
# 2 kHz RT tick: the 400 Hz samples (2500 us) fall on tick edges, so the main loop wakes
# on time (with 1 kHz every other sample would wake 500 us late).
APP_EXTRA_DEFS  := $(MT_DEFS) -DCH_CFG_ST_FREQUENCY=2000
APP_EXTRA_INC   := $(MT_INC) $(VEH_DIR) $(VEH_DIR)/src $(VEH_DIR)/sim $(VEH_DIR)/deploy
APP_STRICT_CSRC := $(MT_STRICT_CSRC) $(VEH_FW_CSRC) $(APPDIR)/main.c
# float maths
ULIBS := -lm
# the main loop runs on the process stack: formatting, mission and control need more than 1 KiB
USE_PROCESS_STACKSIZE := 0x2000
# The vehicle and its simulated world are float code: use the Cortex-M4F's FPU (hard-float
# ABI; the RT port then saves the FP context of the threads that use it).
USE_FPU := hard
