#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Chart of the tangential ladder (`ctab bench accuracy --creep DIR` writes the CSV): creep curves |Fx|/muN against
xi per lateral shift (planar), ctab's rungs against CONTACT, and error against time per rung.
Usage: /usr/bin/python3 scripts/creep_chart.py CREEP_CSV PREFIX  (writes PREFIX.png and PREFIX.svg)"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"linear-ellipse": ("tab:gray", ":"), "fastsim-ellipse": ("tab:blue", "--"), "fastsim-strips": ("tab:red", "-"),
         "carter-strips": ("tab:green", "-")}


def main(path, prefix):
    rows = list(csv.DictReader(open(path)))
    shifts = sorted({float(r["dy_m"]) for r in rows})
    fig, axes = plt.subplots(1, len(shifts) + 1, figsize=(4.2 * (len(shifts) + 1), 4))
    for ax, dy in zip(axes, shifts):
        curves = defaultdict(list)
        for r in rows:
            if r["surface"] != "planar" or float(r["dy_m"]) != dy or not r["case"].startswith("xi"):
                continue
            mu_n = 0.3 * float(r["ref_fn_N"])
            curves[r["method"]].append((float(r["xi"]), -float(r["fx_N"]) / mu_n))
            curves["CONTACT"].append((float(r["xi"]), -float(r["ref_fx_N"]) / mu_n))
        for name, points in curves.items():
            points = sorted(set(points))
            colour, line = STYLE.get(name, ("black", "-"))
            ax.plot([p[0] for p in points], [p[1] for p in points], line, color=colour, marker="o" if name ==
                    "CONTACT" else None, label=name)
        ax.set_xscale("log")
        ax.set_ylim(0, 1.1)
        ax.set_title(f"planar, dy {dy * 1e3:.1f} mm: pure xi")
        ax.set_xlabel("xi [-]")
        ax.set_ylabel("-Fx / (mu N)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    ax = axes[-1]
    by_method = defaultdict(lambda: ([], []))
    for r in rows:
        if r["surface"] == "planar":
            by_method[r["method"]][0].append(float(r["time_s"]) * 1e6)
            by_method[r["method"]][1].append(float(r["error_muN"]))
    for name, (times, errors) in by_method.items():
        errors = sorted(errors)
        times = sorted(times)
        colour, _ = STYLE.get(name, ("black", "-"))
        ax.errorbar(times[len(times) // 2], errors[len(errors) // 2], yerr=[[0], [errors[-1] - errors[len(errors) // 2]]],
                    fmt="o", color=colour, capsize=4, label=name)
    ax.set_yscale("log")
    ax.set_xlabel("time per wheel call [us] (median)")
    ax.set_ylabel("error [mu N]: median, bar to worst")
    ax.set_title("planar cases: error against time")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=110)
    fig.savefig(prefix + ".svg")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
