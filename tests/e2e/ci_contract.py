#!/usr/bin/env python3
"""What CI promises about its own runs, held against the scripts that make them (issue 60 item 5).

- Golden files are compared, never approved: scripts/test.sh, .ci/run and debian/rules drop
  APCS_APPROVE, so a caller's environment cannot turn every golden comparison into a warning.
- A test that reports a skip fails CI: .ci/run sets APCS_REQUIRE_EVERY_TEST, and both phases
  (scripts/test.sh, tests/e2e/debian_package.sh) fail on ctest's "The following tests did not run".
- The tests that need the machine to themselves run one at a time across CI's two side-by-side
  phases: every RUN_SERIAL test's script sources tests/e2e/one_at_a_time.sh, and two scripts that
  do, started together with APCS_TERMINAL_TEST_LOCK set, run one after the other (measured here).

Usage: ci_contract.py SOURCE_FOLDER
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

failures = []


def check(condition, what):
    print(("ok      " if condition else "FAILED  ") + what)
    if not condition:
        failures.append(what)


def text(source, name):
    with open(os.path.join(source, name), encoding="utf-8") as file:
        return file.read()


def approvals_dropped(source):
    check(re.search(r"^unset APCS_APPROVE$", text(source, "scripts/test.sh"), re.M) is not None,
          "scripts/test.sh unsets APCS_APPROVE before ctest")
    check(re.search(r"^unset APCS_APPROVE$", text(source, ".ci/run"), re.M) is not None,
          ".ci/run unsets APCS_APPROVE")
    check(re.search(r"^unexport APCS_APPROVE$", text(source, "debian/rules"), re.M) is not None,
          "debian/rules unexports APCS_APPROVE (dh_auto_test)")


def skips_fail(source):
    check(re.search(r"^export APCS_REQUIRE_EVERY_TEST=1$", text(source, ".ci/run"), re.M) is not None,
          ".ci/run requires every test to run")
    for script in ("scripts/test.sh", "tests/e2e/debian_package.sh"):
        body = text(source, script)
        check("APCS_REQUIRE_EVERY_TEST" in body and "The following tests did not run:" in body,
              f"{script} fails on a test that did not run when APCS_REQUIRE_EVERY_TEST is set")


def serial_scripts(source):
    """The script of every test with RUN_SERIAL, from tests/CMakeLists.txt."""
    cmake = text(source, "tests/CMakeLists.txt")
    scripts = {}
    for match in re.finditer(r"add_test\(NAME (\S+)\s+COMMAND bash \$\{CMAKE_CURRENT_SOURCE_DIR\}/(e2e/\S+\.sh)", cmake):
        scripts[match.group(1)] = match.group(2)
    serial = set()
    for match in re.finditer(r"set_tests_properties\(([^)]*?)PROPERTIES([^)]*)\)", cmake, re.S):
        if "RUN_SERIAL TRUE" in match.group(2):
            serial.update(match.group(1).split())
    found = {}
    for test in serial:
        # A test named in a foreach: e2e_batch_faults_${fault} matches its add_test by the same text.
        if test in scripts:
            found[test] = scripts[test]
    return serial, found


def serial_tests_lock(source):
    serial, found = serial_scripts(source)
    check(len(serial) >= 15, f"tests/CMakeLists.txt names {len(serial)} RUN_SERIAL tests (15 or more)")
    check(len(found) == len(serial), f"each RUN_SERIAL test's script is found ({len(found)} of {len(serial)})")
    for test, script in sorted(found.items()):
        body = text(source, os.path.join("tests", script))
        check('source "$(dirname "$0")/one_at_a_time.sh"' in body, f"{test} ({script}) takes the lock")


def lock_serialises(source):
    with tempfile.TemporaryDirectory() as folder:
        shutil.copy(os.path.join(source, "tests/e2e/one_at_a_time.sh"), folder)
        script = os.path.join(folder, "hold.sh")
        with open(script, "w") as file:
            file.write('set -euo pipefail\nsource "$(dirname "$0")/one_at_a_time.sh"\n'
                       'echo "start $1" >> "$2"; sleep 0.5; echo "end $1" >> "$2"\n')
        log = os.path.join(folder, "log")
        environment = dict(os.environ, APCS_TERMINAL_TEST_LOCK=os.path.join(folder, "lock"))
        runs = [subprocess.Popen(["bash", script, name, log], env=environment) for name in ("a", "b")]
        for run in runs:
            run.wait()
        with open(log) as file:
            lines = file.read().split("\n")[:-1]
        first, second = lines[0].split()[1], lines[2].split()[1] if len(lines) > 2 else "?"
        check(lines == [f"start {first}", f"end {first}", f"start {second}", f"end {second}"] and first != second,
              f"two locked scripts started together ran one after the other: {lines}")
        # Without the lock variable they overlap: the check above can tell the two apart.
        os.remove(log)
        environment.pop("APCS_TERMINAL_TEST_LOCK")
        runs = [subprocess.Popen(["bash", script, name, log], env=environment) for name in ("a", "b")]
        for run in runs:
            run.wait()
        with open(log) as file:
            lines = file.read().split("\n")[:-1]
        check([line.split()[0] for line in lines[:2]] == ["start", "start"],
              f"without APCS_TERMINAL_TEST_LOCK the same scripts overlap: {lines}")


def run_hint_fits(source):
    """README's first command (scripts/run.sh) prints a hint before and after the session."""
    body = text(source, "scripts/run.sh")
    hint = re.search(r'^hint="(.*?)"$', body, re.M | re.S)
    check(hint is not None, "scripts/run.sh has its hint")
    if hint:
        lines = hint.group(1).split("\n")
        widest = max(len(line) for line in lines)
        check(widest < 80, f"scripts/run.sh's hint wraps nothing at 80 columns (widest line {widest})")
    for printed in re.findall(r"^printf '([^']*)'", body, re.M):
        for line in printed.split("\\n"):
            width = len(line.replace("%s", "build/session-n-to-l"))
            check(width < 80, f"scripts/run.sh prints '{line}' in {width} columns (under 80)")


def main():
    source = sys.argv[1]
    run_hint_fits(source)
    approvals_dropped(source)
    skips_fail(source)
    serial_tests_lock(source)
    lock_serialises(source)
    if failures:
        print(f"{len(failures)} failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
