#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Gate on a Frama-C/WP JSON report (-wp-report-json): every goal, lemma and
smoke test must be valid (see proofs/wp/README.md for the report's shape).
Prints one line per property that is not, and a summary; exit 1 on any."""
import json
import sys


def main(path):
    with open(path, encoding="utf-8") as f:
        report = json.load(f)
    groups = {**report.get("wp:axiomatics", {}), **report.get("wp:functions", {})}
    total = 0
    bad = []
    for group, props in groups.items():
        for prop, counts in props.items():
            if prop == "wp:section":
                continue
            total += 1
            main_counts = counts.get("wp:main", {})
            if main_counts.get("valid", 0) != main_counts.get("total", -1):
                bad.append(f"{group}: {prop} {main_counts}")
    for line in bad:
        print("not proved:", line)
    print(f"wp gate: {total - len(bad)}/{total} properties valid (goals and smoke tests)")
    return 1 if bad or total == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
