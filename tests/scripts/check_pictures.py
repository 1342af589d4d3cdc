#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The picture scripts on small inputs: each writes a PNG (and the accuracy chart its SVG); the table's dimension
scales as h5py reads them. Exit 77 (CTest: skipped) where h5py or matplotlib is missing.

Usage: check_pictures.py CTAB SOURCE_DIR WORK_DIR {table|accuracy|stability}
"""
import csv
import os
import shutil
import subprocess
import sys

SKIP = 77


def need(*modules):
    for module in modules:
        try:
            __import__(module)
        except ImportError:
            print(f"skipped: no {module} for {sys.executable}")
            sys.exit(SKIP)


def run(*args):
    result = subprocess.run(args, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(args)}: exit {result.returncode}\n{result.stdout}{result.stderr}")
    return result.stdout


def expect_png(path, least_bytes=10000):
    with open(path, "rb") as f:
        head = f.read(8)
    if head != b"\x89PNG\r\n\x1a\n" or os.path.getsize(path) < least_bytes:
        sys.exit(f"{path}: not a PNG of at least {least_bytes} bytes")


def check_dimension_scales(path):
    import h5py
    with h5py.File(path, "r") as f:
        expected = {"patches/normal_force_N": ["dy", "second", "wheel", "slot"],
                    "patches/strip_half_length_m": ["dy", "second", "wheel", "slot", "sample"],
                    "wheels/status": ["dy", "second", "wheel"], "cases/roll_rad": ["dy", "second"]}
        for name, dims in expected.items():
            labels = [d.label for d in f[name].dims]
            scales = [list(d.keys()) for d in f[name].dims]
            if labels != dims or scales != [[d] for d in dims]:
                sys.exit(f"{name}: labels {labels}, scales {scales}, expected {dims}")
        if list(f["patches/normal_force_N"].dims[2][0][:]) != [0, 1]:
            sys.exit("the wheel scale is not [0, 1]")
        if h5py.check_enum_dtype(f["wheels/method"].dtype) is None or f["wheels/method"].attrs["units"] != "1":
            sys.exit("/wheels/method is not an enum with units 1")
        if not isinstance(f.attrs["mirrored"], (bool,)) and str(f.attrs["mirrored"].dtype) != "bool":
            sys.exit(f"mirrored is {f.attrs['mirrored']!r}, not a boolean")


def with_failures(source, target):
    """A copy of the table with failed cases (status < 0, no patch) on both wheels."""
    import h5py
    shutil.copyfile(source, target)
    with h5py.File(target, "r+") as f:
        status = f["wheels/status"][()]
        status[10:13, 0, 1] = -1
        status[30, 0, 0] = -3
        f["wheels/status"][...] = status
        empty = status < 0
        for name in f["patches"]:
            values = f["patches"][name][()]
            values[empty] = 0
            f["patches"][name][...] = values


def check_table(ctab, source, work):
    need("h5py", "matplotlib", "numpy")
    table = os.path.join(work, "t.h5")
    config = os.path.join(source, "examples", "configs", "default.toml")
    run(ctab, "generate", config, "-o", table, "--quiet", "--threads", "1")
    check_dimension_scales(table)
    script = os.path.join(source, "tables", "scripts", "plot_table.py")
    failed = os.path.join(work, "failed.h5")
    with_failures(table, failed)
    for path in (table, failed):
        png = path[:-3] + ".png"
        run(sys.executable, script, path, "-o", png)
        expect_png(png, 50000)


ACCURACY_ROWS = [  # scene, region, method, discretisation, error, time, min, median, max, tolerance
    ("wheelrail", "tread", "mim1d", "0.0002", "0.02", "1e-3", "8e-4", "1e-3", "3e-3", ""),
    ("wheelrail", "tread", "mim1d", "0.0001", "0.01", "3e-3", "2e-3", "3e-3", "5e-3", ""),
    ("wheelrail", "tread", "kp", "0.0002", "0.3", "5e-4", "4e-4", "5e-4", "9e-4", ""),
    ("wheelrail", "tread", "kp", "0.0001", "0.3", "5.1e-4", "4e-4", "5e-4", "9e-4", ""),
    ("wheelrail", "tread", "auto", "", "0.03", "9e-4", "", "", "", "0.02"),  # no spread columns: no bar
    ("hertz_sphere", "all", "hertz", "0.0001", "0", "2e-5", "1e-5", "2e-5", "4e-5", ""),
]


def check_accuracy(source, work):
    need("matplotlib")
    path = os.path.join(work, "accuracy.csv")
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["scene", "region", "method", "discretisation_m", "reference", "error_rel", "time_per_case_s",
                      "time_min_s", "time_median_s", "time_max_s", "tolerance"])
        for scene, region, method, width, error, time, low, mid, high, tolerance in ACCURACY_ROWS:
            out.writerow([scene, region, method, width, "bem2d", error, time, low, mid, high, tolerance])
    prefix = os.path.join(work, "accuracy")
    run(sys.executable, os.path.join(source, "scripts", "accuracy_chart.py"), path, prefix)
    expect_png(prefix + ".png")
    if os.path.getsize(prefix + ".svg") < 10000:
        sys.exit("no SVG chart")


STABILITY_ROWS = [  # scene, case, method, status, error, claimed, bound
    ("elongated", "a", "hertz", "converged", "0", "1", "0.001"),
    ("elongated", "a", "kp", "converged", "0.33", "0", ""),
    ("elongated", "b", "kp", "under-resolved", "0.5", "0", ""),
    ("load", "1 N", "mim1d", "no-contact", "", "0", ""),
    ("load", "1 MN", "mim1d", "converged", "0.04", "0", ""),
    ("curvature_jump", "a", "hertz", "zone-truncated", "", "0", ""),
]


def check_stability(source, work):
    need("matplotlib")
    path = os.path.join(work, "stability.csv")
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["scene", "case", "method", "status", "error_rel", "claimed", "error_bound_rel"])
        out.writerows(STABILITY_ROWS)
    png = os.path.join(work, "stability.png")
    run(sys.executable, os.path.join(source, "scripts", "stability_chart.py"), path, png)
    expect_png(png)


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    ctab, source, work, which = sys.argv[1:]
    os.makedirs(work, exist_ok=True)
    if which == "table":
        check_table(ctab, source, work)
    elif which == "accuracy":
        check_accuracy(source, work)
    elif which == "stability":
        check_stability(source, work)
    else:
        sys.exit(f"unknown check {which}")
    print(f"{which}: pictures written in {work}")


if __name__ == "__main__":
    main()
