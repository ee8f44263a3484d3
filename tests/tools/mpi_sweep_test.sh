#!/usr/bin/env bash
# `mpirun -np 2 coldspray sweep`: the cases are shared between the ranks (rank r runs the cases
# i % 2 == r) and rank 0 writes one sweep.csv with every case, the failing one included
# (docs/studies.md, MPI). Arguments: MPIEXEC COLDSPRAY TEST_DATA.
set -euo pipefail
mpiexec=$1 coldspray=$2 data=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
as_root=()
if [ "$(id -u)" -eq 0 ]; then as_root=(--allow-run-as-root); fi
"$mpiexec" "${as_root[@]}" --oversubscribe -np 2 "$coldspray" sweep "$data/cli/escape.yaml" \
  --out sw --quiet --threads-per-job 1 \
  --vary 'bodies.block.velocity=[0, 0, 1 m/s],[0, 0, 2 m/s],[0, 0, 3 m/s],[0, 0, 1000 m/s]' \
  >log.txt 2>&1 || { cat log.txt; exit 1; }
fail() { echo "FAIL: $*"; cat log.txt; cat sw/sweep.csv 2>/dev/null; exit 1; }
grep -q "sweep rank 0/2: 4 cases, 2 run now (0 failed)" log.txt || fail "rank 0 did not run 2 cases"
grep -q "sweep rank 1/2: 4 cases, 2 run now (1 failed)" log.txt || fail "rank 1 did not run 2 cases"
[ "$(grep -c '^case_000[1-4],ok,' sw/sweep.csv)" -eq 3 ] || fail "3 ok rows expected"
grep -q '^case_0004,"fault: ' sw/sweep.csv || fail "the failing case's row is missing"
for k in 1 2 3 4; do [ -f "sw/case_000$k/summary.json" ] || fail "case_000$k has no summary"; done
echo "ok: 4 cases over 2 ranks, one sweep.csv"
