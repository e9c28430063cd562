#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# tools/test_acsl2cbmc.sh -- tests of tools/acsl2cbmc.py (`make cbmc-test`).
#
#   tools/test_acsl2cbmc.sh [unittest arguments, e.g. KernelMutation.test_cbmc]
#
# Runs tools/test_acsl2cbmc.py from the repository root: the sample contract, the unsupported
# constructs, and one mutated kernel ensures clause that CBMC and Frama-C/WP must both reject
# (the WP half needs frama-c; SKIP_WP=1 skips it). Work files: build/proof/cbmc/test/.
set -eu
cd "$(dirname "$0")/.."
[ -x .tools/bin/cbmc ] || { echo "test_acsl2cbmc: .tools/bin/cbmc missing (tools/bootstrap.sh prove)" >&2; exit 2; }
exec python3 tools/test_acsl2cbmc.py "$@"
