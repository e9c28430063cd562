# SPDX-License-Identifier: Apache-2.0
#
# Metronome - the example vehicle (included by the top-level Makefile).
#
#   make sitl [MISSION=vehicle/missions/<file>.waypoints] [SITL_ARGS=...]
#   make sched-check [SCHED_TABLE=...]  Z3 schedulability check of vehicle/tasks.def (exit 1:
#                                    not schedulable, e.g. SCHED_TABLE=tests/vehicle/overloaded.def)
#   make test-vehicle                the vehicle's file-level call graph is acyclic; SITL
#                                    flights, fault injection, bad missions, sched-check
#                                    against SITL (tests/vehicle/)
#
# The firmware build of the same vehicle: make firmware CHIBIOS=... APP=vehicle
# (vehicle/deploy/chibios/, hal_chibios/mk/targets.mk).

VEH_SRC      := $(wildcard vehicle/src/*.c) $(wildcard vehicle/sim/*.c) \
                vehicle/deploy/builtin_mission.c vehicle/deploy/startup.c
VEH_SITL_SRC := vehicle/deploy/sitl/main.c
VEH_HDR      := $(wildcard vehicle/src/*.h vehicle/sim/*.h vehicle/deploy/*.h) vehicle/tasks.def
VEH_INC      := -Ivehicle -Ivehicle/src -Ivehicle/sim -Ivehicle/deploy $(KERNEL_INC) -Ihal_posix \
                -Imission
# Floating point is fine here (not in kernel/); the kernel's warning set plus float checks.
VEH_WARN     := -std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
                -Wmissing-prototypes -Wundef -Wformat=2 -Wdouble-promotion -Wconversion \
                -Wsign-conversion -Wcast-align -Werror
MISSION      ?= vehicle/missions/plain.waypoints
SITL_ARGS    ?=
SCHED_TABLE  ?= vehicle/tasks.def
SCHED_PYTHON ?= $(shell [ -x /usr/bin/python3 ] && echo /usr/bin/python3 || echo python3)

# $(call veh_sitl,OUT,CC,FLAGS,LIBDIR,EXTRA_DEFS)
define veh_sitl
$(1): $(VEH_SRC) $(VEH_SITL_SRC) $(VEH_HDR) $(4)/libmt.a $(4)/libmt_posix.a \
      $(4)/libmt_mission_host.a
	@mkdir -p $$(@D)
	$(2) $(VEH_WARN) $(3) $(5) $(VEH_INC) $(VEH_SRC) $(VEH_SITL_SRC) \
	    $(4)/libmt_mission_host.a $(4)/libmt_posix.a $(4)/libmt.a -lcjson -pthread -lm -o $$@
endef
$(eval $(call veh_sitl,$(BUILD)/sitl/metronome-sitl,gcc,-O2 -g,$(BUILD)/gcc,))
$(eval $(call veh_sitl,$(BUILD)/sitl-asan/metronome-sitl,clang,$(SAN_ASAN) -fsanitize=undefined \
    -fno-sanitize-recover=all,$(BUILD)/asanubsan,))
$(eval $(call veh_sitl,$(BUILD)/sitl-tsan/metronome-sitl,clang,$(SAN_TSAN),$(BUILD)/tsan,))
$(eval $(call veh_sitl,$(BUILD)/sitl/metronome-sitl-overloaded,gcc,-O2 -g,$(BUILD)/gcc,\
    -DVEHICLE_TASKS_DEF='"$(CURDIR)/tests/vehicle/overloaded.def"'))
$(BUILD)/sitl/metronome-sitl-overloaded: tests/vehicle/overloaded.def

# the console formatter against the C library's printf (ASan + UBSan)
$(BUILD)/sitl/test_vprint: tests/vehicle/test_vprint.c vehicle/src/vprint.c vehicle/src/vprint.h
	@mkdir -p $(@D)
	clang $(VEH_WARN) $(SAN_ASAN) -fsanitize=undefined -fno-sanitize-recover=all \
	    -Ivehicle/src tests/vehicle/test_vprint.c vehicle/src/vprint.c -o $@

.PHONY: sitl sched-check test-vehicle deps-sched
sitl: $(BUILD)/sitl/metronome-sitl
	@mkdir -p $(BUILD)/sitl
	$(BUILD)/sitl/metronome-sitl --log $(BUILD)/sitl/flight.bin $(SITL_ARGS) $(MISSION)

deps-sched:
	@tools/bootstrap.sh sched >/dev/null

sched-check: deps-sched
	$(SCHED_PYTHON) tools/sched_check.py $(SCHED_TABLE)

test-vehicle: deps-sched $(BUILD)/sitl/metronome-sitl $(BUILD)/sitl/metronome-sitl-overloaded \
              $(BUILD)/sitl-asan/metronome-sitl $(BUILD)/sitl-tsan/metronome-sitl $(BUILD)/sitl/test_vprint
	$(SCHED_PYTHON) tests/vehicle/check_callgraph.py gcc $(VEH_WARN) $(VEH_INC) \
	    -Ihal_chibios/port -Ihal_chibios/include
	$(SCHED_PYTHON) tests/vehicle/run_tests.py --build $(BUILD)
