# SPDX-License-Identifier: Apache-2.0
# Metronome: one Makefile, named gates. `make help` lists them.

SHELL := /bin/bash
.DEFAULT_GOAL := all

BUILD     ?= build
NPROC     := $(shell nproc 2>/dev/null || echo 2)
KERNEL_INC := -Ikernel/include -Ikernel/port -Ikernel/spec
KERNEL_SRC := $(wildcard kernel/src/*.c)
POSIX_SRC  := $(wildcard hal_posix/*.c)
WARN_C     := -std=c11 -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wshadow \
              -Wstrict-prototypes -Wmissing-prototypes -Wcast-align -Wundef -Wformat=2 -Werror
WARN_POSIX := -std=c11 -Wall -Wextra -Wshadow -Wundef -Werror
WARN_CXX   := -std=c++17 -Wall -Wextra -Wshadow -Werror

.PHONY: help all kernel test test-fast test-asan test-ubsan test-tsan test-clang cross lint \
        format-check demo deps-test deps-cross deps-lint clean

# `make help`: the targets by purpose (each has a rule; tests/proofs/test_make_targets.py).
help:
	@echo "Build"
	@echo "  make                 kernel and host port with gcc and clang (warnings are errors)"
	@echo "  make cross           the kernel for Cortex-M4, bytes per module"
	@echo "  make mission-tool    build/mt-mission (check and convert WPL 110 and .plan mission files)"
	@echo "  make clean"
	@echo "Test"
	@echo "  make test            install test deps; googletest suite under gcc, clang, ASan, UBSan,"
	@echo "                       TSan; mt-mission over the mission files; check-mav-cmds;"
	@echo "                       test-mission-diff; test-vehicle; test-proof-tools"
	@echo "  make test-fast       the suite once (gcc);  make test-clang | test-asan | test-ubsan |"
	@echo "                       test-tsan: the suite under one of the other builds"
	@echo "  make test-mission    mission tests (gcc, ASan+UBSan), mt-mission over tests/missions and"
	@echo "                       check-mav-cmds, test-mission-diff"
	@echo "  make test-mission-diff  the sequencer against the AP_Mission reference: self-check,"
	@echo "                       ArduPilot autotest fixtures, 1,000 random missions (MISSION_DIFF_SEED)"
	@echo "  make test-mission-deep  the same over 100,000 missions"
	@echo "  make mav-cmds        regenerate the mission command tables from MAVLink's XML (pymavlink);"
	@echo "                       make check-mav-cmds: fail with a diff when the committed ones are stale"
	@echo "  make test-vehicle    SITL flights, fault injection, bad missions, sched-check vs SITL"
	@echo "  make test-proof-tools  pytest: the strict gate fed every kind of failure, the canary"
	@echo "                       checker, the mutants' rotation, shard plan and merge, reprove"
	@echo "  make fuzz            libFuzzer targets (clang, ASan+UBSan), short run (FUZZ_SECONDS)"
	@echo "  make lint            cppcheck (MISRA C:2012 addon) and clang-tidy over kernel/"
	@echo "  make format-check    clang-format over the C sources"
	@echo "Prove"
	@echo "  make prove           install Frama-C/Why3/Z3/CVC4/CBMC/TLC, prove everything, strict gate"
	@echo "  make prove-cold      the same with every cache emptied, plus cbmc-max; the report says cold"
	@echo "  make reprove         developer shortcut: WP modules and TLC models with unchanged"
	@echo "                       inputs replayed, not proved"
	@echo "  make prove-selftest  seeded bugs (proofs/mutants.json), each rejected as its entry says"
	@echo "  make prove PROVE_SHARD=i/N;  make prove-merge SHARDS=\"dir ...\"   proofs over N machines"
	@echo "  make wp | wp-<module> | wp-gate | wp-canary | wp-diversity | wp-cache-save"
	@echo "  make cbmc | cbmc-<function> | cbmc-max | cbmc-test | cbmc-viewer"
	@echo "  make tla | tla-deep | tla-trace | tla-trace-mission | tla-update"
	@echo "  make chibios-prove   WP and CBMC of the ChibiOS port's time arithmetic"
	@echo "  make check-<module>  one module: its tests, WP, CBMC, TLC and traces (ring objring"
	@echo "                       wordring sem proc sched time status bus wq mission; proofs/check.mk)"
	@echo "Vehicle, firmware, performance"
	@echo "  make sitl [MISSION=vehicle/missions/<file>.waypoints] [SITL_ARGS=...]   fly the example"
	@echo "  make sitl-gcs [GCS=127.0.0.1:14550] [GCS_MISSION=...] [SITL_ARGS=...]   the same on"
	@echo "                       MAVLink (UDP) for a ground station, in real time (--speedup N)"
	@echo "  make mavlink-headers the MAVLink C headers (pymavlink's mavgen) into build/mavlink"
	@echo "  make sched-check     Z3: is the vehicle's task table (vehicle/tasks.def) schedulable?"
	@echo "  make firmware CHIBIOS=/path [BOARD=...] [APP=...];  make qemu-smoke CHIBIOS=/path"
	@echo "  make test-vehicle-fw CHIBIOS=/path   the MAVLink client tests against the firmware (QEMU)"
	@echo "  make fw-gcs CHIBIOS=/path [FW_GCS_PORT=5760]   the firmware for your ground station (TCP)"
	@echo "  make demo            run a task table on the host port and print its statistics"
	@echo "  make bench           benchmarks side by side with boost and ArduPilot-style references"
	@echo "  make bench-check     the exact bench targets (instruction counts, sizes); exit 1 on a miss"

# ---------------------------------------------------------------- host builds
# $(call host_lib,NAME,CC,EXTRA_CFLAGS)
define host_lib
$(BUILD)/$(1)/obj/kernel/%.o: kernel/src/%.c $$(wildcard kernel/include/mt/*.h kernel/port/*.h kernel/spec/*.h kernel/src/*.h)
	@mkdir -p $$(@D)
	$(2) $(WARN_C) $(3) $(KERNEL_INC) -Ikernel/src -c $$< -o $$@
$(BUILD)/$(1)/obj/posix/%.o: hal_posix/%.c $$(wildcard hal_posix/*.h kernel/include/mt/*.h kernel/port/*.h)
	@mkdir -p $$(@D)
	$(2) $(WARN_POSIX) $(3) $(KERNEL_INC) -Ihal_posix -c $$< -o $$@
$(BUILD)/$(1)/libmt.a: $(patsubst kernel/src/%.c,$(BUILD)/$(1)/obj/kernel/%.o,$(KERNEL_SRC))
	@mkdir -p $$(@D)
	ar rcs $$@ $$^
$(BUILD)/$(1)/libmt_posix.a: $(patsubst hal_posix/%.c,$(BUILD)/$(1)/obj/posix/%.o,$(POSIX_SRC))
	@mkdir -p $$(@D)
	ar rcs $$@ $$^
endef

SAN_ASAN  := -O1 -g -fsanitize=address -fno-omit-frame-pointer
SAN_UBSAN := -O1 -g -fsanitize=undefined -fno-sanitize-recover=all
SAN_TSAN  := -O1 -g -fsanitize=thread

$(eval $(call host_lib,gcc,gcc,-O2 -g))
$(eval $(call host_lib,clang,clang,-O2 -g))
$(eval $(call host_lib,asan,clang,$(SAN_ASAN)))
$(eval $(call host_lib,ubsan,clang,$(SAN_UBSAN)))
$(eval $(call host_lib,tsan,clang,$(SAN_TSAN)))
$(eval $(call host_lib,cov,gcc,-O0 -g --coverage))

all: kernel
kernel: $(BUILD)/gcc/libmt.a $(BUILD)/gcc/libmt_posix.a $(BUILD)/clang/libmt.a $(BUILD)/clang/libmt_posix.a
	@echo "kernel: built with gcc and clang, warnings as errors"

# ---------------------------------------------------------------- tests
TEST_SRC := $(wildcard tests/*.cpp)
TEST_HDR := $(wildcard tests/*.h)

# $(call test_bin,NAME,CXX,FLAGS)
define test_bin
$(BUILD)/$(1)/mt_tests: $(TEST_SRC) $(TEST_HDR) $(BUILD)/$(1)/libmt.a $(BUILD)/$(1)/libmt_posix.a \
                        $(BUILD)/$(1)/libmt_mission_host.a
	$(2) $(WARN_CXX) $(3) $(KERNEL_INC) -Ihal_posix -Itests -Imission $(TEST_SRC) \
	    $(BUILD)/$(1)/libmt_mission_host.a $(BUILD)/$(1)/libmt_posix.a $(BUILD)/$(1)/libmt.a \
	    -lcjson -lgtest -lgtest_main -pthread -lm -o $$@
endef
$(eval $(call test_bin,gcc,g++,-O2 -g))
$(eval $(call test_bin,clang,clang++,-O2 -g))
$(eval $(call test_bin,asan,clang++,$(SAN_ASAN)))
$(eval $(call test_bin,ubsan,clang++,$(SAN_UBSAN)))
$(eval $(call test_bin,tsan,clang++,$(SAN_TSAN)))

deps-test:
	@tools/bootstrap.sh test

# The suite runs once per build; stress tests run under TSan (and everywhere).
test: deps-test
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/gcc/mt_tests $(BUILD)/clang/mt_tests \
	    $(BUILD)/asan/mt_tests $(BUILD)/ubsan/mt_tests $(BUILD)/tsan/mt_tests
	@set -e; for v in gcc clang asan ubsan tsan; do \
	    echo "== mt_tests ($$v)"; \
	    TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" ASAN_OPTIONS=detect_leaks=1 \
	    $(BUILD)/$$v/mt_tests --gtest_brief=1; \
	done
	@$(MAKE) --no-print-directory test-mission-tool
	@$(MAKE) --no-print-directory check-mav-cmds
	@$(MAKE) --no-print-directory test-mission-diff
	@$(MAKE) --no-print-directory test-vehicle
	@$(MAKE) --no-print-directory test-proof-tools

test-fast: $(BUILD)/gcc/mt_tests
	$(BUILD)/gcc/mt_tests

# The suite under one build: make test-clang, test-asan, test-ubsan, test-tsan.
test-clang test-asan test-ubsan test-tsan: test-%: deps-test
	@$(MAKE) --no-print-directory $(BUILD)/$*/mt_tests
	TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" ASAN_OPTIONS=detect_leaks=1 \
	    $(BUILD)/$*/mt_tests --gtest_brief=1

# ---------------------------------------------------------------- cross
ARM_CC    := arm-none-eabi-gcc
ARM_FLAGS := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -Os -ffunction-sections \
             -fdata-sections
deps-cross:
	@tools/bootstrap.sh cross

cross: deps-cross
	@mkdir -p $(BUILD)/cross
	@set -e; for f in $(KERNEL_SRC); do \
	    m=$$(basename $$f .c); \
	    $(ARM_CC) $(ARM_FLAGS) $(WARN_C) $(KERNEL_INC) -Ikernel/src -c $$f -o $(BUILD)/cross/$$m.o; \
	done
	@echo "Cortex-M4 (-mcpu=cortex-m4 -mthumb -Os), bytes per module:"
	@arm-none-eabi-size $(BUILD)/cross/*.o | tee $(BUILD)/cross/sizes.txt

# ---------------------------------------------------------------- lint, format
deps-lint:
	@tools/bootstrap.sh lint

lint: deps-lint
	@tools/lint.sh

format-check: deps-lint
	@tools/format-check.sh

# ---------------------------------------------------------------- demo
$(BUILD)/demo/mt_demo: tools/demo/demo.c $(BUILD)/gcc/libmt.a $(BUILD)/gcc/libmt_posix.a
	@mkdir -p $(@D)
	gcc $(WARN_POSIX) -O2 -g $(KERNEL_INC) -Ihal_posix tools/demo/demo.c \
	    $(BUILD)/gcc/libmt_posix.a $(BUILD)/gcc/libmt.a -pthread -o $@

demo: $(BUILD)/demo/mt_demo
	$(BUILD)/demo/mt_demo $(DEMO_ARGS)

clean:
	rm -rf $(BUILD)

# ---------------------------------------------------------------- sub-makefiles (proofs, tla, bench, firmware)
-include proofs/proofs.mk
-include tla/tla.mk
-include bench/bench.mk
-include hal_chibios/mk/targets.mk
-include vehicle/vehicle.mk
-include tools/tools.mk
-include mission/mission.mk

