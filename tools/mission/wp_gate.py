#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Gate on a Frama-C/WP JSON report (-wp-report-json): every goal, smoke tests
included, must be valid. Prints the counts; exit 1 otherwise."""
import json
import sys

rep = json.load(open(sys.argv[1]))
total = valid = 0
bad = []
for fn, props in rep.get("wp:functions", {}).items():
    for prop, provers in props.items():
        total += 1
        ok = any(isinstance(v, dict) and v.get("valid", 0) >= v.get("total", 1) and v.get("total", 0) > 0
                 for k, v in provers.items() if k != "wp:main")
        main = provers.get("wp:main", {})
        if main:
            ok = main.get("valid", 0) == main.get("total", 0) and main.get("total", 0) > 0
        if ok:
            valid += 1
        else:
            bad.append(f"{fn}: {prop}")
print(f"wp-gate: {valid}/{total} goals valid")
for b in bad:
    print("  unproved:", b)
sys.exit(0 if valid == total else 1)
