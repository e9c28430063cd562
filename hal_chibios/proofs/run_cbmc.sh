#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Metronome - CBMC proofs of the ChibiOS port's time arithmetic.
#
#   hal_chibios/proofs/run_cbmc.sh [harness...]
#
# Runs every harness of time_harness.c (or the ones named) with CBMC from
# .tools/bin (tools/bootstrap.sh prove) or the PATH, with the overflow,
# conversion and undefined-shift checks on; then a coverage pass per harness
# (every assertion of the harness must be reachable), so that a vacuous
# proof (assumptions that exclude everything) fails.
# Exit 0 only when every property is proved and every assertion is reached.
#
# Also writes $BUILD/proof/hal_chibios/cbmc-summary.json (BUILD: env, default build, relative
# to the repository root), read by tools/proof_report.py:
#   {"harnesses": N, "passed": K, "results": [{"name", "passed", "coverage_reached",
#    "coverage_total", "seconds"}]}
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
CBMC="$ROOT/.tools/bin/cbmc"
[ -x "$CBMC" ] || CBMC="$(command -v cbmc || true)"
[ -n "$CBMC" ] || { echo "run_cbmc: cbmc not found (tools/bootstrap.sh prove)"; exit 1; }

HARNESSES=(harness_wrap harness_wrap_maxima harness_ticks_ceil harness_subtick_monotonic
           harness_deadline_chunks)
[ "$#" -gt 0 ] && HARNESSES=("$@")

SRC=("$HERE/time_harness.c" "$ROOT/hal_chibios/port/mt_chibios_time.c" "$ROOT/kernel/src/time.c")
INC=(-I "$ROOT/kernel/include" -I "$ROOT/kernel/port" -I "$ROOT/kernel/spec" -I "$ROOT/hal_chibios/port")
CHECKS=(--bounds-check --pointer-check --signed-overflow-check --unsigned-overflow-check
        --conversion-check --undefined-shift-check --div-by-zero-check)

BUILD="${BUILD:-build}"
case "$BUILD" in
    /*) SUMMARY_DIR="$BUILD/proof/hal_chibios" ;;
    *) SUMMARY_DIR="$ROOT/$BUILD/proof/hal_chibios" ;;
esac
mkdir -p "$SUMMARY_DIR"
SUMMARY="$SUMMARY_DIR/cbmc-summary.json"
rm -f "$SUMMARY"   # no summary of an earlier run survives a run that stops early

fail=0
passed=0
results=()
for h in "${HARNESSES[@]}"; do
    t0=$(date +%s)
    if out="$("$CBMC" "${SRC[@]}" "${INC[@]}" -DCBMC --function "$h" "${CHECKS[@]}" 2>&1)"; then
        res="VERIFIED"
    else
        res="FAILED"
        fail=1
        printf '%s\n' "$out" | grep -E 'FAILURE|error' | head -n 20
    fi
    # Coverage goals inside the harness itself: every one must be reachable.
    cov="$("$CBMC" "${SRC[@]}" "${INC[@]}" -DCBMC --function "$h" --cover assertion 2>&1 || true)"
    total="$(printf '%s\n' "$cov" | grep -c "^\[$h\.coverage\." || true)"
    hit="$(printf '%s\n' "$cov" | grep "^\[$h\.coverage\." | grep -c ': SATISFIED$' || true)"
    ok=true
    [ "$res" = VERIFIED ] || ok=false
    if [ "$total" -eq 0 ] || [ "$hit" != "$total" ]; then
        fail=1
        ok=false
    fi
    if [ "$ok" = true ]; then passed=$((passed + 1)); fi
    secs=$(( $(date +%s) - t0 ))
    res="$res, harness assertions reached $hit/$total"
    printf '%-28s %s (%ss)\n' "$h" "$res" "$secs"
    results+=("$(printf '{"name": "%s", "passed": %s, "coverage_reached": %d, ' "$h" "$ok" "$hit"
                 printf '"coverage_total": %d, "seconds": %d}' "$total" "$secs")")
done
{
    printf '{"harnesses": %d, "passed": %d, "results": [' "${#HARNESSES[@]}" "$passed"
    sep=""
    for r in "${results[@]}"; do
        printf '%s\n  %s' "$sep" "$r"
        sep=","
    done
    printf '\n]}\n'
} >"$SUMMARY"
exit "$fail"
