#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Picture of `ctab bench stability`: where each method fails. A grid of scenes (rows) x methods (columns); each
cell is a bar of its cases, coloured by outcome from "within ctab's claimed error bound" to "failed", with the
worst error of its converged cases (and of its under-resolved ones) written in it.

Usage: /usr/bin/python3 scripts/stability_chart.py DIR/stability.csv OUTPUT.png
Outcomes per case (in the bar's order): within bound (ctab claims a bound there and meets it); converged, error
under 10 % (no bound claimed); under-resolved (the status says so); no-contact; not compared (no reference error);
converged but 10 % or more off (silently wrong); failed (a failure status, named in the cell).
"""
import csv
import os
import sys
from collections import Counter

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stability_table import METHODS, SCENE_TITLES, USABLE  # noqa: E402

SILENT_ERROR = 0.10  # a converged result this far off is "silently wrong"
OUTCOMES = (("within bound", "#1a9850"), ("converged, error < 10 %", "#a6d96a"), ("under-resolved", "#fee08b"),
            ("no-contact", "#d9d9d9"), ("not compared", "#ffffff"), ("converged, error ≥ 10 %", "#f46d43"),
            ("failed (status named)", "#a50026"))


def outcome(row):
    """Index into OUTCOMES of one case."""
    status = row["status"]
    if status not in USABLE and status != "no-contact":
        return 6
    if status == "no-contact":
        return 3
    if status == "under-resolved":
        return 2
    if row["error_rel"] == "":
        return 4
    error = float(row["error_rel"])
    if row.get("claimed") == "1" and error <= float(row.get("error_bound_rel") or "inf"):
        return 0
    return 1 if error < SILENT_ERROR else 5


def percent(value):
    return f"{100 * value:.1f} %" if value < 0.1 else f"{100 * value:.0f} %"


def cell_text(rows):
    """The worst error of the converged cases, of the under-resolved ones, and the failure statuses with counts."""
    parts = []
    for status, text in (("converged", "worst {}"), ("under-resolved", "under-res. {}")):
        errors = [float(r["error_rel"]) for r in rows if r["status"] == status and r["error_rel"] != ""]
        if errors:
            parts.append(text.format(percent(max(errors))))
    failures = Counter(r["status"] for r in rows if outcome(r) == 6)
    parts += [f"{status} ×{count}" for status, count in failures.items()]
    return "\n".join(parts)


def draw_cell(ax, x, y, rows):
    counts = Counter(outcome(r) for r in rows)
    left = x - 0.45
    for index, (_, colour) in enumerate(OUTCOMES):
        width = 0.9 * counts.get(index, 0) / len(rows)
        if width > 0:
            ax.add_patch(Rectangle((left, y - 0.38), width, 0.76, facecolor=colour, edgecolor="0.5", lw=0.3))
            left += width
    text = cell_text(rows)
    if text:
        ax.text(x, y, text, ha="center", va="center", fontsize=7,
                bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.8})


def main(csv_path, output):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    scenes = [s for s in SCENE_TITLES if any(r["scene"] == s for r in rows)]
    scenes += sorted({r["scene"] for r in rows} - set(scenes))
    methods = [m for m in METHODS if any(r["method"] == m for r in rows)]
    fig, ax = plt.subplots(figsize=(2.0 * len(methods) + 3.2, 0.62 * len(scenes) + 1.9))
    for y, scene in enumerate(scenes):
        for x, method in enumerate(methods):
            cell = [r for r in rows if r["scene"] == scene and r["method"] == method]
            if cell:
                draw_cell(ax, x, y, cell)
    ax.set_xlim(-0.5, len(methods) - 0.5)
    ax.set_ylim(len(scenes) - 0.5, -0.5)
    ax.set_xticks(range(len(methods)))
    ax.set_xticklabels(methods)
    ax.xaxis.tick_top()
    ax.set_yticks(range(len(scenes)))
    cases = {s: len({r["case"] for r in rows if r["scene"] == s}) for s in scenes}
    ax.set_yticklabels([f"{SCENE_TITLES.get(s, s)} ({cases[s]})" for s in scenes])
    for side in ax.spines.values():
        side.set_visible(False)
    ax.tick_params(length=0)
    present = {outcome(r) for r in rows}
    ax.legend(handles=[Patch(facecolor=c, edgecolor="0.5", label=n) for i, (n, c) in enumerate(OUTCOMES) if i in present],
              loc="upper center",
              bbox_to_anchor=(0.5, -0.01), ncol=4, fontsize=8, frameon=False)
    ax.set_title("ctab bench stability: outcome of every case per scene (cases) and method; bar widths: share of "
                 "the cases;\ntext: worst error (larger of area and max pressure) of the converged cases, and of the "
                 "under-resolved ones", fontsize=9, pad=24)
    fig.tight_layout()
    fig.savefig(output, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: stability_chart.py STABILITY_CSV OUTPUT_PNG")
    main(sys.argv[1], sys.argv[2])
