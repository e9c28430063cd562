#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Metronome - ChibiOS firmware smoke test.
#
#   CHIBIOS=/path/to/ChibiOS [BUILD=build] hal_chibios/scripts/fw_smoke.sh
#
# Builds the QEMU mps2-an386 apps (hello, hello FAIL=1, port_smoke, and
# port_smoke with waits forced through the split path) and the STM32F407
# Discovery hello and smoke (build only; no warnings allowed anywhere), runs
# each QEMU image twice, and checks: exit status 0 and identical output for
# the passing apps, non-zero exit for the FAIL variants. The kernel smoke
# firmware (apps/smoke) has its own script, qemu_smoke.sh. Without CHIBIOS it
# skips (exit 0).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${BUILD:-build}"
case "$BUILD" in
    /*) ;;
    *) BUILD="$ROOT/$BUILD" ;;
esac
MK=(make --no-print-directory -C "$ROOT" -f hal_chibios/mk/firmware.mk -j"$(nproc 2>/dev/null || echo 2)" BUILD="$BUILD")
FW="$BUILD/fw"
QEMU_TIMEOUT="${QEMU_TIMEOUT:-60}"

if [ -z "${CHIBIOS:-}" ]; then
    echo "fw_smoke: skipped: CHIBIOS not set (give CHIBIOS=/path/to/ChibiOS, tested with ver21.11.5)"
    exit 0
fi

fail=0
note() { printf '%s\n' "$*"; }
bad() { printf 'FAIL: %s\n' "$*"; fail=1; }

build() { # board app variant [make args...]
    local board=$1 app=$2 variant=$3 log
    shift 3
    log="$FW/$board/$variant.build.log"
    mkdir -p "$FW/$board"
    if ! "${MK[@]}" CHIBIOS="$CHIBIOS" BOARD="$board" APP="$app" VARIANT="$variant" "$@" \
            >"$log" 2>&1; then
        bad "build $board/$variant (see $log)"
        return 1
    fi
    if grep -qi 'warning' "$log"; then
        bad "build $board/$variant has warnings (see $log)"
        return 1
    fi
    printf 'size %-34s %s\n' "$board/$variant" "$(grep 'without .heap' "$log" | sed 's/^ *without .heap: //')"
}

run() { # elf outfile -> prints rc
    local rc=0
    timeout "$QEMU_TIMEOUT" qemu-system-arm -M mps2-an386 -display none -monitor none \
        -serial stdio -semihosting-config enable=on,target=native -icount shift=5 \
        -kernel "$1" >"$2" 2>&1 || rc=$?
    echo "$rc"
}

expect_pass() { # variant app
    local elf="$FW/qemu-mps2-an386/$1/$2.elf" o1 o2 r1 r2
    o1="$FW/qemu-mps2-an386/$1.run1.txt"
    o2="$FW/qemu-mps2-an386/$1.run2.txt"
    r1=$(run "$elf" "$o1")
    r2=$(run "$elf" "$o2")
    note "run  $1: rc=$r1/$r2 output: $(tr -d '\r' <"$o1" | tr '\n' ' ')"
    [ "$r1" = 0 ] && [ "$r2" = 0 ] || bad "$1 exit status $r1/$r2"
    cmp -s "$o1" "$o2" || bad "$1 output differs between runs"
}

expect_fail() { # variant app
    local elf="$FW/qemu-mps2-an386/$1/$2.elf" o r
    o="$FW/qemu-mps2-an386/$1.run1.txt"
    r=$(run "$elf" "$o")
    note "run  $1: rc=$r output: $(tr -d '\r' <"$o" | tr '\n' ' ')"
    case "$r" in
        0) bad "$1 exited 0, expected failure" ;;
        124) bad "$1 hung (timeout), expected failure exit" ;;
    esac
}

B=qemu-mps2-an386
build $B hello hello && expect_pass hello hello
build $B hello hello-fail FAIL=1 && expect_fail hello-fail hello
build $B port_smoke port_smoke && expect_pass port_smoke port_smoke
build $B port_smoke port_smoke-chunk3 EXTRA_DEFS=-DMT_PORT_CHIBIOS_MAX_CHUNK=3 &&
    expect_pass port_smoke-chunk3 port_smoke
build $B port_smoke port_smoke-fail FAIL=1 && expect_fail port_smoke-fail port_smoke
build stm32f407-discovery hello hello || true
build stm32f407-discovery smoke smoke || true

if [ "$fail" -ne 0 ]; then
    echo "fw_smoke: FAILED"
    exit 1
fi
echo "fw_smoke: OK"
