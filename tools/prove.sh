#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `make prove`: every proof part, timed, then one report.
#
#   1. tools/bootstrap.sh prove   (installs Frama-C/Why3/Z3/CVC4, CBMC 6, TLC; versions printed)
#   2. make wp     Frama-C WP on every kernel module (+ the data-type laws), gated on JSON
#   3. make cbmc   the CBMC harnesses generated from the same ACSL contracts, with coverage
#   4. make cbmc-test  the translator's tests: sample contract, unsupported constructs, and one
#                  mutated kernel ensures clause that both CBMC and WP must reject
#   5. make tla    TLC on every CI configuration of tla/models.json
#      make tla-trace-mission  trace validation of mission.c against MissionSeq (the ring
#                  and semaphore traces stay in `make tla-trace` only, as before)
#   6. tools/proof_report.py   table, build/proof/summary.json, junit.xml, report.md;
#      fails when any part is not complete or any count is below proofs/baseline.json
#
# A failing part does not stop the others: the report says what failed.
set -uo pipefail
cd "$(dirname "$0")/.."
BUILD="${BUILD:-build}"
OUT="$BUILD/proof"
mkdir -p "$OUT"

tools/bootstrap.sh prove | tee "$OUT/versions.txt"
[ "${PIPESTATUS[0]}" -eq 0 ] || { echo "prove: tool installation failed"; exit 1; }

# Cold run (no WP session/cache from an earlier run) or warm (incremental) run: recorded
# beside the timings, so `make bench` can say which one its proof row shows.
if compgen -G "$OUT/wp/*/session" >/dev/null; then echo warm >"$OUT/cache.txt"; else echo cold >"$OUT/cache.txt"; fi

declare -A secs=()
# CBMC joins when its harness farm is in the tree (proofs/cbmc/cbmc.mk).
default_parts="wp tla tla-trace-mission"
[ -f proofs/cbmc/cbmc.mk ] && default_parts="wp cbmc cbmc-test tla tla-trace-mission"
parts=(${PROVE_PARTS:-$default_parts})
for part in "${parts[@]}"; do
    printf '\n==== make %s\n' "$part"
    t0=$(date +%s.%N)
    make --no-print-directory "$part"
    rc=$?
    t1=$(date +%s.%N)
    secs[$part]=$(python3 -c "print(round($t1 - $t0, 1))")
    echo "make $part: exit $rc, ${secs[$part]} s"
done
{
    printf '{'
    sep=""
    for part in "${parts[@]}"; do
        printf '%s"%s": %s' "$sep" "$part" "${secs[$part]}"
        sep=", "
    done
    printf '}\n'
} >"$OUT/timing.json"
# Kept per cache state, so the bench table shows both the full (cold) and the incremental
# (warm) figures of the last runs of each kind.
cp "$OUT/timing.json" "$OUT/timing-$(cat "$OUT/cache.txt").json"
printf '\n==== proof report\n'
BUILD="$BUILD" python3 tools/proof_report.py
