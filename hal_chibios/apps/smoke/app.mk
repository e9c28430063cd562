# SPDX-License-Identifier: Apache-2.0
# smoke: every kernel module on the ChibiOS port (see main.c). main.c
# includes no ChibiOS header, so it gets the kernel's strict warnings too.
include $(HALDIR)/mk/kernel.mk
APP_EXTRA_CSRC  := $(MT_KERNEL_CSRC) $(MT_PORT_CSRC)
APP_EXTRA_DEFS  := $(MT_DEFS)
APP_EXTRA_INC   := $(MT_INC)
APP_STRICT_CSRC := $(MT_STRICT_CSRC) $(APPDIR)/main.c
