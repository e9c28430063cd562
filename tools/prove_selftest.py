#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make prove-selftest`: seeded bugs must be rejected by WP or CBMC.

Each mutant in proofs/mutants.json names a file, an exact text to find (it must occur
exactly once) and its replacement, the kernel function it breaks and the WP module and CBMC
harness that cover it. For each mutant the repository is copied to
build/selftest/<id>/ (sources only; the tool folder is linked), the mutation is applied, and
  - WP runs on that module restricted to that function (`make wp-<module> WP_FCT=<function>`),
    killed when any goal or smoke test is not proved;
  - CBMC runs that function's harness (`make cbmc-<function>`), killed when it fails.
A mutant survives only if both tools accept it. The script writes
build/selftest/summary.json and build/proof/selftest/summary.json and exits 1 if a mutant
survives or if a mutation does not apply (the list must follow the code).
"""
import json
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
BUILD = os.environ.get("BUILD", "build")
SKIP = {".git", "build", ".tools", ".cache"}


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
    with open(log, "w", encoding="utf-8") as f:
        p = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, env=env)
    return p.returncode


def main():
    only = set(sys.argv[1:])
    # Functions with open goals in the unmutated kernel (last `make wp`): a WP failure
    # there proves nothing about the mutant, so such a mutant is "inconclusive" for WP.
    open_fns = set()
    base = os.path.join(ROOT, BUILD, "proof", "wp", "summary.json")
    if os.path.exists(base):
        with open(base, encoding="utf-8") as f:
            for mod in json.load(f).get("modules", {}).values():
                for fail in mod.get("failures", []):
                    open_fns.add(fail.split(":", 1)[0].strip())
    with open(os.path.join(ROOT, "proofs", "mutants.json"), encoding="utf-8") as f:
        mutants = json.load(f)
    results = []
    killed = 0
    t_all = time.time()
    for m in mutants:
        if only and m["id"] not in only:
            continue
        t0 = time.time()
        work = os.path.join(ROOT, BUILD, "selftest", m["id"])
        copy_tree(work)
        path = os.path.join(work, m["file"])
        with open(path, encoding="utf-8") as f:
            text = f.read()
        n = text.count(m["find"])
        if n != 1:
            print(f"{m['id']}: mutation does not apply ({n} matches of the find text in {m['file']})")
            results.append({"id": m["id"], "applied": False, "killed": False})
            continue
        with open(path, "w", encoding="utf-8") as f:
            f.write(text.replace(m["find"], m["replace"]))
        # frama-c exits 0 even with unproved goals: the verdict is the JSON gate's
        wp_dir = os.path.join(BUILD, "proof", "wp")
        run(["make", "--no-print-directory", f"wp-{m['wp_module']}", f"WP_FCT={m['function']}",
             "WP_CACHE=none"], work, os.path.join(work, "wp.log"))
        # The verdict is the module's goal and smoke-test counts in the gate's summary, not the
        # gate's exit status: the copied tree has no smoke-canary result (the canary is not a
        # per-mutant check), so the gate itself always fails there.
        wp_sum = os.path.join(work, "wp-summary.json")
        run(["python3", "proofs/wp/gate.py", "--wp-dir", wp_dir, "--modules", m["wp_module"],
             "--summary", wp_sum], work, os.path.join(work, "wp-gate.log"))
        wp_kill = False
        if os.path.exists(wp_sum):
            with open(wp_sum, encoding="utf-8") as f:
                mod = json.load(f).get("modules", {}).get(m["wp_module"], {})
            wp_kill = bool(mod.get("failures")) or mod.get("proved", 0) < mod.get("goals", 0) or \
                mod.get("smoke_passed", 0) < mod.get("smoke", 0) or bool(mod.get("fatal"))
            if mod.get("goals", 0) == 0:
                wp_kill = False  # no report (the mutant did not parse): no WP verdict
        if m["function"] in open_fns:
            wp_kill = None  # inconclusive: the function has open goals without the mutation
        harness = m.get("harness", m["function"])
        cb_kill = None  # no harness for this function yet: CBMC has no verdict
        # CBMC gives a verdict only when the harness's make target exists (a missing rule
        # is not a rejection) and the run says VERIFICATION FAILED.
        target = f"cbmc-{harness}"
        pending_file = os.path.join(ROOT, "proofs", "cbmc", "pending.json")
        pending = json.load(open(pending_file)) if os.path.exists(pending_file) else {}
        if harness in pending:
            pass  # the harness does not finish within the budget yet: no CBMC verdict
        elif subprocess.run(["make", "-n", target], cwd=work, stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode == 0:
            cb_log = os.path.join(work, "cbmc.log")
            # the property run always runs on the mutant (a recorded verdict is never replayed
            # for it: records hold only passing runs, B10)
            cb_rc = run(["make", "--no-print-directory", target], work, cb_log,
                        env=dict(os.environ, CBMC_RECORD="properties"))
            with open(cb_log, encoding="utf-8", errors="replace") as f:
                cb_text = f.read()
            cb_kill = cb_rc != 0 and "VERIFICATION FAILED" in cb_text
            if not cb_kill and ("timeout: killed" in cb_text or "harnesses passed" not in cb_text):
                cb_kill = None  # no verdict (a time-out or a build error), not an acceptance
        k = bool(wp_kill) or bool(cb_kill)
        killed += 1 if k else 0
        secs = time.time() - t0
        results.append({"id": m["id"], "applied": True, "description": m["description"],
                        "function": m["function"], "wp": wp_kill, "cbmc": cb_kill, "killed": k,
                        "seconds": round(secs, 1)})
        cb_word = "n/a" if cb_kill is None else ("killed" if cb_kill else "accepted")
        wp_word = "n/a" if wp_kill is None else ("killed" if wp_kill else "accepted")
        print(f"{m['id']:4s} {m['function']:28s} WP {wp_word:8s} "
              f"CBMC {cb_word:8s} {secs:6.1f} s  {m['description']}")
    total = len(results)
    by_wp = sum(1 for r in results if r.get("wp") is True)
    by_cb = sum(1 for r in results if r.get("cbmc") is True)
    summary = {"mutants": total, "killed": killed, "killed_by_wp": by_wp, "killed_by_cbmc": by_cb,
               "seconds": round(time.time() - t_all, 1), "results": results}
    for d in (os.path.join(ROOT, BUILD, "selftest"), os.path.join(ROOT, BUILD, "proof", "selftest")):
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "summary.json"), "w", encoding="utf-8") as f:
            json.dump(summary, f, indent=2)
            f.write("\n")
    rate = (100.0 * killed / total) if total else 0.0
    print(f"kill rate: {killed}/{total} ({rate:.0f}%); WP alone {by_wp}/{total}, CBMC alone {by_cb}/{total}")
    ok = total > 0 and killed == total and all(r["applied"] for r in results)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
