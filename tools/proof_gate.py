#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The strict gate of `make prove`: read what the proof parts wrote, list every problem.

Used by tools/proof_report.py (which writes the reports and exits with the gate's verdict);
python3 stdlib only. Inputs, under $BUILD/proof/ ($BUILD: default build; an absolute path is
used as it is):
  parts.json                     exit status, wall seconds and start time of each part that
                                 tools/prove.sh ran ({"wp": {"rc": 0, "seconds": 12.3}, ...})
  wp/summary.json                Frama-C WP (proofs/wp/gate.py)
  cbmc/summary.json              CBMC harnesses (proofs/cbmc/run.py)
  cbmc/test/summary.json         translator tests (make cbmc-test)
  tla/summary.json               TLC models (tla/run_tlc.py)
  tla/trace-mission/summary.json mission trace validation (make tla-trace-mission)
  tla/trace/summary.json         ring, semaphore and mission traces (make tla-trace), if present
  hal_chibios/cbmc-summary.json  the ChibiOS port's CBMC proofs (make chibios-cbmc), if present
  selftest/summary.json          mutation check (tools/prove_selftest.py), if present
and proofs/assumptions.json (an entry's "acsl_sites", "<path>:<keyword>:<name or line>",
accept WP's ACSL keyword findings in that file, matched on path and keyword) and
proofs/baseline.json (committed counts: a floor, always checked).

A problem is: a part that exited non-zero; a required or run part without a readable summary
(required: wp, cbmc, cbmc-test, tla, tla-trace-mission, all of them without parts.json, else
those in tools/prove.sh's default part list), or with a summary older than the part's run; a WP
goal not proved, a smoke test not passed, the WP gate's own verdict false, an ACSL keyword
finding no assumption accepts, a smoke canary not run or not as expected, a module with log
findings or listed failures; a CBMC harness failed, timed out or pending, a public function
without a harness, no harness at all; a translator test, TLC model, trace, ChibiOS harness or
selected mutant not as expected; a requirement of proofs/requirements.json not discharged (or
no matrix); a count below the baseline. One function per check, in the
table CHECKS; each returns the problems it found, naming the goal, harness, model or part.
"""
import json
import os
import re

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SHOW = 5                      # failures listed per module, harness or summary
COVERAGE_MIN = 90.0           # proofs/cbmc/run.py's coverage threshold (only to name the cause)
CANARY_RE = re.compile(r"^wp-canary: \d+ functions as expected")
FINDING_RE = re.compile(r"^(?P<path>[^:]+):(?P<line>\d+): ACSL keyword '(?P<kw>\w+)'")

# Summary files, by key, under $BUILD/proof/.
SUMMARIES = {
    "wp": "wp/summary.json",
    "cbmc": "cbmc/summary.json",
    "translator": "cbmc/test/summary.json",
    "tla": "tla/summary.json",
    "tla_trace": "tla/trace-mission/summary.json",
    "tla_trace_all": "tla/trace/summary.json",
    "chibios_cbmc": "hal_chibios/cbmc-summary.json",
    "cbmc_max": "cbmc/summary-max.json",
    "selftest": "selftest/summary.json",
}
# The make target of each part -> the summary it writes.
PART_SUMMARY = {
    "wp": "wp", "cbmc": "cbmc", "cbmc-test": "translator", "tla": "tla",
    "tla-trace-mission": "tla_trace", "tla-trace": "tla_trace_all",
    "chibios-cbmc": "chibios_cbmc", "chibios-prove": "chibios_cbmc",
    "prove-selftest": "selftest", "prove-selftest-ci": "selftest", "cbmc-max": "cbmc_max",
}
REQUIRED = ("wp", "cbmc", "cbmc-test", "tla", "tla-trace-mission")


# ------------------------------------------------------------------------------ inputs

def read_json(path):
    """(value, None); (None, None) when the file is absent; (None, why) when unreadable."""
    if not os.path.exists(path):
        return None, None
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f), None
    except (OSError, UnicodeDecodeError, ValueError) as e:
        return None, f"{type(e).__name__}: {e}"


def read_object(path):
    """read_json, and the value must be a JSON object."""
    value, why = read_json(path)
    if value is not None and not isinstance(value, dict):
        return None, "not a JSON object"
    return value, why


def read_text(path):
    if not os.path.exists(path):
        return ""
    with open(path, encoding="utf-8") as f:
        return f.read().strip()


class Run:
    """What the checks read: the part statuses, the summaries and the committed lists.

    build: the build folder (relative to the repository, or absolute); default_parts:
    tools/prove.sh's default part list (None: every required part); assumptions, baseline:
    the committed lists, relative to the repository (or absolute)."""

    def __init__(self, build, default_parts=None, assumptions="proofs/assumptions.json",
                 baseline="proofs/baseline.json"):
        self.build = build
        self.out = os.path.join(ROOT, build, "proof")
        self.parts, self.parts_error = read_object(os.path.join(self.out, "parts.json"))
        self.default_parts = list(REQUIRED) if default_parts is None else list(default_parts)
        self.sums, self.unreadable = {}, {}
        for key, rel in SUMMARIES.items():
            self.sums[key], why = read_object(os.path.join(self.out, rel))
            if why:
                self.unreadable[key] = why
        self.assumptions_path, self.baseline_path = assumptions, baseline
        items, self.assumptions_error = read_json(os.path.join(ROOT, assumptions))
        if items is not None and not isinstance(items, list):
            items, self.assumptions_error = None, "not a JSON list"
        self.assumptions = items or []
        self.baseline, self.baseline_error = read_object(os.path.join(ROOT, baseline))
        self.baseline = self.baseline or {}
        self.timing = read_object(os.path.join(self.out, "timing.json"))[0] or {}
        self.versions = read_text(os.path.join(self.out, "versions.txt"))
        # tools/prove.sh's mode: cold (make prove-cold), warm (make prove), reprove.
        self.mode = (read_text(os.path.join(self.out, "cache.txt")) or "").strip() or "warm"

    def path(self, key):
        return os.path.join(self.build, "proof", SUMMARIES[key])

    def expected(self):
        """Summary keys that must be there: those of the parts that ran, and the required
        parts (all of them without parts.json, else those of the default part list)."""
        ran = list(self.parts or {})
        needed = REQUIRED if self.parts is None else \
            [p for p in REQUIRED if p in self.default_parts]
        return [PART_SUMMARY[p] for p in dict.fromkeys(list(needed) + ran) if p in PART_SUMMARY]


def first(items, n=SHOW):
    """The first n items as text, and how many more there are."""
    items = list(items)
    more = f" (and {len(items) - n} more)" if len(items) > n else ""
    return "; ".join(str(x) for x in items[:n]) + more


# ------------------------------------------------------------------------------ parts

def check_part_status(run):
    if run.parts_error:
        return [f"{run.build}/proof/parts.json unreadable: {run.parts_error}"]
    bad = []
    for part, entry in (run.parts or {}).items():
        rc = entry.get("rc") if isinstance(entry, dict) else None
        if not isinstance(rc, int) or isinstance(rc, bool):
            bad.append(f"part {part}: no exit status in parts.json")
        elif rc != 0:
            bad.append(f"part {part}: make {part} exited with status {rc}")
    return bad


def check_summaries_present(run):
    bad = []
    targets = {v: k for k, v in PART_SUMMARY.items() if k != "chibios-prove"}
    for key in run.expected():
        if run.sums[key] is None and key not in run.unreadable:
            bad.append(f"part {targets[key]}: summary {run.path(key)} missing "
                       f"(make {targets[key]} did not run or did not finish)")
    for key, why in sorted(run.unreadable.items()):
        bad.append(f"part {targets[key]}: summary {run.path(key)} unreadable: {why}")
    return bad


def check_committed_lists(run):
    """The assumptions (listed in the report, accepting ACSL findings) and the baseline floor
    must be readable: without them the report would certify less than it says."""
    bad = []
    if run.assumptions_error:
        bad.append(f"{run.assumptions_path} unreadable: {run.assumptions_error}")
    if run.baseline_error:
        bad.append(f"{run.baseline_path} unreadable: {run.baseline_error}")
    for a in run.assumptions:
        bad += [f"{run.assumptions_path}: {a.get('id', '?')}: acsl_sites entry {site!r} is not "
                "\"<path>:<keyword>:<name or line>\"" for site in a.get("acsl_sites") or []
                if len(str(site).rsplit(":", 2)) != 3]
    return bad


def check_summaries_fresh(run):
    """A part that ran must have written its summary during this run (parts.json "started")."""
    bad = []
    for part, entry in (run.parts or {}).items():
        key = PART_SUMMARY.get(part)
        started = entry.get("started") if isinstance(entry, dict) else None
        if key is None or run.sums[key] is None or not isinstance(started, (int, float)):
            continue
        if os.path.getmtime(os.path.join(ROOT, run.path(key))) < started - 2.0:
            bad.append(f"part {part}: summary {run.path(key)} is older than this run of "
                       f"make {part} (stale: the part did not write it)")
    return bad


# ------------------------------------------------------------------------------ WP

def check_requirements(run):
    """The traceability matrix (tools/requirements.py, written into the WP summary by the
    full-module WP gate): present, and every requirement discharged."""
    wp = run.sums["wp"]
    if wp is None:
        return []
    trace = wp.get("requirements")
    if not isinstance(trace, list) or not trace:
        return [f"traceability: no requirements matrix in {run.path('wp')} (make wp checks "
                "proofs/requirements.json over the whole module set)"]
    bad = []
    for r in trace:
        if r.get("ok") is not True:
            bad += [f"traceability: requirement {r.get('id', '?')}: {p}"
                    for p in (r.get("problems") or ["not discharged"])]
    return bad


def wp_modules(run):
    return sorted(((run.sums["wp"] or {}).get("modules") or {}).items())


def count_problem(label, done, total, what):
    return [] if total and done == total else [f"{label}: {done}/{total} {what}"]


def check_wp_goals(run):
    wp = run.sums["wp"]
    if wp is None:
        return []
    bad = count_problem("WP", wp.get("proved", 0), wp.get("goals", 0), "goals proved")
    for mod, m in wp_modules(run):
        bad += count_problem(f"WP module {mod}", m.get("proved", 0), m.get("goals", 0),
                             "goals proved")
    return bad


def check_wp_smoke(run):
    wp = run.sums["wp"]
    if wp is None:
        return []
    done, total = wp.get("smoke_passed", 0), wp.get("smoke", 0)
    bad = [] if done == total else [
        f"WP: {done}/{total} smoke tests passed (a smoke test that is proved means a "
        "contradictory precondition or dead code)"]
    for mod, m in wp_modules(run):
        if m.get("smoke_passed", 0) != m.get("smoke", 0):
            bad.append(f"WP module {mod}: {m.get('smoke_passed', 0)}/{m.get('smoke', 0)} "
                       "smoke tests passed")
    return bad


def check_wp_gate(run):
    wp = run.sums["wp"]
    if wp is None or wp.get("pass") is True:
        return []
    return [f"WP: the WP gate did not pass (pass: {json.dumps(wp.get('pass'))} in "
            f"{run.path('wp')}; proofs/wp/gate.py)"]


def acsl_sites(assumptions):
    """{(path, keyword): assumption id} from the "acsl_sites" of the assumptions."""
    sites = {}
    for a in assumptions:
        for site in a.get("acsl_sites") or []:
            parts = str(site).rsplit(":", 2)
            if len(parts) == 3:
                sites[(parts[0], parts[1])] = a.get("id", "?")
    return sites


def acsl_accepted(run):
    """[(finding, assumption id or None)] for the ACSL keyword findings of the WP gate."""
    sites = acsl_sites(run.assumptions)
    res = []
    findings = (run.sums["wp"] or {}).get("acsl_forbidden")
    for finding in findings if isinstance(findings, list) else []:
        m = FINDING_RE.match(str(finding))
        res.append((finding, sites.get((m["path"], m["kw"])) if m else None))
    return res


def check_wp_acsl(run):
    wp = run.sums["wp"]
    if wp is None:
        return []
    if not isinstance(wp.get("acsl_forbidden"), list):
        return [f"WP: no ACSL keyword scan (acsl_forbidden) in {run.path('wp')}"]
    return [f"WP: {finding} is not accepted by an assumption (proofs/assumptions.json "
            "acsl_sites: \"<path>:<keyword>:<name>\")"
            for finding, aid in acsl_accepted(run) if aid is None]


def check_wp_canary(run):
    wp = run.sums["wp"]
    if wp is None:
        return []
    canary = str(wp.get("smoke_canary", "not recorded"))
    if CANARY_RE.match(canary):
        return []
    return [f"WP smoke canary: {canary} (expected 'wp-canary: N functions as expected'; "
            "make wp-canary, proofs/wp/canary/)"]


def check_wp_log(run):
    return [f"WP module {mod}: log: {first(m['fatal'])}"
            for mod, m in wp_modules(run) if m.get("fatal")]


def check_wp_replayed(run):
    """A module replayed from this tree's last run (not run by Frama-C now) is allowed only in
    `make reprove`, whose report says so; `make prove` and CI prove every module."""
    if run.mode == "reprove":
        return []
    return [f"WP module {mod}: replayed from a local run, not proved in this {run.mode} run"
            for mod, m in wp_modules(run) if m.get("replayed_local")]


def check_wp_failures(run):
    """The goals the WP gate lists: unproved goals, and smoke tests that were proved."""
    return [f"WP module {mod}: goal not proved or smoke test failed: "
            + first(str(x).split(" {")[0] for x in m["failures"])
            for mod, m in wp_modules(run) if m.get("failures")]


# ------------------------------------------------------------------------------ CBMC

def cbmc_results(run):
    return (run.sums["cbmc"] or {}).get("results") or []


def cbmc_timeout_text(r):
    """The timeout line of a harness killed by run.py's timer, or None."""
    for line in str(r.get("error", "")).splitlines():
        if line.startswith("timeout: killed after"):
            return line
    return "timeout: killed" if r.get("timeout") is True else None


def cbmc_cause(r):
    """Why a harness that is not pending and did not time out did not pass."""
    if r.get("failed"):
        props = [f"{x.get('property')} ({x.get('description', '')})" for x in r.get("failures", [])]
        return f"failed property: {first(props) or str(r['failed']) + ' failed'}"
    if r.get("error"):
        return "error: " + str(r["error"]).strip().splitlines()[-1][:200]
    unreached = [x.get("witness") for x in r.get("reach", []) if not x.get("reached")]
    if unreached:
        return f"witness not reached: {first(unreached)}"
    if r.get("coverage", 0.0) < COVERAGE_MIN:
        return f"coverage {r.get('coverage', 0.0)}% below {COVERAGE_MIN:.0f}%"
    return "not passed"


def check_cbmc_count(run):
    cb = run.sums["cbmc"]
    if cb is None:
        return []
    return count_problem("CBMC", cb.get("passed", 0), cb.get("harnesses", 0), "harnesses passed")


def check_cbmc_failed(run):
    return [f"CBMC harness {r.get('function', '?')}: {cbmc_cause(r)}" for r in cbmc_results(run)
            if r.get("passed") is not True and not r.get("pending") and not cbmc_timeout_text(r)]


def check_cbmc_timeout(run):
    return [f"CBMC harness {r.get('function', '?')}: timeout ({cbmc_timeout_text(r)})"
            for r in cbmc_results(run)
            if r.get("passed") is not True and not r.get("pending") and cbmc_timeout_text(r)]


def check_cbmc_pending(run):
    return [f"CBMC harness {r.get('function', '?')}: pending, not run ({r['pending']}; "
            "proofs/cbmc/pending.json)" for r in cbmc_results(run)
            if r.get("passed") is not True and r.get("pending")]


def check_cbmc_missing(run):
    cb = run.sums["cbmc"]
    if cb is None:
        return []
    missing = cb.get("missing_proofs")
    if not isinstance(missing, list):
        return [f"CBMC: no missing_proofs list in {run.path('cbmc')}"]
    bad = [f"CBMC: public function {f} has a contract but no harness (proofs/cbmc/proofs/{f}/)"
           for f in missing]
    unchecked = cb.get("clauses_unchecked")
    if not isinstance(unchecked, list):
        return bad + [f"CBMC: no clauses_unchecked list in {run.path('cbmc')}"]
    return bad + [f"CBMC: contract clause {u}" for u in unchecked]


# ------------------------------------------------------------------------------ the others

def check_translator(run):
    t = run.sums["translator"]
    if t is None:
        return []
    bad = count_problem("translator tests (make cbmc-test)", t.get("passed", 0),
                        t.get("tests", 0), "passed")
    if bad and t.get("not_passed"):
        bad[0] += f": not passed: {first(t['not_passed'])}"
    return bad


def check_tla(run):
    t = run.sums["tla"]
    if t is None:
        return []
    bad = count_problem("TLC", t.get("passed", 0), t.get("total", 0), "models as expected")
    return bad + [f"TLC model {m.get('name', '?')}: expected {m.get('expect')}, got "
                  f"{m.get('result')}" + (f" ({m['problem']})" if m.get("problem") else "")
                  for m in t.get("models", []) if m.get("ok") is not True]


def check_tla_replayed(run):
    """TLC's summary kept from this tree's last run (identical inputs) is allowed only in `make
    reprove`, whose report says so; `make prove` and CI check every model."""
    t = run.sums["tla"]
    if run.mode == "reprove" or t is None or not t.get("replayed_local"):
        return []
    return [f"TLC: models replayed from the local run of {t['replayed_local']}, not checked in "
            f"this {run.mode} run"]


def trace_problems(t, label):
    if t is None:
        return []
    bad = count_problem(f"trace validation ({label})", t.get("passed", 0), t.get("total", 0),
                        "traces and controls as expected")
    return bad + [f"trace validation ({label}) {r.get('name', '?')}: expected {r.get('expect')}, "
                  f"got {r.get('result')}" for r in t.get("traces", []) if r.get("ok") is not True]


def check_trace_mission(run):
    return trace_problems(run.sums["tla_trace"], "make tla-trace-mission")


def check_trace_all(run):
    return trace_problems(run.sums["tla_trace_all"], "make tla-trace")


def harness_problems(summary, label, name_key, cause):
    """A harness summary ({"harnesses", "passed", "results"}) that is present: its count and
    every harness not passed, named by name_key, with cause(result)."""
    if summary is None:
        return []
    bad = count_problem(label, summary.get("passed", 0), summary.get("harnesses", 0),
                        "harnesses passed")
    return bad + [f"{label} harness {r.get(name_key, '?')}: {cause(r)}"
                  for r in summary.get("results") or [] if r.get("passed") is not True]


def check_chibios(run):
    return harness_problems(run.sums["chibios_cbmc"], "ChibiOS port CBMC", "name",
                            lambda r: f"not passed (harness assertions reached "
                                      f"{r.get('coverage_reached')}/{r.get('coverage_total')})")


def check_cbmc_max(run):
    return harness_problems(run.sums["cbmc_max"], "CBMC capacity-maximum tier", "function",
                            cbmc_cause)


def mutant_ok(r):
    """A mutant is as its entry says: "ok" (new format) or "killed" (old) true, applied."""
    if r.get("ok") is False or r.get("killed") is False or r.get("applied") is False:
        return False
    return r.get("ok") is True or r.get("killed") is True


def check_selftest(run):
    s = run.sums["selftest"]
    if s is None:
        return []
    results = s.get("results") or []
    done = s.get("ok", s.get("killed", 0))
    bad = count_problem("mutation check", done if isinstance(done, int) else 0,
                        s.get("mutants", 0), "mutants rejected as required")
    if not results:
        bad.append("mutation check: no mutant result in the summary")
    return bad + [f"mutation check: mutant {r.get('id', '?')} ({r.get('function', '?')}) not "
                  f"rejected as required: {r.get('reason', 'not killed')}"
                  for r in results if not mutant_ok(r)]


def counts(run):
    """The counts compared with the baseline floor."""
    s = run.sums
    c = {
        "wp.proved": (s["wp"] or {}).get("proved", 0),
        "wp.smoke_passed": (s["wp"] or {}).get("smoke_passed", 0),
        "cbmc.passed": (s["cbmc"] or {}).get("passed", 0),
        "tla.passed": (s["tla"] or {}).get("passed", 0),
        "translator.passed": (s["translator"] or {}).get("passed", 0),
        "tla_trace.passed": (s["tla_trace"] or {}).get("passed", 0),
    }
    if s["selftest"] is not None:
        c["selftest.killed"] = s["selftest"].get("killed", 0)
    if s["tla_trace_all"] is not None:
        c["tla_trace_all.passed"] = s["tla_trace_all"].get("passed", 0)
    if s["chibios_cbmc"] is not None:
        c["chibios_cbmc.passed"] = s["chibios_cbmc"].get("passed", 0)
    return c


def check_baseline(run):
    c = counts(run)
    return [f"baseline: {key} = {c[key]} < {base} (floor in {run.baseline_path})"
            for key, base in sorted(run.baseline.items())
            if key in c and isinstance(base, int) and c[key] < base]


# (kind, check): every kind is one testcase of the junit "gate" suite.
CHECKS = [
    ("part-status", check_part_status),
    ("summary-present", check_summaries_present),
    ("summary-fresh", check_summaries_fresh),
    ("committed-lists", check_committed_lists),
    ("wp-goals", check_wp_goals),
    ("wp-smoke", check_wp_smoke),
    ("wp-gate", check_wp_gate),
    ("wp-acsl", check_wp_acsl),
    ("wp-canary", check_wp_canary),
    ("wp-log", check_wp_log),
    ("wp-replayed", check_wp_replayed),
    ("wp-failures", check_wp_failures),
    ("traceability", check_requirements),
    ("cbmc-count", check_cbmc_count),
    ("cbmc-failed", check_cbmc_failed),
    ("cbmc-timeout", check_cbmc_timeout),
    ("cbmc-pending", check_cbmc_pending),
    ("cbmc-missing-proof", check_cbmc_missing),
    ("translator", check_translator),
    ("tla", check_tla),
    ("tla-replayed", check_tla_replayed),
    ("tla-trace-mission", check_trace_mission),
    ("tla-trace", check_trace_all),
    ("chibios-cbmc", check_chibios),
    ("cbmc-max", check_cbmc_max),
    ("selftest", check_selftest),
    ("baseline", check_baseline),
]


def run_checks(run):
    return [(kind, check(run)) for kind, check in CHECKS]


# A shard of a sharded run (PROVE_SHARD=i/N, tools/prove_shard.py) proves part of the work, and
# the merge's report judges the whole. In a shard's own report these checks are left to the
# merge: the baseline floor (counts of the whole run) and the traceability matrix (clauses of
# every module) in every shard; the smoke canary and the
# WP gate's own verdict in every shard but the first (the canary runs in shard 1 only, and
# proofs/wp/gate.py fails without it; every other item of its verdict is a check here:
# wp-goals, wp-smoke, wp-log, wp-failures, wp-acsl).
SHARD_WAIVED = ("baseline", "traceability")
SHARD_WAIVED_AFTER_FIRST = ("wp-canary", "wp-gate")


def waive_for_shard(found, shard):
    """(found with the waived kinds emptied, [(kind, problems)] waived) for shard "i/N"."""
    kinds = SHARD_WAIVED + (SHARD_WAIVED_AFTER_FIRST if shard.split("/")[0] != "1" else ())
    return ([(k, [] if k in kinds else ps) for k, ps in found],
            [(k, ps) for k, ps in found if k in kinds and ps])
