# SPDX-License-Identifier: Apache-2.0
"""The translator tests' summary: build/proof/cbmc/test/summary.json, read by
tools/proof_report.py and tools/proof_gate.py (`make prove` counts a skipped test as not
passed). Written at the end of every pytest run that loads this folder."""

import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
WORK = os.path.join(ROOT, "build", "proof", "cbmc", "test")

# test id -> "passed", "failed" or "skipped": a failure in its setup, call or teardown fails
# it, else a skip skips it
OUTCOMES = {}


def pytest_runtest_logreport(report):
    old = OUTCOMES.get(report.nodeid)
    if report.failed:
        OUTCOMES[report.nodeid] = "failed"
    elif report.skipped and old != "failed":
        OUTCOMES[report.nodeid] = "skipped"
    elif report.when == "call" and old is None:
        OUTCOMES[report.nodeid] = "passed"


def pytest_sessionfinish(session, exitstatus):
    failed = sum(1 for v in OUTCOMES.values() if v == "failed")
    skipped = sum(1 for v in OUTCOMES.values() if v == "skipped")
    summary = {"tests": len(OUTCOMES), "failed": failed, "skipped": skipped,
               "passed": len(OUTCOMES) - failed - skipped,
               "not_passed": [k for k, v in OUTCOMES.items() if v != "passed"]}
    os.makedirs(WORK, exist_ok=True)
    with open(os.path.join(WORK, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
        f.write("\n")
