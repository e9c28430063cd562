# SPDX-License-Identifier: Apache-2.0
# mission/mission.mk -- the mission file library (QGC WPL and .plan readers/writers, the check report),
# the mt-mission tool, its tests and the fuzzers; included by the top Makefile (paths relative
# to the root). The library is host C linked by tools/mission/main.c (mt-mission), the SITL
# vehicle, the tests and the fuzzers; it depends on the kernel only.
#
#   make mission-tool      build/mt-mission
#   make test-mission      the mission gtest suites (gcc, ASan+UBSan) and test-mission-tool
#   make fuzz              libFuzzer on the readers (WPL, .plan), the sequencer and the round trips
#   make test-mission-diff the sequencer against the AP_Mission reference (tests/mission_diff):
#                          self-check, ArduPilot autotest fixtures, 1,000 random missions
#   make test-mission-deep the same diff over 100,000 missions
#   make mav-cmds          regenerate the mission command tables from MAVLink's XML
#   make check-mav-cmds    fail (with a diff) when the committed tables are stale (make test)

MISSION_HOST_SRC := $(wildcard mission/item.c mission/wpl.c mission/plan.c mission/mfile.c mission/report.c)
# .plan files are JSON, read and written with cJSON (Debian libcjson-dev, tools/bootstrap.sh test)
MISSION_LIBS := -lcjson
MISSION_TEST_SRC := $(wildcard tests/test_mission*.cpp)
WARN_HOST := -std=c11 -Wall -Wextra -Wshadow -Wundef -Wformat=2 -Werror

# $(call mission_host_lib,NAME,CC,FLAGS): the file layer for one test build
define mission_host_lib
$(BUILD)/$(1)/obj/mission/%.o: mission/%.c $$(wildcard mission/*.h kernel/include/mt/*.h)
	@mkdir -p $$(@D)
	$(2) $(WARN_HOST) $(3) $(KERNEL_INC) -Imission -c $$< -o $$@
$(BUILD)/$(1)/libmt_mission_host.a: $(patsubst mission/%.c,$(BUILD)/$(1)/obj/mission/%.o,$(MISSION_HOST_SRC))
	@mkdir -p $$(@D)
	ar rcs $$@ $$^
endef
$(eval $(call mission_host_lib,gcc,gcc,-O2 -g))
$(eval $(call mission_host_lib,clang,clang,-O2 -g))
$(eval $(call mission_host_lib,asan,clang,$(SAN_ASAN)))
$(eval $(call mission_host_lib,ubsan,clang,$(SAN_UBSAN)))
$(eval $(call mission_host_lib,tsan,clang,$(SAN_TSAN)))
$(eval $(call mission_host_lib,cov,gcc,-O0 -g --coverage))
$(eval $(call host_lib,asanubsan,clang,$(SAN_ASAN) -fsanitize=undefined -fno-sanitize-recover=all))
$(eval $(call mission_host_lib,asanubsan,clang,$(SAN_ASAN) -fsanitize=undefined -fno-sanitize-recover=all))

.PHONY: mission-tool test-mission test-mission-tool fuzz
mission-tool: $(BUILD)/mt-mission
# The tool has its own build of the file library and of the kernel's sequencer and checks, at
# the kernel's largest mission setting, so it takes a mission of any size ArduPilot takes
# whatever the vehicle's kernel was built with; `check` says whether the mission fits a kernel
# built with MISSION_KERNEL_MAX_CMDS (config.h's default; --kernel-max N for another one).
MISSION_TOOL_MAX_CMDS := 32766u
MISSION_KERNEL_MAX_CMDS ?= 700u
# The mission module's files (mission.c, mission_check.c, mission_seq.c, mission_invoke.c).
MISSION_KERNEL_SRC := $(sort $(wildcard kernel/src/mission*.c))
MISSION_TOOL_KERNEL_SRC := $(MISSION_KERNEL_SRC) kernel/src/status.c
$(BUILD)/mt-mission: tools/mission/main.c $(MISSION_HOST_SRC) $(wildcard mission/*.h) $(MISSION_TOOL_KERNEL_SRC) \
                     $(wildcard kernel/include/mt/*.h kernel/src/*.h)
	@mkdir -p $(@D)
	gcc $(WARN_HOST) -O2 -g -DMT_CFG_MISSION_MAX_CMDS=$(MISSION_TOOL_MAX_CMDS) \
	    -DMT_TOOL_KERNEL_MAX=$(MISSION_KERNEL_MAX_CMDS) $(KERNEL_INC) -Ikernel/src -Imission $< \
	    $(MISSION_HOST_SRC) $(MISSION_TOOL_KERNEL_SRC) $(MISSION_LIBS) -lm -o $@

# $(call mission_test_bin,NAME,CXX,FLAGS)
define mission_test_bin
$(BUILD)/$(1)/mt_mission_tests: $(MISSION_TEST_SRC) tests/mission_test_util.h tests/mission_file_test_util.h $(BUILD)/$(1)/libmt.a \
                                $(BUILD)/$(1)/libmt_mission_host.a
	$(2) $(WARN_CXX) $(3) $(KERNEL_INC) -Itests -Imission $(MISSION_TEST_SRC) \
	    $(BUILD)/$(1)/libmt_mission_host.a $(BUILD)/$(1)/libmt.a $(MISSION_LIBS) -lgtest -lgtest_main -pthread \
	    -lm -o $$@
endef
$(eval $(call mission_test_bin,gcc,g++,-O2 -g))
$(eval $(call mission_test_bin,asanubsan,clang++,$(SAN_ASAN) -fsanitize=undefined -fno-sanitize-recover=all))

test-mission: $(BUILD)/gcc/mt_mission_tests $(BUILD)/asanubsan/mt_mission_tests
	$(BUILD)/gcc/mt_mission_tests --gtest_brief=1
	ASAN_OPTIONS=detect_leaks=1 $(BUILD)/asanubsan/mt_mission_tests --gtest_brief=1
	@$(MAKE) --no-print-directory test-mission-tool
	@$(MAKE) --no-print-directory test-mission-diff
	@$(MAKE) --no-print-directory check-mav-cmds

# The mission command tables, generated from MAVLink's definitions (common.xml and
# ardupilotmega.xml of the pymavlink that tools/bootstrap.sh test pins) by
# tools/mavcmd/gen_mav_cmds.py and committed, since the kernel builds and is proved without
# Python: kernel/src/mt_mission_cmds.h (the rows of the kernel's k_cmds), kernel/spec/mt_spec_mission_cmds.h
# (the ACSL predicates MtMissionIsNavId / MtMissionIsDoId over the same rows) and
# mission/mav_cmd_names.h (the names mt-mission prints). check-mav-cmds regenerates them in memory and fails with a diff
# when a committed one differs (a hand edit, or a changed command list in the generator).
MAV_CMDS_PYTHON ?= python3
.PHONY: mav-cmds check-mav-cmds
mav-cmds: deps-test
	$(MAV_CMDS_PYTHON) tools/mavcmd/gen_mav_cmds.py
check-mav-cmds: deps-test
	$(MAV_CMDS_PYTHON) tools/mavcmd/gen_mav_cmds.py --check

# mt-mission over the committed mission files (part of make test; the gtest suites of the
# mission module are in every mt_tests build): tests/missions/* valid, tests/missions/warn/*
# valid with at least one warning, tests/missions/bad/* invalid (exit 1), a directory an I/O
# error (exit 2), and the .plan -> WPL -> .plan round trip of convert keeps every item.
MISSION_TOOL_TMP := $(BUILD)/mission-tool
test-mission-tool: $(BUILD)/mt-mission
	@set -e; for f in tests/missions/*.waypoints tests/missions/*.plan; do \
	    $(BUILD)/mt-mission check --json $$f >/dev/null || { echo "mt-mission: $$f should be valid"; exit 1; }; \
	done; \
	for f in tests/missions/warn/*; do \
	    out=$$($(BUILD)/mt-mission check --json $$f) || { echo "mt-mission: $$f should be valid"; exit 1; }; \
	    case "$$out" in *'"warnings": []'*) echo "mt-mission: $$f should give a warning"; exit 1;; esac; \
	    $(BUILD)/mt-mission check $$f | grep -q ": warning: " || { echo "mt-mission: $$f: no warning in text mode"; exit 1; }; \
	done; \
	for f in tests/missions/bad/*; do \
	    rc=0; $(BUILD)/mt-mission check $$f >/dev/null || rc=$$?; \
	    [ $$rc -eq 1 ] || { echo "mt-mission: $$f should be invalid (exit 1), got $$rc"; exit 1; }; \
	done; \
	rc=0; $(BUILD)/mt-mission check tests/missions >/dev/null 2>&1 || rc=$$?; \
	[ $$rc -eq 2 ] || { echo "mt-mission: a directory should be an I/O error (exit 2), got $$rc"; exit 1; }; \
	rc=0; $(BUILD)/mt-mission check tests/missions/no-such-file.plan >/dev/null 2>&1 || rc=$$?; \
	[ $$rc -eq 2 ] || { echo "mt-mission: a missing file should be an I/O error (exit 2), got $$rc"; exit 1; }; \
	mkdir -p $(MISSION_TOOL_TMP); t=$(MISSION_TOOL_TMP); \
	$(BUILD)/mt-mission convert tests/missions/qgc_example.plan $$t/qgc.waypoints 2>/dev/null; \
	$(BUILD)/mt-mission convert $$t/qgc.waypoints $$t/qgc.plan; \
	$(BUILD)/mt-mission fmt tests/missions/qgc_example.plan >$$t/a.waypoints 2>/dev/null; \
	$(BUILD)/mt-mission fmt $$t/qgc.plan >$$t/b.waypoints; \
	cmp -s $$t/a.waypoints $$t/b.waypoints || { echo "mt-mission: .plan -> WPL -> .plan changed the mission"; \
	    diff $$t/a.waypoints $$t/b.waypoints; exit 1; }; \
	$(BUILD)/mt-mission convert tests/missions/plain.waypoints $$t/plain.plan; \
	$(BUILD)/mt-mission convert $$t/plain.plan $$t/plain.waypoints; \
	$(BUILD)/mt-mission fmt tests/missions/plain.waypoints | cmp -s - $$t/plain.waypoints || { \
	    echo "mt-mission: WPL -> .plan -> WPL changed the mission"; exit 1; }; \
	python3 -c 'import sys; print("QGC WPL 110"); \
	    print("0\t1\t0\t16\t0\t0\t0\t0\t-35.363262\t149.165237\t584.09\t1"); \
	    [print("%d\t0\t3\t16\t0\t0\t0\t0\t%.6f\t149.165237\t30\t1" % (i, -35.36 + i * 1e-5)) for i in range(1, 1000)]' \
	    >$$t/big.waypoints; \
	$(BUILD)/mt-mission check $$t/big.waypoints | grep -q "does NOT fit a kernel built with MT_CFG_MISSION_MAX_CMDS=700: 1000 commands" || { \
	    echo "mt-mission: a 1000-item mission should be valid and not fit the default kernel"; exit 1; }; \
	$(BUILD)/mt-mission check --json --kernel-max 1000 $$t/big.waypoints | grep -q '"items": 1000, "kernel_max_cmds": 1000, "fits_kernel": true' || { \
	    echo "mt-mission: a 1000-item mission should fit --kernel-max 1000"; exit 1; }; \
	$(BUILD)/mt-mission check tests/missions/plain.waypoints | grep -q "^fits a kernel built with MT_CFG_MISSION_MAX_CMDS=700" || { \
	    echo "mt-mission: plain.waypoints should fit the default kernel"; exit 1; }; \
	rc=0; $(BUILD)/mt-mission convert tests/missions/plain.waypoints $$t/plain.json 2>/dev/null || rc=$$?; \
	[ $$rc -eq 2 ] || { echo "mt-mission: convert to an unknown extension should exit 2, got $$rc"; exit 1; }; \
	echo "mt-mission: tests/missions/* valid, warn/* valid with warnings, bad/* rejected, I/O errors exit 2," \
	     "convert round trips, a 1000-item mission checked and said not to fit a 700-command kernel"

# Differential test of the sequencer (kernel/src/mission.c, public API only, through a small
# driver) against an executable reference of ArduPilot's AP_Mission update step
# (tests/mission_diff/ap_mission_ref.py): tests/mission_diff/run_diff.py generates missions and
# operation scripts, compares the callback streams, prints the first mismatch and exits 1.
# --all also runs the self-check (a seeded do-order bug must be caught) and the fixtures
# taken from ArduPilot's autotests; pytest first runs the reference's hand-worked cases
# (tests/mission_diff/test_ap_mission_ref.py). MISSION_DIFF_SEED picks another fixed seed.
MISSION_DIFF_DRIVER := $(BUILD)/mission_diff/mission_diff_driver
MISSION_DIFF_PYTHON ?= $(shell [ -x /usr/bin/python3 ] && echo /usr/bin/python3 || echo python3)
MISSION_DIFF_SEED ?= 1
$(MISSION_DIFF_DRIVER): tests/mission_diff/mission_diff_driver.c $(BUILD)/gcc/libmt.a \
                        $(wildcard kernel/include/mt/*.h kernel/port/*.h kernel/spec/*.h)
	@mkdir -p $(@D)
	gcc $(WARN_C) -O2 -g $(KERNEL_INC) $< $(BUILD)/gcc/libmt.a -o $@

.PHONY: test-mission-diff test-mission-deep
test-mission-diff: $(MISSION_DIFF_DRIVER)
	$(MISSION_DIFF_PYTHON) -m pytest -q -p no:cacheprovider tests/mission_diff
	$(MISSION_DIFF_PYTHON) tests/mission_diff/run_diff.py --driver $(MISSION_DIFF_DRIVER) --all \
	    --count 1000 --seed $(MISSION_DIFF_SEED)

test-mission-deep: $(MISSION_DIFF_DRIVER)
	$(MISSION_DIFF_PYTHON) tests/mission_diff/run_diff.py --driver $(MISSION_DIFF_DRIVER) --all \
	    --count 100000 --seed $(MISSION_DIFF_SEED)

# libFuzzer (clang). FUZZ_SECONDS is the time per target (5 targets: four here, the vehicle's
# MAVLink link in vehicle/vehicle.mk); seeds in fuzz/<mission|vehicle>/corpus/<target>.
FUZZ_SECONDS ?= 10
FUZZ_FLAGS := -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
FUZZ_TARGETS := fuzz_wpl fuzz_sequencer fuzz_roundtrip fuzz_plan fuzz_link
$(BUILD)/fuzz/%: fuzz/mission/%.c $(MISSION_HOST_SRC) $(wildcard mission/*.h) $(MISSION_KERNEL_SRC) \
                 kernel/src/status.c $(wildcard kernel/include/mt/*.h) \
                 $(wildcard kernel/src/*.h)
	@mkdir -p $(@D)
	clang $(FUZZ_FLAGS) $(KERNEL_INC) -Ikernel/src -Imission $< $(MISSION_HOST_SRC) \
	    $(MISSION_KERNEL_SRC) kernel/src/status.c $(MISSION_LIBS) -lm -o $@
fuzz: deps-test
	@$(MAKE) --no-print-directory $(addprefix $(BUILD)/fuzz/,$(FUZZ_TARGETS))
	@set -e; for t in $(FUZZ_TARGETS); do \
	    mkdir -p $(BUILD)/fuzz/corpus/$$t $(BUILD)/fuzz/artifacts; \
	    seeds=$$(ls -d fuzz/*/corpus/$$t); \
	    echo "== $$t ($(FUZZ_SECONDS) s, seeds $$seeds)"; \
	    rc=0; $(BUILD)/fuzz/$$t -max_total_time=$(FUZZ_SECONDS) -max_len=8192 -print_final_stats=1 \
	        -artifact_prefix=$(BUILD)/fuzz/artifacts/$$t- \
	        $(BUILD)/fuzz/corpus/$$t $$seeds >$(BUILD)/fuzz/$$t.log 2>&1 || rc=$$?; \
	    grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)" \
	        $(BUILD)/fuzz/$$t.log || true; \
	    [ $$rc -eq 0 ] || { tail -40 $(BUILD)/fuzz/$$t.log; echo "fuzz: $$t failed (exit $$rc)"; exit 1; }; \
	done
