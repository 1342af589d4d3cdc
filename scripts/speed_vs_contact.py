#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""ctab's speed against CONTACT and the paper's Matlab MIM-1D (the docs/performance.md tables).

ctab's figures come from `ctab bench solver --json` and `ctab bench wheelrail --json`: run here (--runs times)
or read from saved files (--solver-json, --wheelrail-json; several files are several runs). CONTACT's CPU
times are read from the reference data (../shared/reference/contact: hertz_sphere.csv `cpu_s_median5`,
wheelrail/summary.csv `cpu_s_case`, both whole-process CPU times on the project's machine kind). The ctab
binary holds no reference times of other programs.

Over several runs a row shows the median of the runs' means and the smallest minimum; the speed-up is
CONTACT's time over that median mean. Standard library only (/usr/bin/python3).

  scripts/speed_vs_contact.py                       # runs build/bin/ctab once per benchmark
  scripts/speed_vs_contact.py --runs 3 --seconds 2
  scripts/speed_vs_contact.py --solver-json s1.json s2.json --wheelrail-json w1.json
"""
import argparse
import csv
import json
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_REFERENCE = ROOT.parent / "shared" / "reference" / "contact"

# Qazi et al., A semi-analytical numerical method for modelling the normal wheel-rail contact, Vehicle System
# Dynamics 60(4), 2022, pp. 1322-1340, doi:10.1080/00423114.2020.1854319, Table 1, column MIM-1D (Matlab,
# 2.70 GHz Intel): CPU time [s] on the Hertz sphere, by mesh size [m]. Published figures, not measured here.
PAPER_MATLAB_S = {0.2e-3: 2.0e-3, 0.08e-3: 2.9e-2, 0.04e-3: 9.2e-2}

HERTZ_FORCE_N = 963e3  # the CONTACT rows hertz_F_* (force 963 kN prescribed)
WHEELRAIL_FORCE_N = 78.5e3  # wheelrail/summary.csv (FN_N)


class ScriptError(Exception):
    """A problem with the inputs, reported as one line on stderr (exit code 2)."""


def run_bench(ctab, benchmark, seconds):
    command = [str(ctab), "bench", benchmark, "--seconds", str(seconds), "--json"]
    try:
        done = subprocess.run(command, capture_output=True, text=True, check=False)
    except OSError as error:
        raise ScriptError(f"{ctab}: cannot run ({error.strerror}); build it or give --ctab PATH") from error
    if done.returncode != 0:
        raise ScriptError(f"{' '.join(command)}: exit code {done.returncode}: {done.stderr.strip()}")
    return parse_bench(done.stdout, " ".join(command), benchmark)


def parse_bench(text, source, benchmark):
    try:
        document = json.loads(text)
    except json.JSONDecodeError as error:
        raise ScriptError(f"{source}: line {error.lineno}: not JSON ({error.msg})") from error
    if not isinstance(document, dict) or document.get("benchmark") != benchmark or "rows" not in document:
        raise ScriptError(f"{source}: expected the output of `ctab bench {benchmark} --json`")
    return document


def read_bench(path, benchmark):
    try:
        text = Path(path).read_text()
    except OSError as error:
        raise ScriptError(f"{path}: cannot read ({error.strerror})") from error
    return parse_bench(text, path, benchmark)


def read_csv(path):
    try:
        with open(path, newline="") as file:
            return list(csv.DictReader(file))
    except OSError as error:
        raise ScriptError(f"{path}: cannot read ({error.strerror}); give --reference DIR") from error


def number(row, column, path):
    try:
        return float(row[column])
    except (KeyError, TypeError, ValueError) as error:
        raise ScriptError(f"{path}: expected a number in column {column!r}, got {row.get(column)!r}") from error


def contact_hertz_times(reference):
    """CONTACT CPU time [s] of the force-prescribed sphere, by element size [m]."""
    path = reference / "hertz_sphere.csv"
    return {number(row, "dx_mm", path) * 1e-3: number(row, "cpu_s_median5", path)
            for row in read_csv(path) if row.get("case", "").startswith("hertz_F_")}


def contact_wheelrail_times(reference):
    """CONTACT CPU time per case [s], by lateral shift [m] (one value per case, repeated on its patch rows)."""
    path = reference / "wheelrail" / "summary.csv"
    times = {}
    for row in read_csv(path):
        times.setdefault(number(row, "dy_mm", path) * 1e-3, number(row, "cpu_s_case", path))
    return times


def lookup(table, key, tolerance=1e-9):
    for candidate, value in table.items():
        if abs(candidate - key) <= tolerance:
            return value
    return None


def check_load(documents, expected_N, what):
    for document in documents:
        if abs(document.get("normal_load_N", float("nan")) - expected_N) > 1e-6 * expected_N:
            raise ScriptError(f"the CONTACT {what} reference is at N = {expected_N:g} N; ctab bench reports "
                              f"normal_load_N = {document.get('normal_load_N')}")


def merge_runs(documents, key):
    """Rows of several runs of one benchmark, matched by `key`: the first run's row fields, plus the median of
    the runs' means and the smallest minimum."""
    merged = []
    for row in documents[0]["rows"]:
        runs = [r for d in documents for r in d["rows"] if abs(r[key] - row[key]) <= 1e-12]
        merged.append(dict(row, mean_s=statistics.median(r["mean_s"] for r in runs),
                           min_s=min(r["min_s"] for r in runs), runs=len(runs)))
    return merged


def ms_number(seconds):
    """Milliseconds with three significant digits (no trailing point)."""
    return f"{seconds * 1e3:#.3g}".rstrip(".")


def ms(seconds):
    return "—" if seconds is None else ms_number(seconds) + " ms"


def mm(metres):
    text = f"{metres * 1e3:g}"
    return "0" if text in ("0", "-0") else text.replace("-", "−") + " mm"


def speedup(reference_s, ctab_s):
    return "—" if reference_s is None or not ctab_s > 0 else f"{reference_s / ctab_s:.0f}×"


def solver_table(documents, contact):
    lines = ["| strip width | strips | Newton iterations | ctab mean (min) | paper, Matlab | CONTACT, this machine "
             "| speed-up vs CONTACT |", "|---|---|---|---|---|---|---|"]
    for row in merge_runs(documents, "strip_width_m"):
        width = row["strip_width_m"]
        paper, reference = lookup(PAPER_MATLAB_S, width), lookup(contact, width)
        lines.append(f"| {mm(width)} | {row['strips']} | {row['iterations']} | {ms(row['mean_s'])} "
                     f"({ms_number(row['min_s'])}) | {ms(paper)} | {ms(reference)} | {speedup(reference, row['mean_s'])} |")
    return lines


def wheelrail_table(documents, contact):
    lines = ["| Δy | patches | iterations | ctab mean (min) | CONTACT | speed-up (mean) |",
             "|---|---|---|---|---|---|"]
    for row in merge_runs(documents, "dy_m"):
        reference = lookup(contact, row["dy_m"])
        lines.append(f"| {mm(row['dy_m'])} | {row['patches']} | {row['iterations']} | {ms(row['mean_s'])} "
                     f"({ms_number(row['min_s'])}) | {ms(reference)} | {speedup(reference, row['mean_s'])} |")
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ctab", default=str(ROOT / "build" / "bin" / "ctab"), help="ctab executable to run")
    parser.add_argument("--runs", type=int, default=1, help="runs of each benchmark (when not reading files)")
    parser.add_argument("--seconds", type=float, default=1.0, help="measuring time per row [s]")
    parser.add_argument("--solver-json", nargs="+", metavar="FILE", help="saved `ctab bench solver --json` runs")
    parser.add_argument("--wheelrail-json", nargs="+", metavar="FILE", help="saved `ctab bench wheelrail --json` runs")
    parser.add_argument("--reference", type=Path, default=DEFAULT_REFERENCE,
                        help="CONTACT reference directory (default: %(default)s)")
    args = parser.parse_args(argv)
    try:
        if args.runs < 1 or not args.seconds > 0:
            raise ScriptError("--runs must be at least 1 and --seconds positive")
        solver = ([read_bench(p, "solver") for p in args.solver_json] if args.solver_json
                  else [run_bench(args.ctab, "solver", args.seconds) for _ in range(args.runs)])
        wheelrail = ([read_bench(p, "wheelrail") for p in args.wheelrail_json] if args.wheelrail_json
                     else [run_bench(args.ctab, "wheelrail", args.seconds) for _ in range(args.runs)])
        check_load(solver, HERTZ_FORCE_N, "sphere")
        check_load(wheelrail, WHEELRAIL_FORCE_N, "wheel-rail")
        out = [f"MIM-1D, sphere R = 40 mm on a flat, N = 963 kN prescribed, one thread ({len(solver)} run(s); "
               "CONTACT: hertz_sphere.csv cpu_s_median5; paper: Qazi et al. 2022, Table 1):", ""]
        out += solver_table(solver, contact_hertz_times(args.reference))
        out += ["", f"Wheel-rail, geometry plus MIM-1D per case, S1002/UIC60 1:40, single wheel, N = 78.5 kN, "
                f"strips 0.2 mm, one thread ({len(wheelrail)} run(s); CONTACT: wheelrail/summary.csv cpu_s_case):", ""]
        out += wheelrail_table(wheelrail, contact_wheelrail_times(args.reference))
    except ScriptError as error:
        print(f"speed_vs_contact.py: {error}", file=sys.stderr)
        return 2
    except (KeyError, TypeError) as error:
        print(f"speed_vs_contact.py: a bench row lacks the field {error} (not `ctab bench ... --json` output?)",
              file=sys.stderr)
        return 2
    print("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
