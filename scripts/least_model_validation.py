#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Validation of the least model (docs/validation.md "The least model"): the S1002/UIC60 sweep dy -6 ... +8 mm in 0.1 mm,
single wheel, 78.5 kN normal force, with the built-in and the Manchester profiles. For each set it generates three
tables with `ctab generate --threads 1`: MIM-1D at 0.05 mm (the reference), MIM-1D at 0.2 mm and `method = "auto"`
(tolerance 0.02), reports the error of the latter two against the reference (larger of total area and max pressure,
relative: max, p95, median), the least model's choices (/wheels/strip_width_m), and the sweep time (ctab's own
"in X s" figure) of RUNS alternating runs of both: median and minimum, and the speed-up.

Usage: scripts/least_model_validation.py CTAB SHARED_PROFILES_DIR [--runs 7] [--tolerance 0.02]
Needs Debian's python3-h5py and python3-numpy (/usr/bin/python3).
"""
import argparse
import collections
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile

import h5py
import numpy as np

SOLVER = {"reference": 'method = "mim1d"\nstrip_width_m = 0.05e-3',
          "mim1d_0.2mm": 'method = "mim1d"\nstrip_width_m = 0.2e-3',
          "auto": 'method = "auto"\ntolerance = {tolerance}'}


def config(profiles: str, solver: str) -> str:
    return (f"[profiles]\n{profiles}\n[solver]\nmode = \"wheel\"\n{solver}\n[axes]\n"
            "lateral_displacement_m = { start = -6e-3, stop = 8e-3, step = 0.1e-3 }\nnormal_load_N = 78.5e3\n")


def generate(ctab: str, toml: pathlib.Path, out: pathlib.Path) -> float:
    run = subprocess.run([ctab, "generate", "--threads", "1", "-o", str(out), str(toml)], capture_output=True,
                         text=True, check=True)
    return float(re.search(r" in ([0-9.]+) s on", run.stdout + run.stderr).group(1))


def totals(path: pathlib.Path):
    with h5py.File(path) as f:
        area = f["/patches/area_m2"][:, 0, 0, :].sum(-1)
        pressure = f["/patches/max_pressure_Pa"][:, 0, 0, :].max(-1)
        status = f["/wheels/status"][:, 0, 0].astype(int)
        width = f["/wheels/strip_width_m"][:, 0, 0] if "/wheels/strip_width_m" in f else None
    return area, pressure, status, width


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("ctab")
    parser.add_argument("profiles_dir")
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--tolerance", type=float, default=0.02)
    a = parser.parse_args()
    a.profiles_dir = str(pathlib.Path(a.profiles_dir).resolve())  # the configs live in a temporary directory
    sets = {"built-in": 'wheel = "S1002"\nrail = "UIC60"\ninclination = "1/40"',
            "Manchester": f'wheel = "{a.profiles_dir}/MBench_S1002_v3.prw"\n'
                          f'rail = "{a.profiles_dir}/MBench_UIC60_v3.prr"\ninclination = "0"'}
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        for name, profiles in sets.items():
            tables = {}
            for variant, solver in SOLVER.items():
                toml = work / f"{variant}.toml"
                toml.write_text(config(profiles, solver.format(tolerance=a.tolerance)))
                tables[variant] = work / f"{variant}.h5"
                generate(a.ctab, toml, tables[variant])
            ref_area, ref_pressure, ref_status, _ = totals(tables["reference"])
            for variant in ("mim1d_0.2mm", "auto"):
                area, pressure, status, width = totals(tables[variant])
                ok = (ref_status >= 0) & (status >= 0) & (ref_area > 0)
                err = np.maximum(abs(area / ref_area - 1), abs(pressure / ref_pressure - 1))[ok]
                line = (f"{name:10s} {variant:12s} {ok.sum()}/{len(ok)} cases: error max {100 * err.max():.2f} %, "
                        f"p95 {100 * np.percentile(err, 95):.2f} %, median {100 * np.median(err):.2f} %; "
                        f"under-resolved {int((status == 2).sum())}")
                if variant == "auto" and width is not None:
                    choices = collections.Counter(np.round(width * 1e3, 3).tolist())
                    line += "; widths " + ", ".join(f"{w:g} mm x{n}" for w, n in sorted(choices.items()))
                print(line)
            times = collections.defaultdict(list)
            for _ in range(a.runs):
                for variant in ("mim1d_0.2mm", "auto"):
                    times[variant].append(generate(a.ctab, work / f"{variant}.toml", work / "timing.h5"))
            plain, least = times["mim1d_0.2mm"], times["auto"]
            print(f"{name:10s} sweep time over {a.runs} runs: mim1d 0.2 mm median {statistics.median(plain):.3f} s "
                  f"(min {min(plain):.3f}), auto median {statistics.median(least):.3f} s (min {min(least):.3f}); "
                  f"speed-up {statistics.median(plain) / statistics.median(least):.2f}x median, "
                  f"{min(plain) / min(least):.2f}x min")
    return 0


if __name__ == "__main__":
    sys.exit(main())
