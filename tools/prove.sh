#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `make prove`: every proof part, timed, then one report with one strict gate.
#
#   1. tools/bootstrap.sh prove   (installs Frama-C/Why3/Z3/CVC4, CBMC 6, TLC; versions printed)
#   2. the parts, in two lanes that run side by side (the machine has 2 cores; WP's own two
#      modules at a time fill them, and the other lane takes the gaps):
#      lane 1: make wp     Frama-C WP on every module, always from source (kernel, laws, the
#                          ChibiOS port's time arithmetic), canary and WP gate
#      lane 2: make cbmc   the CBMC harnesses generated from the same ACSL contracts
#              make cbmc-test  the translator's tests
#              make chibios-cbmc  CBMC on the ChibiOS port's time arithmetic
#              make tla    TLC on every CI configuration of tla/models.json
#              make tla-trace-mission  trace validation of mission*.c against Mission
#      PROVE_EXTRA="part ..." appends parts (CI: the ring and semaphore traces and the rotating
#      share of the mutants, which run in lane 1 after WP); PROVE_PARTS="part ..." replaces the
#      default list;
#      PROVE_LANES=1 runs everything in one lane, in order.
#      PROVE_SHARD=i/N runs shard i of N (tools/prove_shard.py, for a CI job matrix): the plan
#      splits the WP units (module, function) and (module, lemmas) and the CBMC harnesses over
#      the N shards, longest first; this shard's part wp runs its WP units, its part cbmc its
#      harnesses; the other parts (and the WP canary) run in shard 1 only. The report judges
#      what the shard ran ("shard i/N: partial"); `make prove-merge SHARDS="dir1 ... dirN"`
#      merges the shards' build folders into one report with the strict gate.
#   3. tools/proof_report.py   table, build/proof/summary.json, junit.xml, report.md; fails
#                  on any problem (tools/proof_gate.py): a part that exited non-zero, a
#                  missing summary, anything not proved or not as expected, a count below
#                  proofs/baseline.json. Its exit status is the exit status of `make prove`.
#
# Each part's output goes to $BUILD/proof/logs/<part>.log and is printed when the part ends;
# its exit status, wall seconds and start time go to $BUILD/proof/parts.json (the seconds also
# to timing.json, read by `make bench`). A failing part does not stop the others.
set -uo pipefail
cd "$(dirname "$0")/.."
BUILD="${BUILD:-build}"
export BUILD
OUT="$BUILD/proof"
mkdir -p "$OUT/logs" "$OUT/parts"
rm -f "$OUT/parts.json" "$OUT"/parts/* "$OUT/shard.json"
rm -rf "$OUT/shard"

tools/bootstrap.sh prove | tee "$OUT/versions.txt"
[ "${PIPESTATUS[0]}" -eq 0 ] || { echo "prove: tool installation failed"; exit 1; }

# cold: nothing reused (make prove-cold); warm: verdict caches and records in use;
# reprove (make reprove): WP modules whose inputs are those of this tree's last run are replayed.
if [ -n "${PROVE_COLD:-}" ]; then echo cold >"$OUT/cache.txt"
elif [ "${WP_REUSE_LOCAL:-}" = yes ]; then echo reprove >"$OUT/cache.txt"
else echo warm >"$OUT/cache.txt"; fi

lane1_default="wp"
lane2_default="cbmc cbmc-test chibios-cbmc tla tla-trace-mission"
# make prove-cold adds the capacity-maximum CBMC tier.
cold_extra=""
[ -n "${PROVE_COLD:-}" ] && cold_extra="cbmc-max"
selected=(${PROVE_PARTS:-$lane1_default $lane2_default $cold_extra ${PROVE_EXTRA:-}})
report_parts="$lane1_default $lane2_default"
if [ -n "${PROVE_SHARD:-}" ]; then
    python3 tools/prove_shard.py plan "$PROVE_SHARD" --parts "${selected[*]}" \
        --default-parts "$report_parts" --out "$OUT" || { echo "prove: no shard plan"; exit 1; }
    mine=()
    for part in "${selected[@]}"; do
        case "$part" in
            wp | cbmc) [ -s "$OUT/shard/$part.txt" ] && mine+=("$part") ;;
            *) [ $((10#${PROVE_SHARD%%/*})) = 1 ] && mine+=("$part") ;;
        esac
    done
    selected=("${mine[@]}")
    report_parts="${mine[*]}"
fi
# Lane 1 takes WP and, after it, the extra parts (CI's traces and mutants, the cold CBMC tier):
# in CI lane 2's fresh CBMC property runs are the longest part, so the extras balance lane 1.
# When every property run is fresh (CBMC_RECORD=properties or fresh), the mission traces
# (about 160 s) move to lane 1 as well: measured in CI, lane 2 was then the longer by 320 s.
# Since the topic bus's functional contracts (about 180 s more of CBMC property runs) TLC's
# models (92 s here) and the translator's tests (56 s) move there too.
lane1_parts=" wp tla-trace prove-selftest prove-selftest-ci cbmc-max "
case "${CBMC_RECORD:-}" in
    properties | fresh) lane1_parts+="tla-trace-mission tla cbmc-test " ;;
esac
lane1=()
lane2=()
for part in "${selected[@]}"; do
    case "$lane1_parts" in
        *" $part "*) lane1+=("$part") ;;
        *) lane2+=("$part") ;;
    esac
done
parts=("${lane1[@]}" "${lane2[@]}")
if [ "${PROVE_LANES:-2}" = 1 ]; then echo "prove: one lane: ${parts[*]}"
else echo "prove: lane 1: ${lane1[*]}; lane 2: ${lane2[*]}"; fi

# The summaries of the optional parts this run does not make go: the gate reads every summary
# present, and one left by an earlier run (make prove-selftest, make prove-cold's tier) would
# be judged as this run's result.
optional=("prove-selftest selftest/summary.json" "prove-selftest-ci selftest/summary.json"
          "cbmc-max cbmc/summary-max.json" "tla-trace tla/trace/summary.json"
          "chibios-cbmc hal_chibios/cbmc-summary.json")
keep=()
for opt in "${optional[@]}"; do
    case " ${parts[*]} " in *" ${opt%% *} "*) keep+=("${opt#* }") ;; esac
done
for opt in "${optional[@]}"; do
    case " ${keep[*]:-} " in *" ${opt#* } "*) ;; *) rm -f "$OUT/${opt#* }" ;; esac
done

# part_run PART: make PART; in a shard, parts wp and cbmc run this shard's units only.
part_run() {
    case "${PROVE_SHARD:+shard}:$1" in
        shard:wp) python3 tools/prove_shard.py wp "$OUT/shard.json" ;;
        shard:cbmc) make --no-print-directory cbmc CBMC_HARNESSES="$OUT/shard/cbmc.txt" ;;
        *) make --no-print-directory "$1" ;;
    esac
}

# run_part PART: part_run PART with its output in logs/PART.log, then its status in parts/PART.
run_part() {
    local part="$1" t0 t1 rc
    t0=$(date +%s.%N)
    part_run "$part" >"$OUT/logs/$part.log" 2>&1
    rc=$?
    t1=$(date +%s.%N)
    printf '%s %s %s\n' "$rc" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')" \
        "$t0" >"$OUT/parts/$part"
    # one block per part on the console, whole, when it ends (lanes never interleave lines)
    {
        printf '\n==== make %s\n' "$part"
        cat "$OUT/logs/$part.log"
        printf 'make %s: exit %s, %s s\n' "$part" "$rc" "$(cut -d' ' -f2 "$OUT/parts/$part")"
    } | flock "$OUT/parts/.console" cat
}

run_lane() {
    local part
    for part in "$@"; do run_part "$part"; done
}

if [ "${PROVE_LANES:-2}" = 1 ]; then
    run_lane "${parts[@]}"
else
    run_lane "${lane1[@]}" &
    lane1_pid=$!
    run_lane "${lane2[@]}"
    wait "$lane1_pid"
fi

# json_by_part timing|parts: one JSON object with one member per part, its wall seconds
# (timing.json) or {"rc", "seconds", "started"} (parts.json; started: epoch seconds).
json_by_part() {
    local fmt="$1" sep="" part rc secs started
    printf '{'
    for part in "${parts[@]}"; do
        if [ -f "$OUT/parts/$part" ]; then
            read -r rc secs started <"$OUT/parts/$part"
        else
            rc=127 secs=0 started=0
        fi
        printf '%s' "$sep"
        case "$fmt" in
            timing) printf '"%s": %s' "$part" "$secs" ;;
            parts) printf '"%s": {"rc": %d, "seconds": %s, "started": %s}' "$part" \
                       "$rc" "$secs" "$started" ;;
        esac
        sep=", "
    done
    printf '}\n'
}
json_by_part timing >"$OUT/timing.json"
json_by_part parts >"$OUT/parts.json"
cp "$OUT/timing.json" "$OUT/timing-$(cat "$OUT/cache.txt").json"
printf '\n==== proof report\n'
exec python3 tools/proof_report.py --default-parts "$report_parts" \
    ${PROVE_SHARD:+--shard "$PROVE_SHARD"}
