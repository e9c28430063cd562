# SPDX-License-Identifier: Apache-2.0
#
# Metronome - ChibiOS firmware gates, included by the top-level Makefile
# (make runs from the repository root; $(BUILD) defaults to build).
#
#   make firmware   CHIBIOS=/path/to/ChibiOS [BOARD=qemu-mps2-an386|stm32f407-discovery] [APP=smoke]
#                   (APP=vehicle: the example vehicle, vehicle/deploy/chibios/)
#   make qemu-smoke CHIBIOS=/path/to/ChibiOS
#   make chibios-prove                 WP + CBMC proofs of the port's time arithmetic
#
# firmware builds $(APP) for $(BOARD) (text/data/bss printed after the
# build); qemu-smoke runs hal_chibios/scripts/qemu_smoke.sh. Both skip with
# success when CHIBIOS is not set: ChibiOS is never part of this repository.

FW_CHIBIOS_TESTED := ver21.11.5
FW_SKIP := skipped: CHIBIOS not set (give CHIBIOS=/path/to/ChibiOS, tested with $(FW_CHIBIOS_TESTED))

.PHONY: firmware qemu-smoke chibios-prove chibios-wp chibios-cbmc

firmware:
ifeq ($(strip $(CHIBIOS)),)
	@echo "firmware: $(FW_SKIP)"
else
	@tools/bootstrap.sh cross
	@$(MAKE) --no-print-directory -f hal_chibios/mk/firmware.mk -j$(NPROC) CHIBIOS="$(CHIBIOS)" \
	    BUILD="$(BUILD)" BOARD="$(or $(BOARD),qemu-mps2-an386)" APP="$(or $(APP),smoke)" \
	    $(if $(filter vehicle,$(APP)),APPDIR="$(CURDIR)/vehicle/deploy/chibios")
endif

qemu-smoke:
ifeq ($(strip $(CHIBIOS)),)
	@echo "qemu-smoke: $(FW_SKIP)"
else
	@tools/bootstrap.sh cross qemu
	@CHIBIOS="$(CHIBIOS)" BUILD="$(BUILD)" bash hal_chibios/scripts/qemu_smoke.sh
endif

# ---------------------------------------------------------------- proofs of the port's time helpers
FW_WP_DIR := $(BUILD)/proof/hal_chibios
FW_WP_SRC := hal_chibios/port/mt_chibios_time.c

chibios-prove: chibios-wp chibios-cbmc

chibios-wp:
	@tools/bootstrap.sh prove
	@proofs/wp/mkconf.sh $(FW_WP_DIR) >/dev/null
	@WHY3CONFIG=$(FW_WP_DIR)/why3.conf frama-c -wp -wp-rte -warn-unsigned-overflow \
	    -warn-unsigned-downcast -wp-smoke-tests -wp-prover z3,cvc4 -wp-timeout 10 \
	    -wp-par $(NPROC) -cpp-extra-args="$(KERNEL_INC) -Ihal_chibios/port" \
	    -wp-report-json $(FW_WP_DIR)/wp.json $(FW_WP_SRC) >$(FW_WP_DIR)/wp.log 2>&1 || \
	    { tail -n 30 $(FW_WP_DIR)/wp.log; exit 1; }
	@grep -E '^\[wp\] Proved goals' $(FW_WP_DIR)/wp.log
	@python3 hal_chibios/proofs/wp_gate.py $(FW_WP_DIR)/wp.json

chibios-cbmc:
	@tools/bootstrap.sh prove
	@bash hal_chibios/proofs/run_cbmc.sh
