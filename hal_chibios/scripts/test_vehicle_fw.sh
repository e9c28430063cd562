#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Metronome - the vehicle's MAVLink client tests against the ChibiOS firmware.
#
#   CHIBIOS=/path/to/ChibiOS [BUILD=build] [PYTHON=python3] hal_chibios/scripts/test_vehicle_fw.sh [TEST-NAME-SUBSTRING]
#
# Builds the vehicle's ground-station session firmware for QEMU mps2-an386 (APP=vehicle
# GCS=1, variant vehicle-gcs; no warning allowed) and runs the ground-station tests of
# tests/vehicle/run_tests.py against it (--firmware: the pymavlink and the MAVProxy ones):
# each test starts QEMU with the link UART on a local TCP socket (tests/vehicle/mavgcs.py,
# Qemu, FirmwareSession) and drives the vehicle as it drives the SITL. Tests the firmware
# cannot run say why (SKIP). Without CHIBIOS it skips (exit 0).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${BUILD:-build}"
case "$BUILD" in
    /*) ;;
    *) BUILD="$ROOT/$BUILD" ;;
esac
OUT="$BUILD/fw/qemu-mps2-an386"
PYTHON="${PYTHON:-python3}"

if [ -z "${CHIBIOS:-}" ]; then
    echo "test-vehicle-fw: skipped: CHIBIOS not set (give CHIBIOS=/path/to/ChibiOS, tested with ver21.11.5)"
    exit 0
fi

mkdir -p "$OUT"
log="$OUT/vehicle-gcs.build.log"
if ! { make --no-print-directory -C "$ROOT" BUILD="$BUILD" mavlink-headers "$BUILD/mt-mission" &&
       make --no-print-directory -C "$ROOT" -f hal_chibios/mk/firmware.mk -j"$(nproc 2>/dev/null || echo 2)" \
           CHIBIOS="$CHIBIOS" BUILD="$BUILD" BOARD=qemu-mps2-an386 APP=vehicle \
           APPDIR="$ROOT/vehicle/deploy/chibios" VARIANT=vehicle-gcs GCS=1; } >"$log" 2>&1; then
    tail -n 30 "$log"
    echo "test-vehicle-fw: FAILED (build; log: $log)"
    exit 1
fi
if grep -qi 'warning' "$log"; then
    grep -i 'warning' "$log" | head -n 10
    echo "test-vehicle-fw: FAILED (build warnings; log: $log)"
    exit 1
fi
echo "test-vehicle-fw: $OUT/vehicle-gcs/vehicle.elf: $(sed -n 's/^ *without .heap: //p' "$log")"
exec "$PYTHON" "$ROOT/tests/vehicle/run_tests.py" --build "$BUILD" --firmware "$OUT/vehicle-gcs/vehicle.elf" \
    -k "${1:-}"
