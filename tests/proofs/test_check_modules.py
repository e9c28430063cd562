# SPDX-License-Identifier: Apache-2.0
"""make check-<module> (proofs/check.mk) covers every artifact of the kernel: each kernel module
has a target; each CBMC harness, each TLA+ model of tla/models.json and each googletest suite of
a module's test file belongs to exactly one module's check (or to the listed shared ones).

    /usr/bin/python3 -m pytest -q tests/proofs/test_check_modules.py
"""
import glob
import json
import os
import re
import subprocess

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
# Modules without a source of their own in the check table: the call trampolines (A1).
NOT_MODULES = {"invoke", "mission_invoke", "bus_invoke"}
# Suites that test several modules together, and the mission file library (not kernel).
SHARED_SUITES = {"Stress", "CxxHeaders", "PortDeath", "PortReal", "PortSim"}


def variables():
    out = subprocess.run(["make", "-pqrR"], cwd=ROOT, capture_output=True, text=True,
                         timeout=120).stdout
    return {m.group(1): m.group(2).strip() for m in
            re.finditer(r"^(CHECK_[A-Za-z_]+) :?= ?(.*)$", out, re.M)}


def suites(path):
    with open(path, encoding="utf-8") as f:
        return set(re.findall(r"^TEST(?:_F)?\((\w+),", f.read(), re.M))


def matches(pattern, suite):
    """Does the gtest filter PATTERN (a:b:c, '*' wildcards) select tests of SUITE?"""
    return any(re.fullmatch(p.replace(".", r"\.").replace("*", ".*"), suite + ".x")
               for p in pattern.split(":"))


def test_every_kernel_module_has_a_check():
    """Each source file belongs to exactly one module's check: the file <m>.c or <m>_*.c (a
    module split over several files, whose WP modules check-<m> runs), and every module has
    its own file <m>.c."""
    v = variables()
    mods = set(v["CHECK_MODULES"].split())
    src = {os.path.basename(p)[:-2] for p in glob.glob(os.path.join(ROOT, "kernel/src/*.c"))}
    src -= NOT_MODULES
    assert mods <= src
    for f in src:
        owners = [m for m in mods if f == m or f.startswith(m + "_")]
        assert len(owners) == 1, (f, owners)
    for m in mods:
        assert v.get(f"CHECK_TEST_{m}") and v.get(f"CHECK_CBMC_{m}"), m


def test_every_harness_belongs_to_exactly_one_module():
    v = variables()
    mods = v["CHECK_MODULES"].split()
    for h in os.listdir(os.path.join(ROOT, "proofs/cbmc/proofs")):
        owners = [m for m in mods if any(h.startswith(p) for p in v[f"CHECK_CBMC_{m}"].split())]
        assert len(owners) == 1, (h, owners)


def test_every_model_is_checked_by_a_module():
    v = variables()
    checked = {name for k in v if k.startswith("CHECK_TLA_") for name in v[k].split()}
    with open(os.path.join(ROOT, "tla/models.json"), encoding="utf-8") as f:
        models = {m["module"] for m in json.load(f)["models"]}
    assert models == checked


def test_every_suite_of_a_module_test_file_is_in_its_check():
    v = variables()
    for m in v["CHECK_MODULES"].split():
        path = os.path.join(ROOT, "tests", f"test_{m}.cpp")
        assert os.path.exists(path), path
        found = suites(path)
        assert found, path
        missing = [s for s in found if not matches(v[f"CHECK_TEST_{m}"], s)]
        assert missing == [], (m, missing)
    everything = set()
    for path in glob.glob(os.path.join(ROOT, "tests", "test_*.cpp")):
        if not os.path.basename(path).startswith("test_mission_"):
            everything |= suites(path)
    owned = {s for s in everything for m in v["CHECK_MODULES"].split()
             if matches(v[f"CHECK_TEST_{m}"], s)}
    assert everything - owned - SHARED_SUITES == set()
