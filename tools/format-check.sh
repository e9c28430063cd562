#!/usr/bin/env bash
# tools/format-check.sh — check C/C++ formatting against the repository's .clang-format.
#
#   tools/format-check.sh          check kernel/, hal_posix/, tests/, vehicle/ (fails on any difference)
#   tools/format-check.sh --fix    reformat those files in place
#   tools/format-check.sh [--fix] FILE...   only the given files
#
# Prints the offending places and a one-line summary; exits 1 when a file is not formatted.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

fix=0
if [ "${1:-}" = "--fix" ]; then
    fix=1
    shift
fi
args=()
for a in "$@"; do
    args+=("$(realpath -m --relative-base="$ROOT" -- "$a")")
done
cd "$ROOT"

command -v clang-format >/dev/null || "$ROOT/tools/bootstrap.sh" lint >/dev/null

files=()
if [ "${#args[@]}" -gt 0 ]; then
    files=("${args[@]}")
else
    dirs=()
    for d in kernel hal_posix tests vehicle; do
        [ -d "$d" ] && dirs+=("$d")
    done
    if [ "${#dirs[@]}" -gt 0 ]; then
        while IFS= read -r -d '' f; do
            files+=("$f")
        done < <(find "${dirs[@]}" -type f \( -name '*.c' -o -name '*.h' -o -name '*.cc' \
                 -o -name '*.cpp' -o -name '*.hpp' \) -print0 | sort -z)
    fi
fi

version="$(clang-format --version | awk '{for (i = 1; i < NF; i++) if ($i == "version") {print $(i + 1); exit}}')"
if [ "${#files[@]}" -eq 0 ]; then
    echo "format: OK: no C/C++ files (clang-format $version)"
    exit 0
fi

if [ "$fix" -eq 1 ]; then
    clang-format -i --style="file:$ROOT/.clang-format" "${files[@]}"
    echo "format: fixed ${#files[@]} files (clang-format $version)"
    exit 0
fi

bad=0
for f in "${files[@]}"; do
    if ! out="$(clang-format --dry-run -Werror --style="file:$ROOT/.clang-format" "$f" 2>&1)"; then
        bad=$((bad + 1))
        printf '%s\n' "$out" | grep -E ': error: ' | head -n 5
    fi
done
if [ "$bad" -eq 0 ]; then
    echo "format: OK: ${#files[@]} files (clang-format $version)"
else
    echo "format: FAIL: $bad of ${#files[@]} files need formatting (tools/format-check.sh --fix) (clang-format $version)"
    exit 1
fi
