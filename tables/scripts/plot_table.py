#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Plot the main quantities of a ctab contact table (schema 2) against the lateral shift.

Usage: /usr/bin/python3 tables/scripts/plot_table.py TABLE.h5 [-o TABLE.png]
Needs Debian's python3-h5py and python3-matplotlib. Units in the file are SI; the plot shows mm, kN, MPa, deg.
Marks, in every quantity panel: under-resolved cases (a yellow band under the line), failed cases (red bands),
rows of a locally refined dy axis (blue shading) and the table's jumps (dotted lines); below, a status map (case
status per wheel along dy; dots where the least model refined the strip width below the table's coarsest) and the
jumps by wheel and slot with their kind and dy.
Any problem with the file gives one line "plot_table.py: FILE: ..." on stderr and exit status 2.
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

SLOT_NAMES = ("tread", "flange")  # slots 0 and 1; further slots are "spare N"
WHEELS = ("right", "left")
REQUIRED = ("/axes/lateral_displacement_m", "/axes/second", "/cases/roll_rad", "/cases/rolling_radius_difference_m",
            "/wheels/status", "/patches/present", "/patches/normal_force_N", "/patches/force_lateral_N",
            "/patches/force_vertical_N", "/patches/contact_angle_rad", "/patches/y_rail_m", "/patches/area_m2",
            "/patches/max_pressure_Pa", "/jumps")
# Status categories of the status map: (name, colour); failures are every negative status.
CATEGORIES = (("converged", "#b8e0b8"), ("no-contact", "#d9d9d9"), ("under-resolved", "#e6c200"),
              ("failed", "#d62728"))
UNDER_RESOLVED = 2
JUMP_STYLE = {1: ("appears", "^", "tab:green"), 2: ("disappears", "v", "tab:red"), 3: ("moves", "D", "tab:purple")}
REFINED_COLOUR = "tab:blue"


class TableError(Exception):
    """A file that is not a readable schema-2 table; the message is the whole explanation."""


def slot_name(slot: int) -> str:
    return SLOT_NAMES[slot] if slot < len(SLOT_NAMES) else f"spare {slot}"


def open_table(path: str) -> h5py.File:
    if not os.path.exists(path):
        raise TableError("no such file")
    if not h5py.is_hdf5(path):
        raise TableError("not an HDF5 file")
    f = h5py.File(path, "r")
    version = f.attrs.get("schema_version")
    if version is None:
        raise TableError("no schema_version attribute: not a ctab table")
    if not np.issubdtype(np.asarray(version).dtype, np.integer):
        if float(version) == 1.0:
            raise TableError("schema 1 table: regenerate it with this ctab: ctab generate CONFIG -o FILE")
        raise TableError(f"schema_version {version} is not an integer")
    if int(version) != 2:
        raise TableError(f"schema version {int(version)}, this script reads 2")
    missing = [name for name in REQUIRED if name not in f]
    if missing:
        raise TableError(f"missing dataset {missing[0]}")
    return f


def status_names(f: h5py.File) -> dict:
    return {value: name for name, value in (h5py.check_enum_dtype(f["/wheels/status"].dtype) or {}).items()}


def status_summary(f: h5py.File) -> str:
    names = status_names(f)
    values, counts = np.unique(f["/wheels/status"][()], return_counts=True)
    return ", ".join(f"{names.get(int(v), int(v))} {c}" for v, c in zip(values, counts))


def cell_edges(dy: np.ndarray) -> np.ndarray:
    """Edges halfway between the dy rows (each row's cell), the outer ones half a step out."""
    if len(dy) == 1:
        return np.array([dy[0] - 0.05, dy[0] + 0.05])
    middle = 0.5 * (dy[1:] + dy[:-1])
    return np.concatenate(([2 * dy[0] - middle[0]], middle, [2 * dy[-1] - middle[-1]]))


def refined_rows(dy: np.ndarray) -> np.ndarray:
    """Rows on a locally refined axis: a neighbouring step under 0.9 of the axis's most common step."""
    if len(dy) < 3:
        return np.zeros(len(dy), bool)
    steps = np.diff(dy)
    values, counts = np.unique(np.round(steps, 12), return_counts=True)
    common = values[np.argmax(counts)]
    fine = steps < 0.9 * common
    return np.concatenate(([False], fine)) | np.concatenate((fine, [False]))


def spans(mask: np.ndarray, edges: np.ndarray):
    """(start, stop) in the units of `edges` of each run of True in `mask`."""
    runs, start = [], None
    for i, flag in enumerate(np.append(mask, False)):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            runs.append((edges[start], edges[i]))
            start = None
    return runs


def category(status: np.ndarray) -> np.ndarray:
    """0 converged, 1 no-contact, 2 under-resolved, 3 failed (any negative status)."""
    return np.where(status < 0, 3, np.clip(status, 0, 2))


class Marks:
    """What every quantity panel marks: refined rows, failed rows, the jumps' positions (all in mm)."""

    def __init__(self, dy_mm, status, jumps_mm):
        edges = cell_edges(dy_mm)
        self.refined = spans(refined_rows(dy_mm), edges)
        self.failed = spans((status < 0).any(axis=-1), edges)
        self.jumps = jumps_mm

    def draw(self, ax):
        for low, high in self.refined:
            ax.axvspan(low, high, color=REFINED_COLOUR, alpha=0.08, lw=0)
        for low, high in self.failed:
            ax.axvspan(low, high, color=CATEGORIES[3][1], alpha=0.25, lw=0)
        for x in self.jumps:
            ax.axvline(x, color="0.35", ls=":", lw=0.7)


def draw_quantity(ax, dy, data, present, status, label):
    """One slot line per wheel and slot; under-resolved cases underlaid in the status map's colour."""
    for wheel in range(2):
        for slot in range(present.shape[-1]):
            mask = present[:, wheel, slot]
            if not mask.any():
                continue
            values = np.where(mask, data[:, wheel, slot], np.nan)
            ax.plot(dy, values, ".-" if slot else "-", ms=2, label=f"{WHEELS[wheel]} {slot_name(slot)}", zorder=2)
            coarse = np.where(mask & (status[:, wheel] == UNDER_RESOLVED), values, np.nan)
            ax.plot(dy, coarse, "-", color=CATEGORIES[2][1], lw=6, alpha=0.45, solid_capstyle="round", zorder=1)
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)


def draw_status_map(ax, f, dy, i2, marks):
    status = f["/wheels/status"][:, i2]
    edges = cell_edges(dy)
    cmap = ListedColormap([colour for _, colour in CATEGORIES])
    ax.pcolormesh(edges, [-0.5, 0.5, 1.5], category(status).T, cmap=cmap, vmin=-0.5, vmax=3.5)
    for low, high in marks.refined:
        ax.add_patch(plt.Rectangle((low, -0.5), high - low, 2, fill=False, hatch="////", ec=REFINED_COLOUR, lw=0))
    handles = [Patch(color=colour, label=name) for name, colour in CATEGORIES]
    handles.append(Patch(fill=False, hatch="////", ec=REFINED_COLOUR, label="refined dy rows"))
    if "/wheels/strip_width_m" in f:  # the least model refines from its coarsest width down
        width = f["/wheels/strip_width_m"][:, i2]
        coarsest = float(np.max(width)) if width.size else 0.0
        for wheel in range(2):
            finer = (width[:, wheel] > 0) & (width[:, wheel] < 0.99 * coarsest)
            ax.plot(dy[finer], np.full(finer.sum(), wheel), "k.", ms=2)
        handles.append(Line2D([], [], ls="", marker=".", color="k", label="strip width refined (finer than the "
                                                                          "table's coarsest)"))
    failures = sorted({int(v) for v in np.unique(status) if v < 0})
    if failures:
        names = status_names(f)
        handles[3] = Patch(color=CATEGORIES[3][1], label="failed: " + ", ".join(names.get(v, str(v)) for v in failures))
    ax.set_yticks([0, 1])
    ax.set_yticklabels(["right wheel", "left wheel"])
    ax.set_ylim(-0.5, 1.5)
    ax.set_title("case status per wheel along dy", fontsize=9, loc="left")
    ax.legend(handles=handles, fontsize=7, ncol=len(handles), loc="upper center", bbox_to_anchor=(0.5, -0.18),
              frameon=False)


def draw_jumps(ax, jumps, dy, n_slots, i2):
    """One lane per wheel and slot with a jump; each jump's kind as its marker and its cell's middle dy as text."""
    rows = jumps[jumps["i_second"] == i2] if len(jumps) else jumps
    lanes = sorted({(int(r["wheel"]), int(r["slot"])) for r in rows})
    span = float(dy[-1] - dy[0]) or 1.0
    for lane, (wheel, slot) in enumerate(lanes):
        ax.axhline(lane, color="0.85", lw=0.8, zorder=0)
        mine = sorted((0.5e3 * (r["dy_low_m"] + r["dy_high_m"]), int(r["kind"])) for r in rows
                      if int(r["wheel"]) == wheel and int(r["slot"]) == slot)
        last = -np.inf
        for x, kind in mine:
            _, marker, colour = JUMP_STYLE.get(kind, ("?", "x", "k"))
            ax.plot(x, lane, marker, color=colour, ms=7)
            raise_text = x - last < 0.06 * span  # close to the previous label: the other side of the lane
            ax.annotate(f"{x:+.2f}", (x, lane), textcoords="offset points", xytext=(0, -11 if raise_text else 7),
                        ha="center", fontsize=7)
            last = x
    ax.set_yticks(range(len(lanes)))
    ax.set_yticklabels([f"{WHEELS[w]} {slot_name(s)}" for w, s in lanes] or [""], fontsize=8)
    ax.set_ylim(-0.7, max(len(lanes), 1) - 0.3)
    ax.grid(True, axis="x", alpha=0.3)
    handles = [Line2D([], [], ls="", marker=m, color=c, label=n) for n, m, c in JUMP_STYLE.values()]
    ax.legend(handles=handles, fontsize=7, ncol=3, loc="upper right")
    ax.set_title(f"contact jumps ({len(rows)}): slot appears, disappears or moves between two dy rows "
                 "(text: the cell's middle dy [mm])" if len(rows) else "contact jumps: none", fontsize=9, loc="left")


def plot(f: h5py.File, path: str, output: str) -> None:
    dy = f["/axes/lateral_displacement_m"][:] * 1e3
    second = f["/axes/second"]
    i2 = 0  # the first value of the second axis
    present = f["/patches/present"][:, i2] > 0
    status = f["/wheels/status"][:, i2]
    jumps = f["/jumps"][()]
    on_i2 = jumps[jumps["i_second"] == i2] if len(jumps) else jumps
    marks = Marks(dy, status, sorted({0.5e3 * (r["dy_low_m"] + r["dy_high_m"]) for r in on_i2}))
    quantities = [
        ("/patches/normal_force_N", 1e-3, "normal force N [kN]"),
        ("/patches/force_vertical_N", 1e-3, "vertical force on rail [kN]"),
        ("/patches/force_lateral_N", 1e-3, "lateral force on rail,\n+ field side [kN]"),
        ("/patches/contact_angle_rad", 180 / np.pi, "contact angle [deg]"),
        ("/patches/y_rail_m", 1e3, "contact point on rail [mm]"),
        ("/patches/area_m2", 1e6, "area [mm²]"),
        ("/patches/max_pressure_Pa", 1e-6, "max pressure [MPa]"),
    ]
    fig = plt.figure(figsize=(12, 20))
    grid = fig.add_gridspec(7, 2, height_ratios=[1, 1, 1, 1, 1, 0.45, 0.75], hspace=0.32)
    panels = [fig.add_subplot(grid[r, c]) for r in range(5) for c in range(2)]
    for ax in panels[1:]:
        ax.sharex(panels[0])
    for ax, (name, scale, label) in zip(panels, quantities):
        draw_quantity(ax, dy, f[name][:, i2] * scale, present, status, label)
    for ax, (name, label) in zip(panels[7:9], (("/cases/rolling_radius_difference_m", "r_right − r_left [mm]"),
                                               ("/cases/roll_rad", "roll [mrad]"))):
        ax.plot(dy, f[name][:, i2] * 1e3, "-")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    ax = panels[9]
    if "/wheels/strip_width_m" in f:
        for wheel in range(2):
            ax.plot(dy, f["/wheels/strip_width_m"][:, i2, wheel] * 1e3, "-" if wheel == 0 else "--",
                    label=f"{WHEELS[wheel]} wheel")
        ax.legend(fontsize=8)
    ax.set_ylabel("strip width of the solve [mm]")
    ax.grid(True, alpha=0.3)
    for ax in panels:
        marks.draw(ax)
    legend = panels[0].legend(fontsize=8)
    legend.get_frame().set_alpha(0.9)
    fig.legend(handles=[Line2D([], [], color=CATEGORIES[2][1], lw=6, alpha=0.45, label="under-resolved case"),
                        Patch(color=CATEGORIES[3][1], alpha=0.25, label="failed case (either wheel)"),
                        Patch(color=REFINED_COLOUR, alpha=0.15, label="refined dy rows"),
                        Line2D([], [], color="0.35", ls=":", label="contact jump (cell middle)")],
               loc="upper center", bbox_to_anchor=(0.5, 0.962), ncol=4, fontsize=8, frameon=False)
    status_ax = fig.add_subplot(grid[5, :], sharex=panels[0])
    draw_status_map(status_ax, f, dy, i2, marks)
    jump_ax = fig.add_subplot(grid[6, :], sharex=panels[0])
    draw_jumps(jump_ax, jumps, dy, present.shape[-1], i2)
    jump_ax.set_xlabel("lateral shift dy [mm]")
    for ax in panels[8:]:
        ax.tick_params(labelbottom=True)
    attrs = {name: str(f.attrs.get(name, "?")) for name in ("wheel_profile", "rail_profile", "rail_inclination", "mode")}
    fig.suptitle(f"{path}: {attrs['wheel_profile']} on {attrs['rail_profile']} {attrs['rail_inclination']}, "
                 f"{attrs['mode']}, {second.attrs.get('name', '?')} = {second[i2]:g} {second.attrs.get('units', '')}\n"
                 f"status (case × wheel, whole table): {status_summary(f)}", y=0.995)
    fig.subplots_adjust(left=0.08, right=0.98, top=0.945, bottom=0.03)
    fig.savefig(output, dpi=90)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table")
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    output = args.output or args.table.rsplit(".", 1)[0] + ".png"
    try:
        with open_table(args.table) as f:
            plot(f, args.table, output)
    except TableError as e:
        print(f"plot_table.py: {args.table}: {e}", file=sys.stderr)
        return 2
    except (OSError, KeyError, ValueError, TypeError, IndexError) as e:  # damaged or wrong content
        print(f"plot_table.py: {args.table}: not a readable schema-2 table ({type(e).__name__}: {e})", file=sys.stderr)
        return 2
    print(f"plot written to {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
