# SPDX-License-Identifier: Apache-2.0
# proofs/check.mk -- make check-<module>: everything about one kernel module, included by
# proofs/proofs.mk (paths relative to the root). In order, each must pass:
#   1. its googletest suites (build/gcc/mt_tests, CHECK_TEST_<m> as the gtest filter)
#   2. Frama-C WP on the module's files from source (the WP modules <m> and <m>_*: a module
#      split over several files, such as wq.c, wq_timer.c, ...), the smoke canary, and the WP
#      gate on those
#   3. its CBMC harnesses (proofs/cbmc/proofs/<function>/, CHECK_CBMC_<m>: name prefixes)
#   4. TLC on the CI configurations of its models (tla/models.json "module" in CHECK_TLA_<m>)
#   5. its trace validation (tools/trace/run_traces.py --only CHECK_TRACE_<m>)
# Results go to $(BUILD)/check/<module>/. `make prove` remains the run of record: this target is
# for working on one module. The table in README.md ("Modules") lists the same mapping.

CHECK_MODULES := ring objring wordring sem proc sched time status bus wq mission

CHECK_TEST_ring    := ByteRing*
CHECK_TEST_objring := ObjRing*
CHECK_TEST_wordring := WordRing*
CHECK_TEST_sem     := Sem*
CHECK_TEST_proc    := Proc*
CHECK_TEST_sched   := Sched*
CHECK_TEST_time    := TimeExt*:TimeTicksToUs*
CHECK_TEST_status  := Status*
CHECK_TEST_bus     := Bus*
CHECK_TEST_wq      := Wq*
CHECK_TEST_mission := Mission.*:MissionCheck.*:MissionState.*:MissionStatus.*:MissionReplace.*

CHECK_CBMC_ring    := mt_bring_
CHECK_CBMC_objring := mt_oring_
CHECK_CBMC_wordring := mt_wring_
CHECK_CBMC_sem     := mt_sem_
CHECK_CBMC_proc    := mt_proc_
CHECK_CBMC_sched   := mt_sched_
CHECK_CBMC_time    := mt_time_
CHECK_CBMC_status  := mt_status_
CHECK_CBMC_bus     := mt_topic_ mt_sub_
CHECK_CBMC_wq      := mt_wq_ mt_work_
CHECK_CBMC_mission := mt_mission_

# Ring models both rings (its configurations name the byte or the object ring); the word ring
# follows the same protocol (own index written with release, the other's cached and re-read
# with acquire) with slot indices instead of mirror ones, which WP and CBMC check.
CHECK_TLA_ring     := Ring
CHECK_TLA_objring  := Ring
CHECK_TLA_wordring := Ring
CHECK_TLA_sem      := Sem
CHECK_TLA_proc     := Proc
CHECK_TLA_sched    := Sched
CHECK_TLA_bus      := Bus
CHECK_TLA_wq       := WqMC
CHECK_TLA_mission  := MissionMC MissionSwap

# The ring traces run both rings.
CHECK_TRACE_ring    := ring
CHECK_TRACE_objring := ring
CHECK_TRACE_sem     := sem
CHECK_TRACE_mission := mission

check_comma := ,
check_wp = $(filter $(1) $(1)_%,$(WP_MODULES))
check_harnesses = $(foreach p,$(CHECK_CBMC_$(1)),$(filter $(p)%,$(CBMC_PROOF_NAMES)))
check_models = python3 -c 'import json; print(" ".join(m["name"] for m in \
    json.load(open("tla/models.json"))["models"] if m["module"] in "$(1)".split() and not m["deep"]))'

.PHONY: $(addprefix check-,$(CHECK_MODULES))

$(addprefix check-,$(CHECK_MODULES)): check-%: deps-test deps-prove
	@rm -rf $(BUILD)/check/$* && mkdir -p $(BUILD)/check/$*
	@echo "== check-$*: googletest ($(CHECK_TEST_$*))"
	@$(MAKE) --no-print-directory $(BUILD)/gcc/mt_tests >/dev/null
	@n=$$($(BUILD)/gcc/mt_tests --gtest_list_tests --gtest_filter='$(CHECK_TEST_$*)' | grep -c '^  '); \
	[ "$$n" -gt 0 ] || { echo "check-$*: no test matches $(CHECK_TEST_$*)"; exit 1; }
	@$(BUILD)/gcc/mt_tests --gtest_brief=1 --gtest_filter='$(CHECK_TEST_$*)'
	@echo "== check-$*: WP ($(call check_wp,$*))"
	@$(MAKE) --no-print-directory -j$(WP_JOBS) $(addprefix wp-,$(call check_wp,$*)) wp-canary
	@set -o pipefail; python3 proofs/wp/gate.py --wp-dir $(WP_DIR) --modules $(call wp_list,$(call check_wp,$*)) --quiet \
	    --summary $(BUILD)/check/$*/wp-summary.json | tail -n 4
	@echo "== check-$*: CBMC ($(words $(call check_harnesses,$*)) harnesses)"
	@set -o pipefail; python3 proofs/cbmc/run.py -j $(CBMC_JOBS) --summary $(BUILD)/check/$*/cbmc-summary.json \
	    $(call check_harnesses,$*) | tail -n 1
	@set -o pipefail; $(if $(CHECK_TLA_$*),echo "== check-$*: TLC ($(CHECK_TLA_$*))" && \
	    python3 tla/run_tlc.py --jar $(TLA_JAR) --out $(BUILD)/check/$*/tla \
	        --only $$($(call check_models,$(CHECK_TLA_$*))) | tail -n 1,true)
	@set -o pipefail; $(if $(CHECK_TRACE_$*),echo "== check-$*: traces ($(CHECK_TRACE_$*))" && \
	    python3 tools/trace/run_traces.py --only $(CHECK_TRACE_$*) --jar $(TLA_JAR) \
	        --out $(BUILD)/check/$*/trace | tail -n 1,true)
	@echo "check-$*: passed (tests, WP, CBMC$(if $(CHECK_TLA_$*),$(check_comma) TLC)$(if \
	    $(CHECK_TRACE_$*),$(check_comma) traces))"
