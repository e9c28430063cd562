# SPDX-License-Identifier: Apache-2.0
"""tools/assurance.py: the README's per-function assurance table stays true to the tree.

    /usr/bin/python3 -m pytest -q tests/proofs/test_assurance.py
"""
import copy
import importlib.util
import os
import shutil

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SPEC = importlib.util.spec_from_file_location("assurance", os.path.join(ROOT, "tools", "assurance.py"))
A = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(A)


def test_tree_and_readme_agree(capsys):
    assert A.main(["--check"]) == 0, capsys.readouterr().out


def test_every_public_function_once_with_a_module():
    data = A.load()
    names = [e["name"] for e in data["functions"]]
    assert len(names) == len(set(names))
    assert set(names) == A.cbmc_run.header_functions()
    assert all(A.wp_module(n) for n in names)


def test_a_missing_or_doubled_function_fails():
    data = A.load()
    d = copy.deepcopy(data)
    gone = d["functions"].pop(0)["name"]
    assert any(gone in b and "missing" in b for b in A.problems(d))
    d = copy.deepcopy(data)
    d["functions"].append(copy.deepcopy(d["functions"][0]))
    assert any("listed 2 times" in b for b in A.problems(d))


def test_class_reason_and_harnesses_are_checked():
    data = A.load()
    d = copy.deepcopy(data)
    p = next(e for e in d["functions"] if e["class"] == "partial")
    p["reason"] = ""
    f = next(e for e in d["functions"] if e["class"] == "functional")
    f["class"] = "mostly"
    bad = A.problems(d)
    assert any(p["name"] in b and "reason" in b for b in bad)
    assert any(f["name"] in b and "mostly" in b for b in bad)
    d = copy.deepcopy(data)
    e = next(e for e in d["functions"] if e["name"] == "mt_sched_run")
    del e["cbmc_bounds"]["mt_sched_run__tasks"]
    assert any("mt_sched_run" in b and "CBMC harnesses" in b for b in A.problems(d))


def test_a_changed_contract_needs_a_new_review(tmp_path):
    inc = tmp_path / "mt"
    shutil.copytree(os.path.join(ROOT, "kernel", "include", "mt"), inc)
    ring = inc / "ring.h"
    text = ring.read_text()
    old = "ensures empty: MtBRingCount(r) == 0 && r->cap == cap && r->buf == storage;"
    assert text.count(old) == 1
    ring.write_text(text.replace(old, "ensures empty: MtBRingCount(r) == 0 && r->cap == cap;"))
    bad = A.problems(A.load(), inc=str(inc))
    assert [b.split(":")[0] for b in bad] == ["mt_bring_init"], bad
    # layout alone (spaces, line breaks) is not a change
    ring.write_text(text.replace(old, "ensures empty: MtBRingCount(r) == 0 &&\n        r->cap == cap && r->buf == storage;"))
    assert A.problems(A.load(), inc=str(inc)) == []


def test_stale_readme_fails(tmp_path, capsys):
    readme = tmp_path / "README.md"
    text = open(A.README, encoding="utf-8").read()
    readme.write_text(text.replace("| `mt_sem_init` |", "| `mt_sem_init_old` |"))
    assert A.main(["--check", "--readme", str(readme)]) == 1
    assert "stale" in capsys.readouterr().out
