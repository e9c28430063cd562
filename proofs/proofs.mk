# SPDX-License-Identifier: Apache-2.0
# proofs/proofs.mk -- proof gates, included by the top Makefile (paths relative to the root).
#
#   make prove          tools/bootstrap.sh prove, then every proof part (for now: wp)
#   make wp             Frama-C/WP on every kernel module + the data-type laws, 2 modules at a
#                       time, then proofs/wp/gate.py (fails unless 100 % goals + smoke tests)
#   make wp-<module>    one module (status time sem proc ring objring sched mission wq bus laws), no gate
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
WP_ORDER     := mission sched wq bus ring objring proc laws sem time status
WP_ALL_MODS  := $(filter-out invoke mission_invoke bus_invoke,$(basename $(notdir $(wildcard kernel/src/*.c)))) laws
WP_MODULES   := $(filter $(WP_ALL_MODS),$(WP_ORDER)) $(filter-out $(WP_ORDER),$(WP_ALL_MODS))
# Per proof goal; smoke tests have their own limit (-wp-smoke-timeout, 2 s by default). The
# slowest passing goal takes about 7 s on an idle 2-core machine: 20 s leaves room for a loaded
# CI runner, and costs nothing on goals that pass.
WP_TIMEOUT   := 20
# Smoke tests (proofs/wp/README.md, "Smoke tests"): decided by Qed and CVC4; Z3 declines a task
# with this limit (proofs/wp/goal_only.sh), so it must differ from WP_TIMEOUT. `make wp-canary`
# (part of `make wp`) shows that these settings still find contradictions.
WP_SMOKE_TIMEOUT := 2
ifeq ($(WP_SMOKE_TIMEOUT),$(WP_TIMEOUT))
$(error WP_SMOKE_TIMEOUT must differ from WP_TIMEOUT: Z3 declines tasks with the smoke limit)
endif
WP_PAR       := 2
WP_JOBS      := 2
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
wp_src        = $(or $(WP_SRC_$(1)),kernel/src/$(1).c)
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
wp_model      = $(or $(WP_MODEL_$(1)),Typed)

# WP_SMOKE=no drops the smoke tests (only for the prover-diversity runs, which compare goals).
WP_SMOKE     ?= yes
# WP_KEY_FLAGS: every option that can change a verdict (the module record's key hashes them);
# WP_FLAGS adds the session cache mode and the number of parallel prover runs.
WP_CORE_FLAGS = -wp -wp-rte -warn-unsigned-overflow -warn-unsigned-downcast \
           $(if $(filter no,$(WP_SMOKE)),-wp-no-smoke-tests,-wp-smoke-tests) -wp-smoke-timeout $(WP_SMOKE_TIMEOUT) -wp-prover $(WP_PROVERS) -wp-timeout $(WP_TIMEOUT) \
           $(if $(WP_FCT),-wp-fct $(WP_FCT))
WP_KEY_FLAGS = $(WP_CORE_FLAGS) $(WP_INC)
WP_FLAGS = $(WP_CORE_FLAGS) -wp-par $(WP_PAR) -wp-cache $(WP_CACHE) -cpp-extra-args="$(WP_INC)"
# Module records (proofs/wp/record.py, assumption W5): a module whose key (preprocessed source,
# WP_KEY_FLAGS, model, Why3 configuration, tool versions) matches its last passing run in
# $(WP_DIR), or its committed record proofs/wp/records/<m>.json.gz, is not re-run: the run's
# report and log are restored, and the gate and the report say so. Only with WP_CACHE=update or
# replay and without WP_FCT; WP_RECORD=no (or WP_CACHE=none) runs Frama-C on every module.
WP_RECORD    ?= yes
wp_use_record = $(and $(filter yes,$(WP_RECORD)),$(filter update replay,$(WP_CACHE)),$(if $(WP_FCT),,yes))

.PHONY: prove prove-selftest deps-prove wp wp-all wp-gate wp-canary wp-clean wp-diversity wp-conf \
        wp-cache-save \
        $(addprefix wp-,$(WP_MODULES))

deps-prove:
	@tools/bootstrap.sh prove

# Every proof part (WP, CBMC, TLC), timed, then the report (tools/prove.sh).
# PROVE_GATE=full (default) fails unless everything is proved; PROVE_GATE=baseline fails
# only when a count drops below proofs/baseline.json.
prove:
	@tools/prove.sh

# Seeded bugs (proofs/mutants.json) that WP or CBMC must reject.
prove-selftest: deps-prove $(WP_WHY3CONF)
	@python3 tools/prove_selftest.py

$(WP_WHY3CONF): proofs/wp/mkconf.sh proofs/wp/why3.conf proofs/wp/z3_fixedto.drv \
                proofs/wp/goal_only.sh proofs/proofs.mk
	@proofs/wp/mkconf.sh $(WP_ROOT) $(WP_SMOKE_TIMEOUT) >/dev/null

wp-conf: $(WP_WHY3CONF)

# One module: log, JSON report, wall time. The session (and the WP cache, stored in the
# session directory by default) lives under $(WP_DIR)/<m>/session, so an unchanged module
# re-proves from the cache.
$(addprefix wp-,$(WP_MODULES)): wp-%: $(WP_WHY3CONF)
	@mkdir -p $(WP_DIR)/$*
	@WHY3CONFIG=$(WP_WHY3CONF) python3 proofs/wp/record.py key $* $(WP_DIR)/$*/key.new -- $(WP_KEY_FLAGS) \
	    -wp-model $(call wp_model,$*) -- $(call wp_src,$*)
	@$(if $(wp_use_record),if why=$$(python3 proofs/wp/record.py replay $* \
	        "$$(cat $(WP_DIR)/$*/key.new)" $(WP_DIR)/$*); then \
	    printf 'wp %-8s %s (%s)\n' "$*" \
	        "$$(grep -m1 'Proved goals' $(WP_DIR)/$*/wp.log | sed 's/.*Proved goals: *//')" "$$why"; \
	    rm -f $(WP_DIR)/$*/key.new; exit 0; fi;) \
	rm -f $(WP_DIR)/$*/key.txt $(WP_DIR)/$*/record.txt; \
	$(if $(filter none,$(WP_CACHE)),true,python3 proofs/wp/cache.py seed $(WP_CACHE_DIR)/$*.json \
	    $(WP_DIR)/$*/session/cache >/dev/null;) \
	start=$$(date +%s.%N); \
	WHY3CONFIG=$(WP_WHY3CONF) frama-c $(WP_FLAGS) -wp-model $(call wp_model,$*) \
	    -wp-session $(WP_DIR)/$*/session -wp-report-json $(WP_DIR)/$*/report.json \
	    $(call wp_src,$*) >$(WP_DIR)/$*/wp.log 2>&1; rc=$$?; \
	end=$$(date +%s.%N); \
	awk -v a=$$start -v b=$$end 'BEGIN { printf "%.1f\n", b - a }' >$(WP_DIR)/$*/time.txt; \
	printf 'wp %-8s %s (%ss; %s)\n' "$*" \
	    "$$(grep -m1 'Proved goals' $(WP_DIR)/$*/wp.log | sed 's/.*Proved goals: *//')" \
	    "$$(cut -d. -f1 $(WP_DIR)/$*/time.txt)" \
	    "$$(python3 proofs/wp/cache.py count $(WP_DIR)/$*/wp.log)"; \
	mv $(WP_DIR)/$*/key.new $(WP_DIR)/$*/key.txt; \
	exit $$rc

wp-all: $(addprefix wp-,$(WP_MODULES))

wp_empty :=
wp_comma := ,
wp_list   = $(subst $(wp_empty) $(wp_empty),$(wp_comma),$(strip $(1)))

# Smoke canary: contradictions the smoke tests must find, and clean controls, run with the
# same flags and prover configuration as the kernel (proofs/wp/canary/).
wp-canary: $(WP_WHY3CONF)
	@mkdir -p $(WP_DIR)/canary
	@WHY3CONFIG=$(WP_WHY3CONF) frama-c $(WP_FLAGS) -wp-model Typed -wp-cache none \
	    proofs/wp/canary/smoke_canary.c >$(WP_DIR)/canary/wp.log 2>&1 || \
	    { tail -n 20 $(WP_DIR)/canary/wp.log; exit 1; }
	@python3 proofs/wp/canary/check.py $(WP_DIR)/canary/wp.log | tee $(WP_DIR)/canary/result.txt | tail -n 1
	@grep -q '^wp-canary: [0-9]* functions as expected' $(WP_DIR)/canary/result.txt || \
	    { cat $(WP_DIR)/canary/result.txt; exit 1; }

# Refresh the committed cache bundles: every module in cleanup mode (replays what is cached,
# runs provers on the rest, drops entries no goal of this run uses), the canary and the gate;
# only a run that passes the gate is saved (a goal that timed out on a loaded machine must not
# be recorded), one bundle per module.
wp-cache-save: $(WP_WHY3CONF)
	@$(MAKE) --no-print-directory -j$(WP_JOBS) wp-all WP_CACHE=cleanup
	@$(MAKE) --no-print-directory wp-canary
	@$(MAKE) --no-print-directory wp-gate >$(WP_DIR)/gate.txt || \
	    { tail -n 30 $(WP_DIR)/gate.txt; echo "wp-cache-save: the gate failed, bundles not written"; exit 1; }
	@for m in $(WP_MODULES); do \
	    python3 proofs/wp/cache.py save $(WP_DIR)/$$m/session/cache $(WP_CACHE_DIR)/$$m.json; \
	    python3 proofs/wp/record.py save $$m $(WP_DIR)/$$m || exit 1; \
	done

wp-gate:
	@python3 proofs/wp/gate.py --wp-dir $(WP_DIR) --modules $(call wp_list,$(WP_MODULES))

wp: $(WP_WHY3CONF)
	@start=$$(date +%s); \
	$(MAKE) --no-print-directory -j$(WP_JOBS) wp-all; rc=$$?; \
	echo "wp: $$(( $$(date +%s) - start ))s wall for $(words $(WP_MODULES)) modules"; \
	[ $$rc -eq 0 ] || exit $$rc
	@$(MAKE) --no-print-directory wp-canary
	@$(MAKE) --no-print-directory wp-gate

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

# CBMC harnesses generated from the ACSL contracts (tools/acsl2cbmc.py), when present.
-include proofs/cbmc/cbmc.mk
