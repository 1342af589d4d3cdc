#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""README table of `ctab bench stability`: per scene and method the worst error (larger of area and max pressure
against the scene's reference) where the smallest loaded patch spans at least 8 strips, in brackets the worst where
it spans fewer (under-resolved; not for Hertz, one ellipse), and every status other than converged / under-resolved with its count.

Usage: python3 scripts/stability_table.py docs/figures/stability.csv   (prints Markdown; standard library only)
"""
import csv
import sys
from collections import OrderedDict

RESOLVED_STRIPS = 8  # docs/validation.md "Stability where methods fail": the resolution rule of ctab/contact/resolution.hpp
METHODS = ["hertz", "kp", "analyn", "mim1d", "bem2d"]
SCENE_TITLES = OrderedDict([
    ("elongated", "elongated a/b 20, 1/20"),
    ("load", "load 1 N–1 MN"),
    ("barely_touching", "barely touching"),
    ("curvature_jump", "curvature jump"),
    ("hollow_gap", "double well"),
    ("wheelrail_regions", "wheel–rail regions"),
    ("wheelrail_hollow", "hollow-worn wheel"),
    ("wheelrail_noise", "measured with noise"),
    ("wheelrail_load", "wheel–rail loads"),
    ("wheelrail_jump_sweep", "jump sweeps 0.01 mm"),
])
USABLE = {"converged", "under-resolved"}


def percent(value):
    return f"{100 * value:.1f} %" if value < 0.1 else f"{100 * value:.0f} %"


def cell(rows, discretised):
    resolved, coarse, statuses = [], [], OrderedDict()
    for row in rows:
        if row["status"] not in USABLE:
            statuses[row["status"]] = statuses.get(row["status"], 0) + 1
        if row["status"] not in USABLE or row["error_rel"] == "":
            continue
        strips = float(row["resolved_strips"]) if discretised and row["resolved_strips"] else RESOLVED_STRIPS
        (resolved if strips >= RESOLVED_STRIPS else coarse).append(float(row["error_rel"]))
    parts = []
    if resolved:
        parts.append(percent(max(resolved)) + (f" ({percent(max(coarse))})" if coarse else ""))
    elif coarse:
        parts.append(f"({percent(max(coarse))})")
    parts += [f"{status} ×{count}" for status, count in statuses.items()]
    return "; ".join(parts) if parts else "–"


def main(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    by_scene = OrderedDict()
    for row in rows:
        by_scene.setdefault(row["scene"], []).append(row)
    print("| scene (cases) | " + " | ".join(m if m != "bem2d" else "bem2d 0.2 mm" for m in METHODS) + " |")
    print("|---|" + "---|" * len(METHODS))
    for scene, title in SCENE_TITLES.items():
        scene_rows = by_scene.get(scene, [])
        if not scene_rows:
            continue
        cases = len({row["case"] for row in scene_rows})
        cells = [cell([r for r in scene_rows if r["method"] == m], m != "hertz") for m in METHODS]
        print(f"| {title} ({cases}) | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: stability_table.py STABILITY_CSV")
    main(sys.argv[1])
