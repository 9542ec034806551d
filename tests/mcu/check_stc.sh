#!/usr/bin/env bash
# check_stc.sh MAP VARIANT [antkit stc options...]: scripts/run-on-mcu.sh's JSON against antkit
# stc's for the same arguments (hash, covered, repeats, returned_to_start). When the map's floor
# (2 bits per sub-cell, 1 byte per cell for ant and online, 2 for ant-edge, cells with a border)
# and, for online, its memory of the cells seen exceed the image's 114688 bytes, the run must
# instead be refused (exit 2) with that limit in the message.
set -euo pipefail
[ -z "${ANTKIT_MCU_MISSING:-}" ] || { echo "skipped: no arm-none-eabi-g++ or qemu-system-arm"; exit 77; }
here=$(cd "$(dirname "$0")/../.." && pwd)
map=$1 variant=$2
shift 2
fields='{hash, covered, repeats, returned_to_start}'
host_json=$("$ANTKIT_EXE" stc --map "$map" --variant "$variant" "$@" --format json)
host=$(jq -c "$fields" <<<"$host_json")
w=$(jq .width <<<"$host_json") h=$(jq .height <<<"$host_json")
cx=$((w / 2)) cy=$((h / 2)) per_cell=1
[ "$variant" = ant-edge ] && per_cell=2
# floor_bytes (floor.hpp): both bit arrays rounded up to 8 bytes, then the cells with a border.
bits=$(((4 * cx * cy + 7) / 8))
need=$(((2 * bits + 7) / 8 * 8 + (cx + 2) * (cy + 2) * per_cell))
if [ "$variant" = online ]; then # and FixedCellMemory::bytes_for(mcu_online_tiles) (mcu_input.hpp)
  tiles=$(((cx / 16 + 2) * (cy / 16 + 2))) slots=2
  while [ $slots -lt $((2 * tiles)) ]; do slots=$((slots * 2)); done
  need=$(((need + 7) / 8 * 8 + tiles * 256 + slots * 12))
fi
err=$(mktemp)
trap 'rm -f "$err"' EXIT
status=0
chip=$("$here/scripts/run-on-mcu.sh" stc --map "$map" --variant "$variant" "$@" 2>"$err") || status=$?
echo "host: $host (floor $need bytes)"
if [ "$need" -gt 114688 ]; then
  echo "chip: exit $status: $(cat "$err")"
  [ $status -eq 2 ] && grep -q "need $need bytes of floor.* which has 114688" "$err"
  exit
fi
[ $status -eq 0 ] || { echo "run-on-mcu.sh failed ($status): $(cat "$err")"; exit 1; }
chip=$(jq -c "$fields" <<<"$chip")
echo "chip: $chip"
[ "$chip" = "$host" ]
