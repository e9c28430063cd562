# SPDX-License-Identifier: Apache-2.0
#
# Metronome - the kernel and the ChibiOS port as firmware sources, for an
# app.mk to add to APP_EXTRA_CSRC / APP_EXTRA_INC / APP_EXTRA_DEFS
# (firmware.mk sets ROOTDIR and HALDIR before it includes app.mk). Unused
# kernel functions cost nothing: the link drops unreferenced sections.
#
# MT_STRICT_CSRC lists the sources that include no ChibiOS header: they are
# built with the kernel's strict warning set on top of the firmware's.

MT_KERNEL_CSRC := $(wildcard $(ROOTDIR)/kernel/src/*.c)
MT_PORT_CSRC   := $(HALDIR)/port/mt_port_chibios.c \
                  $(HALDIR)/port/mt_chibios_time.c
MT_INC         := $(ROOTDIR)/kernel/include \
                  $(ROOTDIR)/kernel/port \
                  $(ROOTDIR)/kernel/spec \
                  $(HALDIR)/port
MT_STRICT_CSRC := $(MT_KERNEL_CSRC) $(HALDIR)/port/mt_chibios_time.c
# Cortex-M4 parts have no data cache: no padding between ring halves.
MT_DEFS        := -DMT_CFG_CACHE_LINE=0
