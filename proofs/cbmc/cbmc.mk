# SPDX-License-Identifier: Apache-2.0
# proofs/cbmc/cbmc.mk -- CBMC gates, included by proofs/proofs.mk (paths relative to the root).
#
#   make cbmc            every proof in proofs/cbmc/proofs/ (2 at a time): property run with all
#                        check flags + coverage run; fails if a property fails, a harness
#                        covers < 90 % of the kernel code it reaches, or a reachability
#                        witness (MTC_REACH) is not reached. Writes build/proof/cbmc/summary.json.
#   make cbmc-<fn>       one proof (same judgement), e.g. make cbmc-mt_bring_write
#   CBMC_HARNESSES=FILE  make cbmc runs only the harnesses named in FILE, one a line (a shard's
#                        share, tools/prove_shard.py; pending ones are listed, not run)
#   CBMC_RECORD=         replay (default): a property or coverage verdict is replayed from
#                        proofs/cbmc/records.json when the digest of its run's inputs is the
#                        recorded one (assumption B10), else run; properties: every property run
#                        is run (and must agree with a record of the same digest), coverage
#                        verdicts replayed (CI); fresh: every run is run; save: as replay, and
#                        every fresh verdict of a passing harness is recorded
#                        (make cbmc CBMC_RECORD=save)
#   make cbmc-max        the capacity-maximum tier (ring capacities 2^30 - 1 and 2^30, 31-bit
#                        indices; make prove-cold): only the proofs whose analysed program
#                        CBMC_BIG=1 changes (18 ring proofs), the others being the default
#                        tier's program; build/proof/cbmc/summary-max.json
#   make cbmc-gen        only translate the ACSL contracts (build/proof/cbmc/gen/)
#   make cbmc-test       the translator's tests (tools/test_acsl2cbmc.sh: pytest over
#                        tools/acsl2cbmc/tests): sample contract, unsupported constructs, and
#                        a mutated ensures caught by CBMC and WP
#   make cbmc-viewer     cbmc-viewer's browsable report (the CBMC starter kit's viewer, pinned
#                        by tools/bootstrap.sh prove) of each proof named in H="f g ..."
#                        (default: each proof with a property run in this tree):
#                        build/proof/cbmc/proofs/<f>/report/html/index.html (CBMC_VIEWER_WORK=D:
#                        D/<f>/...). A proof whose verdicts run.py replayed has no run here:
#                        make runs it first.
#   make cbmc-clean
#
# The contracts come from the ACSL annotations only (tools/acsl2cbmc); see
# proofs/cbmc/README.md and proofs/assumptions.json (the B entries).

CBMC_JOBS ?= 2
CBMC_PROOF_NAMES := $(notdir $(patsubst %/cbmc-proof.txt,%,$(wildcard proofs/cbmc/proofs/*/cbmc-proof.txt)))

.PHONY: cbmc cbmc-max cbmc-gen cbmc-test cbmc-viewer cbmc-clean cbmc-deps $(addprefix cbmc-,$(CBMC_PROOF_NAMES))

cbmc-deps:
	@[ -x .tools/bin/cbmc ] && [ -x .tools/bin/goto-cc ] && [ -x .tools/bin/goto-analyzer ] && \
	    [ -x .tools/cbmc-viewer/bin/cbmc-viewer ] || tools/bootstrap.sh prove

cbmc: cbmc-deps
	@python3 proofs/cbmc/run.py -j $(CBMC_JOBS) $(if $(CBMC_HARNESSES),--harnesses $(CBMC_HARNESSES))

cbmc-max: cbmc-deps
	@python3 proofs/cbmc/run.py -j $(CBMC_JOBS) --max

$(addprefix cbmc-,$(CBMC_PROOF_NAMES)): cbmc-%: cbmc-deps
	@python3 proofs/cbmc/run.py --summary $(BUILD)/proof/cbmc/summary-$*.json $*

cbmc-gen:
	@python3 tools/acsl2cbmc

cbmc-test: cbmc-deps
	@tools/test_acsl2cbmc.sh
	@$(PROOF_TOOLS_PYTHON) -c 'import pytest' 2>/dev/null || tools/bootstrap.sh test
	@MT_REQUIRE_VIEWER=1 $(PROOF_TOOLS_PYTHON) -m pytest -q -p no:cacheprovider tests/proofs/test_cbmc_viewer.py

# CBMC_VIEWER_WORK=D: the runs and reports go to D/<f>/ and the translated contracts to D/gen/
# instead of build/proof/cbmc/ (the viewer's test, which may run while `make prove` does).
CBMC_VIEWER_WORK ?=
CBMC_VIEWER_OUT := $(or $(CBMC_VIEWER_WORK),build/proof/cbmc/proofs)
cbmc_viewer_dirs = $(if $(CBMC_VIEWER_WORK),OUT=$(abspath $(CBMC_VIEWER_WORK))/$(1) \
    GEN=$(abspath $(CBMC_VIEWER_WORK))/gen)
CBMC_VIEWER_H = $(or $(H),$(notdir $(patsubst %/result.json,%,$(wildcard $(CBMC_VIEWER_OUT)/*/result.json))))
cbmc-viewer: cbmc-deps
	@[ -n "$(strip $(CBMC_VIEWER_H))" ] || \
	    { echo "cbmc-viewer: name the proofs (H=...): none has run in this tree" >&2; exit 2; }
	@for h in $(CBMC_VIEWER_H); do \
	    [ -f proofs/cbmc/proofs/$$h/cbmc-proof.txt ] || { echo "cbmc-viewer: no proof $$h" >&2; exit 2; }; \
	    $(MAKE) --no-print-directory -s -C proofs/cbmc/proofs/$$h report \
	        $(call cbmc_viewer_dirs,$$h) || exit 1; \
	    echo "cbmc-viewer: $(CBMC_VIEWER_OUT)/$$h/report/html/index.html"; done

cbmc-clean:
	rm -rf $(BUILD)/proof/cbmc
