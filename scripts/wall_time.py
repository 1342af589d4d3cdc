#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Wall time of whole processes, interleaved: wall_time.py BIN1[,BIN2...] ARGS... runs each binary with ARGS,
N times in turn (N from the environment, default 15), and prints each binary's minimum and median [s]. An entry
BIN:EXTRA runs BIN with ARGS EXTRA (the same binary on two configs: `build/bin/ctab,build/bin/ctab:planar.toml
generate -o /tmp/t.h5 --force --quiet`). Interleaving puts the drift of a shared machine on every entry alike
(docs/performance.md)."""
import os
import statistics
import subprocess
import sys
import time

if len(sys.argv) < 2:
    sys.exit("usage: wall_time.py BIN1[,BIN2...] ARGS...")
binaries = sys.argv[1].split(",")
arguments = sys.argv[2:]
runs = int(os.environ.get("N", "15"))
times = {b: [] for b in binaries}
for _ in range(runs):
    for b in binaries:
        start = time.perf_counter()
        binary, _, extra = b.partition(":")
        subprocess.run([binary] + arguments + ([extra] if extra else []), check=True)
        times[b].append(time.perf_counter() - start)
for b in binaries:
    print(f"{b} min {min(times[b]):.4f} median {statistics.median(times[b]):.4f}")
