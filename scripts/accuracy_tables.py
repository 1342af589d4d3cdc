#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""README tables of `ctab bench accuracy` (docs/method.md "The method ladder"): worst error against the reference with time per
case, and the worst deviation from CONTACT (area / max pressure / centre of pressure), one column per rung at
0.2 mm (Hertz: its one ellipse; auto: its tolerance).

Usage: /usr/bin/python3 scripts/accuracy_tables.py docs/figures/accuracy.csv
"""
import csv
import sys

RUNGS = [("hertz", None), ("kp", "0.0002"), ("analyn", "0.0002"), ("mim1d", "0.0002"), ("bem2d", "0.0002"),
         ("auto", "")]
HEADER = "| region | hertz | kp | analyn | mim1d | bem2d | auto (T 2 %) |\n|---|---|---|---|---|---|---|"
REGIONS = [("hertz_sphere", "all", "Hertz sphere (analytic)"), ("nonhertz", "all", "non-Hertzian body"),
           ("wheelrail", "tread", "tread (Δy < 4.5 mm)"), ("wheelrail", "two_point", "two-point (4.5–5.75 mm)"),
           ("wheelrail", "flange_root", "flange root (5.75–6.55 mm)"), ("wheelrail", "knee", "knee (6.55–7.1 mm)"),
           ("wheelrail", "flange_flank", "flange flank (> 7.1 mm)")]


def percent(value):
    v = 100.0 * float(value)
    return f"{v:.1f} %" if v < 10.0 else f"{v:.0f} %"


def duration(seconds):
    s = float(seconds)
    if s >= 0.995:
        return f"{s:.2f} s"
    if s >= 0.01:
        return f"{s * 1e3:.0f} ms"
    return f"{s * 1e3:.2g} ms" if s >= 1e-3 else f"{s * 1e3:.2f} ms"


def find(rows, scene, region, method, width):
    for r in rows:
        if r["scene"] != scene or r["method"] != method or (region != "all" and r["region"] != region):
            continue
        if width is None or r["discretisation_m"] == width:
            return r
    return None


def main(path):
    rows = list(csv.DictReader(open(path, newline="")))
    print(HEADER)
    for scene, region, label in REGIONS:
        cells = []
        for method, width in RUNGS:
            r = find(rows, scene, region, method, width)
            cells.append("–" if r is None else f"{percent(r['error_rel'])}, {duration(r['time_per_case_s'])}")
        print(f"| {label} | " + " | ".join(cells) + " |")
    print()
    print(HEADER)
    for scene, region, label in REGIONS[2:]:
        cells = []
        for method, width in RUNGS:
            r = find(rows, scene, region, method, width)
            if r is None or not r["vs_contact_area_error_rel"]:
                cells.append("–")
                continue
            point_mm = 1e3 * float(r["vs_contact_point_error_m"])
            cells.append(f"{percent(r['vs_contact_area_error_rel'])} / {percent(r['vs_contact_max_pressure_error_rel'])}"
                         f" / {point_mm:.2f} mm")
        print(f"| {label.split(' (')[0]} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "docs/figures/accuracy.csv")
