# SPDX-License-Identifier: Apache-2.0
"""Plot an interpolated sweep over a contact table through the C library (what a HIL target computes).

    /usr/bin/python3 lookup/python/example_sweep.py TABLE.blob [-o sweep.png] [--wheel right|left]
        [--pchip] [--library build/lib/libctab_lookup.so]

Queries 4001 points over the table's dy range (40x finer than the default table) and draws, per patch slot,
normal force, contact point on the rail and area, with the table's grid points on top.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ctab_lookup  # noqa: E402


def sweep(table, dys, wheel, second):
    rows = []
    for dy in dys:
        r = table.query(dy, second, wheel)
        rows.append(r)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("table")
    parser.add_argument("-o", "--output", default="sweep.png")
    parser.add_argument("--wheel", default="right", choices=["right", "left"])
    parser.add_argument("--pchip", action="store_true")
    parser.add_argument("--library")
    args = parser.parse_args()
    mode = ctab_lookup.PCHIP if args.pchip else ctab_lookup.LINEAR
    with ctab_lookup.Table(args.table, interpolation=mode, library=args.library) as table:
        second = table.second_axis[0]
        n = 4001
        dys = [table.dy_min_m + (table.dy_max_m - table.dy_min_m) * i / (n - 1) for i in range(n)]
        grid = [table.dy_min_m + (table.dy_max_m - table.dy_min_m) * i / (table.n_dy - 1) for i in range(table.n_dy)]
        fine, coarse = sweep(table, dys, args.wheel, second), sweep(table, grid, args.wheel, second)
        fig, axes = plt.subplots(3, 1, figsize=(9, 10), sharex=True)
        quantities = [("normal_force_N", 1e-3, "normal force [kN]"), ("y_rail_m", 1e3, "contact point on rail [mm]"),
                      ("area_m2", 1e6, "area [mm²]")]
        for ax, (name, scale, label) in zip(axes, quantities):
            for slot in range(table.n_slots):
                xs = [dy * 1e3 for dy, r in zip(dys, fine) if slot in r.patches]
                ys = [r.patches[slot][name] * scale for r in fine if slot in r.patches]
                if not xs:
                    continue
                line, = ax.plot(xs, ys, ".", markersize=1.5, label="slot %d (interpolated)" % slot)
                gx = [dy * 1e3 for dy, r in zip(grid, coarse) if slot in r.patches]
                gy = [r.patches[slot][name] * scale for r in coarse if slot in r.patches]
                ax.plot(gx, gy, "o", markersize=2.5, mfc="none", color=line.get_color())
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
        axes[0].legend(fontsize=8)
        axes[0].set_title("%s wheel, %s = %g, %s interpolation (circles: table grid points)"
                          % (args.wheel, table.second_axis_name, second, "PCHIP" if args.pchip else "linear"))
        axes[-1].set_xlabel("lateral displacement dy [mm]")
        fig.tight_layout()
        fig.savefig(args.output, dpi=120)
        print("%s: %d interpolated points, %d slots" % (args.output, n, table.n_slots))


if __name__ == "__main__":
    main()
