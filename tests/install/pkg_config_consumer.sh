#!/bin/sh
# A C program built by plain `cc` with pkg-config against the installed prefix (CTest install.pkg_config_*).
#   pkg_config_consumer.sh PREFIX PACKAGE SOURCE.c OUT_DIR TABLE.blob RESULTS      (PACKAGE: ctab-lookup[-hdf5])
set -eu
prefix=$1 package=$2 source=$3 out=$4 blob=$5 results=$6
PKG_CONFIG_PATH=$(dirname "$(find "$prefix" -name "$package.pc" | head -n 1)")
export PKG_CONFIG_PATH
mkdir -p "$out"
# CFLAGS: the build's own flags where it is instrumented (the sanitizers); empty otherwise. Flags are words.
# shellcheck disable=SC2046,SC2086
cc -std=c99 -Wall -Wextra -Werror ${CFLAGS:-} "$source" $(pkg-config --cflags --libs "$package") \
   -Wl,-rpath,"$(pkg-config --variable=libdir "$package")" -o "$out/query_blob_$package"
"$out/query_blob_$package" "$blob" "$results"
