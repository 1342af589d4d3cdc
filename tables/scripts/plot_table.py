#!/usr/bin/python3
"""Plot the main quantities of a ctab contact table (schema 2) against the lateral shift.

Usage: /usr/bin/python3 tables/scripts/plot_table.py TABLE.h5 [-o TABLE.png]
Needs Debian's python3-h5py and python3-matplotlib. Units in the file are SI; the plot shows mm, kN, MPa, deg.
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

SLOT_NAMES = ("tread", "flange")  # slots 0 and 1; further slots are "spare N"
WHEELS = ("right", "left")
REQUIRED = ("/axes/lateral_displacement_m", "/axes/second", "/cases/roll_rad", "/cases/rolling_radius_difference_m",
            "/wheels/status", "/patches/present", "/patches/normal_force_N", "/patches/force_lateral_N",
            "/patches/force_vertical_N", "/patches/contact_angle_rad", "/patches/y_rail_m", "/patches/area_m2",
            "/patches/max_pressure_Pa", "/jumps")


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


def status_summary(f: h5py.File) -> str:
    names = {value: name for name, value in (h5py.check_enum_dtype(f["/wheels/status"].dtype) or {}).items()}
    values, counts = np.unique(f["/wheels/status"][()], return_counts=True)
    return ", ".join(f"{names.get(int(v), int(v))} {c}" for v, c in zip(values, counts))


def plot(f: h5py.File, path: str, output: str) -> None:
    dy = f["/axes/lateral_displacement_m"][:] * 1e3
    second = f["/axes/second"]
    i2 = 0  # the first value of the second axis
    present = f["/patches/present"][:, i2] > 0
    n_slots = present.shape[-1]
    quantities = [
        ("/patches/normal_force_N", 1e-3, "normal force N [kN]"),
        ("/patches/force_vertical_N", 1e-3, "vertical force on rail [kN]"),
        ("/patches/force_lateral_N", 1e-3, "lateral force on rail, + field side [kN]"),
        ("/patches/contact_angle_rad", 180 / np.pi, "contact angle [deg]"),
        ("/patches/y_rail_m", 1e3, "contact point on rail [mm]"),
        ("/patches/area_m2", 1e6, "area [mm²]"),
        ("/patches/max_pressure_Pa", 1e-6, "max pressure [MPa]"),
    ]
    fig, axes = plt.subplots(5, 2, figsize=(12, 16), sharex=True)
    for ax, (name, scale, label) in zip(axes.flat, quantities):
        data = f[name][:, i2] * scale
        for wheel in range(2):
            for slot in range(n_slots):
                mask = present[:, wheel, slot]
                if mask.any():
                    values = np.where(mask, data[:, wheel, slot], np.nan)
                    ax.plot(dy, values, ".-" if slot else "-", ms=2, label=f"{WHEELS[wheel]} {slot_name(slot)}")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes.flat[0].legend(fontsize=8)
    for ax, (name, label) in zip(axes.flat[7:9], (("/cases/rolling_radius_difference_m", "r_right − r_left [mm]"),
                                                  ("/cases/roll_rad", "roll [mrad]"))):
        ax.plot(dy, f[name][:, i2] * 1e3, "-")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    ax = axes.flat[9]
    jumps = f["/jumps"][()]
    for wheel in range(2):
        rows = jumps[(jumps["i_second"] == i2) & (jumps["wheel"] == wheel)] if len(jumps) else jumps
        ax.plot(0.5e3 * (rows["dy_low_m"] + rows["dy_high_m"]), rows["slot"] + 0.1 * wheel, "v" if wheel else "^",
                label=f"{WHEELS[wheel]} wheel")
    ax.set_ylabel("contact jumps: slot")
    ax.set_yticks(range(n_slots))
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("lateral shift dy [mm]")
    attrs = {name: str(f.attrs.get(name, "?")) for name in ("wheel_profile", "rail_profile", "rail_inclination", "mode")}
    fig.suptitle(f"{path}: {attrs['wheel_profile']} on {attrs['rail_profile']} {attrs['rail_inclination']}, "
                 f"{attrs['mode']}, {second.attrs.get('name', '?')} = {second[i2]:g} {second.attrs.get('units', '')}\n"
                 f"status (case × wheel): {status_summary(f)}")
    fig.tight_layout()
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
