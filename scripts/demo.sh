#!/usr/bin/env bash
# `make demo`: the main job on a built-in default. It shows each family of the kit on the papers'
# own settings and writes what it draws and tabulates into build/demo/:
#   1. the eight arena families of paper 000 (Figure 3), exact areas;
#   2. the shared real maps, read and counted;
#   3. the four papers reproduced: `antkit reproduce --quick --out build/demo`, whose claims table
#      (holds / partly / does not hold, with the measured figure) is printed; the report with every
#      table and figure (SVG and PNG) is build/demo/README.md;
#   4. a robot: the Khepera firmware emulator on a pseudo-terminal, two Buffon visits recorded over
#      the tty, replayed bit for bit, and the area computed from the two logs;
#   5. paper 002's marker-floor robot: its emulator rendering camera frames (with sensor noise),
#      ant-edge STC driven through the camera pipeline over the tty, the log replayed, and the tour
#      compared with the simulated one.
set -euo pipefail
antkit=${1:-build/release/cli/antkit}
out=${DEMO_OUT:-build/demo}
here=$(cd "$(dirname "$0")/.." && pwd)
maps="$here/data/maps"
mkdir -p "$out"
# Absolute, so that the sections that run from the checkout find them.
antkit=$(realpath "$antkit")
out=$(cd "$out" && pwd)

section() { printf '\n== %s\n' "$*"; }

"$antkit" --version

section "Arenas of paper 000, Figure 3 (unit: robot diameter)"
printf '%-34s %12s %-26s %9s %6s\n' spec area area_exact perimeter holes
for spec in standard circle:d=10 square:d=100 ellipse:e=0.968 ellipse:e=0.998 \
  barrier-i:len=0.4 barrier-plus:len=0.4 ring plus obstacles; do
  "$antkit" arena "$spec" --format json | jq -r --arg spec "$spec" \
    '[$spec, .area, (if (.area_exact | length) <= 24 then .area_exact else .area_exact[0:21] + "..." end),
      .perimeter, .holes] | @tsv' |
    while IFS=$'\t' read -r s a e p h; do printf '%-34s %12.4f %-26s %9.3f %6d\n' "$s" "$a" "$e" "$p" "$h"; done
done

if [ -d "$maps" ]; then
  section "Real maps (data/maps)"
  printf '%-36s %9s %9s %9s %9s %10s\n' map size free blocked unknown components
  for m in movingai/room-32-32-4.map movingai/Berlin_1_256.map movingai/brc202d.map \
    ros/turtlebot3_world.yaml ros/willow-2010-02-18-0.10.yaml; do
    "$antkit" map info "$maps/$m" --format json |
      jq -r --arg m "$m" '"\($m)\t\(.width)x\(.height)\t\(.free)\t\(.blocked)\t\(.unknown // 0)\t\(.components)"' |
      while IFS=$'\t' read -r n size free blocked unknown comps; do
        printf '%-36s %9s %9s %9s %9s %10s\n' "$n" "$size" "$free" "$blocked" "$unknown" "$comps"
      done
  done
else
  section "data/maps not found in the checkout: skipping the real maps"
fi

section "The papers reproduced: antkit reproduce --quick (report: $out/README.md)"
# From the checkout, so that the report's command names the maps as data/maps.
(cd "$here" && "$antkit" reproduce --quick --out "$out")

section "A robot over a serial link: Khepera emulator, two recorded visits, replay, area from logs"
emu_out="$out/emulator.txt"
"$antkit" emulate khepera --arena circle:d=20 --seed 3 >"$emu_out" &
emu_pid=$!
trap 'kill "$emu_pid" 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s "$emu_out" ] && break; sleep 0.05; done
port=$(head -n 1 "$emu_out")
echo "emulator on $port"
for visit in 1 2; do
  # --force: the demo's directory is made anew by each run (a recording never replaces a log
  # otherwise). --arena names the emulator's arena in the log, for the true area below.
  "$antkit" record --device khepera --port "$port" --controller buffon --visit "$visit" \
    --steps 3000 --arena circle:d=20 --out "$out/khepera-visit$visit.jsonl" --force --format json |
    jq -r '"visit '"$visit"': \(.steps) steps, \(.exchanges) exchanges, \(.retries) resends, stopped: \(.stopped), hash \(.hash)"'
done
"$antkit" replay "$out/khepera-visit1.jsonl" --format json |
  jq -r '"replay of visit 1: \(.steps) steps, identical: \(.identical), hash \(.hash)"'
"$antkit" buffon-from-logs "$out/khepera-visit1.jsonl" "$out/khepera-visit2.jsonl"
kill "$emu_pid" 2>/dev/null || true
wait "$emu_pid" 2>/dev/null || true
trap - EXIT

section "Paper 002's marker-floor robot: rendered camera frames, ant-edge STC over a pseudo-terminal"
floor_map="$maps/movingai/random-32-32-20.map"
floor_out="$out/floor-emulator.txt"
"$antkit" emulate stc-floor --map "$floor_map" --noise 20 --format json >"$floor_out" &
floor_pid=$!
trap 'kill "$floor_pid" 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s "$floor_out" ] && break; sleep 0.05; done
port=$(head -n 1 "$floor_out")
echo "marker-floor emulator on $port"
"$antkit" record --device stc-floor --port "$port" --controller ant-edge --map "$floor_map" \
  --out "$out/floor.jsonl" --force --format json |
  jq -r '"recorded: \(.steps) steps, \(.tour.covered) of \(.tour.reachable_subcells) sub-cells, \(.tour.repeats) repeats, back at the start: \(.tour.returned_to_start), tour hash \(.tour.hash)"'
"$antkit" stc --map "$floor_map" --variant ant-edge --format json |
  jq -r '"simulated ant-edge:       tour hash \(.hash)"'
"$antkit" replay "$out/floor.jsonl" --format json |
  jq -r '"replay of the log: \(.steps) steps, identical: \(.identical)"'
kill "$floor_pid" 2>/dev/null || true
wait "$floor_pid" 2>/dev/null || true
trap - EXIT

section "Figures and tables are in $out/"
ls "$out"
