#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Traceability: proofs/requirements.json against what the proofs, tests and models hold.

Each requirement is one behaviour a user relies on, with what discharges it:
  clauses  contract clause labels, "function:label" or "function:behavior.label"; each must be
           a WP goal of this run (build/proof/wp/<module>/report.json: the goal
           <function>[_<behavior>]_ensures_<label>, split parts included) and proved. At least
           one per requirement: tests and models add to a proof, they do not replace it.
  tests    unit tests, "Suite.Name": a TEST or TEST_F of tests/ (the suite runs in make test).
  models   TLA+ properties, "Module.Name": defined in tla/<Module>.tla and checked by a
           configuration of tla/models.json that must pass (of that module or one that EXTENDS
           it), listed there (INVARIANT, PROPERTY) or used by a definition listed there.
check() returns one result per requirement; a requirement is ok when every item it names
exists, every clause is proved, and it names a clause. proofs/wp/gate.py runs it over the full
module set (make wp; a shard's gate leaves it to the merge) and puts the results in
wp/summary.json; tools/proof_gate.py fails on any requirement not ok, and tools/proof_report.py
prints the matrix. python3 stdlib only.
"""
import glob
import json
import os
import re

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CLAUSE_RE = re.compile(r"^(?P<fn>\w+):(?:(?P<bhv>\w+)\.)?(?P<label>\w+)$")
TEST_RE = re.compile(r"^\s*TEST(?:_F)?\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.M)
DEF_RE = re.compile(r"^([A-Za-z_]\w*)(?:\([^)]*\))?\s*==", re.M)
CFG_LIST_RE = re.compile(r"^\s*(?:INVARIANTS?|PROPERTY|PROPERTIES)\s+(.*)$")


def load(path):
    with open(path, encoding="utf-8") as f:
        reqs = json.load(f)
    if not isinstance(reqs, list):
        raise ValueError(f"{path}: not a JSON list")
    return reqs


def wp_goals(wp_dir, modules):
    """{goal name: proved?} from the modules' WP reports (proved: every prover result valid
    for the goal, as wp:main reports it)."""
    goals = {}
    for m in modules:
        path = os.path.join(wp_dir, m, "report.json")
        if not os.path.exists(path):
            continue
        with open(path, encoding="utf-8") as f:
            rep = json.load(f)
        for per_goal in (rep.get("wp:functions") or {}).values():
            for name, res in per_goal.items():
                main = (res or {}).get("wp:main") or {}
                goals[name] = main.get("total", 0) > 0 and main.get("valid") == main.get("total")
    return goals


def clause_goals(clause, goals):
    """The WP goals of a clause name, or None when the name is malformed."""
    m = CLAUSE_RE.match(clause)
    if not m:
        return None
    prefix = m["fn"] + ("_" + m["bhv"] if m["bhv"] else "") + "_ensures_" + m["label"]
    return [g for g in goals if g == prefix or re.fullmatch(re.escape(prefix) + r"_part\d+", g)]


def unit_tests(root):
    names = set()
    for path in glob.glob(os.path.join(root, "tests", "**", "*.cpp"), recursive=True):
        with open(path, encoding="utf-8") as f:
            names.update(f"{a}.{b}" for a, b in TEST_RE.findall(f.read()))
    return names


def definitions(text):
    """{name: body text} of a TLA+ module's top-level definitions."""
    found = list(DEF_RE.finditer(text))
    return {m.group(1): text[m.end():(found[i + 1].start() if i + 1 < len(found) else len(text))]
            for i, m in enumerate(found)}


def module_defs(root, mod, seen=None):
    """{name: (defining module, body)} of a TLA+ module and the tla/ modules it EXTENDS."""
    seen = set() if seen is None else seen
    path = os.path.join(root, "tla", f"{mod}.tla")
    if mod in seen or not os.path.exists(path):
        return {}
    seen.add(mod)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    defs = {}
    ext = re.search(r"^EXTENDS\s+(.*)$", text, re.M)
    for base in re.findall(r"\w+", ext.group(1)) if ext else []:
        defs.update(module_defs(root, base, seen))
    defs.update({n: (mod, body) for n, body in definitions(text).items()})
    return defs


def checked_properties(root):
    """{"Module.Name"}: the definitions the passing configurations of tla/models.json check,
    listed in the configuration or used by a listed one, named by their defining module."""
    with open(os.path.join(root, "tla", "models.json"), encoding="utf-8") as f:
        models = json.load(f)["models"]
    out = set()
    for m in models:
        if m.get("expect") != "pass":
            continue
        defs = module_defs(root, m["module"])
        todo = []
        with open(os.path.join(root, "tla", m["config"]), encoding="utf-8") as f:
            listing = False  # inside an INVARIANTS/PROPERTIES list (it goes on on indented lines)
            for line in f:
                line = re.sub(r"\\\*.*", "", line)
                hit = CFG_LIST_RE.match(line)
                if hit:
                    todo += re.findall(r"[A-Za-z_]\w*", hit.group(1))
                    listing = True
                elif listing and line[:1].isspace() and line.strip():
                    todo += re.findall(r"[A-Za-z_]\w*", line)
                else:
                    listing = False
        seen = set()
        while todo:
            n = todo.pop()
            if n in seen or n not in defs:
                continue
            seen.add(n)
            out.add(f"{defs[n][0]}.{n}")
            todo += [w for w in re.findall(r"[A-Za-z_]\w*", defs[n][1]) if w in defs]
    return out


def check(reqs, goals, root=ROOT):
    tests = unit_tests(root)
    props = checked_properties(root)
    results = []
    for r in reqs:
        res = {"id": r.get("id", "?"), "text": r.get("text", ""), "clauses": [], "tests": [],
               "models": [], "problems": []}
        for c in r.get("clauses") or []:
            gs = clause_goals(c, goals)
            if gs is None:
                state = "malformed"
            elif not gs:
                state = "missing"
            else:
                state = "proved" if all(goals[g] for g in gs) else "not proved"
            res["clauses"].append({"name": c, "state": state})
            if state != "proved":
                res["problems"].append(f"clause {c}: {state}")
        for t in r.get("tests") or []:
            ok = t in tests
            res["tests"].append({"name": t, "state": "exists" if ok else "missing"})
            if not ok:
                res["problems"].append(f"test {t}: no such TEST in tests/")
        for p in r.get("models") or []:
            ok = p in props
            res["models"].append({"name": p, "state": "checked" if ok else "not checked"})
            if not ok:
                res["problems"].append(f"model {p}: not checked by a passing configuration")
        if not r.get("clauses"):
            res["problems"].append("no contract clause")
        res["ok"] = not res["problems"]
        results.append(res)
    return results


def matrix_lines(results):
    """The matrix as markdown table rows."""
    rows = ["| requirement | contract clauses (WP) | tests | TLA+ |", "|---|---|---|---|"]
    for r in results:
        proved = sum(c["state"] == "proved" for c in r["clauses"])
        rows.append(
            f"| {r['id']} {r['text']}{'' if r['ok'] else ' **(FAIL)**'} | "
            f"{proved}/{len(r['clauses'])}: " + ", ".join(f"`{c['name']}`" for c in r["clauses"]) +
            " | " + (", ".join(t["name"] for t in r["tests"]) or "-") +
            " | " + (", ".join(m["name"] for m in r["models"]) or "-") + " |")
    return rows


def main():
    import argparse
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--wp-dir", default=os.path.join(ROOT, "build", "proof", "wp"))
    ap.add_argument("--requirements", default=os.path.join(ROOT, "proofs", "requirements.json"))
    args = ap.parse_args()
    mods = [d for d in sorted(os.listdir(args.wp_dir))
            if os.path.exists(os.path.join(args.wp_dir, d, "report.json"))]
    results = check(load(args.requirements), wp_goals(args.wp_dir, mods))
    print("\n".join(matrix_lines(results)))
    bad = [r for r in results if not r["ok"]]
    for r in bad:
        for p in r["problems"]:
            print(f"{r['id']}: {p}")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
