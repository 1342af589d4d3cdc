#!/usr/bin/env bash
# Convergence benchmark (issue 8, "Convergence everywhere"): 0.01 mm dy sweeps from -12 to +12 mm at ten loads
# (20 ... 150 kN; for the approach kind ten approaches 20 ... 200 um), both modes, built-in and Manchester profiles,
# each loading kind, through `ctab generate`. Prints one line per table and the total count of failed wheel cases.
#
#   tests/bench/convergence_sweep.sh [CTAB] [PROFILES_DIR] [STEP_M] [SURFACE] [REFERENCE_POINT] [REFERENCE_ANGLE]
#
# CTAB defaults to build/bin/ctab, PROFILES_DIR to ../shared/profiles (the Manchester files), STEP_M to 1e-5,
# SURFACE (planar or conformal, [solver] surface) to planar, REFERENCE_POINT (deepest or interpenetration-centre,
# [solver] reference_point) to deepest, REFERENCE_ANGLE (tangent or interpenetration-mean, [solver] reference_angle)
# to the reference point's own.
# Exit status: 0 when no case failed, 1 otherwise.
set -euo pipefail
ctab=${1:-build/bin/ctab}
profiles=$(cd "${2:-../shared/profiles}" && pwd)
step=${3:-1e-5}
surface=${4:-planar}
reference_point=${5:-deepest}
reference_angle_line=${6:+reference_angle = \"$6\"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

loads='[20e3, 34.4e3, 48.9e3, 63.3e3, 77.8e3, 92.2e3, 106.7e3, 121.1e3, 135.6e3, 150e3]'
approaches='[20e-6, 40e-6, 60e-6, 80e-6, 100e-6, 120e-6, 140e-6, 160e-6, 180e-6, 200e-6]'
total_failed=0
total_cases=0
for set in builtin manchester; do
  if [[ $set == builtin ]]; then
    profile_lines='wheel = "S1002"
rail = "UIC60"
inclination = "1/40"'
  else
    profile_lines="wheel = \"$profiles/MBench_S1002_v3.prw\"
rail = \"$profiles/MBench_UIC60_v3.prr\"
inclination = \"0\""
  fi
  for mode in wheel wheelset; do
    for kind in vertical_load_N normal_load_N approach_m; do
      values=$loads
      [[ $kind == approach_m ]] && values=$approaches
      config="$work/$set-$mode-$kind.toml"
      cat > "$config" <<EOF
[profiles]
$profile_lines
[solver]
mode = "$mode"
surface = "$surface"
reference_point = "$reference_point"
$reference_angle_line
[axes]
lateral_displacement_m = { start = -12e-3, stop = 12e-3, step = $step }
$kind = $values
EOF
      set +e
      "$ctab" generate "$config" -o "$work/table.h5" --quiet > /dev/null 2> "$work/stderr"
      set -e
      counts=$("$ctab" inspect "$work/table.h5" | sed -n 's/^status counts (case x wheel): //p')
      failed=$(awk '{ for (i = 1; i < NF; i += 2) if ($i != "converged" && $i != "no-contact" && $i != "under-resolved") s += $(i + 1) } END { print s + 0 }' <<< "$counts")
      cases=$(awk '{ for (i = 2; i <= NF; i += 2) s += $i } END { print s + 0 }' <<< "$counts")
      printf '%-10s %-8s %-15s %8d wheel cases, %5d failed   (%s)\n' "$set" "$mode" "$kind" "$cases" "$failed" "$counts"
      total_failed=$((total_failed + failed))
      total_cases=$((total_cases + cases))
    done
  done
done
echo "total: $total_failed failed of $total_cases wheel cases"
[[ $total_failed == 0 ]]
