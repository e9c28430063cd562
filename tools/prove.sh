#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `make prove`: every proof part, timed, then one report with one strict gate.
#
#   1. tools/bootstrap.sh prove   (installs Frama-C/Why3/Z3/CVC4, CBMC 6, TLC; versions printed)
#   2. the parts, in two lanes that run side by side (the machine has 2 cores) and take them
#      from one queue, longest first, each the next part when it is free:
#        make cbmc   the CBMC harnesses generated from the same ACSL contracts
#        make wp     Frama-C WP on every module, always from source (kernel, laws, the ChibiOS
#                    port's time arithmetic), canary and WP gate
#        make tla    TLC on every CI configuration of tla/models.json
#        make tla-trace-mission  trace validation of mission*.c against Mission
#        make cbmc-test  the translator's tests
#        make chibios-cbmc  CBMC on the ChibiOS port's time arithmetic
#      PROVE_EXTRA="part ..." adds parts (CI: the ring and semaphore traces and the rotating
#      share of the mutants); PROVE_PARTS="part ..." replaces the default list;
#      PROVE_LANES=1 runs everything in one lane, in the queue's order.
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

default_parts="wp cbmc cbmc-test chibios-cbmc tla tla-trace-mission"
# make prove-cold adds the capacity-maximum CBMC tier.
cold_extra=""
[ -n "${PROVE_COLD:-}" ] && cold_extra="cbmc-max"
selected=(${PROVE_PARTS:-$default_parts $cold_extra ${PROVE_EXTRA:-}})
report_parts="$default_parts"
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
# The parts form one queue, longest first (the order of QUEUE_ORDER; a part not named there goes
# last): each lane takes the next part whenever it is free, so no lane idles while parts wait.
# The two longest start together: WP (about 10 minutes in make prove) and CBMC (about half an
# hour when every property run is fresh, as in CI; a minute or two when verdicts are replayed).
# After a kernel edit (make reprove) WP re-runs one module while CBMC re-runs the harnesses that
# reach the edit, and the lane that ends first takes TLC, the traces and the translator's tests.
QUEUE_ORDER=(cbmc wp prove-selftest prove-selftest-ci cbmc-max tla-trace tla tla-trace-mission
             cbmc-test chibios-cbmc chibios-prove)
parts=()
for part in "${QUEUE_ORDER[@]}"; do
    case " ${selected[*]} " in *" $part "*) parts+=("$part") ;; esac
done
for part in "${selected[@]}"; do
    case " ${QUEUE_ORDER[*]} " in *" $part "*) ;; *) parts+=("$part") ;; esac
done
lanes="${PROVE_LANES:-2}"
[ "$lanes" = 1 ] || lanes=2
echo "prove: $lanes lane(s) take the parts in this order: ${parts[*]}"

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

# run_part PART LANE: part_run PART with its output in logs/PART.log, then its status in
# parts/PART.
run_part() {
    local part="$1" lane="$2" t0 t1 rc
    t0=$(date +%s.%N)
    part_run "$part" >"$OUT/logs/$part.log" 2>&1
    rc=$?
    t1=$(date +%s.%N)
    printf '%s %s %s %s\n' "$rc" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')" \
        "$t0" "$lane" >"$OUT/parts/$part"
    # one block per part on the console, whole, when it ends (lanes never interleave lines)
    {
        printf '\n==== make %s\n' "$part"
        cat "$OUT/logs/$part.log"
        printf 'make %s: exit %s, %s s (lane %s)\n' "$part" "$rc" \
            "$(cut -d' ' -f2 "$OUT/parts/$part")" "$lane"
    } | flock "$OUT/parts/.console" cat
}

# run_lane LANE: take the next part from the queue (one line a part) until it is empty. The
# lock is a file of its own: sed -i replaces the queue file, and a lock taken on the replaced
# file would not keep the other lane out.
printf '%s\n' "${parts[@]}" >"$OUT/parts/.queue"
take_part() {
    flock "$OUT/parts/.queue.lock" sh -c 'head -n 1 "$1"; sed -i 1d "$1"' take \
        "$OUT/parts/.queue"
}
run_lane() {
    local part
    while part=$(take_part) && [ -n "$part" ]; do run_part "$part" "$1"; done
}

if [ "$lanes" = 1 ]; then
    run_lane 1
else
    run_lane 1 &
    lane1_pid=$!
    run_lane 2
    wait "$lane1_pid"
fi

# json_by_part timing|parts: one JSON object with one member per part, its wall seconds
# (timing.json) or {"rc", "seconds", "started"} (parts.json; started: epoch seconds).
json_by_part() {
    local fmt="$1" sep="" part rc secs started lane
    printf '{'
    for part in "${parts[@]}"; do
        if [ -f "$OUT/parts/$part" ]; then
            read -r rc secs started lane <"$OUT/parts/$part"
        else
            rc=127 secs=0 started=0 lane=0
        fi
        printf '%s' "$sep"
        case "$fmt" in
            timing) printf '"%s": %s' "$part" "$secs" ;;
            parts) printf '"%s": {"rc": %d, "seconds": %s, "started": %s, "lane": %d}' \
                       "$part" "$rc" "$secs" "$started" "$lane" ;;
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
