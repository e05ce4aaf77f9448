"""Runs scipy's own test files (as Debian's python3-scipy installs them) with hullkit standing in:
used by test_interpolate.py and test_scipy_qhull.py. Nothing of scipy's files is kept in this
repository: each is read from the installed scipy, its imports rewritten in a temporary copy."""
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import pytest


def run_scipy_suites(tmp_path, directory, suites, *pytest_args):
    """Copies the test files ``suites`` ({file name: {old text: new text}}) from scipy's test
    ``directory`` into ``tmp_path`` with each old text (which must be there) replaced, links the
    directory's ``data`` beside them, runs pytest on them in a fresh interpreter and returns
    {"file.py::Class::test": "passed" | "failed" | "skipped"}."""
    missing = [name for name in suites if not os.path.exists(os.path.join(directory, name))]
    if missing:
        pytest.fail(f"scipy's test files {missing} are not installed in {directory} (Debian's python3-scipy has them)")
    for name, replacements in suites.items():
        text = open(os.path.join(directory, name)).read()
        for old, new in replacements.items():
            assert old in text, f"{name} no longer has {old!r}: update its replacements"
            text = text.replace(old, new)
        (tmp_path / name).write_text(text)
    if os.path.isdir(os.path.join(directory, "data")):
        os.symlink(os.path.join(directory, "data"), tmp_path / "data")
    report = tmp_path / "report.xml"
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", f"--junitxml={report}",
                          *pytest_args, *suites], cwd=tmp_path, capture_output=True, text=True)
    assert report.exists(), run.stdout[-2000:] + run.stderr[-2000:]
    outcomes = {}
    for case in ElementTree.parse(report).iter("testcase"):
        module, cls = case.get("classname").split(".", 1)
        failed = case.find("failure") is not None or case.find("error") is not None
        skipped = case.find("skipped") is not None
        outcomes[f"{module}.py::{cls}::{case.get('name')}"] = "skipped" if skipped else "failed" if failed else "passed"
    return outcomes


def assert_failures_are(outcomes, expected):
    """The failed tests are exactly ``expected``: naming any test that starts failing or passing."""
    failed = {name for name, outcome in outcomes.items() if outcome == "failed"}
    assert failed == expected, (f"newly failing: {sorted(failed - expected)}; "
                                f"now passing (update the expected failures): {sorted(expected - failed)}")
