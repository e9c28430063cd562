#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""proofs/wp/canary/check.py LOG [--json PATH] -- judge a WP run over smoke_canary.c.

EXPECT below is the one declaration of what each function of proofs/wp/canary/smoke_canary.c
must show: a seeded contradiction ("caught": at least one failed smoke test) or a clean control
("clean": every goal proved, every smoke test passed, at least one of each). Prints one line per
function, then the summary line

    wp-canary: N functions as expected (caught C/S seeded contradictions, K controls clean)

whose prefix `wp-canary: N functions as expected` the WP gate requires. Anything else (a seeded
contradiction missed, a control not clean, a function absent from the log or from EXPECT, a log
without WP's final tally, a failed smoke test outside every declared function) prints
`wp-canary: FAIL ...` instead and exits 1. `--json PATH` also writes
{"ok", "seeded", "caught", "controls", "controls_clean", "functions": [{name, kind, expect, ok}]}.

WP names a dead-call smoke test after the callee (`typed_mt_port_lock_wp_smoke_dead_call_s14`),
not after the function that makes the call; a failed one is attributed through the source line
of the warning WP prints after it (`smoke_canary.c:87: Warning: Failed smoke-test`). A passed
one names no line and is not counted.
"""
import argparse
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.join(HERE, "smoke_canary.c")

CAUGHT = "caught"
CLEAN = "clean"

# name, kind (the contract shape), expected outcome. canary_* are seeded, control_* are clean.
EXPECT = (
    ("canary_quantified", "table-entry", CAUGHT),
    ("canary_sorted", "ordering", CAUGHT),
    ("canary_nonlinear", "nonlinear", CAUGHT),
    ("canary_null", "null-pointer", CAUGHT),
    ("canary_sum", "field-sum", CAUGHT),
    ("canary_dead_branch", "dead-branch", CAUGHT),
    ("canary_empty_behavior", "empty-behavior", CAUGHT),
    ("canary_task_table", "struct-table", CAUGHT),
    ("canary_grid", "modulo", CAUGHT),
    ("canary_quotient", "quotient", CAUGHT),
    ("canary_ghost_stamp", "ghost-state", CAUGHT),
    ("canary_lock_class", "port-lock", CAUGHT),
    ("canary_clock_backwards", "port-clock", CAUGHT),
    ("control_positive", "table-entry", CLEAN),
    ("control_sorted", "ordering", CLEAN),
    ("control_loop", "loop", CLEAN),
    ("control_task_table", "struct-table", CLEAN),
    ("control_grid", "modulo", CLEAN),
    ("control_quotient", "quotient", CLEAN),
    ("control_ghost_stamp", "ghost-state", CLEAN),
    ("control_lock_class", "port-lock", CLEAN),
    ("control_clock_elapsed", "port-clock", CLEAN),
)

RESULT = re.compile(r"^\[wp\] \[([^\]]+)\] (Goal|Smoke-test) typed_(\S+)(?: : (\w+))?")
WARNING = re.compile(r"^\[wp\] (\S+):(\d+): Warning: Failed smoke-test")
TALLY = re.compile(r"^\[wp\] Proved goals:")
DEFINITION = re.compile(r"^[A-Za-z_][\w \t*]*?\b((?:canary|control)_\w+)\(")


def source_functions(path):
    """[(name, first line, last line)] of the functions defined in the canary source. A
    function owns the lines after the previous function's closing brace (its comment and
    contract) up to its own closing brace."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    spans = []
    start = 1
    i = 0
    while i < len(lines):
        m = DEFINITION.match(lines[i])
        if m:
            end = i
            while end < len(lines) and lines[end] != "}":
                end += 1
            spans.append((m.group(1), start, end + 1))
            start = end + 2
            i = end
        i += 1
    return spans


def owner_by_name(name, fns):
    best = None
    for fn in fns:
        if name.startswith(fn + "_") and (best is None or len(fn) > len(best)):
            best = fn
    return best


def owner_by_line(path, line, spans):
    if os.path.basename(path) != os.path.basename(SRC):
        return None
    for fn, first, last in spans:
        if first <= line <= last:
            return fn
    return None


def read_log(path, fns, spans):
    """{fn: {"goals": {name: ok}, "smoke": {name: "passed"|"failed"|other}}}, the stray failed
    smoke tests (no declared owner), and whether WP's final tally is present."""
    seen = {fn: {"goals": {}, "smoke": {}} for fn in fns}
    stray = []
    tally = False
    last = None  # the unowned smoke test whose warning line may follow
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if TALLY.match(line):
                tally = True
            w = WARNING.match(line)
            if w and last is not None:
                fn = owner_by_line(w.group(1), int(w.group(2)), spans)
                if fn in seen:
                    seen[fn]["smoke"][last] = "failed"
                else:
                    stray.append(f"{last} at {w.group(1)}:{w.group(2)}")
                last = None
                continue
            m = RESULT.match(line)
            if not m:
                continue
            if last is not None:
                stray.append(f"{last} (no location)")
                last = None
            status, what, name, result = m.groups()
            fn = owner_by_name(name, fns)
            if what == "Goal":
                if fn is not None:
                    ok = result == "Valid"
                    seen[fn]["goals"][name] = seen[fn]["goals"].get(name, True) and ok
                continue
            verdict = status.lower()  # Passed, Failed; anything else is neither
            if fn is not None:
                # WP prints a failed smoke test twice (result, then warning list): once is enough.
                if seen[fn]["smoke"].get(name) != "failed":
                    seen[fn]["smoke"][name] = verdict
            elif verdict == "failed":
                last = name
    if last is not None:
        stray.append(f"{last} (no location)")
    stray = sorted(set(stray))
    return seen, stray, tally


def short(fn, name):
    """typed_-less smoke-test name without its owner: `default_requires`, `dead_code_s12`,
    `dead_call_s43 (mt_port_lock)` for a dead call named after its callee."""
    if name.startswith(fn + "_wp_smoke_"):
        return name[len(fn + "_wp_smoke_"):]
    callee, sep, rest = name.partition("_wp_smoke_")
    return f"{rest} ({callee})" if sep else name


def judge(fn, expect, s):
    """(ok, what) for one function."""
    goals, smoke = s["goals"], s["smoke"]
    if not goals and not smoke:
        return False, "not in the log"
    failed = sorted(n for n, v in smoke.items() if v == "failed")
    if expect == CAUGHT:
        if failed:
            shown = ", ".join(short(fn, n) for n in failed)
            return True, f"{len(failed)} failed smoke test(s): {shown}"
        return False, f"no failed smoke test ({len(smoke)} smoke test(s) not failed)"
    proved = sum(goals.values())
    passed = sum(v == "passed" for v in smoke.values())
    ok = goals and proved == len(goals) and smoke and passed == len(smoke)
    what = f"{proved}/{len(goals)} goals proved, {passed}/{len(smoke)} smoke tests passed"
    return bool(ok), what


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("log", help="the Frama-C/WP log of the canary run")
    ap.add_argument("--json", metavar="PATH", help="also write the verdicts as JSON")
    args = ap.parse_args(argv)

    spans = source_functions(SRC)
    declared = [name for name, _, _ in EXPECT]
    problems = []
    defined = [fn for fn, _, _ in spans]
    for fn in defined:
        if fn not in declared:
            problems.append(f"{fn} is defined in {os.path.basename(SRC)} but not in EXPECT")
    for name, _, expect in EXPECT:
        if name not in defined:
            problems.append(f"{name} is in EXPECT but not defined in {os.path.basename(SRC)}")
        if (expect == CAUGHT) != name.startswith("canary_"):
            problems.append(f"{name}: expectation '{expect}' does not match its name")

    seen, stray, tally = read_log(args.log, declared, spans)
    if not tally:
        problems.append("the log has no 'Proved goals' tally (WP did not finish)")
    for s in stray:
        problems.append(f"failed smoke test outside every declared function: {s}")

    rows = []
    for name, kind, expect in EXPECT:
        ok, what = judge(name, expect, seen[name])
        if expect == CAUGHT:
            word = "caught " if ok else "MISSED "
        else:
            word = "clean  " if ok else "UNCLEAN"
        print(f"{word} {name:24s} {kind:15s} {what}")
        rows.append({"name": name, "kind": kind, "expect": expect, "ok": ok})
    for p in problems:
        print(f"ERROR   {p}")

    seeded = [r for r in rows if r["expect"] == CAUGHT]
    controls = [r for r in rows if r["expect"] == CLEAN]
    caught = sum(r["ok"] for r in seeded)
    clean = sum(r["ok"] for r in controls)
    good = not problems and all(r["ok"] for r in rows)
    counts = (f"caught {caught}/{len(seeded)} seeded contradictions, "
              f"{clean}/{len(controls)} controls clean")
    if good:
        print(f"wp-canary: {len(rows)} functions as expected (caught {caught}/{len(seeded)} "
              f"seeded contradictions, {clean} controls clean)")
    else:
        bad = [r["name"] for r in rows if not r["ok"]]
        more = f"; {len(problems)} error(s)" if problems else ""
        names = ", ".join(bad) or "no function"
        print(f"wp-canary: FAIL: {counts} ({names} not as expected{more})")
    if args.json:
        report = {"ok": good, "seeded": len(seeded), "caught": caught,
                  "controls": len(controls), "controls_clean": clean, "functions": rows}
        d = os.path.dirname(args.json)
        if d:
            os.makedirs(d, exist_ok=True)
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(report, f, indent=1)
            f.write("\n")
    return 0 if good else 1


if __name__ == "__main__":
    sys.exit(main())
