#!/usr/bin/env bash
# proofs/wp/mkconf.sh — generate the project Why3 configuration for Frama-C/WP.
#
#   proofs/wp/mkconf.sh [OUTDIR [SMOKE_LIMIT]]   (defaults: build/proof, 2 s)
#   proofs/wp/mkconf.sh --selftest [OUTDIR [SMOKE_LIMIT]]
#
# SMOKE_LIMIT must be the -wp-smoke-timeout of the WP runs that use the configuration: Z3 runs
# through proofs/wp/goal_only.sh, which declines tasks with that time limit (smoke tests).
#
# Writes OUTDIR/why3.conf and OUTDIR/z3_fixedto.drv. `why3 config detect` writes absolute,
# machine-specific paths, so the configuration is generated at proof time and never
# committed. The committed inputs are proofs/wp/why3.conf (template of the extra prover
# entry "Z3 4.8.12 fixedTO") and proofs/wp/z3_fixedto.drv. Use the result with
#
#   WHY3CONFIG=OUTDIR/why3.conf frama-c -wp ... -wp-prover cvc4,'Z3:4.8.12:fixedTO'
#
# --selftest additionally checks, with a fake prover that prints "timeout", that the stock
# Z3 driver reports "High failure" and the fixedTO driver reports "Timeout".
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"

selftest=0
if [ "${1:-}" = "--selftest" ]; then
    selftest=1
    shift
fi
OUT="${1:-$ROOT/build/proof}"
SMOKE="${2:-2}"
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"

die() {
    printf 'mkconf: %s\n' "$*" >&2
    exit 1
}

case "$SMOKE" in
    ''|*[!0-9]*) die "smoke-test limit '$SMOKE' is not a whole number of seconds" ;;
esac
command -v why3 >/dev/null || die "why3 not found (run tools/bootstrap.sh prove)"
DATADIR="$(why3 --print-datadir)"
STOCK_DRV="$DATADIR/drivers/z3_471.drv"
[ -f "$STOCK_DRV" ] || die "stock driver $STOCK_DRV not found"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# 1. Detect the provers into a fresh file (never touches ~/.why3.conf).
why3 -C "$tmp/why3.conf" config detect >"$tmp/detect.log" 2>&1 ||
    { cat "$tmp/detect.log" >&2; die "why3 config detect failed"; }
grep -q '^Found prover CVC4 version 1\.8, OK\.' "$tmp/detect.log" ||
    { cat "$tmp/detect.log" >&2; die "CVC4 1.8 not detected"; }
grep -q '^Found prover Z3 version 4\.8\.12, OK\.' "$tmp/detect.log" ||
    { cat "$tmp/detect.log" >&2; die "Z3 4.8.12 not detected"; }

# Path of a detected prover binary (from its [partial_prover] section).
partial_path() {
    awk -v want="\"$1\"" '
        /^\[/ { sect = $0; name = ""; path = "" }
        sect == "[partial_prover]" && $1 == "name" { name = $3 }
        sect == "[partial_prover]" && $1 == "path" { path = $3 }
        name == want && path != "" { gsub(/"/, "", path); print path; exit }' "$2"
}
Z3="$(partial_path Z3 "$tmp/why3.conf")"
CVC4="$(partial_path CVC4 "$tmp/why3.conf")"
[ -x "$Z3" ] || die "could not find the detected z3 path in the generated config"

# 2. Driver: Why3 resolves `import` relative to the importing file, so point it at the stock
#    driver by absolute path.
sed "s|^import \"z3_471.drv\"|import \"$STOCK_DRV\"|" "$HERE/z3_fixedto.drv" >"$tmp/z3_fixedto.drv"
grep -qF "import \"$STOCK_DRV\"" "$tmp/z3_fixedto.drv" || die "z3_fixedto.drv: import line not found"

# 3. Extra prover entry from the template (comments dropped).
{
    cat "$tmp/why3.conf"
    printf '\n'
    sed -e '/^#/d' -e "s|@Z3@|$Z3|g" -e "s|@DRIVER@|$OUT/z3_fixedto.drv|g" \
        -e "s|@GATE@|$HERE/goal_only.sh|g" -e "s|@SMOKE@|$SMOKE|g" "$HERE/why3.conf"
} >"$tmp/why3.conf.new"

mv -f "$tmp/z3_fixedto.drv" "$OUT/z3_fixedto.drv"
mv -f "$tmp/why3.conf.new" "$OUT/why3.conf"

# 4. Check that Why3 loads it and knows the three provers the proofs use.
why3 -C "$OUT/why3.conf" config list-provers >"$tmp/provers" 2>&1 ||
    { cat "$tmp/provers" >&2; die "why3 cannot load $OUT/why3.conf"; }
for p in 'CVC4 1.8' 'Z3 4.8.12' 'Z3 4.8.12 (fixedTO)'; do
    grep -qxF "$p" "$tmp/provers" || { cat "$tmp/provers" >&2; die "prover '$p' missing"; }
done

if [ "$selftest" -eq 1 ]; then
    printf '#!/bin/sh\necho timeout\n' >"$tmp/fakez3"
    chmod +x "$tmp/fakez3"
    cp "$OUT/why3.conf" "$tmp/fake.conf"
    for alt in fakeStock fakeFixed; do
        drv=z3_471
        [ "$alt" = fakeFixed ] && drv="$OUT/z3_fixedto.drv"
        printf '\n[prover]\nalternative = "%s"\ncommand = "%s %%f"\ndriver = "%s"\neditor = ""\nin_place = false\ninteractive = false\nname = "Z3"\nshortcut = "%s"\nversion = "4.8.12"\n' \
            "$alt" "$tmp/fakez3" "$drv" "$alt" >>"$tmp/fake.conf"
    done
    printf 'module T\nuse int.Int\ngoal g: forall x:int. x + 0 = x\nend\n' >"$tmp/t.mlw"
    # why3 prove exits non-zero when the goal is not proved: only its output matters here.
    why3 -C "$tmp/fake.conf" prove -t 5 -P fakeStock "$tmp/t.mlw" >"$tmp/stock.log" 2>&1 || true
    why3 -C "$tmp/fake.conf" prove -t 5 -P fakeFixed "$tmp/t.mlw" >"$tmp/fixed.log" 2>&1 || true
    grep -q 'High failure' "$tmp/stock.log" ||
        { cat "$tmp/stock.log" >&2; die "selftest: stock driver no longer reports High failure"; }
    grep -q 'result is: Timeout' "$tmp/fixed.log" ||
        { cat "$tmp/fixed.log" >&2; die "selftest: fixedTO driver does not report Timeout"; }
    # The smoke gate: Z3 declines a task with the smoke limit, proves it with any other limit.
    why3 -C "$OUT/why3.conf" prove -t "$SMOKE" -P z3-fixedto "$tmp/t.mlw" >"$tmp/gate1.log" 2>&1 || true
    why3 -C "$OUT/why3.conf" prove -t "$((SMOKE + 1))" -P z3-fixedto "$tmp/t.mlw" >"$tmp/gate2.log" 2>&1 || true
    grep -q 'Unknown' "$tmp/gate1.log" ||
        { cat "$tmp/gate1.log" >&2; die "selftest: Z3 did not decline a task with the smoke limit"; }
    grep -q 'Valid' "$tmp/gate2.log" ||
        { cat "$tmp/gate2.log" >&2; die "selftest: Z3 did not prove a goal through the gate"; }
fi

printf 'why3:  %s (config: %s)\n' "$(why3 --version 2>&1 | head -n 1)" "${OUT#"$ROOT"/}/why3.conf"
printf 'cvc4:  CVC4 1.8 (%s)\n' "$CVC4"
printf 'z3:    Z3 4.8.12 and Z3 4.8.12 (fixedTO) (%s; smoke tests of %s s declined)\n' "$Z3" "$SMOKE"
