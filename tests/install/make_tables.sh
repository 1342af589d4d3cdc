#!/bin/sh
# CTest fixture install.tables: a small HDF5 table (the default config on a 1 mm dy axis) and its blob, made by
# the installed ctab, for the installed Python module's HDF5 path.
#   make_tables.sh PREFIX/bin/ctab OUT_DIR
set -eu
ctab=$1 out=$2
mkdir -p "$out"
"$ctab" config --print-default |
  sed -e 's/^lateral_displacement_m = .*/lateral_displacement_m = { start = -10e-3, stop = 10e-3, step = 1e-3 }/' \
      -e '/^lateral_refinement_m/,/}.*]/d' > "$out/small.toml"
"$ctab" generate "$out/small.toml" -o "$out/small.h5" --quiet --threads 2
"$ctab" export "$out/small.h5" -o "$out/small.blob" --force
