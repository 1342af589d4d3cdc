#!/usr/bin/python3
"""Plot the main quantities of a ctab contact table against the lateral shift.

Usage: /usr/bin/python3 tables/scripts/plot_table.py TABLE.h5 [-o TABLE.png]
Needs Debian's python3-h5py and python3-matplotlib. Units in the file are SI; the plot shows mm, kN, MPa, deg.
"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SLOTS = ("tread", "flange", "spare")
WHEELS = ("right", "left")


def text(value) -> str:
    return value.decode() if isinstance(value, bytes) else str(value)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table")
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    output = args.output or args.table.rsplit(".", 1)[0] + ".png"
    with h5py.File(args.table, "r") as f:
        if int(f.attrs["schema_version"]) != 1:
            print(f"{args.table}: schema version {f.attrs['schema_version']}, this script reads 1", file=sys.stderr)
            return 2
        dy = f["/axes/lateral_displacement_m"][:] * 1e3
        second = f["/axes/second"][:]
        second_name = text(f.attrs["second_axis_name"])
        i2 = 0  # the first value of the second axis
        present = f["/patches/present"][:, i2] > 0
        quantities = [
            ("/patches/normal_force_N", 1e-3, "normal force [kN]"),
            ("/patches/contact_angle_rad", 180 / np.pi, "contact angle [deg]"),
            ("/patches/y_rail_m", 1e3, "contact point on rail [mm]"),
            ("/patches/area_m2", 1e6, "area [mm²]"),
            ("/patches/max_pressure_Pa", 1e-6, "max pressure [MPa]"),
            ("/patches/rolling_radius_m", 1e3, "rolling radius [mm]"),
        ]
        fig, axes = plt.subplots(4, 2, figsize=(12, 13), sharex=True)
        for ax, (path, scale, label) in zip(axes.flat, quantities):
            data = f[path][:, i2] * scale
            for wheel in range(2):
                for slot in range(3):
                    mask = present[:, wheel, slot]
                    if mask.any():
                        values = np.where(mask, data[:, wheel, slot], np.nan)
                        ax.plot(dy, values, ".-" if slot else "-", ms=2, label=f"{WHEELS[wheel]} {SLOTS[slot]}")
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
        axes.flat[0].legend(fontsize=8)
        ax = axes.flat[6]
        ax.plot(dy, f["/cases/rolling_radius_difference_m"][:, i2] * 1e3, "-")
        ax.set_ylabel("r_right − r_left [mm]")
        ax.grid(True, alpha=0.3)
        ax = axes.flat[7]
        ax.plot(dy, f["/cases/roll_rad"][:, i2] * 1e3, "-")
        ax.set_ylabel("roll [mrad]")
        ax.grid(True, alpha=0.3)
        for ax in axes[-1]:
            ax.set_xlabel("lateral shift dy [mm]")
        attrs = {name: text(f.attrs[name]) for name in ("wheel_profile", "rail_profile", "rail_inclination", "mode")}
        fig.suptitle(f"{args.table}: {attrs['wheel_profile']} on {attrs['rail_profile']} {attrs['rail_inclination']}, "
                     f"{attrs['mode']}, {second_name} = {second[i2]:g}")
        fig.tight_layout()
        fig.savefig(output, dpi=90)
    print(f"plot written to {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
