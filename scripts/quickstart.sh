#!/usr/bin/env bash
# Quick start, part one: install dependencies, build (Release) and run the default job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
bin=build/release/coldspray

echo
echo "== The default case: a 14 um Al particle at 810 m/s on an Al substrate =="
"$bin" run examples/al-14um-810.yaml --overwrite  # the script may be run again
