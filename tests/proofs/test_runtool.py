# SPDX-License-Identifier: Apache-2.0
"""proofs/runtool.py: the proof runners' one helper for a tool run with a time limit and its
CPU time (CBMC's run.py, TLC's run_tlc.py, the trace runner)."""
import os
import signal
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "proofs"))
from runtool import run_timed  # noqa: E402


def test_exit_status_and_output_both_streams(tmp_path):
    r = run_timed(["sh", "-c", "echo out; echo err >&2; pwd; exit 3"], 30, cwd=str(tmp_path))
    assert r.rc == 3 and not r.timed_out
    assert r.out.split() == ["out", "err", str(tmp_path)]


def test_cpu_time_is_the_tools_own():
    # one second of CPU in a grandchild: counted (waited for by its parent), and the wall time
    # of a sleeping run is not counted as CPU
    busy = "import time\nt = time.process_time()\nwhile time.process_time() - t < 1.0: pass\n"
    r = run_timed(["sh", "-c", f"{sys.executable} -c '{busy}'"], 60)
    assert r.rc == 0 and 0.9 <= r.cpu <= r.wall + 0.5
    s = run_timed(["sleep", "1"], 60)
    assert s.cpu < 0.5 <= s.wall


def test_the_time_limit_kills_the_whole_group(tmp_path):
    pid_file = tmp_path / "pid"
    t0 = time.monotonic()
    r = run_timed(["sh", "-c", f"sleep 60 & echo $! > {pid_file}; wait"], 1)
    assert r.timed_out and r.rc == -signal.SIGKILL
    assert time.monotonic() - t0 < 30
    pid = int(pid_file.read_text())
    time.sleep(0.2)
    try:
        os.kill(pid, 0)
        with open(f"/proc/{pid}/stat", encoding="utf-8") as f:
            alive = f.read().split()[2] != "Z"
    except ProcessLookupError:
        alive = False
    assert not alive, "the tool's child outlived the time limit"


def test_a_run_that_ends_in_time_is_not_timed_out():
    r = run_timed(["sh", "-c", "kill -KILL $$"], 30)
    assert r.rc == -signal.SIGKILL and not r.timed_out


def test_a_run_has_a_group_of_its_own_in_the_callers_session():
    # its own process group (the time limit kills the group), but not its own session: a session
    # is an autogroup of the scheduler, which would void the nice value CI gives the proofs
    r = run_timed(["sh", "-c", "ps -o pid=,pgid=,sid= -p $$"], 30)
    pid, pgid, sid = (int(x) for x in r.out.split())
    assert pgid == pid != os.getpgrp()
    assert sid == os.getsid(0)
