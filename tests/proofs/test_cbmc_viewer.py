# SPDX-License-Identifier: Apache-2.0
"""`make cbmc-viewer`: cbmc-viewer's browsable report of a proof beside ours, and the viewer
reporting a failed property as failed.

    MT_REQUIRE_VIEWER=1 python3 -m pytest -q tests/proofs/test_cbmc_viewer.py

`make cbmc-test` (part of `make prove`) sets MT_REQUIRE_VIEWER=1: there a missing viewer is a
failure, not a skip. Elsewhere the tests skip when `tools/bootstrap.sh prove` has not run.
"""
import json
import os
import subprocess

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
BIN = os.path.join(ROOT, ".tools", "bin")
VIEWER = os.path.join(ROOT, ".tools", "cbmc-viewer")
NEEDED = (os.path.join(BIN, "cbmc"), os.path.join(BIN, "goto-analyzer"),
          os.path.join(VIEWER, "bin", "cbmc-viewer"))
INSTALLED = all(os.access(p, os.X_OK) for p in NEEDED)
pytestmark = pytest.mark.skipif(
    not INSTALLED and os.environ.get("MT_REQUIRE_VIEWER") != "1",
    reason="CBMC or cbmc-viewer not installed (tools/bootstrap.sh prove)")


def viewer_json(report, kind):
    with open(os.path.join(report, "json", f"viewer-{kind}.json"), encoding="utf-8") as f:
        return json.load(f)[f"viewer-{kind}"]


def test_report_of_a_proof(tmp_path):
    # its own folder: `make prove` may be running on build/proof at the same time (.ci/run)
    p = subprocess.run(["make", "--no-print-directory", "cbmc-viewer", "H=mt_status_str",
                        f"CBMC_VIEWER_WORK={tmp_path}"],
                       cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
    out = os.path.join(str(tmp_path), "mt_status_str")
    report = os.path.join(out, "report")
    assert os.path.exists(os.path.join(report, "html", "index.html"))
    assert os.path.exists(os.path.join(str(tmp_path), "gen", "mt_status_str_contract.h"))
    assert f"{out}/report/html/index.html" in p.stdout
    res = viewer_json(report, "result")
    assert res["prover"] == "success"
    # the viewer read the same property run as ours: one result per property of result.json
    with open(os.path.join(out, "result.json"), encoding="utf-8") as f:
        ours = [m for m in json.load(f) if "result" in m][0]["result"]
    assert res["results"]["false"] == [] and len(res["results"]["true"]) == len(ours)
    cov = viewer_json(report, "coverage")["overall_coverage"]
    assert 0 < cov["hit"] <= cov["total"]


def test_unknown_proof_is_an_error():
    p = subprocess.run(["make", "--no-print-directory", "cbmc-viewer", "H=mt_no_such_function"],
                       cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert p.returncode != 0 and "no proof mt_no_such_function" in p.stderr


def test_a_failed_property_reads_as_failed(tmp_path):
    src = tmp_path / "f.c"
    src.write_text("int nondet_int(void);\nvoid harness(void)\n{\n    int x = nondet_int();\n"
                   "    __CPROVER_assert(x != 7, \"never seven\");\n}\n", encoding="utf-8")
    goto = str(tmp_path / "f.goto")
    subprocess.run([os.path.join(BIN, "goto-cc"), "--function", "harness", "-o", goto, str(src)],
                   check=True, cwd=tmp_path)
    cbmc = os.path.join(BIN, "cbmc")
    for name, extra in (("result", []), ("coverage", ["--cover", "location"]),
                        ("property", ["--show-properties"])):
        with open(tmp_path / f"{name}.json", "w", encoding="utf-8") as f:
            rc = subprocess.run([cbmc, goto, "--json-ui"] + extra, stdout=f,
                                cwd=tmp_path).returncode
        assert rc in (0, 10), name
    env = dict(os.environ, PATH=BIN + os.pathsep + os.environ.get("PATH", ""), PYTHONPATH=VIEWER)
    subprocess.run(["python3", os.path.join(VIEWER, "bin", "cbmc-viewer"),
                    "--result", "result.json", "--coverage", "coverage.json",
                    "--property", "property.json", "--srcdir",
                    str(tmp_path), "--goto", goto, "--reportdir", "report"],
                   check=True, cwd=tmp_path, env=env, capture_output=True)
    res = viewer_json(str(tmp_path / "report"), "result")
    assert res["prover"] == "failure"
    # the one failed property is the assertion; the viewer names it among the false ones
    assert len(res["results"]["false"]) == 1
    assert res["results"]["false"][0].startswith("harness.assertion")
