#!/bin/bash
# The figures of docs/images/materials/: each Johnson-Cook built-in driven by
# `coldspray material-test` (uniaxial stress, isothermal, 298 K, to a log strain of -0.5) at
# 1e3 and 1e7 1/s, beside the Johnson-Cook formula with the constants of its publication.
# The constants are written here from the papers (as in tests/case/builtin_materials_test.cpp),
# not read from data/materials/, so the figure compares the code with the paper.
#
# Usage: tools/material_plots.sh [COLDSPRAY_BINARY] [OUT_DIR]
#   defaults: build/release/coldspray and docs/images/materials
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build/release/coldspray}
out=${2:-docs/images/materials}
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name | A,B,n,C,m,T_m (MPa, K) | publication
materials=(
  "cu-jc|90,292,0.31,0.025,1.09,1356|Johnson & Cook 1983"
  "ni-jc|163,648,0.33,0.006,1.44,1726|Johnson & Cook 1983"
  "steel4340-jc|792,510,0.26,0.014,1.03,1793|Johnson & Cook 1983"
  "ti64-jc|1098,1092,0.93,0.014,1.1,1878|Lesuer 2000"
  "al6061-jc|324,114,0.42,0.002,1.34,925|Lesuer, Kay & LeBlanc 2001"
  "in718-jc|1241,622,0.6522,0.0134,1.3,1609|Kobayashi et al. 2008"
  "ss316l-jc|305,1161,0.61,0.01,0.517,1670|Umbrello et al. 2007"
)

for entry in "${materials[@]}"; do
  IFS='|' read -r name constants source <<<"$entry"
  csvs=()
  for rate in 1e3 1e7; do
    csv="$work/$name-$rate.csv"
    "$binary" material-test --material "$name" --mode uniaxial-stress --strain-rate "$rate 1/s" \
      --final-strain -0.5 --temperature '298 K' --isothermal --steps 2000 --out "$csv" >/dev/null
    csvs+=("$csv")
  done
  /usr/bin/python3 tools/coldspray_plot.py material-test "${csvs[@]}" \
    --labels "1e3 1/s,1e7 1/s" --johnson-cook "$constants" --source "$source" \
    --title "$name, uniaxial stress, isothermal, 298 K" --out "$out/$name.png"
  echo "$out/$name.png"
done
