# SPDX-License-Identifier: Apache-2.0
"""Every TLC run has a java.io.tmpdir of its own (tla/run_tlc.py, tools/trace/run_traces.py).

TLC copies the standard modules (Naturals.tla, ...) into java.io.tmpdir before it parses them.
With the default /tmp, models, traces and mutants checked side by side read each other's
half-written copies and fail with "Parsing or semantic analysis failed" (seen once in CI, on
Wq_SignalAnyRun). These tests put a fake `java` first on PATH that records its arguments and
checks its tmpdir, and run the real drivers with it.

    /usr/bin/python3 -m pytest -q tests/proofs/test_tlc_tmpdir.py
"""
import importlib.util
import json
import os
import subprocess
import sys
import types

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_prove_driver import put_exec  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

# Records argv and cwd as one JSON line, fails (exit 3) when the tmpdir it was given is missing
# or outside its working directory, and prints a TLC-like "no error" log.
FAKE_JAVA = r"""#!/usr/bin/env python3
import json, os, sys
if sys.argv[1:] == ["-version"]:  # run_tlc.py's input digest (--reuse-local)
    sys.exit(0)
tmp = [a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("-Djava.io.tmpdir=")]
with open(os.environ["FAKE_JAVA_LOG"], "a") as f:
    f.write(json.dumps({"argv": sys.argv[1:], "cwd": os.getcwd()}) + "\n")
if len(tmp) != 1 or not os.path.isdir(tmp[0]) or \
        not os.path.realpath(tmp[0]).startswith(os.path.realpath(os.getcwd()) + os.sep):
    print("fake java: no private tmpdir")
    sys.exit(3)
print("Model checking completed. No error has been found.")
print("10 states generated, 5 distinct states found, 0 states left on queue.")
"""


def fake_env(tmp_path):
    bindir = tmp_path / "bin"
    put_exec(str(bindir / "java"), FAKE_JAVA)
    log = tmp_path / "java.log"
    env = dict(os.environ, PATH=str(bindir) + os.pathsep + os.environ["PATH"],
               FAKE_JAVA_LOG=str(log))
    return env, log


def calls(log):
    with open(log) as f:
        return [json.loads(line) for line in f]


def tmpdir_of(call):
    return [a.split("=", 1)[1] for a in call["argv"] if a.startswith("-Djava.io.tmpdir=")]


def test_run_tlc_gives_each_model_its_own_tmpdir(tmp_path):
    env, log = fake_env(tmp_path)
    jar = tmp_path / "tla2tools.jar"
    jar.write_text("")
    out = tmp_path / "out"
    names = ["Wq_SignalAnyRun", "Bus_q1", "Sched_fit"]
    p = subprocess.run([sys.executable, os.path.join(ROOT, "tla", "run_tlc.py"), "--jar", str(jar),
                        "--out", str(out), "-j", "3", "--only"] + names,
                       cwd=ROOT, env=env, capture_output=True, text=True)
    seen = calls(log)
    assert len(seen) == 3, p.stdout + p.stderr
    dirs = [tmpdir_of(c) for c in seen]
    assert all(len(d) == 1 for d in dirs)
    assert len({d[0] for d in dirs}) == 3          # never shared between models
    for c, d in zip(seen, dirs):
        assert d[0].startswith(c["cwd"] + os.sep)  # inside the model's own work folder
    assert "fake java: no private tmpdir" not in p.stdout + p.stderr


def load_traces():
    spec = importlib.util.spec_from_file_location(
        "run_traces", os.path.join(ROOT, "tools", "trace", "run_traces.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_trace_tlc_gives_each_trace_its_own_tmpdir(tmp_path, monkeypatch):
    env, log = fake_env(tmp_path)
    monkeypatch.setenv("PATH", env["PATH"])
    monkeypatch.setenv("FAKE_JAVA_LOG", env["FAKE_JAVA_LOG"])
    rt = load_traces()
    args = types.SimpleNamespace(jar=str(tmp_path / "tla2tools.jar"), timeout=30)
    works = []
    for label in ("a", "b"):
        work = tmp_path / label
        work.mkdir()
        works.append(str(work))
        rt.tlc(args, str(work), "RingTrace")
    seen = calls(log)
    assert len(seen) == 2
    dirs = [tmpdir_of(c) for c in seen]
    assert [len(d) for d in dirs] == [1, 1]
    assert dirs[0][0] != dirs[1][0]
    for w, d in zip(works, dirs):
        assert d[0].startswith(w + os.sep)


# A passing TLC log with the state count pinned for the entry in FAKE_DISTINCT.
FAKE_JAVA_PASS = r"""#!/usr/bin/env python3
import json, os, sys
if sys.argv[1:] == ["-version"]:
    print('openjdk version "17-fake"', file=sys.stderr)
    sys.exit(0)
with open(os.environ["FAKE_JAVA_LOG"], "a") as f:
    f.write(json.dumps({"argv": sys.argv[1:], "cwd": os.getcwd()}) + "\n")
print("Model checking completed. No error has been found.")
print("9 states generated, %s distinct states found, 0 states left on queue."
      % os.environ["FAKE_DISTINCT"])
"""


def test_run_tlc_reuse_local_replays_only_identical_inputs(tmp_path):
    """make reprove (--reuse-local): a run whose inputs are those of the output folder's last
    passing run is replayed and marked, any change of an input runs TLC again, and a run
    without the flag always runs it."""
    bindir = tmp_path / "bin"
    put_exec(str(bindir / "java"), FAKE_JAVA_PASS)
    log = tmp_path / "java.log"
    log.write_text("")
    pinned = [e for e in json.load(open(os.path.join(ROOT, "tla", "models.json")))["models"]
              if e["name"] == "Sem_2w"][0]["distinct_states"]
    env = dict(os.environ, PATH=str(bindir) + os.pathsep + os.environ["PATH"],
               FAKE_JAVA_LOG=str(log), FAKE_DISTINCT=str(pinned))
    jar = tmp_path / "tla2tools.jar"
    jar.write_text("v1")
    out = tmp_path / "out"

    def run(*extra):
        before = len(calls(log))
        p = subprocess.run([sys.executable, os.path.join(ROOT, "tla", "run_tlc.py"), "--jar",
                            str(jar), "--out", str(out), "--only", "Sem_2w"] + list(extra),
                           cwd=ROOT, env=env, capture_output=True, text=True)
        assert p.returncode == 0, p.stdout + p.stderr
        with open(out / "summary.json") as f:
            return len(calls(log)) - before, json.load(f), p.stdout

    ran, s, _ = run("--reuse-local")            # nothing recorded yet: runs
    assert ran == 1 and s["passed"] == 1 and "replayed_local" not in s
    ran, s, text = run("--reuse-local")         # same inputs: replayed, marked
    assert ran == 0 and s["replayed_local"] and "not checked now" in text
    ran, s, _ = run()                            # make prove: always runs
    assert ran == 1 and "replayed_local" not in s
    jar.write_text("v2")                         # another TLC
    ran, s, _ = run("--reuse-local")
    assert ran == 1 and "replayed_local" not in s
    ran, s, _ = run("--reuse-local", "--timeout", "99")   # another option
    assert ran == 1
    env["FAKE_DISTINCT"] = "1"                   # a failed run is never replayed
    p = subprocess.run([sys.executable, os.path.join(ROOT, "tla", "run_tlc.py"), "--jar",
                        str(jar), "--out", str(out), "--only", "Sem_2w"], cwd=ROOT, env=env,
                       capture_output=True, text=True)
    assert p.returncode == 1
    env["FAKE_DISTINCT"] = str(pinned)
    ran, s, _ = run("--reuse-local")
    assert ran == 1 and s["passed"] == 1
