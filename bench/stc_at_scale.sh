#!/usr/bin/env bash
# `antkit stc` at scale, end to end (issue 15): whole processes on empty maps of 1024^2, 4096^2 and
# 16384^2 sub-cells, offline variant; wall time and peak memory (GNU time, installed by the
# bootstrap) of the table output, the JSON path into /dev/null and the binary --path-out.
#   bench/stc_at_scale.sh [build/release/cli/antkit] [sides...]
# The maps are written once into build/bench-maps/ (16384^2: 268 MB). Each figure is the median
# of three runs.
set -euo pipefail
antkit=${1:-build/release/cli/antkit}
shift || true
sides=("$@")
[ ${#sides[@]} -gt 0 ] || sides=(1024 4096 16384)
maps=build/bench-maps
mkdir -p "$maps"

empty_map() { # side file
  local n=$1 f=$2 row
  [ -f "$f" ] && return
  row=$(head -c "$n" /dev/zero | tr '\0' '.')
  { printf 'type octile\nheight %d\nwidth %d\nmap\n' "$n" "$n"
    for ((i = 0; i < n; ++i)); do printf '%s\n' "$row"; done; } >"$f.tmp"
  mv "$f.tmp" "$f"
}

median3() { sort -n | sed -n 2p; }

measure() { # label args...
  local label=$1 times=() mems=() out
  shift
  for _ in 1 2 3; do
    out=$( { /usr/bin/time -f '%e %M' "$@" >/dev/null; } 2>&1 | tail -n 1)
    times+=("${out% *}")
    mems+=("${out#* }")
  done
  printf '%-10s %-34s %8s s %10s KB\n' "$side^2" "$label" \
    "$(printf '%s\n' "${times[@]}" | median3)" "$(printf '%s\n' "${mems[@]}" | median3)"
}

printf '%-10s %-34s %10s %13s\n' map command time peak
for side in "${sides[@]}"; do
  empty_map "$side" "$maps/empty-$side.map"
  m="$maps/empty-$side.map"
  measure "stc --variant offline (table)" "$antkit" stc --map "$m" --variant offline
  measure "stc ... --format json >/dev/null" "$antkit" stc --map "$m" --variant offline --format json
  measure "stc ... --path-out p.bin" "$antkit" stc --map "$m" --variant offline --path-out "$maps/p.bin"
done
rm -f "$maps/p.bin"
