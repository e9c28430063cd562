#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""proofs/wp/gate.py -- the Frama-C/WP gate (python3 stdlib only).

    proofs/wp/gate.py [--wp-dir DIR] [--modules m1,m2,...] [--summary FILE] [--quiet]
    proofs/wp/gate.py --diversity --wp-dir DIR_BOTH --z3-dir DIR_Z3 --cvc4-dir DIR_CVC4 --out FILE

Gate mode (default) reads DIR/<module>/report.json (-wp-report-json), DIR/<module>/wp.log (the
Frama-C log) and DIR/<module>/time.txt (wall seconds), prints a per-module and per-function table
and writes DIR/summary.json. It fails (exit 1) unless, for every expected module:
  * the report exists and holds at least one goal,
  * every goal (contract, RTE, lemma) is Valid and every smoke test Passed
    (in the JSON both read wp:main.valid == wp:main.total, see proofs/wp/README.md),
  * the log holds none of the kernel/WP warnings listed in FATAL_LOG (missing specifications,
    generated default assigns, annotation errors, casts outside the reviewed list, ...),
and unless the ACSL of kernel/ and proofs/wp/laws/ is free of `axiom`, `admit` and `check`.

Diversity mode compares three runs (both provers, Z3 alone, CVC4 alone) and writes a Markdown
table (proofs/wp/diversity.md).
"""
import argparse
import json
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cache as wp_cache  # noqa: E402  (proofs/wp/cache.py)
sys.path.insert(0, os.path.join(ROOT, "tools"))
import requirements as reqs  # noqa: E402  (tools/requirements.py)

# Log lines that fail the gate: (regex, why).
FATAL_LOG = [
    (r"Neither code nor (explicit )?specification", "function without code or contract"),
    (r"No code nor (explicit|implicit) assigns", "function without assigns"),
    (r"generating default assigns", "default assigns generated"),
    (r"Missing assigns clause", "missing assigns clause"),
    (r"\[kernel:annot-error\]", "ACSL annotation error"),
    (r"User Error|Frama-C aborted|invalid user input", "Frama-C error"),
    (r"implicit-function-declaration|Calling undeclared function", "undeclared function"),
    (r"No Why3 provers detected|not found in why3\.conf|Prover .* not (found|installed)",
     "prover configuration"),
    (r"No goal generated", "no goal generated"),
    (r"Cast with incompatible pointers types", "pointer cast (see CAST_ALLOWED)"),
    (r"Failed Unknown error|HighFailure|Prover error", "prover failure"),
]
# Reviewed exceptions: module -> regexes of the only cast warnings accepted there. The object
# ring and the topic bus take `void *` objects and read/write them only as bytes (uint8_t); WP's
# Typed model sees void* as sint8*. objring is proved with -wp-model Typed+cast (the cast keeps the pointer
# value); sound because no object byte is ever accessed as anything but uint8_t in the module.
CAST_ALLOWED = {
    "objring": [r"\(source: sint8\*\) \(target: uint8\*\)"],
    # The work queue's void * entry points (callback shapes: a publish hook, a proc, a thread
    # body) convert their argument back to the mt_work_t / mt_wq_t it is (proofs/proofs.mk).
    "wq": [r"\(source: sint8\*\)\s+\(target: (mt_wq|mt_work)\*\)"],
    "bus": [r"\(source: sint8\*\) \(target: uint8\*\)"],
}


def cast_allowed(module):
    """The reviewed casts of a WP module: a module split over several files (wq_timer.c is
    module wq) shares its module's list; the part before the first '_' names the module."""
    return CAST_ALLOWED.get(module, CAST_ALLOWED.get(module.split("_")[0], []))

# Informational warnings (counted, printed, not fatal).
INFO_LOG = [r"\[wp:pedantic-assigns\]"]

GOAL_RE = re.compile(
    r"^\[wp\] \[([^\]]+)\] (Goal|Smoke-test) (typed_(?:cast_)?)?(\S+) : (\w+)(.*)$")
TIME_RE = re.compile(r"\((?:Qed:)?([0-9.]+)(ms|s)\)")


def load_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def goal_time(rest):
    """Prover time of one log line, in seconds (the last time in parentheses, Qed included)."""
    total = 0.0
    times = TIME_RE.findall(rest)
    if times:
        v, unit = times[-1]
        total = float(v) / (1000.0 if unit == "ms" else 1.0)
    return total


def parse_log(path):
    """Per-goal times and the warning lines of a Frama-C log."""
    times = {}
    lines = []
    if not os.path.exists(path):
        return times, lines
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()
    for ln in lines:
        m = GOAL_RE.match(ln)
        if m:
            name = m.group(4)
            times[name] = times.get(name, 0.0) + goal_time(m.group(6))
    return times, lines


def log_findings(module, lines):
    """Fatal and informational findings in a log (one message line at a time)."""
    fatal, info = [], []
    for i, ln in enumerate(lines):
        for rx, why in FATAL_LOG:
            if not re.search(rx, ln):
                continue
            # Frama-C may wrap the cast warning: "(target: ...)" on the next, indented line.
            full = ln
            if i + 1 < len(lines) and re.match(r"\s+\(target:", lines[i + 1]):
                full = ln + " " + lines[i + 1].strip()
            if why.startswith("pointer cast") and \
                    any(re.search(a, full) for a in cast_allowed(module)):
                continue
            where = lines[i - 1].strip() if i > 0 and "Warning:" in lines[i - 1] else ""
            fatal.append(f"{why}: {(where + ' ' + ln.strip()).strip()}")
            break
        for rx in INFO_LOG:
            if re.search(rx, ln):
                info.append(ln.strip())
    return sorted(set(fatal)), info


def is_smoke(prop):
    return "_wp_smoke_" in prop


def module_stats(module, wp_dir):
    d = os.path.join(wp_dir, module)
    rep = os.path.join(d, "report.json")
    res = {"module": module, "missing": not os.path.exists(rep), "functions": {},
           "goals": 0, "proved": 0, "smoke": 0, "smoke_passed": 0, "by_prover": {},
           "time_s": None, "prover_time_s": 0.0, "failures": [], "fatal": [], "info": []}
    times, lines = parse_log(os.path.join(d, "wp.log"))
    res["cache_replayed"], res["cache_fresh"] = wp_cache.count(os.path.join(d, "wp.log"))
    res["fatal"], res["info"] = log_findings(module, lines)
    # make reprove: the module's Frama-C run was skipped because its inputs are identical to
    # those of this tree's last run (replayed.txt: that run's time); not re-proved now.
    rfile = os.path.join(d, "replayed.txt")
    res["replayed_local"] = (open(rfile, encoding="utf-8").read().strip() or "?") \
        if os.path.exists(rfile) else None
    if res["replayed_local"]:
        res["cache_replayed"], res["cache_fresh"] = 0, 0
    tfile = os.path.join(d, "time.txt")
    if os.path.exists(tfile):
        try:
            res["time_s"] = round(float(open(tfile, encoding="utf-8").read().split()[0]), 1)
        except (ValueError, IndexError):
            pass
    if res["missing"]:
        return res
    rj = load_json(rep)
    groups = {}
    for g, ps in rj.get("wp:axiomatics", {}).items():
        groups["lemma" + (":" + g if g else "")] = ps
    groups.update(rj.get("wp:functions", {}))
    names = sorted(groups, key=len, reverse=True)
    # goal time per function: match the goal name against the property keys of each group
    for g, ps in groups.items():
        f = {"goals": 0, "proved": 0, "smoke": 0, "smoke_passed": 0, "time_s": 0.0}
        for p, v in ps.items():
            if p == "wp:section":
                continue
            main = v.get("wp:main", {})
            tot, val = main.get("total", 0), main.get("valid", 0)
            if is_smoke(p):
                f["smoke"] += tot
                f["smoke_passed"] += val
            else:
                f["goals"] += tot
                f["proved"] += val
            if val != tot:
                res["failures"].append(f"{g}: {p} {main}")
        res["functions"][g] = f
    for goal, t in times.items():
        owner = None
        if goal.startswith("lemma_"):
            owner = next((n for n in names if n.startswith("lemma")), None)
        else:
            owner = next((n for n in names if goal == n or goal.startswith(n + "_")), None)
        if owner is not None:
            res["functions"][owner]["time_s"] += t
        res["prover_time_s"] += t
    for f in res["functions"].values():
        f["time_s"] = round(f["time_s"], 2)
        for k in ("goals", "proved", "smoke", "smoke_passed"):
            res[k] += f[k]
    res["prover_time_s"] = round(res["prover_time_s"], 1)
    for prover, v in rj.get("wp:global", {}).items():
        if prover == "wp:main":
            continue
        res["by_prover"][prover] = v.get("valid", 0)
    if res["cache_fresh"] is None and not res["replayed_local"]:
        # No cache line: the cache was off (WP_CACHE=none, make prove-cold), so every goal and
        # smoke test that Qed did not decide went to the provers in this run.
        res["cache_fresh"] = res["goals"] + res["smoke"] - res["by_prover"].get("qed", 0)
    return res


ANNOT_RE = re.compile(r"/\*@(.*?)\*/|//@([^\n]*)", re.S)
FORBIDDEN_RE = re.compile(r"(?<![\w\\])(axiom|admit|check)(?!\w)")


def acsl_scan(paths):
    """`axiom`, `admit`, `check` keywords inside ACSL annotations."""
    bad = []
    for top in paths:
        for dp, _, files in os.walk(top):
            for fn in sorted(files):
                if not fn.endswith((".c", ".h")):
                    continue
                p = os.path.join(dp, fn)
                text = open(p, encoding="utf-8", errors="replace").read()
                for m in ANNOT_RE.finditer(text):
                    body = m.group(1) if m.group(1) is not None else m.group(2)
                    # drop ACSL line comments inside the annotation
                    body_nc = re.sub(r"//[^\n]*", "", body)
                    for k in FORBIDDEN_RE.finditer(body_nc):
                        line = text.count("\n", 0, m.start()) + 1 + body_nc.count("\n", 0, k.start())
                        bad.append(f"{os.path.relpath(p, ROOT)}:{line}: ACSL keyword '{k.group(1)}'")
    return bad


def discover(wp_dir):
    if not os.path.isdir(wp_dir):
        return []
    return sorted(m for m in os.listdir(wp_dir)
                  if os.path.isdir(os.path.join(wp_dir, m)) and
                  os.path.exists(os.path.join(wp_dir, m, "wp.log")))


def fmt_time(t):
    return "-" if t is None else f"{t:.1f}s"


def gate(args):
    wp_dir = args.wp_dir
    modules = args.modules.split(",") if args.modules else discover(wp_dir)
    ok = True
    stats = [module_stats(m, wp_dir) for m in modules]
    out = []
    hdr = f"{'module / function':44} {'goals':>11} {'smoke':>9} {'time':>8}"
    out.append(hdr)
    out.append("-" * len(hdr))
    tot = {"goals": 0, "proved": 0, "smoke": 0, "smoke_passed": 0}
    by_prover = {}
    for s in stats:
        if s["missing"]:
            out.append(f"{s['module']:44} {'NO REPORT':>11}")
            ok = False
            continue
        flag = "" if (s["proved"] == s["goals"] and s["smoke_passed"] == s["smoke"] and
                      not s["fatal"] and s["goals"] > 0) else "  <-- FAIL"
        out.append(f"{s['module']:44} {s['proved']:>5}/{s['goals']:<5} "
                   f"{s['smoke_passed']:>4}/{s['smoke']:<4} {fmt_time(s['time_s']):>8}{flag}  "
                   + (f"(REPLAYED from this tree's run of {s['replayed_local']}, identical "
                      "inputs: not re-proved now)" if s["replayed_local"] else
                      f"(prover verdicts: {s.get('cache_replayed') or 0} reused, "
                      f"{s.get('cache_fresh') or 0} fresh)"))
        if not args.quiet:
            for fn in sorted(s["functions"]):
                f = s["functions"][fn]
                out.append(f"  {fn:42} {f['proved']:>5}/{f['goals']:<5} "
                           f"{f['smoke_passed']:>4}/{f['smoke']:<4} {f['time_s']:>7.2f}s")
        for k in tot:
            tot[k] += s[k]
        for p, v in s["by_prover"].items():
            by_prover[p] = by_prover.get(p, 0) + v
        if flag:
            ok = False
    out.append("-" * len(hdr))
    out.append(f"{'total':44} {tot['proved']:>5}/{tot['goals']:<5} "
               f"{tot['smoke_passed']:>4}/{tot['smoke']:<4}")
    out.append("proved by (WP counts, smoke tests included): " +
               ", ".join(f"{p} {v}" for p, v in sorted(by_prover.items())))
    replayed = sum(s.get("cache_replayed") or 0 for s in stats)
    fresh = sum(s.get("cache_fresh") or 0 for s in stats)
    out.append(f"prover verdicts (goals and smoke tests): {fresh} from provers run now, "
               f"{replayed} reused from the WP cache (verdicts recorded for byte-identical prover "
               "tasks; proofs/wp/cache, assumption W4; WP_CACHE=none runs every prover)")
    run = [s["module"] for s in stats if not s["missing"] and not s["replayed_local"]]
    replayed_local = [s["module"] for s in stats if not s["missing"] and s["replayed_local"]]
    out.append(f"modules: {len(run)} run by Frama-C now, every VC generated from the current "
               "source" + (f" ({', '.join(run)})" if run else ""))
    if replayed_local:
        out.append(f"modules: {len(replayed_local)} replayed, not proved in this run (make "
                   "reprove: inputs identical to this tree's last run of the module: "
                   f"{', '.join(replayed_local)})")
    problems = []
    for s in stats:
        problems += [f"{s['module']}: unproved: {x}" for x in s["failures"]]
        problems += [f"{s['module']}: log: {x}" for x in s["fatal"]]
        if not s["missing"] and s["goals"] == 0:
            problems.append(f"{s['module']}: no goals")
    acsl = acsl_scan([os.path.join(ROOT, "kernel"), os.path.join(ROOT, "proofs", "wp", "laws")])
    problems += acsl
    # The smoke canary (make wp-canary): the smoke-test settings must still find contradictions.
    canary = "not run"
    cfile = os.path.join(wp_dir, "canary", "result.txt")
    if os.path.exists(cfile):
        with open(cfile, encoding="utf-8") as f:
            lines = [x.strip() for x in f if x.strip()]
        canary = lines[-1] if lines else "empty"
    out.append(f"smoke canary: {canary}")
    if not re.match(r"^wp-canary: \d+ functions as expected", canary):
        problems.append(f"smoke canary: {canary} (make wp-canary, proofs/wp/canary/)")
    # Traceability (tools/requirements.py): only over the full module set (make wp, a merge).
    trace = None
    if args.requirements:
        trace = reqs.check(reqs.load(args.requirements), reqs.wp_goals(wp_dir, modules))
        good = sum(r["ok"] for r in trace)
        out.append(f"requirements: {good}/{len(trace)} discharged (every named clause proved, "
                   "every named test and model present; the matrix is in the proof report)")
        problems += [f"requirement {r['id']}: {p}" for r in trace for p in r["problems"]]
    info = sum(len(s["info"]) for s in stats)
    if info:
        out.append(f"note: {info} [wp:pedantic-assigns] warnings (no \\from on assigned "
                   "pointers; informational)")
    if problems:
        ok = False
        out.append("")
        out.append("GATE FAILURES:")
        out += ["  " + p for p in problems]
    out.append("wp gate: " + ("PASS" if ok else "FAIL"))
    print("\n".join(out))
    summary = {
        "modules": {s["module"]: {k: s[k] for k in ("goals", "proved", "smoke", "smoke_passed",
                                                    "time_s", "prover_time_s", "by_prover",
                                                    "cache_replayed", "cache_fresh",
                                                    "functions", "failures", "fatal",
                                                    "replayed_local")}
                    for s in stats},
        "goals": tot["goals"], "proved": tot["proved"],
        "smoke": tot["smoke"], "smoke_passed": tot["smoke_passed"],
        "by_prover": by_prover,
        "cache_replayed": replayed, "cache_fresh": fresh,
        "modules_run": run,
        "modules_replayed_local": replayed_local,
        "acsl_forbidden": acsl,
        "smoke_canary": canary,
        "pass": ok,
    }
    if trace is not None:
        summary["requirements"] = trace
    sfile = args.summary or os.path.join(wp_dir, "summary.json")
    os.makedirs(os.path.dirname(sfile) or ".", exist_ok=True)
    with open(sfile, "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
        f.write("\n")
    return 0 if ok else 1


def solo_counts(wp_dir, module):
    """(goals proved, goals, smoke passed, smoke) of a run."""
    s = module_stats(module, wp_dir)
    if s["missing"]:
        return None
    return s


def diversity(args):
    modules = args.modules.split(",") if args.modules else discover(args.wp_dir)
    rows = []
    tot = {k: [0, 0] for k in ("both", "z3", "cvc4")}
    tots = {k: [0, 0] for k in ("both", "z3", "cvc4")}
    times = {k: 0.0 for k in ("both", "z3", "cvc4")}
    for m in modules:
        cells = []
        for key, d in (("both", args.wp_dir), ("z3", args.z3_dir), ("cvc4", args.cvc4_dir)):
            s = solo_counts(d, m)
            if s is None:
                cells.append("n/a")
                continue
            tot[key][0] += s["proved"]
            tot[key][1] += s["goals"]
            tots[key][0] += s["smoke_passed"]
            tots[key][1] += s["smoke"]
            times[key] += s["time_s"] or 0.0
            pct = 100.0 * s["proved"] / s["goals"] if s["goals"] else 0.0
            cells.append(f"{s['proved']}/{s['goals']} ({pct:.1f} %), smoke {s['smoke_passed']}/"
                         f"{s['smoke']}, {fmt_time(s['time_s'])}")
        rows.append(f"| {m} | " + " | ".join(cells) + " |")
    lines = [
        "# WP prover diversity",
        "",
        "Generated by `make wp-diversity` (proofs/wp/gate.py --diversity); do not edit by hand.",
        "Each column is one full run of every module with the options of `make wp`",
        "(`-wp-rte -warn-unsigned-overflow -warn-unsigned-downcast`, timeout pinned in",
        "proofs/proofs.mk), with the prover list changed: both provers (the main `make wp` run,",
        "smoke tests included), Z3 4.8.12 (fixedTO driver) alone, CVC4 1.8 alone (these two",
        "without smoke tests: smoke tests are decided in the main run, assumption W1). Goals",
        "count contract, RTE and lemma goals (Qed, WP's simplifier, closes some without any",
        "prover). Times are wall times of the run, on whatever load the machine had.",
        "",
        "| module | Z3 + CVC4 | Z3 alone | CVC4 alone |",
        "|---|---|---|---|",
    ] + rows
    def cell(k):
        g, n = tot[k]
        sp, sn = tots[k]
        pct = 100.0 * g / n if n else 0.0
        return f"**{g}/{n} ({pct:.1f} %)**, smoke {sp}/{sn}, {times[k]:.0f}s"
    lines.append(f"| **total** | {cell('both')} | {cell('z3')} | {cell('cvc4')} |")
    lines.append("")
    # goals each prover misses alone
    for key, d in (("z3", args.z3_dir), ("cvc4", args.cvc4_dir)):
        miss = []
        for m in modules:
            s = solo_counts(d, m)
            if s:
                miss += [f"{m}: {x.split(' {')[0]}" for x in s["failures"]]
        name = "Z3 alone" if key == "z3" else "CVC4 alone"
        lines.append(f"Goals not closed by {name} ({len(miss)}):")
        lines.append("")
        lines += [f"- `{x}`" for x in miss] or ["- none"]
        lines.append("")
    with open(args.out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--wp-dir", default=os.path.join(ROOT, "build", "proof", "wp"))
    ap.add_argument("--modules", default="")
    ap.add_argument("--summary", default="")
    ap.add_argument("--requirements", default="",
                    help="check this traceability file (proofs/requirements.json) too")
    ap.add_argument("--quiet", action="store_true", help="module lines only")
    ap.add_argument("--diversity", action="store_true")
    ap.add_argument("--z3-dir", default="")
    ap.add_argument("--cvc4-dir", default="")
    ap.add_argument("--out", default=os.path.join(ROOT, "proofs", "wp", "diversity.md"))
    args = ap.parse_args()
    if args.diversity:
        return diversity(args)
    return gate(args)


if __name__ == "__main__":
    sys.exit(main())
