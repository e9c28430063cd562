#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Metronome - QEMU smoke test of the kernel on ChibiOS (apps/smoke).
#
#   CHIBIOS=/path/to/ChibiOS [BUILD=build] hal_chibios/scripts/qemu_smoke.sh
#
# Builds for QEMU mps2-an386 (no warning allowed in any build log):
#   smoke          the firmware
#   smoke-fail     FAIL=1: a task table whose budgets cannot fit
#   smoke-fail2    FAIL=2: a task executes an undefined instruction
#   smoke-wrap32   the RT system time starts 2 s before its 32-bit wrap
#   smoke-wrap16   16-bit system time, starting 2 s before its wrap
#   vehicle        the example vehicle (vehicle/deploy/chibios) with its built-in mission
#   vehicle-fail   FAIL=1: the mission has a jump to a command that does not exist
# Runs each under qemu-system-arm -icount shift=5 with a timeout, and checks:
# smoke twice with exit 0 and byte-identical UART output; both wrap builds
# exit 0; FAIL=1 exits non-zero with "RESULT: FAIL"; FAIL=2 exits non-zero
# with "FAULT:"; the vehicle completes its mission (exit 0, "RESULT: PASS") and
# starts the same commands in the same order as SITL flying the same mission;
# the vehicle with the bad mission never arms and exits non-zero; no run hits
# the timeout. Without CHIBIOS it skips (exit 0).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${BUILD:-build}"
case "$BUILD" in
    /*) ;;
    *) BUILD="$ROOT/$BUILD" ;;
esac
BOARD=qemu-mps2-an386
OUT="$BUILD/fw/$BOARD"
QEMU_TIMEOUT="${QEMU_TIMEOUT:-60}"
VEHICLE_TIMEOUT="${VEHICLE_TIMEOUT:-300}" # about 65 s of flight: 25-60 s of QEMU wall time
JOBS="$(nproc 2>/dev/null || echo 2)"

if [ -z "${CHIBIOS:-}" ]; then
    echo "qemu-smoke: skipped: CHIBIOS not set (give CHIBIOS=/path/to/ChibiOS, tested with ver21.11.5)"
    exit 0
fi

fail=0
bad() { printf 'qemu-smoke: FAIL: %s\n' "$*"; fail=1; }

build() { # variant [make args...]; APP_NAME/APP_DIR select another app than smoke
    local variant=$1 log
    shift
    mkdir -p "$OUT"
    log="$OUT/$variant.build.log"
    if [ -n "${APP_DIR:-}" ] && ! make --no-print-directory -C "$ROOT" BUILD="$BUILD" mavlink-headers \
            >"$log" 2>&1; then
        tail -n 30 "$log"
        bad "MAVLink headers for $variant (log: $log)"
        return 1
    fi
    if ! make --no-print-directory -C "$ROOT" -f hal_chibios/mk/firmware.mk -j"$JOBS" \
            CHIBIOS="$CHIBIOS" BUILD="$BUILD" BOARD="$BOARD" APP="${APP_NAME:-smoke}" \
            ${APP_DIR:+APPDIR="$APP_DIR"} VARIANT="$variant" "$@" \
            >"$log" 2>&1; then
        tail -n 30 "$log"
        bad "build $variant (log: $log)"
        return 1
    fi
    if grep -qi 'warning' "$log"; then
        grep -i 'warning' "$log" | head -n 10
        bad "build $variant has warnings (log: $log)"
        return 1
    fi
    printf 'size %-13s %s\n' "$variant" "$(sed -n 's/^ *without .heap: //p' "$log")"
}

# run variant tag [app [timeout]]: runs the image, output in $OUT/<variant>.<tag>.txt;
# sets RC and SECS.
run() {
    local t0 t1 limit="${4:-$QEMU_TIMEOUT}"
    t0=$(date +%s%N)
    RC=0
    timeout "$limit" qemu-system-arm -M mps2-an386 -display none -monitor none \
        -serial stdio -semihosting-config enable=on,target=native -icount shift=5 \
        -kernel "$OUT/$1/${3:-smoke}.elf" >"$OUT/$1.$2.txt" 2>&1 || RC=$?
    t1=$(date +%s%N)
    SECS="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", (b - a) / 1e9 }')"
    [ "$RC" -ne 124 ] || bad "$1 ($2) hit the ${limit} s timeout"
}

build smoke || true
build smoke-fail FAIL=1 || true
build smoke-fail2 FAIL=2 || true
build smoke-wrap32 EXTRA_DEFS="-DMT_PORT_CHIBIOS_ST_OFFSET=0xFFFFF830" || true
build smoke-wrap16 EXTRA_DEFS="-DCH_CFG_ST_RESOLUTION=16 -DCH_CFG_INTERVALS_SIZE=16 -DMT_PORT_CHIBIOS_ST_OFFSET=0xF830" || true
APP_NAME=vehicle APP_DIR="$ROOT/vehicle/deploy/chibios" build vehicle || true
APP_NAME=vehicle APP_DIR="$ROOT/vehicle/deploy/chibios" build vehicle-fail FAIL=1 || true
[ "$fail" -eq 0 ] || { echo "qemu-smoke: FAILED (build)"; exit 1; }

run smoke run1
r1=$RC s1=$SECS
run smoke run2
r2=$RC s2=$SECS
tr -d '\r' <"$OUT/smoke.run1.txt"
echo "qemu-smoke: smoke exit $r1/$r2, QEMU wall time ${s1} s / ${s2} s"
[ "$r1" -eq 0 ] && [ "$r2" -eq 0 ] || bad "smoke exit status $r1/$r2 (expected 0)"
if cmp -s "$OUT/smoke.run1.txt" "$OUT/smoke.run2.txt"; then
    echo "qemu-smoke: determinism: both runs byte-identical ($(wc -c <"$OUT/smoke.run1.txt") bytes)"
else
    diff "$OUT/smoke.run1.txt" "$OUT/smoke.run2.txt" | head -n 20 || true
    bad "smoke output differs between runs"
fi

for v in smoke-wrap32 smoke-wrap16; do
    run "$v" run1
    echo "qemu-smoke: $v exit $RC ($(grep -a 'RESULT' "$OUT/$v.run1.txt" | tr -d '\r'))"
    [ "$RC" -eq 0 ] || bad "$v exit status $RC (expected 0)"
done

run smoke-fail run1
echo "qemu-smoke: smoke-fail (FAIL=1) exit $RC:"
grep -a -E 'CHECK FAILED|RESULT|att_ctrl' "$OUT/smoke-fail.run1.txt" | tr -d '\r' | sed 's/^/  /'
[ "$RC" -ne 0 ] || bad "FAIL=1 exited 0 (expected non-zero)"
grep -aq 'RESULT: FAIL' "$OUT/smoke-fail.run1.txt" || bad "FAIL=1 did not report RESULT: FAIL"

run smoke-fail2 run1
echo "qemu-smoke: smoke-fail2 (FAIL=2) exit $RC: $(grep -a 'FAULT' "$OUT/smoke-fail2.run1.txt" | tr -d '\r')"
[ "$RC" -ne 0 ] || bad "FAIL=2 exited 0 (expected non-zero)"
grep -aq 'FAULT:' "$OUT/smoke-fail2.run1.txt" || bad "FAIL=2 did not report a fault"

# ---- the example vehicle: the built-in mission, flown on ChibiOS ----
run vehicle run1 vehicle "$VEHICLE_TIMEOUT"
tr -d '\r' <"$OUT/vehicle.run1.txt" >"$OUT/vehicle.run1.log"
sed -n '/== flight summary ==/,$p' "$OUT/vehicle.run1.log"
echo "qemu-smoke: vehicle exit $RC, QEMU wall time ${SECS} s"
[ "$RC" -eq 0 ] || bad "vehicle exit status $RC (expected 0)"
grep -q '^RESULT: PASS' "$OUT/vehicle.run1.log" || bad "vehicle did not report RESULT: PASS"
grep -q '^mission: COMPLETE' "$OUT/vehicle.run1.log" || bad "vehicle mission not complete"
# the battery monitor ran on the work queue's own thread and its readings reached
# housekeeping over the topic bus
bat_runs="$(sed -n 's/^battery item: \([0-9]*\) runs.*/\1/p' "$OUT/vehicle.run1.log")"
bat_got="$(sed -n 's/^topic battery: .*housekeeping: \([0-9]*\) received.*/\1/p' "$OUT/vehicle.run1.log")"
if [ -z "$bat_runs" ] || [ "$bat_runs" -lt 100 ] || [ -z "$bat_got" ] ||
    [ "$bat_got" -lt $((bat_runs - 2)) ]; then
    bad "vehicle battery monitor: ${bat_runs:-no} work-item runs, ${bat_got:-no} readings received"
fi
# the same vehicle in SITL, same mission: the same commands in the same order
if make --no-print-directory -C "$ROOT" BUILD="$BUILD" "$BUILD/sitl/metronome-sitl" \
        >"$OUT/sitl.build.log" 2>&1; then
    "$BUILD/sitl/metronome-sitl" --quiet --builtin >"$OUT/vehicle.sitl.log" 2>/dev/null || true
    seq_of() { sed -n 's/^\[ *[0-9.]*\] mission: \(#[0-9]* [A-Z_]*\) started.*/\1/p' "$1" | tr '\n' ' '; }
    fw_seq="$(seq_of "$OUT/vehicle.run1.log")"
    sitl_seq="$(seq_of "$OUT/vehicle.sitl.log")"
    echo "qemu-smoke: vehicle commands started: $fw_seq"
    if [ -n "$fw_seq" ] && [ "$fw_seq" = "$sitl_seq" ]; then
        echo "qemu-smoke: vehicle: the same command sequence as SITL (--builtin)"
    else
        bad "vehicle command sequence differs from SITL: [$fw_seq] vs [$sitl_seq]"
    fi
else
    tail -n 20 "$OUT/sitl.build.log"
    bad "SITL build for the comparison"
fi

run vehicle-fail run1 vehicle "$VEHICLE_TIMEOUT"
tr -d '\r' <"$OUT/vehicle-fail.run1.txt" >"$OUT/vehicle-fail.run1.log"
echo "qemu-smoke: vehicle-fail (FAIL=1) exit $RC: $(grep -a -E '^mission rejected|^RESULT' "$OUT/vehicle-fail.run1.log" | tr '\n' ' ')"
[ "$RC" -ne 0 ] || bad "vehicle FAIL=1 exited 0 (expected non-zero)"
grep -q '^mission rejected by the sequencer: MT_E_MISSION_JUMP' "$OUT/vehicle-fail.run1.log" ||
    bad "vehicle FAIL=1: no rejection of the mission"
! grep -q 'vehicle: armed' "$OUT/vehicle-fail.run1.log" || bad "vehicle FAIL=1 armed"
grep -q '^RESULT: FAIL' "$OUT/vehicle-fail.run1.log" || bad "vehicle FAIL=1 did not report RESULT: FAIL"

if [ "$fail" -ne 0 ]; then
    echo "qemu-smoke: FAILED"
    exit 1
fi
echo "qemu-smoke: OK"
