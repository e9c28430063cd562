# SPDX-License-Identifier: Apache-2.0
# Tests of the proof tooling (included by the top Makefile; paths relative to the root).
#
#   make test-proof-tools   pytest over tests/proofs: tools/proof_report.py (the strict gate of
#                           `make prove`) fed synthetic summaries, one test per failure kind;
#                           tools/prove.sh with stub tools; the canary's checker; the mutation
#                           check's selection; the shard plan and merge; `make reprove`'s input
#                           digest; every declared make target has a rule. Two tests run Frama-C
#                           on small modules (`time` whole and as 2 merged shards, `status` 3
#                           times: about 1 min); they are skipped where frama-c is not installed,
#                           or with MT_SKIP_FRAMAC=1.
#
# The system interpreter has pytest (python3-pytest, tools/bootstrap.sh test); the `python3`
# on the PATH may be a pyenv shim without it.

PROOF_TOOLS_PYTHON ?= $(shell [ -x /usr/bin/python3 ] && echo /usr/bin/python3 || echo python3)

.PHONY: test-proof-tools

test-proof-tools:
	@$(PROOF_TOOLS_PYTHON) -c 'import pytest' 2>/dev/null || tools/bootstrap.sh test
	$(PROOF_TOOLS_PYTHON) -m pytest -q -p no:cacheprovider tests/proofs
