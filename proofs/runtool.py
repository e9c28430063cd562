# SPDX-License-Identifier: Apache-2.0
"""Run one tool with a time limit and collect its CPU time: the helper the proof runners share
(proofs/cbmc/run.py, tla/run_tlc.py, tools/trace/run_traces.py).

    sys.path.insert(0, os.path.join(ROOT, "proofs")); from runtool import run_timed
"""
import os
import signal
import subprocess
import tempfile
import threading
import time
from collections import namedtuple

# rc: the exit status (negative: the signal); wall, cpu: seconds; out: stdout and stderr
# together; timed_out: the time limit killed it.
Run = namedtuple("Run", "rc wall cpu out timed_out")


def run_timed(cmd, timeout, cwd=None, env=None):
    """Run cmd in a process group of its own; after `timeout` seconds the whole group is
    killed (SIGKILL). The CPU time is the process's and its waited-for children's (wait4), so
    it is the run's own also when other runs go on beside it."""
    t0 = time.monotonic()
    fired = threading.Event()
    with tempfile.TemporaryFile(mode="w+") as log:
        # a process group, not a session: with the kernel's autogroup scheduling each session
        # gets an equal share of the CPU whatever its nice value, so a session per run would
        # take CPU from the tests CI runs beside the proofs at a lower priority (.ci/run)
        p = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT, text=True,
                             process_group=0)

        def kill():
            fired.set()
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass

        timer = threading.Timer(timeout, kill)
        timer.start()
        _, status, ru = os.wait4(p.pid, 0)
        timer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)
        log.seek(0)
        out = log.read()
    timed_out = fired.is_set() and p.returncode == -signal.SIGKILL
    return Run(p.returncode, time.monotonic() - t0, ru.ru_utime + ru.ru_stime, out, timed_out)
