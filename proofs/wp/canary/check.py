#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""proofs/wp/canary/check.py LOG -- judge a WP run over proofs/wp/canary/smoke_canary.c.

Passes (exit 0) when every canary_* function of the canary has at least one failed smoke test
(its contradiction was found) and every control_* function has all its goals proved and all
its smoke tests passed. Prints one line per function.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.join(HERE, "smoke_canary.c")
LINE = re.compile(r"^\[wp\] \[([^\]]+)\] (Goal|Smoke-test) typed_(\S+)(?: : (\w+))?")


def functions():
    with open(SRC, encoding="utf-8") as f:
        return re.findall(r"^\w+ ((?:canary|control)_\w+)\(", f.read(), re.M)


def owner(name, fns):
    best = None
    for fn in fns:
        if name.startswith(fn + "_") and (best is None or len(fn) > len(best)):
            best = fn
    return best


def main():
    fns = functions()
    # WP prints a failed smoke test twice (result, then warning list): count names once.
    seen = {}
    with open(sys.argv[1], encoding="utf-8", errors="replace") as f:
        for line in f:
            m = LINE.match(line)
            if not m:
                continue
            status, kind, name, result = m.groups()
            fn = owner(name, fns)
            if fn is None:
                continue
            ok = (status != "Failed") if kind == "Smoke-test" else (result == "Valid")
            seen[(fn, kind, name)] = seen.get((fn, kind, name), True) and ok
    stats = {fn: {"smoke_failed": 0, "smoke": 0, "goals": 0, "proved": 0} for fn in fns}
    for (fn, kind, _), ok in seen.items():
        s = stats[fn]
        if kind == "Smoke-test":
            s["smoke"] += 1
            s["smoke_failed"] += not ok
        else:
            s["goals"] += 1
            s["proved"] += ok
    bad = []
    for fn in fns:
        s = stats[fn]
        if fn.startswith("canary_"):
            ok = s["smoke_failed"] > 0
            what = f"{s['smoke_failed']} failed smoke test(s): contradiction found" if ok \
                else "NOT FOUND: every smoke test passed"
        else:
            ok = s["goals"] > 0 and s["proved"] == s["goals"] and s["smoke_failed"] == 0 and \
                s["smoke"] > 0
            what = f"{s['proved']}/{s['goals']} goals, {s['smoke'] - s['smoke_failed']}/" \
                   f"{s['smoke']} smoke tests passed"
        print(f"{'ok  ' if ok else 'FAIL'} {fn:28s} {what}")
        if not ok:
            bad.append(fn)
    if bad:
        print(f"wp-canary: FAIL ({', '.join(bad)})")
        return 1
    print(f"wp-canary: {len(fns)} functions as expected "
          f"({sum(f.startswith('canary_') for f in fns)} contradictions found, "
          f"{sum(f.startswith('control_') for f in fns)} controls clean)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
