#!/usr/bin/python3
"""Chart of `ctab bench accuracy`: time per case (log x) against error (log y), one panel per scene/region,
one marker per method and discretisation (the least model "auto": a star labelled with its tolerance), the Pareto front (no other point both faster and more accurate) drawn.

Usage: /usr/bin/python3 scripts/accuracy_chart.py DIR/accuracy.csv DIR/accuracy   (writes .png and .svg)
The error is the CSV's error_rel: the worst of the area, max-pressure and p0-profile RMS relative errors over the
panel's cases, against the reference named in the panel title.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"hertz": "o", "kp": "s", "analyn": "^", "mim1d": "D", "bem2d": "P", "auto": "*"}
COLOURS = {"hertz": "tab:red", "kp": "tab:orange", "analyn": "tab:green", "mim1d": "tab:blue", "bem2d": "tab:purple",
           "auto": "k"}
ERROR_FLOOR = 1e-5  # plotted instead of a zero error (log axis)


def pareto(points):
    """Points (time, error) not dominated by a faster and more accurate one, in time order."""
    front, best = [], float("inf")
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


def main(csv_path, prefix):
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["time_per_case_s"] and r["error_rel"]]
    panels = []
    for r in rows:
        key = (r["scene"], r["region"])
        if key not in panels:
            panels.append(key)
    columns = min(3, len(panels))
    lines = (len(panels) + columns - 1) // columns
    fig, axes = plt.subplots(lines, columns, figsize=(5.2 * columns, 4.2 * lines), squeeze=False)
    for ax, (scene, region) in zip(axes.flat, panels):
        sub = [r for r in rows if (r["scene"], r["region"]) == (scene, region)]
        points = []
        for r in sub:
            t, e = float(r["time_per_case_s"]), max(float(r["error_rel"]), ERROR_FLOOR)
            points.append((t, e))
            ax.scatter(t, e, marker=MARKERS.get(r["method"], "x"), color=COLOURS.get(r["method"], "k"), s=40,
                       label=r["method"])
            label = ("%g" % (float(r["discretisation_m"]) * 1e3) if r["discretisation_m"]
                     else "T %g %%" % (float(r.get("tolerance") or 0) * 100))  # the least model: its tolerance
            ax.annotate(label, (t, e), textcoords="offset points", xytext=(4, 3), fontsize=7)
        front = pareto(points)
        ax.step([p[0] for p in front], [p[1] for p in front], where="post", color="k", lw=1, ls="--",
                label="Pareto front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("time per case [s]")
        ax.set_ylabel("worst relative error [-]")
        ax.set_title("%s / %s (ref. %s)" % (scene, region, sub[0]["reference"]), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        handles, labels = ax.get_legend_handles_labels()
        unique = dict(zip(labels, handles))
        ax.legend(unique.values(), unique.keys(), fontsize=7, loc="best")
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    fig.suptitle("ctab bench accuracy: error against time per case (labels: strip width / element size in mm)")
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=110)
    fig.savefig(prefix + ".svg")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: accuracy_chart.py ACCURACY_CSV OUTPUT_PREFIX")
    main(sys.argv[1], sys.argv[2])
