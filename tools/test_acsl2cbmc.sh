#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# tools/test_acsl2cbmc.sh -- tests of the translator tools/acsl2cbmc (`make cbmc-test`).
#
#   tools/test_acsl2cbmc.sh [pytest arguments, e.g. -k KernelMutation or -k 'Sample and output']
#
# Runs pytest over tools/acsl2cbmc/tests/ from the repository root: the sample contract, the
# unsupported constructs, and one mutated kernel ensures clause that CBMC and Frama-C/WP must
# both reject (the WP half needs frama-c; SKIP_WP=1 skips it). Work files and the summary the
# proof report reads (summary.json): build/proof/cbmc/test/.
set -eu
cd "$(dirname "$0")/.."
[ -x .tools/bin/cbmc ] || { echo "test_acsl2cbmc: .tools/bin/cbmc missing (tools/bootstrap.sh prove)" >&2; exit 2; }
# The interpreter of `make test-proof-tools` (tools/tools.mk): the system one has pytest
# (python3-pytest, tools/bootstrap.sh test).
py=python3
[ -x /usr/bin/python3 ] && py=/usr/bin/python3
"$py" -c 'import pytest' 2>/dev/null || tools/bootstrap.sh test
exec "$py" -m pytest -v -rfEs -p no:cacheprovider tools/acsl2cbmc/tests "$@"
