# SPDX-License-Identifier: Apache-2.0
# port_smoke: the kernel's semaphore and time modules on the ChibiOS port.
APP_EXTRA_CSRC := $(ROOTDIR)/kernel/src/time.c \
                  $(ROOTDIR)/kernel/src/sem.c \
                  $(HALDIR)/port/mt_port_chibios.c
APP_EXTRA_INC  := $(ROOTDIR)/kernel/include \
                  $(ROOTDIR)/kernel/port \
                  $(ROOTDIR)/kernel/spec \
                  $(HALDIR)/port
