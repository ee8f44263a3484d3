#!/usr/bin/env bash
# Quick start, part one: install dependencies, build (Release) and run the default job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
bin=build/release/coldspray

echo
echo "== The default case: a 14 um Al particle at 810 m/s (examples/al-14um-810.yaml) =="
"$bin" check examples/al-14um-810.yaml

echo
echo "== Its material, al-ptw, in uniaxial-stress compression at 1e7 1/s, 298 K, isothermal =="
mkdir -p out
"$bin" material-test --material al-ptw --mode uniaxial-stress --strain-rate "1e7 1/s" \
  --final-strain -0.5 --isothermal --out out/al-ptw-uniaxial-stress.csv
echo
echo "Built: $bin. The MPM solver ('coldspray run') arrives with issue 3."
