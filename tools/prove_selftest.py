#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make prove-selftest`: seeded bugs must be rejected by the tools that are meant to catch them.

    tools/prove_selftest.py [ID ...]            the named mutants (default: all)
    tools/prove_selftest.py --rotate K          K mutants chosen by the commit count (CI)
    tools/prove_selftest.py --list-rotation K C print the rotation for commit count C, run nothing
    tools/prove_selftest.py --no-cache ...      WP runs every prover (WP_CACHE=none)

Each mutant in proofs/mutants.json names a file, an exact text to find (it must occur exactly
once) and its replacement, the kernel function it breaks, the WP module that proves it, the CBMC
harness that checks it (`harness`, default: the function's name) and `reject_by`, the tools
that must reject it (a non-empty subset of "wp" and "cbmc"; a mutant a tool is known to accept
says why in `cbmc_accepts`). For each mutant the repository is copied to build/selftest/<id>/
(sources only; the tool folder is linked), the mutation is applied, and
  - WP runs on that module restricted to that function
    (`make wp-<module> WP_FCT=<function>`): killed when a goal or smoke test is not proved,
    accepted when all are, no verdict (n/a) without a report or when the function has open
    goals in the unmutated kernel (last `make wp`);
  - CBMC runs the harness (`make cbmc-<harness>`, CBMC_RECORD=properties: the property run is
    always made, never replayed): killed when a property fails, accepted when every property
    holds, n/a on a time-out, a build error or without a harness.
Named clauses. A mutant may name, per tool, the contract clauses it breaks (`clauses`:
{"wp": [WP property names, e.g. "mt_sub_copy_next_next_ensures_quiet"], "cbmc": [CBMC property
descriptions, e.g. "mt_sub_copy_next: ensures next.quiet"]}). A tool that names clauses rejects
the mutant only when one of them fails: a WP goal of that clause not proved, a CBMC property of
that clause failed. Any other failure (a goal elsewhere, a smoke test, an RTE or frame check)
is no verdict, so a mutant cannot pass by breaking something else. The summary lists, for every
mutant, the failed goals and properties and the named ones among them (the per-mutant table);
a tool of reject_by without named clauses is reported as "no clause named".
Both tools always run. A mutant is ok when every tool of its reject_by rejected it (judge());
a tool outside reject_by is reported, its rejection as a bonus, its acceptance is no failure.
"n/a" is never read as "accepted": a tool of reject_by without a verdict makes the mutant not ok.

Rotation (--rotate K, for CI): with N mutants and the commit count C (`git rev-list --count
HEAD`, 0 outside a git checkout) the mutants at positions (C*K + j) mod N, j = 0..K-1, run, in
file order. Consecutive commit counts take consecutive windows of K positions, so every mutant
runs at least once within ceil(N/K) consecutive landings.

WP cache. WP uses the per-goal result cache like `make wp` (WP_CACHE=update, each module's
session seeded from proofs/wp/cache/<module>.json, assumption W4), and that is sound here.
An entry is keyed by the digest of the exact prover task text (the Why3 task as the prover's
driver prints it, prover name included), so only a byte-identical task replays. Bundles are
saved only from runs that passed the gate: an entry is a proved goal (Valid) or a passed smoke
test (Unknown: CVC4 found no contradiction within 2 s, Z3 declined, W1).
  - A goal the mutation leaves unchanged replays the verdict of the unmutated kernel, which a
    prover would give again: it can neither invent a rejection nor hide one.
  - A goal the mutation changes finds no entry and goes to a prover, unless its new task is
    byte-identical to a recorded one. That happens: in M07's run the broken ensures (MT_OK
    where MT_E_TIMEOUT is due) reduced to a smoke-test task (`false` under the path's
    hypotheses; both provers' entries Unknown, which no proved goal leaves) and Frama-C
    replayed that Unknown (it does so whatever the time limit). Such a kill stands on W1, as
    the smoke test did: the path is not contradictory, so `false` is not provable there.
  - A replayed Valid is a proof of that very task, so an accepted mutant really meets the goal.
--no-cache (WP_CACHE=none) runs every prover with its full limit, as a release check would.

Writes build/selftest/summary.json and build/proof/selftest/summary.json; exit status 0 only
when every selected mutant is ok and every mutation applied (the list must follow the code).
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
BUILD = os.environ.get("BUILD", "build")
WORK_BUILD = "build"  # the build folder inside each mutant's copy
SKIP = {".git", "build", ".tools", ".cache"}
MUTANTS = os.path.join(ROOT, "proofs", "mutants.json")
TOOLS = ("wp", "cbmc")
# A mutant's CBMC property run may take longer than the unmutated one (a failing property's
# trace) and in CI it runs beside the other proof parts: mt_sched_run's took 716 s under load
# here, over run.py's former default of 600 s. A time-out is still no verdict, never an acceptance.
MUTANT_CBMC_TIMEOUT = "1800"
TOOL_NAME = {"wp": "WP", "cbmc": "CBMC"}


# --- pure parts (tests/proofs/test_prove_selftest.py) -------------------------------------

def load_mutants(path=MUTANTS):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def harness_of(m):
    return m.get("harness", m["function"])


def check_reject_by(reject_by):
    """reject_by must be a non-empty list of distinct tools out of TOOLS."""
    if not isinstance(reject_by, list) or not reject_by or \
            len(set(reject_by)) != len(reject_by) or not set(reject_by) <= set(TOOLS):
        raise ValueError(f"reject_by must be a non-empty subset of {list(TOOLS)}: {reject_by!r}")


def check_clauses(m):
    """`clauses`, when present: {tool: non-empty list of strings} for tools of reject_by."""
    c = m.get("clauses")
    if c is None:
        return
    if not isinstance(c, dict) or not set(c) <= set(m.get("reject_by", [])) or any(
            not isinstance(v, list) or not v or not all(isinstance(x, str) and x for x in v)
            for v in c.values()):
        raise ValueError(f"clauses must map tools of reject_by to non-empty lists of names: {c!r}")


def wp_failed_goals(mod):
    """WP property names of the goals and smoke tests a gate summary module lists as failed."""
    out = set()
    for f in mod.get("failures", []):
        if ": " in f:
            out.add(f.split(": ", 1)[1].split(" {", 1)[0].strip())
    return sorted(out)


def cbmc_failed_properties(entry):
    """Descriptions of the failed CBMC properties of a run.py summary entry."""
    return sorted({x.get("description") or x.get("property", "?")
                   for x in entry.get("failures", [])})


def clause_verdict(named, failed, what):
    """(verdict, detail, hits) from the failures of one tool and the clauses named for it.

    named None: any failure rejects (no clause named). Otherwise only a failure of a named
    clause does; failures elsewhere give no verdict."""
    if not failed:
        return False, None, []
    if named is None:
        return True, f"{what}: {', '.join(failed[:2])} (no clause named)", []
    hits = [x for x in failed if x in set(named)]
    if hits:
        return True, f"named clause failed: {', '.join(hits[:3])}", hits
    return None, (f"{what} failed, but none of its named clauses ({', '.join(named)}): "
                  f"{', '.join(failed[:3])}"), []


def rotation(n, k, c):
    """Positions (0-based, file order) of the K mutants out of N run at commit count C."""
    if n <= 0:
        return []
    if k < 1:
        raise ValueError(f"rotation size must be at least 1: {k}")
    k = min(k, n)
    return sorted({(c * k + j) % n for j in range(k)})


def verdict_word(v):
    return "n/a" if v is None else ("killed" if v else "accepted")


def judge(reject_by, wp, cbmc, detail=None):
    """(ok, reason) for one mutant: ok when every tool of reject_by rejected it.

    wp, cbmc: True (rejected), False (accepted) or None (no verdict); detail: optional
    {tool: text} saying why a tool gave no verdict."""
    check_reject_by(reject_by)
    verdicts = {"wp": wp, "cbmc": cbmc}
    detail = detail or {}
    problems = []
    for t in TOOLS:
        if t not in reject_by:
            continue
        if verdicts[t] is False:
            problems.append(f"{TOOL_NAME[t]} accepted it (must reject)")
        elif verdicts[t] is None:
            why = f" ({detail[t]})" if detail.get(t) else ""
            problems.append(f"{TOOL_NAME[t]} gave no verdict{why} (must reject)")
    if problems:
        return False, "; ".join(problems)
    parts = ["rejected by " + " and ".join(TOOL_NAME[t] for t in TOOLS if t in reject_by)]
    for t in TOOLS:
        if t in reject_by:
            continue
        if verdicts[t] is True:
            parts.append(f"bonus: {TOOL_NAME[t]} rejected it too")
        elif verdicts[t] is False:
            parts.append(f"{TOOL_NAME[t]} accepted it (not required)")
        else:
            why = f" ({detail[t]})" if detail.get(t) else ""
            parts.append(f"{TOOL_NAME[t]} gave no verdict{why} (not required)")
    return True, "; ".join(parts)


def commit_count(root=ROOT):
    """`git rev-list --count HEAD`, 0 when root is not a git checkout."""
    try:
        p = subprocess.run(["git", "-C", root, "rev-list", "--count", "HEAD"],
                           capture_output=True, text=True, check=False)
        return int(p.stdout.strip()) if p.returncode == 0 else 0
    except (OSError, ValueError):
        return 0


def rotation_line(mutants, k, c):
    n = len(mutants)
    pos = rotation(n, k, c)
    kk = min(k, n)
    ids = " ".join(mutants[i]["id"] for i in pos)
    rounds = math.ceil(n / kk) if kk else 0
    return (f"rotation: {kk} of {n} mutants at commit count {c}: positions "
            f"{', '.join(str(i) for i in pos)} (({c}*{kk} + j) mod {n}, j = 0..{kk - 1}) -> {ids}; "
            f"every mutant runs within {rounds} consecutive landings")


# --- running the tools ---------------------------------------------------------------------

def copy_tree(dst):
    if os.path.exists(dst):
        shutil.rmtree(dst)
    os.makedirs(dst)
    for name in os.listdir(ROOT):
        if name in SKIP or name.startswith("build"):
            continue
        src = os.path.join(ROOT, name)
        if os.path.isdir(src):
            shutil.copytree(src, os.path.join(dst, name), symlinks=True)
        else:
            shutil.copy2(src, os.path.join(dst, name))
    tools = os.path.join(ROOT, ".tools")
    if os.path.isdir(tools):
        os.symlink(tools, os.path.join(dst, ".tools"))


def run(cmd, cwd, log, env=None):
    # the copy builds into its own build/ whatever BUILD says for this script's outputs
    env = dict(os.environ if env is None else env, BUILD=WORK_BUILD)
    with open(log, "w", encoding="utf-8") as f:
        p = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, env=env)
    return p.returncode


def open_functions():
    """Functions with open goals in the unmutated kernel (last `make wp`): a WP failure there
    proves nothing about the mutant, so WP has no verdict for such a mutant."""
    fns = set()
    base = os.path.join(ROOT, BUILD, "proof", "wp", "summary.json")
    if os.path.exists(base):
        with open(base, encoding="utf-8") as f:
            for mod in json.load(f).get("modules", {}).values():
                for fail in mod.get("failures", []):
                    fns.add(fail.split(":", 1)[0].strip())
    return fns


def wp_verdict(m, work, open_fns, use_cache):
    """(verdict, detail, cache counts, failed goal names, named ones among them) of WP on the
    mutant in work/, like cbmc_verdict."""
    wp_dir = os.path.join(WORK_BUILD, "proof", "wp")
    # frama-c exits 0 even with unproved goals: the verdict is read from the gate's summary
    run(["make", "--no-print-directory", f"wp-{m['wp_module']}", f"WP_FCT={m['function']}",
         f"WP_CACHE={'update' if use_cache else 'none'}"], work, os.path.join(work, "wp.log"))
    # The module's goal and smoke-test counts, not the gate's exit status: the copied tree has
    # no smoke-canary result (the canary is not a per-mutant check), so the gate always fails.
    wp_sum = os.path.join(work, "wp-summary.json")
    run(["python3", "proofs/wp/gate.py", "--wp-dir", wp_dir, "--modules", m["wp_module"],
         "--summary", wp_sum], work, os.path.join(work, "wp-gate.log"))
    if not os.path.exists(wp_sum):
        return None, "no gate summary (see wp.log)", None, [], []
    with open(wp_sum, encoding="utf-8") as f:
        mod = json.load(f).get("modules", {}).get(m["wp_module"], {})
    cache = {"replayed": mod.get("cache_replayed"), "fresh": mod.get("cache_fresh")}
    goals, smoke = mod.get("goals", 0), mod.get("smoke", 0)
    if mod.get("missing") or goals == 0:
        fatal = "; ".join(str(x) for x in mod.get("fatal", []))[:200]
        return (None, "no WP report (the mutant did not parse?)" + (f": {fatal}" if fatal else ""),
                cache, [], [])
    open_goals = goals - mod.get("proved", 0)
    open_smoke = smoke - mod.get("smoke_passed", 0)
    failed = wp_failed_goals(mod)
    if m["function"] in open_fns:
        return None, "the function has open goals without the mutation", cache, failed, []
    if open_goals > 0 or open_smoke > 0 or failed:
        named = (m.get("clauses") or {}).get("wp")
        v, why, hits = clause_verdict(named, failed or ["?"],
                                      f"{open_goals}/{goals} goals and {open_smoke}/{smoke} "
                                      "smoke tests not proved")
        return v, why, cache, failed, hits
    if mod.get("fatal"):
        fatal = "; ".join(str(x) for x in mod["fatal"])[:200]
        return None, f"every goal proved but the log has errors: {fatal}", cache, failed, []
    return False, f"{goals} goals and {smoke} smoke tests proved", cache, failed, []


def cbmc_verdict(m, work):
    """(verdict, detail, failed property descriptions, named ones among them) of CBMC's
    property run on the mutant in work/."""
    v, why, entry = cbmc_run(m, work)
    if entry is None or not entry.get("failed"):
        return v, why, [], []
    failed = cbmc_failed_properties(entry)
    v, why, hits = clause_verdict((m.get("clauses") or {}).get("cbmc"), failed,
                                  f"{entry['failed']}/{entry.get('properties', 0)} properties")
    return v, why, failed, hits


def cbmc_run(m, work):
    """(verdict, detail, summary entry or None) of CBMC's property run on the mutant."""
    harness = harness_of(m)
    if not os.path.exists(os.path.join(work, "proofs", "cbmc", "proofs", harness, "cbmc-proof.txt")):
        return None, f"no harness proofs/cbmc/proofs/{harness}/", None
    pending_file = os.path.join(work, "proofs", "cbmc", "pending.json")
    if os.path.exists(pending_file):
        with open(pending_file, encoding="utf-8") as f:
            if harness in json.load(f):
                return None, f"harness {harness} is pending (proofs/cbmc/pending.json)", None
    log = os.path.join(work, "cbmc.log")
    # the property run always runs on the mutant (a recorded verdict is never replayed for it:
    # records hold only passing runs of the unmutated inputs, B10)
    run(["make", "--no-print-directory", f"cbmc-{harness}"], work, log,
        env=dict(os.environ, CBMC_RECORD="properties", CBMC_TIMEOUT=MUTANT_CBMC_TIMEOUT))
    summary = os.path.join(work, WORK_BUILD, "proof", "cbmc", f"summary-{harness}.json")
    entry = None
    if os.path.exists(summary):
        with open(summary, encoding="utf-8") as f:
            entry = next((e for e in json.load(f).get("results", [])
                          if e.get("function") == harness), None)
    if entry is None:
        return None, "no CBMC summary for the harness (see cbmc.log)", None
    props, failed = entry.get("properties", 0), entry.get("failed", 0)
    if failed:
        names = ", ".join(x.get("property", "?") for x in entry.get("failures", [])[:2])
        return True, f"{failed}/{props} properties failed ({names})", entry
    if entry.get("error"):
        err = entry["error"]
        if "timeout: killed" in err:
            return None, "time-out", entry
        return None, "error: " + err.strip().splitlines()[-1][:160], entry
    if props == 0:
        return None, "no property checked", entry
    # a coverage shortfall fails the harness but rejects nothing: the properties all hold
    return False, f"{props} properties, none failed", entry


def run_mutant(m, open_fns, use_cache):
    t0 = time.time()
    base = {"id": m["id"], "function": m["function"], "harness": harness_of(m),
            "reject_by": m["reject_by"], "description": m["description"]}
    work = os.path.join(ROOT, BUILD, "selftest", m["id"])
    copy_tree(work)
    path = os.path.join(work, m["file"])
    with open(path, encoding="utf-8") as f:
        text = f.read()
    n = text.count(m["find"])
    if n != 1:
        return dict(base, applied=False, wp=None, cbmc=None, ok=False,
                    reason=f"mutation does not apply: {n} matches of the find text in {m['file']}",
                    seconds=round(time.time() - t0, 1))
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(m["find"], m["replace"]))
    wp, wp_why, cache, wp_failed, wp_hits = wp_verdict(m, work, open_fns, use_cache)
    cb, cb_why, cb_failed, cb_hits = cbmc_verdict(m, work)
    ok, reason = judge(m["reject_by"], wp, cb, {"wp": wp_why, "cbmc": cb_why})
    named = m.get("clauses") or {}
    unnamed = [TOOL_NAME[t] for t in m["reject_by"] if t not in named]
    if unnamed:
        reason += f"; no clause named for {' and '.join(unnamed)}"
    return dict(base, applied=True, wp=wp, cbmc=cb, ok=ok, reason=reason, wp_detail=wp_why,
                cbmc_detail=cb_why, wp_cache=cache, clauses=named, wp_failed=wp_failed,
                cbmc_failed=cb_failed, wp_named_failed=wp_hits, cbmc_named_failed=cb_hits,
                clause_named={t: t in named for t in m["reject_by"]},
                seconds=round(time.time() - t0, 1))


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("ids", nargs="*", help="mutant ids (default: all, or the rotation)")
    ap.add_argument("--rotate", type=int, metavar="K", help="K mutants chosen by the commit count")
    ap.add_argument("--list-rotation", type=int, nargs=2, metavar=("K", "C"),
                    help="print the rotation for commit count C and exit")
    ap.add_argument("--no-cache", action="store_true", help="WP_CACHE=none: every prover runs")
    args = ap.parse_args(argv)
    if args.ids and args.rotate is not None:
        ap.error("name mutants or --rotate, not both")
    for k in (args.rotate, args.list_rotation[0] if args.list_rotation else None):
        if k is not None and k < 1:
            ap.error("the rotation size K must be at least 1")
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    mutants = load_mutants()
    for m in mutants:
        try:
            check_reject_by(m.get("reject_by"))
            check_clauses(m)
        except ValueError as e:
            print(f"prove_selftest: {m.get('id', '?')}: {e}", file=sys.stderr)
            return 2
    if args.list_rotation:
        k, c = args.list_rotation
        print(rotation_line(mutants, k, c))
        return 0
    rot = None
    if args.ids:
        unknown = sorted(set(args.ids) - {m["id"] for m in mutants})
        if unknown:
            print(f"prove_selftest: no such mutant: {', '.join(unknown)}", file=sys.stderr)
            return 2
        selected = [m for m in mutants if m["id"] in set(args.ids)]
    elif args.rotate is not None:
        c = commit_count()
        pos = rotation(len(mutants), args.rotate, c)
        selected = [mutants[i] for i in pos]
        rot = {"k": min(args.rotate, len(mutants)), "commit_count": c,
               "positions": pos, "selected": [m["id"] for m in selected]}
        print(rotation_line(mutants, args.rotate, c))
    else:
        selected = list(mutants)
    print(f"prove_selftest: {len(selected)} mutant(s); WP cache "
          f"{'off (WP_CACHE=none)' if args.no_cache else 'on (WP_CACHE=update, assumption W4)'}",
          flush=True)
    open_fns = open_functions()
    results = []
    t_all = time.time()
    for m in selected:
        r = run_mutant(m, open_fns, not args.no_cache)
        results.append(r)
        print(f"{r['id']:4s} {r['function']:28s} WP {verdict_word(r['wp']):8s} "
              f"CBMC {verdict_word(r['cbmc']):8s} {r['seconds']:6.1f} s  "
              f"{'ok' if r['ok'] else 'NOT OK'}: {r['reason']}", flush=True)
    total = len(results)
    n_ok = sum(r["ok"] for r in results)
    killed = sum(1 for r in results if r["wp"] is True or r["cbmc"] is True)
    by_wp = sum(1 for r in results if r["wp"] is True)
    by_cb = sum(1 for r in results if r["cbmc"] is True)
    n_named = sum(1 for r in results if r.get("clause_named") and all(r["clause_named"].values()))
    summary = {"mutants": total, "ok": n_ok, "killed": killed, "killed_by_wp": by_wp,
               "killed_by_cbmc": by_cb, "clauses_named": n_named, "rotation": rot,
               "wp_cache": "none" if args.no_cache else "update",
               "seconds": round(time.time() - t_all, 1), "results": results}
    for d in (os.path.join(ROOT, BUILD, "selftest"), os.path.join(ROOT, BUILD, "proof", "selftest")):
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "summary.json"), "w", encoding="utf-8") as f:
            json.dump(summary, f, indent=2)
            f.write("\n")
    for r in results:
        if not r["applied"]:
            print(f"{r['id']}: {r['reason']}")
    print("per-mutant clauses (mutant | WP: named clause failed | CBMC: named clause failed):")
    for r in results:
        if r["applied"]:
            print(f"  {r['id']:4s} | WP: {', '.join(r['wp_named_failed']) or '-'} | "
                  f"CBMC: {', '.join(r['cbmc_named_failed']) or '-'}")
    print(f"prove_selftest: {n_ok}/{total} ok; killed {killed}/{total} (WP {by_wp}, CBMC {by_cb}); "
          f"clauses named for every required tool: {n_named}/{total}; "
          f"in {summary['seconds']:.0f} s")
    return 0 if total > 0 and n_ok == total and all(r["applied"] for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
