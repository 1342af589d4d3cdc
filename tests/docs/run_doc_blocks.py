#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Runs every ```sh block of the given Markdown files against a build (docs/doc-tests.md says how).

Each block runs under `bash -e -o pipefail` in a fresh scratch checkout: symlinks to the source tree's top-level
entries, a build/ directory of symlinks to the build tree's entries, and ../shared beside it when the source tree
has one, with build/bin first on PATH. A ```text block that directly follows a ```sh block lists lines that must
each appear in the block's output (stdout and stderr). An HTML comment on the line before a block's fence marks it:
  <!-- doc-test: slow -->     run only with --slow (CTest label slow)
  <!-- doc-test: mpi -->      run only when the build has MPI (--with-mpi ON)
  <!-- doc-test: shared -->   run only when ../shared exists beside the source tree (as are blocks naming ../shared)
Several marks are separated by spaces (<!-- doc-test: slow shared -->).
The Quick start's `make run` and `make test` lines are not run here (they run CTest themselves); .ci/run runs them.
Exit status 0 when every block ran with status 0 and printed its expected lines.

  run_doc_blocks.py --source DIR --build DIR [--slow] [--with-mpi ON|OFF] FILE.md...
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

FENCE = re.compile(r"^(`{3,})\s*([\w+-]*)\s*$")
MARK = re.compile(r"^<!--\s*doc-test:\s*([\w\s-]+?)\s*-->\s*$")
SKIPPED_LINES = {
    "make run": "builds and runs the main job itself; .ci/run runs it before `make test`",
    "make test": "runs CTest, which runs this test (recursion); .ci/run runs it",
}
NOT_ALLOWED = {"bash", "shell", "console", "shell-session"}  # commands belong in ```sh blocks, which are run
BLOCK_TIMEOUT_S = 600


class Block:
    def __init__(self, path, line, lang, text, mark):
        self.path, self.line, self.lang, self.text = path, line, lang, text
        self.marks = set(mark.split()) if mark else set()
        self.followed_by_text = False  # a ```text block follows, blank lines only between
        self.expected = []


def parse(path):
    """The fenced blocks of one Markdown file, each ```text block directly after a ```sh block as its expectation."""
    lines = open(path, encoding="utf-8").read().split("\n")
    blocks, i, last_nonblank = [], 0, ""
    while i < len(lines):
        match = FENCE.match(lines[i])
        if not match:
            if lines[i].strip():
                last_nonblank = lines[i]
            i += 1
            continue
        fence, lang, start = match.group(1), match.group(2), i
        body = []
        i += 1
        while i < len(lines) and lines[i].rstrip() != fence:
            body.append(lines[i])
            i += 1
        mark = MARK.match(last_nonblank.strip())
        blocks.append(Block(path, start + 1, lang, "\n".join(body), mark.group(1) if mark else None))
        last_nonblank = ""
        j = i + 1
        while j < len(lines) and not lines[j].strip():
            j += 1
        nxt = FENCE.match(lines[j]) if j < len(lines) else None
        blocks[-1].followed_by_text = bool(nxt and nxt.group(2) == "text")
        i += 1
    for previous, block in zip(blocks, blocks[1:]):
        if previous.lang == "sh" and previous.followed_by_text and block.lang == "text":
            previous.expected = [line.strip() for line in block.text.split("\n") if line.strip()]
    return blocks


def scratch_checkout(root, source, build):
    """root/checkout: links to the source's entries and build/ of links to the build's; root/shared: ../shared."""
    checkout = os.path.join(root, "checkout")
    os.makedirs(os.path.join(checkout, "build"))
    for name in os.listdir(source):
        if name not in ("build", ".git") and not os.path.exists(os.path.join(checkout, name)):
            os.symlink(os.path.join(source, name), os.path.join(checkout, name))
    for name in os.listdir(build):
        os.symlink(os.path.join(build, name), os.path.join(checkout, "build", name))
    shared = os.path.join(os.path.dirname(source), "shared")
    if os.path.isdir(shared):
        os.symlink(shared, os.path.join(root, "shared"))
    return checkout


def script_of(block):
    """The block's text without the lines that are not run here, and a note for each of those."""
    kept, notes = [], []
    for line in block.text.split("\n"):
        command = line.split("#", 1)[0].strip()
        if command in SKIPPED_LINES:
            notes.append(f"  not run: `{command}`: {SKIPPED_LINES[command]}")
            kept.append(": " + line.replace("`", "'"))
        else:
            kept.append(line)
    return "\n".join(kept), notes


def run_block(block, args):
    script, notes = script_of(block)
    for note in notes:
        print(note)
    root = tempfile.mkdtemp(prefix="ctab_doc_", dir=args.tmp)
    try:
        checkout = scratch_checkout(root, args.source, args.build)
        env = dict(os.environ)
        env["PATH"] = os.pathsep.join([os.path.join(checkout, "build", "bin"), "/usr/bin", env.get("PATH", "")])
        env.setdefault("OMP_NUM_THREADS", "2")
        if os.geteuid() == 0:  # OpenMPI refuses root unless told; CI runs as root
            env["OMPI_ALLOW_RUN_AS_ROOT"] = env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
        start = time.monotonic()
        try:
            done = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", script], cwd=checkout, env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=BLOCK_TIMEOUT_S)
            output, code = done.stdout.decode("utf-8", "replace"), done.returncode
        except subprocess.TimeoutExpired as expired:
            output, code = (expired.stdout or b"").decode("utf-8", "replace"), f"timeout {BLOCK_TIMEOUT_S} s"
        elapsed = time.monotonic() - start
    finally:
        shutil.rmtree(root, ignore_errors=True)
    missing = [line for line in block.expected if line not in output]
    where = f"{os.path.relpath(block.path, args.source)}:{block.line}"
    if code == 0 and not missing:
        print(f"ok   {where} ({elapsed:.1f} s)")
        return True
    print(f"FAIL {where} ({elapsed:.1f} s): exit status {code}")
    for line in missing:
        print(f"  expected line not in the output: {line}")
    print("---- block ----\n" + script + "\n---- output ----\n" + output + "----")
    return False


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--source", required=True, help="source tree (the checkout)")
    parser.add_argument("--build", required=True, help="build tree (build/bin/ctab, build/lib, ...)")
    parser.add_argument("--slow", action="store_true", help="run only the blocks marked slow")
    parser.add_argument("--with-mpi", default="OFF", help="ON: run the blocks marked mpi")
    parser.add_argument("--tmp", default=None, help="where the scratch checkouts go (default: TEST_TMPDIR or /tmp)")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    args.source, args.build = os.path.abspath(args.source), os.path.abspath(args.build)
    args.tmp = args.tmp or os.environ.get("TEST_TMPDIR") or None
    failed, ran = 0, 0
    for path in args.files:
        for block in parse(path):
            where = f"{os.path.relpath(block.path, args.source)}:{block.line}"
            if block.lang in NOT_ALLOWED:
                print(f"FAIL {where}: a ```{block.lang} block; commands go in ```sh blocks (run), output in ```text")
                failed += 1
                continue
            if block.lang != "sh" or ("slow" in block.marks) != args.slow:
                continue
            if "mpi" in block.marks and args.with_mpi.upper() not in ("ON", "1", "TRUE", "YES"):
                print(f"skip {where}: needs a build with MPI (CTAB_WITH_MPI=ON)")
                continue
            needs_shared = "shared" in block.marks or "../shared" in block.text
            if needs_shared and not os.path.isdir(os.path.join(os.path.dirname(args.source), "shared")):
                print(f"skip {where}: needs the project's shared data, ../shared beside the source tree")
                continue
            ran += 1
            failed += 0 if run_block(block, args) else 1
    print(f"{ran} block(s) run, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
