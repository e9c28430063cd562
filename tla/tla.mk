# SPDX-License-Identifier: Apache-2.0
# TLA+ models checked with TLC (included by the top Makefile; paths relative to the root).
#
#   make tla         every CI configuration of tla/models.json (deep == false): each must give
#                    its expected result, and a passing model its pinned distinct-state count
#   make tla-deep    the larger configurations (deep == true), same checks
#   make tla-update  re-measure the CI configurations and rewrite the pinned counts
#   make tla-trace   trace validation: the real ring.c / objring.c under random interleavings
#                    (tools/trace/ring_trace), sem.c on the POSIX port (sem_trace) and
#                    mission*.c under random operations and callback outcomes
#                    (mission_trace), each trace checked against its model by TLC
#   make tla-trace-mission
#                    the mission part of tla-trace only (about 30 s; a part of `make prove`)
#
# Results: $(BUILD)/proof/tla/summary.json (summary-deep.json), logs in $(BUILD)/proof/tla/logs/,
# traces in $(BUILD)/proof/tla/trace/ (summary.json there; tla-trace-mission:
# $(BUILD)/proof/tla/trace-mission/).

TLA_JAR ?= .tools/tla/tla2tools.jar
TLA_OUT := $(BUILD)/proof/tla
TLA_RUN := python3 tla/run_tlc.py --jar $(TLA_JAR) --out $(TLA_OUT)

.PHONY: tla tla-deep tla-update tla-trace tla-trace-mission deps-tla

deps-tla:
	@test -s $(TLA_JAR) || tools/bootstrap.sh prove

# make reprove (WP_REUSE_LOCAL=yes): the models are replayed, not checked, when every input is
# that of this tree's last passing run (run_tlc.py --reuse-local); make prove checks them all.
tla: deps-tla
	@$(TLA_RUN) $(if $(filter yes,$(WP_REUSE_LOCAL)),--reuse-local)

tla-deep: deps-tla
	@$(TLA_RUN) --deep

tla-update: deps-tla
	@$(TLA_RUN) --update

tla-trace: deps-tla
	@python3 tools/trace/run_traces.py --jar $(TLA_JAR) --out $(TLA_OUT)/trace

tla-trace-mission: deps-tla
	@nice python3 tools/trace/run_traces.py --only mission --jar $(TLA_JAR) --out $(TLA_OUT)/trace-mission
