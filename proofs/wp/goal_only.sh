#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# proofs/wp/goal_only.sh LIMIT SMOKE_LIMIT PROVER-COMMAND...
#
# Prover gate used by the project Why3 configuration for Z3 (proofs/wp/why3.conf): WP gives
# smoke tests the time limit -wp-smoke-timeout (SMOKE_LIMIT) and proof goals -wp-timeout, and
# proofs/proofs.mk keeps the two different. For a task whose limit is the smoke limit this
# prints "unknown" (Why3: Unknown) at once and does not start the prover: smoke tests are
# decided by Qed and CVC4. Measured here (proofs/wp/README.md, "Smoke tests"): Z3 ran every
# passing smoke test to its limit and never returned earlier, while every contradiction of the
# smoke canary (proofs/wp/canary/) is found by Qed or by CVC4 in milliseconds. A smoke test
# that Z3 does not attempt can only pass; the canary gate shows that contradictions are still
# caught. Any other task runs the prover command unchanged.
limit="$1"
smoke="$2"
shift 2
if [ "$limit" = "$smoke" ]; then
    echo "unknown"
    exit 0
fi
exec "$@"
