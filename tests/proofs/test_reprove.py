# SPDX-License-Identifier: Apache-2.0
"""`make reprove`'s local replay of a WP module (proofs/proofs.mk, wp_inputs): a module is
replayed only when every input is byte-identical to this tree's last completed run of it.

    /usr/bin/python3 -m pytest -q tests/proofs/test_reprove.py
    MT_SKIP_FRAMAC=1 ...   skips the tests that run Frama-C (module status 3 times, about 20 s)
"""
import os
import shutil
import subprocess

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

pytestmark = pytest.mark.skipif(
    os.environ.get("MT_SKIP_FRAMAC") == "1" or not shutil.which("frama-c"),
    reason="MT_SKIP_FRAMAC=1, or no frama-c")


@pytest.fixture
def tree(tmp_path):
    """A copy of the working tree (no build output, tools or history)."""
    dst = str(tmp_path / "repo")
    shutil.copytree(ROOT, dst, symlinks=True,
                    ignore=shutil.ignore_patterns(".git", "build", ".tools", "__pycache__"))
    return dst


def make(tree, *args, env=None):
    e = dict(os.environ, **(env or {}))
    e.pop("WP_REUSE_LOCAL", None)
    e.update(env or {})
    proc = subprocess.run(["make", "--no-print-directory", *args], cwd=tree, env=e,
                          capture_output=True, text=True, timeout=600)
    return proc.returncode, proc.stdout + proc.stderr


def digest(tree, module):
    rc, out = make(tree, f"wp-inputs-{module}")
    assert rc == 0, out
    return out.strip().splitlines()[-1]


def append(path, text):
    with open(path, "a", encoding="utf-8") as f:
        f.write(text)


def test_digest_follows_the_module_sources_and_every_shared_header(tree):
    before = {m: digest(tree, m) for m in ("sem", "wq", "chibios_time")}
    append(os.path.join(tree, "kernel", "src", "wq.c"), "/* one line */\n")
    after = {m: digest(tree, m) for m in before}
    assert after["wq"] != before["wq"]
    assert after["sem"] == before["sem"] and after["chibios_time"] == before["chibios_time"]
    append(os.path.join(tree, "kernel", "spec", "mt_spec.h"), "/* one line */\n")
    assert digest(tree, "sem") != after["sem"]
    # the flags are inputs too
    rc, out = make(tree, "wp-inputs-sem", "WP_TIMEOUT=21")
    assert rc == 0 and out.strip().splitlines()[-1] != digest(tree, "sem")


def test_module_replayed_only_with_identical_inputs_and_only_when_asked(tree):
    wp = os.path.join(tree, "build", "proof", "wp", "status")
    rc, out = make(tree, "wp-status", env={"WP_REUSE_LOCAL": "yes"})
    assert rc == 0 and "wp status" in out and "replayed" not in out, out
    assert os.path.exists(os.path.join(wp, "inputs.txt"))
    assert not os.path.exists(os.path.join(wp, "replayed.txt"))

    rc, out = make(tree, "wp-status", env={"WP_REUSE_LOCAL": "yes"})
    assert rc == 0 and "replayed from the run of" in out, out
    assert os.path.exists(os.path.join(wp, "replayed.txt"))

    # make prove's setting: Frama-C runs, the replay mark goes
    rc, out = make(tree, "wp-status")
    assert rc == 0 and "replayed" not in out, out
    assert not os.path.exists(os.path.join(wp, "replayed.txt"))

    # a one-line change in the module's source: run again, not replayed
    append(os.path.join(tree, "kernel", "src", "status.c"), "/* one line */\n")
    rc, out = make(tree, "wp-status", env={"WP_REUSE_LOCAL": "yes"})
    assert rc == 0 and "replayed" not in out, out
    assert not os.path.exists(os.path.join(wp, "replayed.txt"))
