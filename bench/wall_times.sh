#!/bin/bash
# Wall-time targets of whole runs (issue 27), measured, never asserted: each case runs to its end
# with `coldspray run` (or `deposit`) on THREADS threads, and the table gives its wall time from
# summary.json, its peak resident memory (/usr/bin/time -v) and the target.
#
#   bench/wall_times.sh [BINARY] [THREADS] [OUT]      # defaults: build/release/coldspray 2 out/bench
#   CASES="3d-fast two-0um" bench/wall_times.sh       # a subset (names below)
#
# Run on an idle machine, one case after another; the machine's speed drifts by up to 20 %, so
# compare two builds by running both in one session. About 80 minutes for all six on 2 cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(realpath "${1:-$root/build/release/coldspray}")
threads=${2:-2}
out=${3:-$root/out/bench}
mkdir -p "$out"

# name | command after the binary | target (s) | what the target is
cases=(
  "3d-fast|run $root/examples/al-14um-810-3d-fast.yaml|120|3D quarter, 14 um at 810 m/s, 0.7/0.175 um, 80 ns"
  "two-0um|run $root/examples/multi-particle/two-particles-0um.yaml|1200|two particles, 0 um offset, 90 ns"
  "two-2.5um|run $root/examples/multi-particle/two-particles-2.5um.yaml|1200|two particles, 2.5 um offset, 90 ns"
  "two-5um|run $root/examples/multi-particle/two-particles-5um.yaml|1200|two particles, 5 um offset, 90 ns"
  "two-7.5um|run $root/examples/multi-particle/two-particles-7.5um.yaml|1200|two particles, 7.5 um offset, 90 ns"
  "ten|deposit $root/examples/deposit/ten-particles.yaml|1800|ten particles, 1.0/0.35 um, 127.3 ns"
)
selected=${CASES:-"3d-fast two-0um two-2.5um two-5um two-7.5um ten"}

wall_seconds() {  # from summary.json, written by every run
  /usr/bin/python3 -c 'import json, sys; print("%.1f" % json.load(open(sys.argv[1]))["wall_seconds"])' "$1"
}

printf '| case | wall (s) | target (s) | peak memory (MB) | threads | what |\n| --- | --- | --- | --- | --- | --- |\n' \
  > "$out/wall_times.md"
for entry in "${cases[@]}"; do
  IFS='|' read -r name command target what <<< "$entry"
  [[ " $selected " == *" $name "* ]] || continue
  echo "running $name: coldspray $command --threads $threads" >&2
  # shellcheck disable=SC2086  # the command is words
  /usr/bin/time -v -o "$out/$name.time" "$bin" $command --threads "$threads" --quiet --overwrite \
    --out "$out/$name" > "$out/$name.log" 2>&1
  rss_kb=$(awk -F: '/Maximum resident set size/ {gsub(/ /, "", $2); print $2}' "$out/$name.time")
  printf '| %s | %s | %s | %d | %s | %s |\n' "$name" "$(wall_seconds "$out/$name/summary.json")" \
    "$target" $((rss_kb / 1024)) "$threads" "$what" >> "$out/wall_times.md"
done
cat "$out/wall_times.md"
