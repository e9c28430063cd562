#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Merge the results of `make prove` into one report and apply the strict gate.

    tools/proof_report.py [--default-parts "wp cbmc ..."] [--assumptions FILE] [--baseline FILE]
                          [--shard i/N]

The gate is tools/proof_gate.py: every problem it finds (a part that failed, a summary missing,
a goal, harness, model, trace or mutant not as expected, a count below proofs/baseline.json) is
listed here, and any one of them makes the exit status 1. There is one gate: PROVE_GATE is
ignored (a warning is printed when it is set to anything but "full"). --shard i/N: the report of
one shard (tools/prove_shard.py): the checks of the whole run are left to the merge's report
(proof_gate.waive_for_shard), the summary says "shard" and "partial", and the exit status is 0
when everything the shard ran passed.

Reads $BUILD/proof/ (BUILD: env, default build; an absolute path is used as it is), the tool
versions (versions.txt) and wall times (timing.json) that tools/prove.sh wrote, and
proofs/assumptions.json, listed in the report. Writes, under $BUILD/proof/:
  summary.json  {"wp", "cbmc", "tla", "translator", "selftest", "tla_trace", "tla_trace_all",
                 "chibios_cbmc", "assumptions", "timing", "versions", "parts", "counts",
                 "problems", "gate": "strict", "ok", "complete"}; ok: no problem; complete:
                 no problem apart from the baseline floor
  junit.xml     a "gate" suite with one testcase per check, one suite per tool with one
                testcase per function, harness, model, trace or mutant
  report.md     readable report for auditors: results, part status, WP cache use per module,
                every assumption
"""
import argparse
import json
import os
import sys
import xml.sax.saxutils as sx

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import proof_gate as gate  # noqa: E402  (tools/proof_gate.py)
import requirements as reqs  # noqa: E402  (tools/requirements.py)


# ------------------------------------------------------------------------------ summary.json

def wp_totals(run):
    wp = run.sums["wp"]
    if wp is None:
        return None
    return {
        "goals": wp.get("goals", 0), "proved": wp.get("proved", 0),
        "smoke": wp.get("smoke", 0), "smoke_passed": wp.get("smoke_passed", 0),
        "by_prover": wp.get("by_prover", {}), "modules": [m for m, _ in gate.wp_modules(run)],
        "cache_replayed": wp.get("cache_replayed", 0), "cache_fresh": wp.get("cache_fresh", 0),
        "modules_cache": {m: {"replayed": v.get("cache_replayed") or 0,
                              "fresh": v.get("cache_fresh") or 0}
                          for m, v in gate.wp_modules(run)},
        "modules_run": wp.get("modules_run", []),
        "modules_replayed_local": wp.get("modules_replayed_local", []),
        "pass": wp.get("pass"), "smoke_canary": wp.get("smoke_canary"),
        "acsl_forbidden": [{"finding": f, "assumption": a} for f, a in gate.acsl_accepted(run)],
    }


def cbmc_totals(run):
    cb = run.sums["cbmc"]
    if cb is None:
        return None
    ran = [r.get("coverage", 0.0) for r in gate.cbmc_results(run) if not r.get("pending")]
    res = {k: cb.get(k, 0) for k in ("harnesses", "passed", "properties_fresh",
                                     "properties_replayed", "coverage_fresh",
                                     "coverage_replayed")}
    res.update(min_coverage=min(ran or [0.0]), record_mode=cb.get("record_mode", "?"),
               missing_proofs=cb.get("missing_proofs"),
               timeouts=[r.get("function") for r in gate.cbmc_results(run)
                         if gate.cbmc_timeout_text(r)])
    return res


def pick(d, keys):
    return None if d is None else {k: d.get(k, 0) for k in keys}


def selftest_totals(st):
    if st is None:
        return None
    ok = st.get("ok")
    return {"mutants": st.get("mutants", 0), "killed": st.get("killed", 0),
            "ok": ok if isinstance(ok, int) else None}


# tools/prove.sh's mode (build/proof/cache.txt), printed at the top of the report.
MODES = {
    "cold": "cold (make prove-cold): every cache emptied; every WP prover task and every CBMC "
            "property and coverage run made in this run",
    "warm": "warm (make prove): Frama-C on every module from source; prover verdicts reused "
            "only for byte-identical tasks (W4), CBMC verdicts per harness digest (B10), as "
            "counted below",
    "reprove": "reprove (make reprove, a developer shortcut): WP modules and TLC's models "
               "whose inputs are identical to this tree's last run are replayed, not proved; "
               "`make prove` proves all",
}


def build_summary(run, found):
    s = run.sums
    problems = [p for _, ps in found for p in ps]
    trace = pick(s["tla_trace"], ("total", "passed"))
    return {
        "wp": wp_totals(run), "cbmc": cbmc_totals(run),
        "tla": None if s["tla"] is None else {"models": s["tla"].get("total", 0),
                                              "passed": s["tla"].get("passed", 0),
                                              "replayed_local": s["tla"].get("replayed_local")},
        "translator": pick(s["translator"], ("tests", "passed", "failed", "skipped")),
        "selftest": selftest_totals(s["selftest"]),
        "tla_trace": None if trace is None else {"traces": trace["total"],
                                                 "passed": trace["passed"]},
        "tla_trace_all": pick(s["tla_trace_all"], ("total", "passed")),
        "chibios_cbmc": pick(s["chibios_cbmc"], ("harnesses", "passed")),
        "assumptions": run.assumptions, "timing": run.timing,
        "versions": run.versions.splitlines(), "parts": run.parts, "counts": gate.counts(run),
        "mode": run.mode, "mode_text": MODES.get(run.mode, run.mode),
        "problems": problems, "gate": "strict", "ok": not problems,
        "complete": not any(ps for kind, ps in found if kind != "baseline"),
    }


# ------------------------------------------------------------------------------ junit.xml

def testcase(suite, name, ok, msg, secs):
    s = (f'    <testcase classname={sx.quoteattr(suite)} name={sx.quoteattr(str(name))} '
         f'time="{float(secs or 0.0):.2f}">')
    if not ok:
        s += f"<failure message={sx.quoteattr(msg)}/>"
    return s + "</testcase>"


def testsuite(name, cases):
    fails = sum(1 for c in cases if "<failure" in c)
    return (f'  <testsuite name="{name}" tests="{len(cases)}" failures="{fails}">\n'
            + "\n".join(cases) + "\n  </testsuite>")


def wp_rows(wp):
    """(module, function, proved, total, smoke_ok, smoke, seconds) from the WP summary."""
    rows = []
    for mod, m in sorted((wp or {}).get("modules", {}).items()):
        funcs = m.get("functions") or {}
        if not funcs:
            rows.append((mod, "*", m.get("proved", 0), m.get("goals", 0),
                         m.get("smoke_passed", 0), m.get("smoke", 0), m.get("time_s") or 0.0))
        for fn, f in sorted(funcs.items()):
            rows.append((mod, fn, f.get("proved", 0), f.get("goals", 0),
                         f.get("smoke_passed", 0), f.get("smoke", 0), f.get("time_s") or 0.0))
    return rows


def expect_cases(suite, entries):
    return [testcase(suite, e.get("name", "?"), e.get("ok") is True,
                     f"expected {e.get('expect')}, got {e.get('result')}", e.get("seconds", 0.0))
            for e in entries]


def gate_cases(found):
    """One testcase per check: it fails with every problem of its kind."""
    return [testcase("gate", kind, not ps, "\n".join(ps), 0.0) for kind, ps in found]


def wp_cases(run):
    return [testcase("wp." + m, fn, p == t and so == st, f"{p}/{t} goals, {so}/{st} smoke", sec)
            for m, fn, p, t, so, st, sec in wp_rows(run.sums["wp"])]


def cbmc_problem_text(r):
    if r.get("pending"):
        return f"pending, not run: {r['pending']}"
    return gate.cbmc_timeout_text(r) or gate.cbmc_cause(r)


def cbmc_cases(run):
    return [testcase("cbmc", r.get("function", "?"), r.get("passed") is True,
                     cbmc_problem_text(r), r.get("seconds", 0.0)) for r in gate.cbmc_results(run)]


def chibios_cases(c):
    return [testcase("chibios-cbmc", r.get("name", "?"), r.get("passed") is True,
                     f"harness assertions reached {r.get('coverage_reached')}/"
                     f"{r.get('coverage_total')}", r.get("seconds", 0.0))
            for r in c.get("results", [])]


def selftest_cases(st):
    return [testcase("selftest", r.get("id", "?"), gate.mutant_ok(r),
                     str(r.get("reason", "not killed")), r.get("seconds"))
            for r in st.get("results", [])]


def junit(run, found):
    s = run.sums
    groups = [("gate", gate_cases(found)), ("wp", wp_cases(run)), ("cbmc", cbmc_cases(run)),
              ("tla", expect_cases("tla", (s["tla"] or {}).get("models", [])))]
    for key, name in (("tla_trace", "tla-trace-mission"), ("tla_trace_all", "tla-trace")):
        if s[key] is not None:
            groups.append((name, expect_cases(name, s[key].get("traces", []))))
    if s["chibios_cbmc"] is not None:
        groups.append(("chibios-cbmc", chibios_cases(s["chibios_cbmc"])))
    if s["selftest"] is not None:
        groups.append(("selftest", selftest_cases(s["selftest"])))
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<testsuites>\n'
            + "\n".join(testsuite(n, c) for n, c in groups) + "\n</testsuites>\n")


# ------------------------------------------------------------------------------ report.md, console

def cbmc_cell(r):
    if r is None:
        return "-", "-"
    if r.get("pending"):
        return "pending (not run)", "-"
    cov = f"{r.get('coverage', 0):.0f}%"
    if r.get("passed") is True:
        return "pass", cov
    if gate.cbmc_timeout_text(r):
        return "TIMEOUT", cov
    if r.get("failed"):
        return f"FAIL ({r.get('failed')} properties)", cov
    return "FAIL (coverage, witnesses or error)", cov


def function_table(run):
    # a function may be checked by several harnesses, each on part of its clauses (B17)
    cb = {}
    for r in gate.cbmc_results(run):
        cb.setdefault(r.get("contract") or r.get("function"), []).append(r)
    lines = ["| module | function | contract | WP goals | smoke | CBMC | coverage | time (s) |",
             "|---|---|---|---|---|---|---|---|"]
    for m, fn, p, t, so, st, sec in wp_rows(run.sums["wp"]):
        rs = cb.get(fn) or [None]
        cells = [cbmc_cell(r) for r in rs]
        cres = cells[0][0]
        if len(rs) > 1:
            cres = f"pass ({len(rs)} harnesses)" if all(c == "pass" for c, _ in cells) else \
                "; ".join(f"{r.get('function')}: {c}" for r, (c, _) in zip(rs, cells))
        cov = min((c for _, c in cells), key=lambda c: float(c.rstrip("%")) if c != "-" else -1)
        secs = sec + sum(float(r.get("seconds", 0.0)) for r in rs if r is not None)
        lines.append(f"| {m} | {fn} | yes | {p}/{t} | {so}/{st} | {cres} | {cov} | {secs:.1f} |")
    return "\n".join(lines)


def part_lines(run):
    if run.parts is None:
        return ["no parts.json: the summaries of an earlier run (the report was run alone)"]
    lines = []
    for part, e in run.parts.items():
        e = e if isinstance(e, dict) else {}
        lane = f" (lane {e['lane']})" if e.get("lane") else ""
        lines.append(f"make {part}: exit {e.get('rc', '?')}, {e.get('seconds', '?')} s{lane}")
    return lines


def wp_cache_lines(summary):
    """Per module: prover verdicts replayed from the WP cache and fresh ones."""
    w = summary["wp"]
    if not w:
        return []
    return [f"{m}: {c['replayed']} prover verdicts replayed from the WP cache, {c['fresh']} "
            "fresh" for m, c in sorted(w["modules_cache"].items())]


def names(items):
    return ", ".join(items) or "none"


def wp_md(w):
    md = [f"- Frama-C WP (RTE, unsigned overflow/downcast, smoke tests): {w['proved']}/"
          f"{w['goals']} goals, {w['smoke_passed']}/{w['smoke']} smoke tests; by prover: "
          f"{json.dumps(w['by_prover'], sort_keys=True)}; smoke canary: {w['smoke_canary']}",
          f"- WP modules: {len(w['modules_run'])} run by Frama-C in this run, every VC generated "
          f"from the current source ({names(w['modules_run'])})"]
    if w["modules_replayed_local"]:
        md.append(f"- WP modules replayed, NOT proved in this run (make reprove: inputs identical "
                  f"to this tree's last run): {names(w['modules_replayed_local'])}")
    md += [
          f"- WP prover results of the modules run: {w['cache_fresh']} from provers run in this "
          f"run, {w['cache_replayed']} replayed from the WP cache (verdicts of byte-identical "
          "prover tasks recorded in proofs/wp/cache; assumption W4; `make prove WP_CACHE=none` "
          "runs every prover)"]
    for f in w["acsl_forbidden"]:
        md.append(f"- ACSL keyword finding {f['finding']}: "
                  + (f"accepted by assumption {f['assumption']}" if f["assumption"]
                     else "NOT accepted by any assumption"))
    return md


def cbmc_md(c):
    return [f"- CBMC: {c['passed']}/{c['harnesses']} harnesses, lowest coverage of a harness "
            f"run {c['min_coverage']:.1f}%; property verdicts: {c['properties_fresh']} from "
            f"property runs made now, {c['properties_replayed']} replayed; coverage verdicts: "
            f"{c['coverage_fresh']} from coverage runs made now, {c['coverage_replayed']} "
            "replayed. Replayed verdicts come from proofs/cbmc/records.json, for byte-identical "
            "preprocessed inputs, options and tool versions (assumption B10; "
            f"CBMC_RECORD={c['record_mode']}; `make prove CBMC_RECORD=properties` runs every "
            "property run, `CBMC_RECORD=fresh` every run)"]


def totals_md(summary):
    md = wp_md(summary["wp"]) if summary["wp"] else []
    md += cbmc_md(summary["cbmc"]) if summary["cbmc"] else []
    return md + other_totals_md(summary)


def other_totals_md(summary):
    md = []
    t = summary["tla"]
    if t:
        md.append(f"- TLC: {t['passed']}/{t['models']} model configurations as expected"
                  + (f"; REPLAYED from this tree's run of {t['replayed_local']} (identical "
                     "inputs), not checked now" if t.get("replayed_local") else ""))
    t = summary["tla_trace"]
    if t:
        md.append(f"- Trace validation (mission*.c against Mission): {t['passed']}/{t['traces']} "
                  "traces accepted and controls rejected as expected")
    t = summary["tla_trace_all"]
    if t:
        md.append(f"- Trace validation (`make tla-trace`: ring, semaphore and mission traces): "
                  f"{t['passed']}/{t['total']} as expected")
    t = summary["translator"]
    if t:
        md.append(f"- Translator tests (`make cbmc-test`: sample contract, unsupported constructs, "
                  f"one mutated kernel ensures rejected by both CBMC and WP): {t['passed']}/"
                  f"{t['tests']} passed")
    t = summary["chibios_cbmc"]
    if t:
        md.append(f"- ChibiOS port CBMC (`make chibios-cbmc`): {t['passed']}/{t['harnesses']} "
                  "harnesses passed")
    t = summary["selftest"]
    if t:
        done = t["killed"] if t["ok"] is None else t["ok"]
        md.append(f"- Mutation check: {done}/{t['mutants']} seeded bugs rejected as required")
    if summary["timing"]:
        md.append("- Wall time: " + ", ".join(f"{k} {float(v):.0f} s"
                                             for k, v in sorted(summary["timing"].items())))
    return md


def tla_md(run):
    tla = run.sums["tla"]
    if not tla:
        return []
    md = ["## TLA+ models", "",
          "| model | config | expected | result | distinct states | time (s) |",
          "|---|---|---|---|---|---|"]
    for m in tla.get("models", []):
        result = "as expected" if m.get("ok") is True else "UNEXPECTED"
        md.append(f"| {m.get('module', m.get('name'))} | {m.get('config', '')} | "
                  f"{m.get('expect', '')} | {result} | {m.get('distinct_states', '')} | "
                  f"{m.get('seconds', '')} |")
    return md + [""]


def assumptions_md(run):
    md = ["## Assumptions", "",
          "Every fact the proofs take without proving it. Each is a reviewable trust point.", "",
          "| id | tool | assumption | reason |", "|---|---|---|---|"]
    for a in run.assumptions:
        sites = f" ACSL sites: {', '.join(a['acsl_sites'])}." if a.get("acsl_sites") else ""
        md.append(f"| {a.get('id')} | {a.get('tool')} | {a.get('what')}{sites} | {a.get('why')} |")
    return md


def report_md(run, summary, table):
    verdict = "everything proved" if summary["ok"] else "PROVE FAILED"
    if summary["ok"] and summary.get("shard"):
        verdict = f"shard {summary['shard']}: partial, everything it ran proved"
    md = ["# Metronome proof report", "", f"Result: **{verdict}** (strict gate)", "",
          f"Run: {summary['mode_text']}", ""]
    md += [f"- {p}" for p in summary["problems"]]
    if run.versions:
        md += ["", "## Tools", "", "```", run.versions, "```"]
    md += ["", "## Parts", ""] + [f"- {x}" for x in part_lines(run)]
    md += ["", "## Totals", ""] + totals_md(summary)
    cache = wp_cache_lines(summary)
    if cache:
        md += ["", "## WP cache per module", ""] + [f"- {x}" for x in cache]
    md += ["", "## Per function", "", table, ""] + trace_md(run) + tla_md(run) + \
        assumptions_md(run)
    return "\n".join(md) + "\n"


def trace_md(run):
    """The traceability matrix: each requirement of proofs/requirements.json with the contract
    clauses (proved by WP), tests and TLA+ properties that discharge it."""
    trace = (run.sums["wp"] or {}).get("requirements")
    if not trace:
        return []
    good = sum(r.get("ok") is True for r in trace)
    return ["## Traceability", "",
            f"{good} of {len(trace)} requirements discharged (proofs/requirements.json; every "
            "named clause proved by WP in this run, every test and model present and checked).",
            ""] + reqs.matrix_lines(trace) + [""]


def console(run, summary, table):
    print(table)
    print()
    for line in part_lines(run):
        print(line)
    for line in wp_cache_lines(summary):
        print("wp cache " + line)
    for k, v in sorted(summary["counts"].items()):
        print(f"{k:22s} {v}")
    trace = (run.sums["wp"] or {}).get("requirements")
    if trace:
        print(f"requirements: {sum(r.get('ok') is True for r in trace)}/{len(trace)} discharged "
              "(matrix in the report)")
    print(f"run: {summary['mode_text']}")
    print(f"report: {run.build}/proof/report.md, {run.build}/proof/summary.json, "
          f"{run.build}/proof/junit.xml")
    if summary["problems"]:
        print(f"PROVE FAILED: {len(summary['problems'])} problem(s) (strict gate):")
        for p in summary["problems"]:
            print("  - " + p)
        return 1
    if summary.get("shard"):
        for p in summary["waived"]:
            print(f"  left to the merge: {p}")
        print(f"PROVE OK: shard {summary['shard']}: partial: everything this shard ran passed "
              "(the verdict is the merge's: make prove-merge)")
        return 0
    replayed = [f"WP {m}" for m in (summary["wp"] or {}).get("modules_replayed_local") or []]
    if (summary["tla"] or {}).get("replayed_local"):
        replayed.append("TLC's models")
    if replayed:
        print(f"REPROVE OK: everything run passed the strict gate; replayed from this tree's "
              f"last run, not proved now: {', '.join(replayed)} (make prove proves all)")
        return 0
    print(f"PROVE OK: everything proved (strict gate, {run.mode})")
    return 0


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--default-parts", default="",
                    help="tools/prove.sh's default part list (default: every required part)")
    ap.add_argument("--assumptions", default="proofs/assumptions.json")
    ap.add_argument("--baseline", default="proofs/baseline.json")
    ap.add_argument("--shard", default="", help="i/N: the report of one shard (partial)")
    return ap.parse_args(argv)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    mode = os.environ.get("PROVE_GATE", "")
    if mode not in ("", "full"):
        print(f"warning: PROVE_GATE={mode} is ignored: there is one strict gate "
              "(proofs/baseline.json is only a floor)", flush=True)
    run = gate.Run(os.environ.get("BUILD", "build"),
                   args.default_parts.split() if args.default_parts else None,
                   args.assumptions, args.baseline)
    found = gate.run_checks(run)
    waived = []
    if args.shard:
        found, waived = gate.waive_for_shard(found, args.shard)
    summary = build_summary(run, found)
    if args.shard:
        summary.update(shard=args.shard, partial=True, complete=False,
                       waived=[p for _, ps in waived for p in ps])
    os.makedirs(run.out, exist_ok=True)
    write(os.path.join(run.out, "summary.json"),
          json.dumps(summary, indent=2, sort_keys=True) + "\n")
    write(os.path.join(run.out, "junit.xml"), junit(run, found))
    table = function_table(run)
    write(os.path.join(run.out, "report.md"), report_md(run, summary, table))
    return console(run, summary, table)


if __name__ == "__main__":
    sys.exit(main())
