# SPDX-License-Identifier: Apache-2.0
#
# Metronome - ChibiOS firmware gates, included by the top-level Makefile
# (make runs from the repository root; $(BUILD) defaults to build).
#
#   make firmware   CHIBIOS=/path/to/ChibiOS [BOARD=qemu-mps2-an386|stm32f407-discovery] [APP=smoke]
#                   (APP=vehicle: the example vehicle, vehicle/deploy/chibios/)
#   make qemu-smoke CHIBIOS=/path/to/ChibiOS
#   make test-vehicle-fw CHIBIOS=/path/to/ChibiOS [FW_TESTS=substring]
#                   the vehicle's MAVLink client tests against its firmware under QEMU
#   make fw-gcs CHIBIOS=/path/to/ChibiOS [FW_GCS_PORT=5760]
#                   the firmware's ground-station session for a ground station of yours
#   make chibios-prove                 WP + CBMC proofs of the port's time arithmetic
#
# firmware builds $(APP) for $(BOARD) (text/data/bss printed after the
# build); qemu-smoke runs hal_chibios/scripts/qemu_smoke.sh. Both skip with
# success when CHIBIOS is not set: ChibiOS is never part of this repository.

FW_CHIBIOS_TESTED := ver21.11.5
FW_SKIP := skipped: CHIBIOS not set (give CHIBIOS=/path/to/ChibiOS, tested with $(FW_CHIBIOS_TESTED))

.PHONY: firmware qemu-smoke test-vehicle-fw fw-gcs chibios-prove chibios-wp chibios-cbmc

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

# The MAVLink tests of tests/vehicle/run_tests.py with the firmware (APP=vehicle GCS=1) as the
# vehicle: QEMU's second serial port (the link UART) is a local TCP socket.
test-vehicle-fw:
ifeq ($(strip $(CHIBIOS)),)
	@echo "test-vehicle-fw: $(FW_SKIP)"
else
	@tools/bootstrap.sh cross qemu
	@tools/bootstrap.sh test
	@CHIBIOS="$(CHIBIOS)" BUILD="$(BUILD)" PYTHON="$(SCHED_PYTHON)" \
	    bash hal_chibios/scripts/test_vehicle_fw.sh $(FW_TESTS)
endif

# The same firmware waiting for a ground station on tcp:127.0.0.1:$(FW_GCS_PORT) (MAVProxy:
# --master tcp:127.0.0.1:5760); 'q' then Enter on the console ends the session. Interactive, so
# -icount sleep=on: idle time passes at the host clock's pace (hal_chibios/README.md).
FW_GCS_PORT ?= 5760
fw-gcs:
ifeq ($(strip $(CHIBIOS)),)
	@echo "fw-gcs: $(FW_SKIP)"
else
	@tools/bootstrap.sh cross qemu
	@$(MAKE) --no-print-directory mavlink-headers
	@$(MAKE) --no-print-directory -f hal_chibios/mk/firmware.mk -j$(NPROC) CHIBIOS="$(CHIBIOS)" \
	    BUILD="$(BUILD)" APP=vehicle APPDIR="$(CURDIR)/vehicle/deploy/chibios" VARIANT=vehicle-gcs GCS=1
	qemu-system-arm -M mps2-an386 -display none -monitor none -serial stdio \
	    -serial tcp:127.0.0.1:$(FW_GCS_PORT),server=on,wait=on,nodelay=on \
	    -semihosting-config enable=on,target=native -icount shift=5,sleep=on \
	    -kernel $(BUILD)/fw/qemu-mps2-an386/vehicle-gcs/vehicle.elf
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
