#!/usr/bin/env python3
"""readme_commands.py - runs every command line of README.md's ```sh blocks
as written, and checks the paths docs/*.md's ```sh blocks name.

Usage: readme_commands.py SOURCE_DIR BUILD_DIR

Each command runs with bash in a scratch folder holding copies of scenes/,
examples/ and include/ and a link build -> BUILD_DIR, so relative paths work
and nothing lands in the source tree.  A line ending in a backslash joins the
next.  An HTML comment just before a block says what cannot run here, and
why; the test prints the reason of every line it does not run:

    <!-- readme-test: skip: REASON -->            no line of the block
    <!-- readme-test: skip-line TEXT: REASON -->  lines containing TEXT
    <!-- readme-test: xvfb: REASON -->            under xvfb-run, ended after
                                                  5 s (alive then: a pass)
    <!-- readme-test: mpi: REASON -->             only when rt-export-mpi and
                                                  mpirun exist; as root, a
                                                  line without
                                                  --allow-run-as-root is not run

A failing command fails the test, showing the command and its output.
In docs/*.md, every scenes/X and build/apps/X a ```sh block names must exist
(scenes/ in the source tree or the course's ../shared, as the docs say;
build/apps/ programs in the build when that program is built here: an optional
one, rt-view or rt-export-mpi, is reported when absent).
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

MARK = re.compile(r"<!--\s*readme-test:\s*(skip-line|skip|xvfb|mpi):?\s*(.*?)\s*-->")


def blocks(text):
    """(marks, lines) of each ```sh block; marks: the readme-test comments
    on the lines just before it."""
    lines = text.split("\n")
    out, i = [], 0
    while i < len(lines):
        if lines[i].strip() == "```sh":
            marks, k = [], i - 1
            while k >= 0 and MARK.search(lines[k]):
                m = MARK.search(lines[k])
                marks.append((m.group(1), m.group(2)))
                k -= 1
            body, i = [], i + 1
            while i < len(lines) and lines[i].strip() != "```":
                body.append(lines[i])
                i += 1
            out.append((marks, body))
        i += 1
    return out


def commands(body):
    cmds, cur = [], ""
    for line in body:
        if line.rstrip().endswith("\\"):
            cur += line.rstrip()[:-1] + " "
            continue
        cur += line
        if cur.strip() and not cur.strip().startswith("#"):
            cmds.append(cur.strip())
        cur = ""
    return cmds


def main():
    src, build = sys.argv[1], sys.argv[2]
    with open(os.path.join(src, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    scratch = tempfile.mkdtemp(prefix="readme-")
    for d in ("scenes", "examples", "include"):
        shutil.copytree(os.path.join(src, d), os.path.join(scratch, d))
    os.symlink(os.path.abspath(build), os.path.join(scratch, "build"))
    mpi = os.path.exists(os.path.join(build, "apps", "rt-export-mpi")) \
        and shutil.which("mpirun")
    xvfb = shutil.which("xvfb-run") and os.path.exists(
        os.path.join(build, "apps", "rt-view"))
    failures = ran = skipped = 0
    for marks, body in blocks(readme):
        kinds = dict(marks)
        for cmd in commands(body):
            why = None
            if "skip" in kinds:
                why = kinds["skip"]
            for kind, arg in marks:
                if kind == "skip-line":
                    text, _, reason = arg.partition(": ")
                    if text in cmd:
                        why = reason
            if why is None and "mpi" in kinds:
                if not mpi:
                    why = "rt-export-mpi or mpirun absent: " + kinds["mpi"]
                elif os.geteuid() == 0 and "--allow-run-as-root" not in cmd:
                    why = "Open MPI refuses root without --allow-run-as-root" \
                          " (the README's root form follows)"
            run = ["bash", "-c", "set -o pipefail; " + cmd]
            if why is None and "xvfb" in kinds:
                if not xvfb:
                    why = "no xvfb-run or no rt-view: " + kinds["xvfb"]
                else:
                    run = ["xvfb-run", "-a", "timeout", "5"] + run
            if why is not None:
                print("SKIP: %s\n      (%s)" % (cmd, why))
                skipped += 1
                continue
            print("$ " + cmd, flush=True)
            p = subprocess.run(run, cwd=scratch, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, timeout=600)
            ran += 1
            ok = p.returncode == 0 or ("xvfb" in kinds and p.returncode == 124)
            if not ok:
                failures += 1
                print("FAILED (exit %d): %s\n%s" % (
                    p.returncode, cmd, p.stdout.decode(errors="replace")[-3000:]))
    # docs: the paths their shell blocks name
    shared = os.path.join(src, "..", "shared")
    for name in sorted(os.listdir(os.path.join(src, "docs"))):
        if not name.endswith(".md"):
            continue
        with open(os.path.join(src, "docs", name), encoding="utf-8") as f:
            text = f.read()
        for _, body in blocks(text):
            for path in re.findall(r"(?<![\w/.-])(?:scenes|build/apps)/[A-Za-z0-9_.+-]+",
                                   "\n".join(body)):
                if path.startswith("scenes/"):
                    base = path[len("scenes/"):]
                    if os.path.exists(os.path.join(src, path)):
                        continue
                    if any(os.path.exists(os.path.join(shared, d, base))
                           for d in ("seed-scenes", "spd-scenes", "formats")):
                        continue
                    print("docs/%s names %s, which does not exist" % (name, path))
                    failures += 1
                elif not os.path.exists(os.path.join(build, path[6:])):
                    prog = os.path.basename(path)
                    if prog in ("rt-view", "rt-export-mpi"):
                        print("SKIP: docs/%s names %s, not built here" % (name, path))
                    else:
                        print("docs/%s names %s, which the build lacks" % (name, path))
                        failures += 1
    shutil.rmtree(scratch, ignore_errors=True)
    print("%d commands ran, %d not run (reasons above), %d failed"
          % (ran, skipped, failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
