#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Chart of `ctab bench accuracy`: time per case (log x) against error (log y), one panel per scene/region.

One marker per method and discretisation (the least model "auto": a star labelled with its tolerance), a horizontal
bar from the fastest to the slowest single solve of the row with a tick at the median (the timing spread: repeats
and cases), and the Pareto front (no other point both faster and more accurate). Labels are placed where they
overlap no other label or marker; points of one method that coincide share one label ("0.1, 0.2").

Usage: /usr/bin/python3 scripts/accuracy_chart.py DIR/accuracy.csv DIR/accuracy   (writes .png and .svg)
The error is the CSV's error_rel: the worst of the area, max-pressure and p0-profile RMS relative errors over the
panel's cases, against the reference named in the panel title.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

MARKERS = {"hertz": "o", "kp": "s", "analyn": "^", "mim1d": "D", "bem2d": "P", "auto": "*"}
COLOURS = {"hertz": "tab:red", "kp": "tab:orange", "analyn": "tab:green", "mim1d": "tab:blue", "bem2d": "tab:purple",
           "auto": "k"}
ERROR_FLOOR = 1e-5  # plotted instead of a zero error (log axis)
Y_LABEL = "worst relative error [1]\nmax(area, max pressure, p0 profile RMS)"
# Label offsets tried in order [points]: right, above, left, below, the diagonals, then further out.
OFFSETS = [(dx * r, dy * r) for r in (1, 2, 3.2) for dx, dy in
           ((5, 0), (0, 5), (-5, 0), (0, -6), (5, 5), (-5, 5), (5, -6), (-5, -6))]
MERGE_PIXELS = 10  # points of one method closer than this share one label


def pareto(points):
    """Points (time, error) not dominated by a faster and more accurate one, in time order."""
    front, best = [], float("inf")
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


def number(row, name):
    text = row.get(name) or ""
    return float(text) if text else None


def label_of(row):
    """Strip width / element size in mm, or the least model's tolerance."""
    if row["discretisation_m"]:
        return "%g" % (float(row["discretisation_m"]) * 1e3)
    return "T %g %%" % (float(row.get("tolerance") or 0) * 100)


def merged_labels(ax, points):
    """[(x, y, colour, text)]: one per group of one method's points within MERGE_PIXELS of each other."""
    groups = []
    for method, t, e, text, _ in points:
        px = ax.transData.transform((t, e))
        for g in groups:
            if g["method"] == method and abs(g["px"][0] - px[0]) < MERGE_PIXELS and abs(g["px"][1] - px[1]) < MERGE_PIXELS:
                g["texts"].append(text)
                break
        else:
            groups.append({"method": method, "px": px, "t": t, "e": e, "texts": [text]})
    return [(g["t"], g["e"], COLOURS.get(g["method"], "k"), ", ".join(g["texts"])) for g in groups]


def overlaps(box, boxes):
    return any(box.overlaps(b) for b in boxes)


def annotate(ax, t, e, text, colour, dx, dy):
    """A label at (dx, dy) points from its point; a leader line when it is not next to it."""
    ha = "left" if dx > 0 else "right" if dx < 0 else "center"
    va = "bottom" if dy > 0 else "top" if dy < 0 else "center"
    far = abs(dx) > 5 or abs(dy) > 6
    arrow = {"arrowstyle": "-", "color": colour, "lw": 0.5, "shrinkA": 0, "shrinkB": 3} if far else None
    return ax.annotate(text, (t, e), textcoords="offset points", xytext=(dx, dy), fontsize=7, ha=ha, va=va,
                       color=colour, arrowprops=arrow)


def text_box(note, renderer):
    """The display box of an annotation's text alone (not its leader line)."""
    note.update_positions(renderer)
    return matplotlib.text.Text.get_window_extent(note, renderer)


def front_boxes(ax, points):
    """Display boxes of the Pareto front's steps (labels avoid them too)."""
    front = [ax.transData.transform(p) for p in pareto([(p[1], p[2]) for p in points])]
    boxes = []
    for (x0, y0), (x1, y1) in zip(front, front[1:]):
        boxes.append(matplotlib.transforms.Bbox([[x0, y0 - 2], [x1, y0 + 2]]))  # along, at the slower error
        boxes.append(matplotlib.transforms.Bbox([[x1 - 2, min(y0, y1)], [x1 + 2, max(y0, y1)]]))  # the drop
    return boxes


def place_labels(fig, ax, points):
    """Annotates each (merged) point at the first offset whose text box overlaps no marker, spread bar, front step
    or placed label."""
    renderer = fig.canvas.get_renderer()
    occupied = front_boxes(ax, points)
    for _, t, e, _, (low, high) in points:  # markers as boxes of about their size, and the spread bars
        x, y = ax.transData.transform((t, e))
        occupied.append(matplotlib.transforms.Bbox([[x - 4, y - 4], [x + 4, y + 4]]))
        x0, x1 = ax.transData.transform((low, e))[0], ax.transData.transform((high, e))[0]
        occupied.append(matplotlib.transforms.Bbox([[x0, y - 3], [x1, y + 3]]))
    axes_box = ax.get_window_extent(renderer)
    for t, e, colour, text in merged_labels(ax, points):
        for dx, dy in OFFSETS:
            note = annotate(ax, t, e, text, colour, dx, dy)
            box = text_box(note, renderer).expanded(1.05, 1.1)
            inside = axes_box.contains(box.x0, box.y0) and axes_box.contains(box.x1, box.y1)
            if inside and not overlaps(box, occupied):
                break
            note.remove()
        else:  # nowhere free: the first offset
            note = annotate(ax, t, e, text, colour, *OFFSETS[0])
            box = text_box(note, renderer)
        occupied.append(box)


def draw_panel(ax, sub):
    points = []
    for r in sub:
        t, e = float(r["time_per_case_s"]), max(float(r["error_rel"]), ERROR_FLOOR)
        colour = COLOURS.get(r["method"], "k")
        low, mid, high = number(r, "time_min_s"), number(r, "time_median_s"), number(r, "time_max_s")
        if low is None or high is None:  # a CSV without the spread columns
            low = mid = high = t
        if high > low:
            ax.plot([low, high], [e, e], color=colour, lw=1, alpha=0.6, solid_capstyle="butt")
            ax.plot([low, high], [e, e], "|", color=colour, ms=5, alpha=0.6)
            ax.plot([mid], [e], "|", color=colour, ms=9, mew=1.5)
        ax.scatter(t, e, marker=MARKERS.get(r["method"], "x"), color=colour, s=40, zorder=3)
        points.append((r["method"], t, e, label_of(r), (low, high)))
    front = pareto([(p[1], p[2]) for p in points])
    ax.step([p[0] for p in front], [p[1] for p in front], where="post", color="k", lw=1, ls="--")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per case [s]")
    ax.set_ylabel(Y_LABEL, fontsize=8)
    ax.set_title("%s / %s (ref. %s)" % (sub[0]["scene"], sub[0]["region"], sub[0]["reference"]), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.margins(x=0.12, y=0.12)
    return points


def legend_handles(methods, spread):
    handles = [Line2D([], [], ls="", marker=MARKERS.get(m, "x"), color=COLOURS.get(m, "k"), label=m) for m in methods]
    handles.append(Line2D([], [], color="k", ls="--", lw=1, label="Pareto front"))
    if spread:
        handles.append(Line2D([], [], color="0.4", lw=1, marker="|", ms=8,
                              label="single solves: fastest – median (tall tick) – slowest"))
    return handles


def main(csv_path, prefix):
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["time_per_case_s"] and r["error_rel"]]
    panels, methods = [], []
    for r in rows:
        if (r["scene"], r["region"]) not in panels:
            panels.append((r["scene"], r["region"]))
        if r["method"] not in methods:
            methods.append(r["method"])
    columns = min(3, len(panels))
    lines = (len(panels) + columns - 1) // columns
    fig, axes = plt.subplots(lines, columns, figsize=(5.4 * columns, 4.4 * lines + 0.8), squeeze=False)
    drawn = [(ax, draw_panel(ax, [r for r in rows if (r["scene"], r["region"]) == key]))
             for ax, key in zip(axes.flat, panels)]
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    fig.suptitle("ctab bench accuracy: worst relative error against time per case\n"
                 "labels: strip width / element size in mm; auto: the least model's tolerance", fontsize=11)
    spread = any(number(r, "time_max_s") is not None for r in rows)  # CSVs of older runs have no spread columns
    fig.legend(handles=legend_handles(methods, spread), loc="lower center", ncol=len(methods) + 2, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.canvas.draw()  # the final layout: labels are placed in display coordinates
    for ax, points in drawn:
        place_labels(fig, ax, points)
    fig.savefig(prefix + ".png", dpi=110)
    fig.savefig(prefix + ".svg")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: accuracy_chart.py ACCURACY_CSV OUTPUT_PREFIX")
    main(sys.argv[1], sys.argv[2])
