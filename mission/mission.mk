# SPDX-License-Identifier: Apache-2.0
# mission/mission.mk -- the mission file library (QGC WPL and .plan readers/writers, the check report),
# the mt-mission tool, its tests and the fuzzers; included by the top Makefile (paths relative
# to the root). The library is host C linked by tools/mission/main.c (mt-mission), the SITL
# vehicle, the tests and the fuzzers; it depends on the kernel only.
#
#   make mission-tool      build/mt-mission
#   make test-mission      the mission gtest suites (gcc, ASan+UBSan) and test-mission-tool
#   make fuzz              libFuzzer on the readers (WPL, .plan), the sequencer and the round trips

MISSION_HOST_SRC := $(wildcard mission/wpl.c mission/plan.c mission/mfile.c mission/report.c)
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
$(BUILD)/mt-mission: tools/mission/main.c $(BUILD)/gcc/libmt_mission_host.a $(BUILD)/gcc/libmt.a
	gcc $(WARN_HOST) -O2 -g $(KERNEL_INC) -Imission $< $(BUILD)/gcc/libmt_mission_host.a \
	    $(BUILD)/gcc/libmt.a $(MISSION_LIBS) -lm -o $@

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
	rc=0; $(BUILD)/mt-mission convert tests/missions/plain.waypoints $$t/plain.json 2>/dev/null || rc=$$?; \
	[ $$rc -eq 2 ] || { echo "mt-mission: convert to an unknown extension should exit 2, got $$rc"; exit 1; }; \
	echo "mt-mission: tests/missions/* valid, warn/* valid with warnings, bad/* rejected, I/O errors exit 2," \
	     "convert round trips"

# libFuzzer (clang). FUZZ_SECONDS is the time per target (4 targets).
FUZZ_SECONDS ?= 10
FUZZ_FLAGS := -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
FUZZ_TARGETS := fuzz_wpl fuzz_sequencer fuzz_roundtrip fuzz_plan
$(BUILD)/fuzz/%: fuzz/mission/%.c $(MISSION_HOST_SRC) $(wildcard mission/*.h) kernel/src/mission.c \
                 kernel/src/mission_invoke.c kernel/src/status.c $(wildcard kernel/include/mt/*.h)
	@mkdir -p $(@D)
	clang $(FUZZ_FLAGS) $(KERNEL_INC) -Ikernel/src -Imission $< $(MISSION_HOST_SRC) \
	    kernel/src/mission.c kernel/src/mission_invoke.c kernel/src/status.c $(MISSION_LIBS) -lm -o $@
fuzz: deps-test
	@$(MAKE) --no-print-directory $(addprefix $(BUILD)/fuzz/,$(FUZZ_TARGETS))
	@set -e; for t in $(FUZZ_TARGETS); do \
	    mkdir -p $(BUILD)/fuzz/corpus/$$t $(BUILD)/fuzz/artifacts; \
	    echo "== $$t ($(FUZZ_SECONDS) s, seeds fuzz/mission/corpus/$$t)"; \
	    rc=0; $(BUILD)/fuzz/$$t -max_total_time=$(FUZZ_SECONDS) -max_len=8192 -print_final_stats=1 \
	        -artifact_prefix=$(BUILD)/fuzz/artifacts/$$t- \
	        $(BUILD)/fuzz/corpus/$$t fuzz/mission/corpus/$$t >$(BUILD)/fuzz/$$t.log 2>&1 || rc=$$?; \
	    grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)" \
	        $(BUILD)/fuzz/$$t.log || true; \
	    [ $$rc -eq 0 ] || { tail -40 $(BUILD)/fuzz/$$t.log; echo "fuzz: $$t failed (exit $$rc)"; exit 1; }; \
	done
