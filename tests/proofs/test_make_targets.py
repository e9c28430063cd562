# SPDX-License-Identifier: Apache-2.0
"""Build hygiene: every target the Makefiles declare (.PHONY) has a rule, and every target
`make help` names exists.

    /usr/bin/python3 -m pytest -q tests/proofs/test_make_targets.py
"""
import os
import re
import subprocess

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def make(*args):
    proc = subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT, capture_output=True,
                          text=True, timeout=120)
    return proc.stdout


def rules():
    """{target: has a recipe or prerequisites} from make's database (nothing is built)."""
    lines = make("-pqrR").split("\n")
    found = {}
    for i, line in enumerate(lines):
        m = re.match(r"^([^\s#:=.][^:=]*?):(?!=)(.*)$", line)
        if not m or (i and lines[i - 1].startswith("# Not a target")):
            continue
        j, recipe = i + 1, False
        while j < len(lines) and lines[j]:
            recipe = recipe or lines[j].startswith("\t")
            j += 1
        found[m.group(1)] = recipe or bool(m.group(2).strip())
    phony = next(x for x in lines if x.startswith(".PHONY:")).split()[1:]
    return found, phony


def test_every_declared_target_has_a_rule():
    found, phony = rules()
    assert len(phony) > 50
    assert [t for t in phony if not found.get(t)] == []


def test_every_target_make_help_names_exists():
    found, _ = rules()
    named = set(re.findall(r"make ([a-z][a-z0-9-]*)", make("help")))
    named |= set(re.findall(r"\| ([a-z][a-z0-9-]*)", make("help")))
    named = {t for t in named if not t.endswith("-")}  # wp-<module>, cbmc-<function>
    assert {"test", "prove", "reprove", "prove-cold", "sitl", "bench", "test-asan"} <= named
    assert sorted(t for t in named if not found.get(t)) == []
