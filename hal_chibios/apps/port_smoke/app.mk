# SPDX-License-Identifier: Apache-2.0
# port_smoke: the port contract (time, lock, suspend/resume, threads) through
# the kernel's semaphore.
include $(HALDIR)/mk/kernel.mk
APP_EXTRA_CSRC  := $(MT_KERNEL_CSRC) $(MT_PORT_CSRC)
APP_EXTRA_DEFS  := $(MT_DEFS)
APP_EXTRA_INC   := $(MT_INC)
APP_STRICT_CSRC := $(MT_STRICT_CSRC)
