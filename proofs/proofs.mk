# SPDX-License-Identifier: Apache-2.0
# proofs/proofs.mk -- proof gates, included by the top Makefile (paths relative to the root).
#
#   make prove          tools/bootstrap.sh prove, then every proof part (tools/prove.sh), strict gate
#   make prove-cold     the same with every cache emptied (no reused verdict at all)
#   make reprove        developer shortcut: WP modules, TLC models with unchanged inputs replayed
#   make wp             Frama-C/WP on every kernel module, the data-type laws and the ChibiOS
#                       port's time arithmetic, 2 modules at a time, always from source, then
#                       the canary and proofs/wp/gate.py (fails unless 100 % goals + smoke tests)
#   make wp-<module>    one module (the names of WP_ORDER below), no gate
#   make wp-gate        the gate alone, on the last reports
#   make wp-diversity   Z3 alone and CVC4 alone, regenerates proofs/wp/diversity.md
#   make wp-clean       drop the WP sessions and caches
#
# kernel/src/invoke.c, mission_invoke.c and bus_invoke.c are not analysed: assumption A1
# (kernel/src/mt_invoke.h, kernel/src/mt_mission_invoke.h, kernel/src/mt_bus_invoke.h).

BUILD ?= build

WP_ROOT      := $(BUILD)/proof
WP_DIR       ?= $(WP_ROOT)/wp
WP_WHY3CONF  := $(WP_ROOT)/why3.conf
# Longest first (make -j starts them in this order, so the slowest module does not start
# last and leave one core idle at the end); modules not named here follow, alphabetically.
# chibios_time is the ChibiOS port's time arithmetic (hal_chibios/port/mt_chibios_time.c): the
# port's proofs go through the same flags and the same gate as the kernel's.
WP_ORDER     := sched sched_loop wq_run bus mission bus_sub mission_check ring mission_seq objring bus_reg \
                wq wq_timer proc wq_report laws time sem chibios_time status
WP_ALL_MODS  := $(filter-out invoke mission_invoke bus_invoke,$(basename $(notdir $(wildcard kernel/src/*.c)))) laws chibios_time
WP_MODULES   := $(filter $(WP_ALL_MODS),$(WP_ORDER)) $(filter-out $(WP_ORDER),$(WP_ALL_MODS))
# Per proof goal; smoke tests have their own limit (-wp-smoke-timeout, 2 s by default). Most
# goals pass in under 7 s on an idle 2-core machine: 20 s leaves room for a loaded CI runner,
# and costs nothing on goals that pass. WP_TIMEOUT_<module> raises it for one module, with the
# goal that needs it named here and in assumption W1, which the report prints:
# - mission: put_all's loop invariant `copied` takes 960 thousand CVC4 steps, 15.8 s to 22.7 s
#   on the 2-core machines here (the same task text, measured twice).
WP_TIMEOUT   := 20
WP_TIMEOUT_mission := 40
wp_timeout    = $(or $(WP_TIMEOUT_$(1)),$(WP_TIMEOUT))
# Smoke tests (proofs/wp/README.md, "Smoke tests"): decided by Qed and CVC4; Z3 declines a task
# with this limit (proofs/wp/goal_only.sh), so it must differ from WP_TIMEOUT. `make wp-canary`
# (part of `make wp`) shows that these settings still find contradictions.
WP_SMOKE_TIMEOUT := 2
ifeq ($(WP_SMOKE_TIMEOUT),$(WP_TIMEOUT))
$(error WP_SMOKE_TIMEOUT must differ from WP_TIMEOUT: Z3 declines tasks with the smoke limit)
endif
# -wp-par (prover processes per module) and modules at a time. A warm run sends few goals to the
# provers, so 2 x 2 is safe there; make prove-cold, where every goal goes to the provers, runs
# one module at a time in one lane (WP_JOBS=1: 2 prover processes on the 2 cores, Z3 and CVC4
# racing on each goal): with more, a goal that takes 7 s on an idle core gets a third of one and
# hits the 20 s limit. (WP_PAR=1 instead runs the provers one after the other: module proc cold
# took 265 s with it, 61 s with WP_PAR=2.)
WP_PAR       ?= 2
WP_JOBS      ?= 2
WP_PROVERS   ?= z3-fixedto,cvc4
# The WP result cache: `update` replays recorded verdicts of byte-identical prover tasks and
# records new ones. Each module's session is seeded from the committed bundle
# proofs/wp/cache/<m>.json (proofs/wp/cache.py), so a clean clone (CI) re-runs provers only on
# changed goals; WP_CACHE=none runs every prover (and ignores the bundles). The report counts
# replayed and fresh results (assumption W4). `make wp-cache-save` refreshes the bundles.
WP_CACHE     ?= update
WP_CACHE_DIR := proofs/wp/cache
WP_INC       := -Ikernel/include -Ikernel/port -Ikernel/spec -Ikernel/src
# Sources per module: kernel/src/<m>.c, or every file of proofs/wp/laws/ for `laws`.
WP_SRC_laws  := $(wildcard proofs/wp/laws/*.c)
WP_SRC_chibios_time := hal_chibios/port/mt_chibios_time.c
WP_INC_chibios_time := -Ihal_chibios/port
wp_src        = $(or $(WP_SRC_$(1)),kernel/src/$(1).c)
wp_inc        = $(WP_INC) $(WP_INC_$(1))
# Memory model per module. objring and bus take `void *` objects (messages) and handle them as
# bytes only; WP's Typed model reads void* as sint8*, so the void* -> uint8_t* casts need +cast
# (keeps the pointer value). Sound there because those modules never access those bytes as
# another type; gate.py accepts exactly that cast warning, in those modules only.
WP_MODEL_objring := Typed+cast
# The work queue's void * entry points (mt_work_notify_i, mt_wq_timer_proc, mt_wq_thread_body:
# the callback shapes of the bus, the proc sets and the port threads) convert their argument
# back to the mt_work_t / mt_wq_t it is; +cast keeps the pointer value. Sound because those
# objects are only ever accessed with their own type; gate.py accepts exactly these casts.
WP_MODEL_wq := Typed+cast
WP_MODEL_bus     := Typed+cast
# A file of a module split over several files (wq_timer.c of wq) takes its module's model: the
# module is the part of the file name before the first '_'.
wp_model      = $(or $(WP_MODEL_$(1)),$(WP_MODEL_$(firstword $(subst _, ,$(1)))),Typed)

# WP_SMOKE=no drops the smoke tests (only for the prover-diversity runs, which compare goals).
WP_SMOKE     ?= yes
# WP_FCT restricts every module to the named functions (prove_selftest); WP_FCT_<module>, set
# by a shard plan (PROVE_SHARD, tools/prove_shard.py), restricts one module.
wp_fct        = $(or $(WP_FCT),$(WP_FCT_$(1)))
# WP_PROP_<module> restricts one module to the named properties (-wp-prop): a shard plan sets
# @lemma to prove the module's lemmas alone (a run with -wp-fct proves no lemma).
wp_prop       = $(WP_PROP_$(1))
WP_CORE_FLAGS = -wp -wp-rte -warn-unsigned-overflow -warn-unsigned-downcast \
           $(if $(filter no,$(WP_SMOKE)),-wp-no-smoke-tests,-wp-smoke-tests) -wp-smoke-timeout $(WP_SMOKE_TIMEOUT) -wp-prover $(WP_PROVERS)
WP_FLAGS = $(WP_CORE_FLAGS) -wp-par $(WP_PAR) -wp-cache $(WP_CACHE) -load-module $(WP_POLL)
# Frama-C's task server sleeps 50 ms between rounds; proofs/wp/wp_poll.ml polls every 2 ms
# (compiled against the installed Frama-C by the rule below). Verdicts are unchanged.
WP_POLL      := $(WP_ROOT)/wp_poll.cmxs

.PHONY: prove reprove prove-cold prove-selftest prove-selftest-ci deps-prove wp wp-all wp-gate wp-canary wp-clean \
        wp-diversity wp-conf wp-cache-save \
        $(addprefix wp-,$(WP_MODULES)) $(addprefix wp-run-,$(WP_MODULES)) \
        $(addprefix wp-inputs-,$(WP_MODULES))

deps-prove:
	@tools/bootstrap.sh prove

# Every proof part (WP, CBMC, TLC, traces), timed, then the report and its strict gate
# (tools/prove.sh, tools/proof_report.py): anything not proved fails.
prove:
	@WP_REUSE_LOCAL= tools/prove.sh

# Developer shortcut after an edit: as `make prove`, but a WP module whose inputs (its sources,
# every header of its include folders, the flags, Frama-C's version, the prover configuration)
# are byte-identical to those of this tree's last run of it is not run again: its report is
# replayed and the proof report says "replayed, not proved" for it; TLC's models likewise when
# every input of tla/run_tlc.py is that of this tree's last passing run (tla/tla.mk). CBMC
# replays per harness digest as in `make prove`. Never in CI.
reprove:
	@WP_REUSE_LOCAL=yes tools/prove.sh

# Everything from nothing: no WP cache (every prover runs on every goal), every CBMC property
# and coverage run made fresh, the capacity-maximum CBMC tier; the report says "cold". One lane
# and one WP module at a time (WP_JOBS above), so no goal times out for want of a core.
prove-cold:
	@rm -rf $(WP_DIR) $(BUILD)/proof/cbmc
	@PROVE_COLD=1 PROVE_LANES=1 WP_JOBS=1 WP_REUSE_LOCAL= WP_CACHE=none CBMC_RECORD=fresh \
	    tools/prove.sh

# Sharded proofs (tools/prove_shard.py): `make prove PROVE_SHARD=i/N` on N machines, then
# `make prove-merge SHARDS="dir1 ... dirN"` (each the BUILD folder of one shard) writes one
# report into PROVE_MERGE_OUT with the strict gate. wp-list: the WP modules, one a line,
# "name|sources|include flags", for the shard plan.
PROVE_MERGE_OUT ?= $(BUILD)/merged
.PHONY: prove-merge wp-list
prove-merge:
	@python3 tools/prove_shard.py merge $(PROVE_MERGE_OUT) $(SHARDS)

wp-list:
	@$(foreach m,$(WP_MODULES),echo '$(m)|$(call wp_src,$(m))|$(strip $(call wp_inc,$(m)))';)

# Seeded bugs (proofs/mutants.json), each rejected by the tools its entry names.
prove-selftest: deps-prove $(WP_WHY3CONF)
	@python3 tools/prove_selftest.py

# CI's share of the mutants: SELFTEST_ROTATE of them per landing, taken in turn by the commit
# count, so every mutant runs within ceil(mutants / SELFTEST_ROTATE) landings.
SELFTEST_ROTATE ?= 2
prove-selftest-ci: deps-prove $(WP_WHY3CONF)
	@python3 tools/prove_selftest.py --rotate $(SELFTEST_ROTATE)

$(WP_WHY3CONF): proofs/wp/mkconf.sh proofs/wp/why3.conf proofs/wp/z3_fixedto.drv \
                proofs/wp/goal_only.sh proofs/proofs.mk
	@proofs/wp/mkconf.sh $(WP_ROOT) $(WP_SMOKE_TIMEOUT) >/dev/null

wp-conf: $(WP_WHY3CONF)

$(WP_POLL): proofs/wp/wp_poll.ml
	@mkdir -p $(WP_ROOT)/poll
	@cp proofs/wp/wp_poll.ml $(WP_ROOT)/poll/wp_poll.ml
	@cd $(WP_ROOT)/poll && ocamlopt -shared -I "$$(frama-c -print-lib-path)" -I +unix \
	    wp_poll.ml -o ../wp_poll.cmxs

# One module: Frama-C always runs (every VC is generated from the current source); prover
# verdicts of byte-identical tasks come from the cache (assumption W4), seeded from the
# committed bundle proofs/wp/cache/<m>.json. Log, JSON report and wall time in $(WP_DIR)/<m>/.
# With WP_REUSE_LOCAL=yes (make reprove) a module whose input digest (wp_inputs) equals the one
# stored by this tree's last completed run of it is not run: replayed.txt marks the replay.
wp_inputs = { frama-c -version; cat $(WP_WHY3CONF) proofs/wp/wp_poll.ml proofs/wp/goal_only.sh \
    proofs/wp/z3_fixedto.drv; echo '$(WP_FLAGS) -wp-timeout $(call wp_timeout,$(1)) $(call wp_model,$(1)) $(call wp_fct,$(1)) \
    $(call wp_prop,$(1)) $(call wp_inc,$(1))'; \
    cat $(call wp_src,$(1)) $(sort $(wildcard $(patsubst -I%,%/*.h,$(call wp_inc,$(1))))); } \
    | sha256sum | cut -d' ' -f1

$(addprefix wp-,$(WP_MODULES)): wp-%: $(WP_WHY3CONF) $(WP_POLL)
	@mkdir -p $(WP_DIR)/$*
	@rm -f $(WP_DIR)/$*/replayed.txt
	@digest=$$($(call wp_inputs,$*)); \
	if [ "$(WP_REUSE_LOCAL)" = yes ] && [ -f $(WP_DIR)/$*/report.json ] && \
	   [ "$$(cut -d' ' -f1 $(WP_DIR)/$*/inputs.txt 2>/dev/null)" = "$$digest" ]; then \
	    cut -d' ' -f2- $(WP_DIR)/$*/inputs.txt >$(WP_DIR)/$*/replayed.txt; \
	    printf 'wp %-12s replayed from the run of %s (identical inputs): not proved now\n' \
	        "$*" "$$(cat $(WP_DIR)/$*/replayed.txt)"; \
	    exit 0; \
	fi; \
	rm -f $(WP_DIR)/$*/inputs.txt; \
	$(MAKE) --no-print-directory wp-run-$* WP_INPUTS=$$digest

# The input digest alone (tests/proofs/test_reprove.py).
$(addprefix wp-inputs-,$(WP_MODULES)): wp-inputs-%: $(WP_WHY3CONF)
	@$(call wp_inputs,$*)

$(addprefix wp-run-,$(WP_MODULES)): wp-run-%: $(WP_WHY3CONF) $(WP_POLL)
	@rm -f $(WP_DIR)/$*/report.json $(WP_DIR)/$*/wp.log $(WP_DIR)/$*/time.txt
	@$(if $(filter none,$(WP_CACHE)),rm -rf $(WP_DIR)/$*/session,python3 proofs/wp/cache.py seed \
	    $(WP_CACHE_DIR)/$*.json $(WP_DIR)/$*/session/cache >/dev/null)
	@start=$$(date +%s.%N); \
	WHY3CONFIG=$(WP_WHY3CONF) frama-c $(WP_FLAGS) -wp-timeout $(call wp_timeout,$*) -wp-model $(call wp_model,$*) \
	    $(if $(call wp_fct,$*),-wp-fct $(call wp_fct,$*)) -cpp-extra-args="$(call wp_inc,$*)" \
	    $(if $(call wp_prop,$*),-wp-prop $(call wp_prop,$*)) \
	    -wp-session $(WP_DIR)/$*/session -wp-report-json $(WP_DIR)/$*/report.json \
	    $(call wp_src,$*) >$(WP_DIR)/$*/wp.log 2>&1; rc=$$?; \
	end=$$(date +%s.%N); \
	awk -v a=$$start -v b=$$end 'BEGIN { printf "%.1f\n", b - a }' >$(WP_DIR)/$*/time.txt; \
	printf 'wp %-12s %s (%ss; prover verdicts %s)\n' "$*" \
	    "$$(grep -m1 'Proved goals' $(WP_DIR)/$*/wp.log | sed 's/.*Proved goals: *//')" \
	    "$$(cut -d. -f1 $(WP_DIR)/$*/time.txt)" \
	    "$$(python3 proofs/wp/cache.py count $(WP_DIR)/$*/wp.log | sed 's/replayed/reused/')"; \
	[ $$rc -ne 0 ] || [ -z "$(WP_INPUTS)" ] || [ ! -f $(WP_DIR)/$*/report.json ] || \
	    echo "$(WP_INPUTS) $$(date -u '+%Y-%m-%d %H:%M:%S UTC')" >$(WP_DIR)/$*/inputs.txt; \
	exit $$rc

wp-all: $(addprefix wp-,$(WP_MODULES))

wp_empty :=
wp_comma := ,
wp_list   = $(subst $(wp_empty) $(wp_empty),$(wp_comma),$(strip $(1)))

# Smoke canary: contradictions of the kinds the kernel's contracts use (quantified table
# invariants, orderings, divisions, ghost state, the port's ghost lock and clock, ...) that the
# smoke tests must find, and clean controls of the same shapes, run with the same flags and
# prover configuration as the kernel (proofs/wp/canary/); the gate shows caught/seeded.
wp-canary: $(WP_WHY3CONF) $(WP_POLL)
	@mkdir -p $(WP_DIR)/canary
	@rm -f $(WP_DIR)/canary/result.txt $(WP_DIR)/canary/result.json
	@WHY3CONFIG=$(WP_WHY3CONF) frama-c $(WP_CORE_FLAGS) -wp-timeout $(WP_TIMEOUT) -wp-par $(WP_PAR) -load-module $(WP_POLL) \
	    -cpp-extra-args="$(WP_INC)" -wp-model Typed -wp-cache none \
	    proofs/wp/canary/smoke_canary.c >$(WP_DIR)/canary/wp.log 2>&1 || \
	    { tail -n 20 $(WP_DIR)/canary/wp.log; exit 1; }
	@python3 proofs/wp/canary/check.py $(WP_DIR)/canary/wp.log --json $(WP_DIR)/canary/result.json \
	    >$(WP_DIR)/canary/result.txt; rc=$$?; tail -n 1 $(WP_DIR)/canary/result.txt; exit $$rc
	@grep -q '^wp-canary: [0-9]* functions as expected' $(WP_DIR)/canary/result.txt || \
	    { cat $(WP_DIR)/canary/result.txt; exit 1; }

# Refresh the committed cache bundles: every module in cleanup mode (replays what is cached,
# runs provers on the rest, drops entries no goal of this run uses), the canary and the gate;
# only a run that passes the gate is saved (a goal that timed out on a loaded machine must not
# be recorded), one bundle per module.
wp-cache-save: $(WP_WHY3CONF) $(WP_POLL)
	@$(MAKE) --no-print-directory -j$(WP_JOBS) wp-all WP_CACHE=cleanup
	@$(MAKE) --no-print-directory wp-canary
	@$(MAKE) --no-print-directory wp-gate >$(WP_DIR)/gate.txt || \
	    { tail -n 30 $(WP_DIR)/gate.txt; echo "wp-cache-save: the gate failed, bundles not written"; exit 1; }
	@for m in $(WP_MODULES); do \
	    python3 proofs/wp/cache.py save $(WP_DIR)/$$m/session/cache $(WP_CACHE_DIR)/$$m.json || exit 1; \
	done

# The traceability matrix (proofs/requirements.json) needs every module's goals: checked only
# when WP_MODULES is the whole set.
wp-gate:
	@python3 proofs/wp/gate.py --wp-dir $(WP_DIR) --modules $(call wp_list,$(WP_MODULES)) \
	    $(if $(filter-out $(WP_MODULES),$(WP_ALL_MODS)),,--requirements proofs/requirements.json)

wp: $(WP_WHY3CONF) $(WP_POLL)
	@start=$$(date +%s); \
	$(MAKE) --no-print-directory -j$(WP_JOBS) wp-all wp-canary; rc=$$?; \
	echo "wp: $$(( $$(date +%s) - start ))s wall for $(words $(WP_MODULES)) modules and the canary"; \
	$(MAKE) --no-print-directory wp-gate || rc=1; \
	exit $$rc

# Prover diversity: the same goals with one prover each, in their own directories. Smoke tests
# are left out of these two runs (they are decided in the main run, assumption W1; with Z3
# alone every smoke test would be declined and pass trivially).
wp-diversity: $(WP_WHY3CONF)
	@$(MAKE) --no-print-directory -j$(WP_JOBS) wp-all WP_DIR=$(WP_ROOT)/wp-z3 WP_PROVERS=z3-fixedto WP_SMOKE=no
	@$(MAKE) --no-print-directory -j$(WP_JOBS) wp-all WP_DIR=$(WP_ROOT)/wp-cvc4 WP_PROVERS=cvc4 WP_SMOKE=no
	@[ -f $(WP_DIR)/sched/report.json ] || $(MAKE) --no-print-directory -j$(WP_JOBS) wp-all
	@python3 proofs/wp/gate.py --diversity --wp-dir $(WP_DIR) --z3-dir $(WP_ROOT)/wp-z3 \
	    --cvc4-dir $(WP_ROOT)/wp-cvc4 --modules $(call wp_list,$(WP_MODULES)) \
	    --out proofs/wp/diversity.md >/dev/null
	@echo "wp-diversity: wrote proofs/wp/diversity.md"

wp-clean:
	rm -rf $(WP_ROOT)/wp $(WP_ROOT)/wp-z3 $(WP_ROOT)/wp-cvc4

# CBMC harnesses generated from the ACSL contracts (tools/acsl2cbmc), when present.
-include proofs/cbmc/cbmc.mk
-include proofs/check.mk
