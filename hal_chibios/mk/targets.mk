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
	$(if $(filter vehicle,$(APP)),@$(MAKE) --no-print-directory mavlink-headers)
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

chibios-prove: chibios-wp chibios-cbmc

# The port's WP proofs are the WP module chibios_time of `make wp` (proofs/proofs.mk): same
# flags, same cache, same gate; `make prove` runs them with the kernel's.
chibios-wp: deps-prove
	@$(MAKE) --no-print-directory wp-chibios_time
	@python3 proofs/wp/gate.py --wp-dir $(WP_DIR) --modules chibios_time --quiet

chibios-cbmc:
	@tools/bootstrap.sh prove
	@BUILD="$(BUILD)" bash hal_chibios/proofs/run_cbmc.sh
