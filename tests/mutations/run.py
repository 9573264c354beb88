#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Deliberate mutations the tests must catch.

Each mutation changes one line of the code under test, builds, and runs the check that
must fail on it: the test command's ctest suite in the release build ("test", stopped at
the first failure) or the deep gate's ThreadSanitizer phase ("tsan"). The source is
restored after each, whatever happens. A mutation the check does not catch is reported
and makes the script fail.

    tests/mutations/run.py [--build BUILD] [NAME...]     (default: build, every mutation)
"""
import argparse
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]

# name, file, the exact text replaced (it must occur once), its replacement, the check.
MUTATIONS = [
    ("jacobi-sign", "core/recipe/session.cpp",
     "                dx[a] = r[a] * inv;",
     "                dx[a] = -r[a] * inv;", "test"),
    ("obj-index-off-by-one", "core/io/read_obj.cpp",
     "raw < 0 ? so_far + raw : raw - 1;",
     "raw < 0 ? so_far + raw : raw;", "test"),
    ("lost-undo-capture", "app/edit/command.h",
     '        .label = "delete set",\n        .captures = kSets,',
     '        .label = "delete set",\n        .captures = 0,', "test"),
    ("save-skips-rename", "core/io/io.cpp",
     "    const int fd = ::mkostemp(tmp.data(), O_CLOEXEC);",
     "    tmp = target; // written in place: no temporary, the rename a no-op\n"
     "    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);",
     "test"),
    ("panel-click-reaches-view", "app/editor/input_router.cpp",
     None, None, "test"),
    ("live-solver-race", "app/editor/live_solver.cpp",
     "std::vector<EnergySample> LiveSolver::energies() const\n{\n    std::lock_guard lock(mutex_);",
     "std::vector<EnergySample> LiveSolver::energies() const\n{", "tsan"),
]


def panel_click(text):
    """The first button press that waits for the interface to let the mouse go."""
    old = "                if (!mouse_captured)"
    at = text.index(old)
    return text[:at] + "                if (true)" + text[at + len(old):]


def check_command(kind, build):
    if kind == "test":
        return ["ctest", "--test-dir", build, "-j2", "--stop-on-failure", "--output-on-failure"]
    if kind == "tsan":
        return ["./.ci/tsan.sh"]
    raise ValueError(kind)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("names", nargs="*")
    args = parser.parse_args()
    chosen = [m for m in MUTATIONS if not args.names or m[0] in args.names]
    logs = ROOT / args.build / "mutations"
    logs.mkdir(parents=True, exist_ok=True)
    rows, survived = [], []
    for name, rel, old, new, kind in chosen:
        path = ROOT / rel
        original = path.read_text()
        if old is None:
            mutated = panel_click(original)
        else:
            if original.count(old) != 1:
                sys.exit(f"mutation {name}: the text to replace occurs {original.count(old)} times in {rel}")
            mutated = original.replace(old, new)
        start = time.monotonic()
        try:
            path.write_text(mutated)
            log = (logs / f"{name}.log").open("w")
            built = subprocess.run(["cmake", "--build", args.build, "-j2"], cwd=ROOT,
                                   stdout=log, stderr=subprocess.STDOUT).returncode == 0
            if not built:
                outcome = "caught (does not build)"
            else:
                code = subprocess.run(check_command(kind, args.build), cwd=ROOT, stdout=log,
                                      stderr=subprocess.STDOUT).returncode
                outcome = "caught" if code != 0 else "SURVIVED"
            log.close()
        finally:
            path.write_text(original)
        failed = [line.strip() for line in (logs / f"{name}.log").read_text().splitlines()
                  if "***Failed" in line or "ThreadSanitizer: data race" in line
                  or "***Timeout" in line][:3]
        rows.append((name, rel, kind, outcome, int(time.monotonic() - start), "; ".join(failed)))
        print(f"{name:26} {kind:5} {outcome:10} {rows[-1][4]:5d} s  {rows[-1][5]}", flush=True)
        if outcome == "SURVIVED":
            survived.append(name)
    # The tree as it was: rebuilt, so that what follows does not test a mutant.
    subprocess.run(["cmake", "--build", args.build, "-j2"], cwd=ROOT, stdout=subprocess.DEVNULL)
    print(f"{len(rows) - len(survived)} of {len(rows)} mutations caught"
          + (f"; survived: {', '.join(survived)}" if survived else ""))
    return 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())
