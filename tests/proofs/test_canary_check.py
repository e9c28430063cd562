# SPDX-License-Identifier: Apache-2.0
"""proofs/wp/canary/check.py, the judge of `make wp-canary`, on synthetic WP logs shaped like
build/proof/wp/canary/wp.log: every seeded contradiction caught and every control clean, then
one change per way to fail (a contradiction missed, a control with a failed smoke test or an
unproved goal, a function absent from the log, a failed dead-call smoke test inside a control,
a log cut short). Each failing case asserts exit status 1, that the culprit is named, and that
the last line no longer carries the prefix the WP gate requires. No prover runs.

    /usr/bin/python3 -m pytest -q tests/proofs/test_canary_check.py
"""
import importlib.util
import json
import os
import re
import subprocess
import sys

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
CHECK = os.path.join(ROOT, "proofs", "wp", "canary", "check.py")
SRC = os.path.join(ROOT, "proofs", "wp", "canary", "smoke_canary.c")
SRC_REL = "proofs/wp/canary/smoke_canary.c"
GATE_RE = re.compile(r"^wp-canary: \d+ functions as expected")  # proofs/wp/gate.py


def load_check():
    spec = importlib.util.spec_from_file_location("canary_check", CHECK)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


C = load_check()
SEEDED = [name for name, _, expect in C.EXPECT if expect == C.CAUGHT]
CONTROLS = [name for name, _, expect in C.EXPECT if expect == C.CLEAN]


def line_of(fn, text):
    """Source line of `text` inside function fn of the real canary source."""
    with open(SRC, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for name, first, last in C.source_functions(SRC):
        if name == fn:
            for n in range(first, last + 1):
                if text in lines[n - 1]:
                    return n
    raise AssertionError(f"{text!r} not found in {fn}")


def smoke_failed(name, line, qed=False):
    """A failed smoke test as WP 25 prints it (twice when Qed closed it)."""
    if qed:
        once = [f"[wp] [Failed] Smoke-test typed_{name}", "       Qed: Valid (0.97ms)",
                f"[wp] {SRC_REL}:{line}: Warning: Failed smoke-test"]
        return once + once
    return [f"[wp] [Failed] Smoke-test typed_{name}",
            "  Z3 4.8.12 (fixedTO): Unknown (Qed:2ms)",
            "  CVC4 1.8: Valid (Qed:2ms) (70ms) (15236)",
            f"[wp] {SRC_REL}:{line}: Warning: Failed smoke-test"]


def smoke_passed(name):
    return [f"[wp] [Passed] Smoke-test typed_{name}"]


def goal(name, ok=True):
    if ok:
        return [f"[wp] [Z3 4.8.12 (fixedTO)] Goal typed_{name} : Valid (Qed:3ms) (30ms) (96471)"]
    return [f"[wp] [Failed] Goal typed_{name}",
            "  Z3 4.8.12 (fixedTO): Timeout (Qed:20ms) (20s)",
            "  CVC4 1.8: Timeout (Qed:20ms) (20s)"]


def records(caught=True, clean=True):
    """{function: [log lines]} of one function as a good run prints it."""
    out = {}
    for fn in SEEDED:
        line = line_of(fn, f"{fn}(")
        out[fn] = (smoke_failed(f"{fn}_wp_smoke_default_requires", line, qed=fn.endswith("null"))
                   if caught else smoke_passed(f"{fn}_wp_smoke_default_requires"))
        out[fn] += goal(f"{fn}_assigns")
    for fn in CONTROLS:
        out[fn] = (smoke_passed(f"{fn}_wp_smoke_default_requires") if clean else
                   smoke_failed(f"{fn}_wp_smoke_default_requires", line_of(fn, f"{fn}(")))
        out[fn] += goal(f"{fn}_ensures") + goal(f"{fn}_assigns")
    # The port calls: dead-call smoke tests are named after the callee. In the seeded lock
    # canary they fail (located at the call); in the lock control they pass (no location).
    out["canary_lock_class"] += smoke_failed(
        "mt_port_unlock_wp_smoke_dead_call_s42", line_of("canary_lock_class", "mt_port_unlock();"))
    out["control_lock_class"] += smoke_passed("mt_port_lock_wp_smoke_dead_call_s64")
    return out


def render(recs, tally=True):
    lines = [f"[kernel] Parsing {SRC_REL} (with preprocessing)", "[wp] Running WP plugin..."]
    lines += [f"[rte:annot] annotating function {fn}" for fn in recs]
    lines.append(f"[wp] {sum(len(v) for v in recs.values())} goals scheduled")
    for fn in recs:
        lines += recs[fn]
    if tally:
        lines += ["[wp] Proved goals:   118 / 136",
                  "  Qed:                   56  (0.21ms-4ms-30ms) (failed: 7)",
                  "  CVC4 1.8:              31  (90ms-140ms) (18466) (failed: 11)",
                  "  Z3 4.8.12 (fixedTO):   69  (10ms-35ms-80ms) (189403)"]
    return "\n".join(lines) + "\n"


def run(tmp_path, text):
    log = tmp_path / "wp.log"
    log.write_text(text, encoding="utf-8")
    out_json = tmp_path / "canary" / "result.json"
    p = subprocess.run([sys.executable, CHECK, str(log), "--json", str(out_json)],
                       capture_output=True, text=True, check=False)
    lines = p.stdout.splitlines()
    report = json.loads(out_json.read_text(encoding="utf-8")) if out_json.exists() else None
    return p.returncode, lines, report


def row(lines, fn):
    hits = [l for l in lines if re.search(rf"\s{re.escape(fn)}\s", l)]
    assert len(hits) == 1, (fn, lines)
    return hits[0]


def assert_failed(rc, lines, report):
    assert rc == 1, lines
    assert lines[-1].startswith("wp-canary: FAIL"), lines[-1]
    assert not GATE_RE.match(lines[-1])
    assert report is not None and report["ok"] is False


def test_expect_matches_the_source():
    defined = [fn for fn, _, _ in C.source_functions(SRC)]
    assert sorted(defined) == sorted(fn for fn, _, _ in C.EXPECT)
    assert len(SEEDED) >= 13 and len(CONTROLS) >= 9
    kinds = {kind for _, kind, expect in C.EXPECT if expect == C.CAUGHT}
    assert {"struct-table", "modulo", "quotient", "ghost-state", "port-lock",
            "port-clock"} <= kinds
    # every kind of the new shapes has a clean control
    for k in ("struct-table", "modulo", "quotient", "ghost-state", "port-lock", "port-clock"):
        assert any(kind == k and e == C.CLEAN for _, kind, e in C.EXPECT), k


def test_all_caught(tmp_path):
    rc, lines, report = run(tmp_path, render(records()))
    assert rc == 0, lines
    n, s, k = len(C.EXPECT), len(SEEDED), len(CONTROLS)
    assert lines[-1] == (f"wp-canary: {n} functions as expected "
                         f"(caught {s}/{s} seeded contradictions, {k} controls clean)")
    assert GATE_RE.match(lines[-1])
    for fn, kind, _ in C.EXPECT:
        r = row(lines, fn)
        assert kind in r
        assert r.startswith("caught " if fn in SEEDED else "clean ")
    # the failed dead call is the lock canary's, found through its source line
    assert "dead_call_s42 (mt_port_unlock)" in row(lines, "canary_lock_class")
    assert report == {
        "ok": True, "seeded": s, "caught": s, "controls": k, "controls_clean": k,
        "functions": [{"name": fn, "kind": kind, "expect": e, "ok": True}
                      for fn, kind, e in C.EXPECT]}


def test_seeded_contradiction_missed(tmp_path):
    recs = records()
    recs["canary_grid"] = smoke_passed("canary_grid_wp_smoke_default_requires") + \
        goal("canary_grid_assigns")
    rc, lines, report = run(tmp_path, render(recs))
    assert_failed(rc, lines, report)
    r = row(lines, "canary_grid")
    assert r.startswith("MISSED") and "modulo" in r
    assert "canary_grid" in lines[-1]
    assert report["caught"] == len(SEEDED) - 1
    assert report["controls_clean"] == len(CONTROLS)
    assert [f["name"] for f in report["functions"] if not f["ok"]] == ["canary_grid"]


def test_control_with_failed_smoke_test(tmp_path):
    recs = records()
    fn = "control_ghost_stamp"
    recs[fn] = smoke_failed(f"{fn}_wp_smoke_default_requires", line_of(fn, f"{fn}(")) + \
        goal(f"{fn}_ensures")
    rc, lines, report = run(tmp_path, render(recs))
    assert_failed(rc, lines, report)
    assert row(lines, "control_ghost_stamp").startswith("UNCLEAN")
    assert report["caught"] == len(SEEDED)
    assert report["controls_clean"] == len(CONTROLS) - 1


def test_control_with_failed_dead_call(tmp_path):
    """A dead call of a control is named after the callee; its warning line ties it to the
    control, which is then not clean."""
    recs = records()
    recs["control_clock_elapsed"] += smoke_failed(
        "mt_port_now_us_wp_smoke_dead_call_s70",
        line_of("control_clock_elapsed", "uint64_t t1 = mt_port_now_us();"))
    rc, lines, report = run(tmp_path, render(recs))
    assert_failed(rc, lines, report)
    assert row(lines, "control_clock_elapsed").startswith("UNCLEAN")


def test_control_with_unproved_goal(tmp_path):
    recs = records()
    recs["control_task_table"] += goal("control_task_table_assert_rte_index_bound", ok=False)
    rc, lines, report = run(tmp_path, render(recs))
    assert_failed(rc, lines, report)
    assert row(lines, "control_task_table").startswith("UNCLEAN")


@pytest.mark.parametrize("fn", ["canary_clock_backwards", "control_lock_class"])
def test_function_missing_from_log(tmp_path, fn):
    recs = records()
    del recs[fn]
    rc, lines, report = run(tmp_path, render(recs))
    assert_failed(rc, lines, report)
    r = row(lines, fn)
    assert r.startswith("MISSED" if fn in SEEDED else "UNCLEAN") and "not in the log" in r
    assert [f["name"] for f in report["functions"] if not f["ok"]] == [fn]


def test_failed_smoke_test_without_owner(tmp_path):
    recs = records()
    recs["control_sorted"] += [
        "[wp] [Failed] Smoke-test typed_mt_port_halt_wp_smoke_dead_call_s99",
        "       Qed: Valid (1ms)"]
    rc, lines, report = run(tmp_path, render(recs))
    assert_failed(rc, lines, report)
    assert any(l.startswith("ERROR") and "mt_port_halt_wp_smoke_dead_call_s99" in l for l in lines)


def test_log_cut_short(tmp_path):
    rc, lines, report = run(tmp_path, render(records(), tally=False))
    assert_failed(rc, lines, report)
    assert any(l.startswith("ERROR") and "Proved goals" in l for l in lines)


def test_nothing_caught_nothing_clean(tmp_path):
    """A run without smoke tests at all (e.g. -wp-no-smoke-tests) cannot pass."""
    recs = {fn: goal(f"{fn}_assigns") for fn, _, _ in C.EXPECT}
    rc, lines, report = run(tmp_path, render(recs))
    assert_failed(rc, lines, report)
    assert report["caught"] == 0 and report["controls_clean"] == 0
