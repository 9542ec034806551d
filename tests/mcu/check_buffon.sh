#!/usr/bin/env bash
# check_buffon.sh ARENA STEPS SEED [antkit buffon options...]: scripts/run-on-mcu.sh buffon's trial
# against `antkit buffon --trials 1`'s for the same arguments (hash, bc, crossings_exact, blocked),
# both the chip's run through the cores and through the C API.
# With ARENA prefixed by "refused:", the run must instead be refused (exit 2, nothing on stdout)
# with the chip's limit (114688 bytes) in the message.
set -euo pipefail
[ -z "${ANTKIT_MCU_MISSING:-}" ] || { echo "skipped: no arm-none-eabi-g++ or qemu-system-arm"; exit 77; }
here=$(cd "$(dirname "$0")/../.." && pwd)
arena=$1 steps=$2 seed=$3
shift 3
err=$(mktemp)
trap 'rm -f "$err"' EXIT
if [ "${arena#refused:}" != "$arena" ]; then
  arena=${arena#refused:}
  status=0
  out=$("$here/scripts/run-on-mcu.sh" buffon --arena "$arena" --steps "$steps" --seed "$seed" "$@" \
    2>"$err") || status=$?
  echo "chip: exit $status: $(cat "$err")"
  [ $status -eq 2 ] && [ -z "$out" ] && grep -Eq "^antkit: error: .*holds 114688 bytes" "$err"
  exit
fi
fields='{hash, bc, crossings_exact, blocked}'
host=$("$ANTKIT_EXE" buffon --arena "$arena" --steps "$steps" --seed "$seed" --trials 1 "$@" \
  --format json | jq -c ".trials[0] | $fields")
echo "host: $host"
status=0
chip=$("$here/scripts/run-on-mcu.sh" buffon --arena "$arena" --steps "$steps" --seed "$seed" "$@" \
  2>"$err") || status=$?
[ $status -eq 0 ] || { echo "run-on-mcu.sh failed ($status): $(cat "$err")"; exit 1; }
# The trial twice on the chip: through run_fixed_trial and through the C API's behaviour,
# detector and hash (c_api).
chip_c_api=$(jq -c ".c_api | $fields" <<<"$chip")
chip=$(jq -c ".trials[0] | $fields" <<<"$chip")
echo "chip: $chip"
echo "chip, C API: $chip_c_api"
[ "$chip_c_api" = "$host" ]
[ "$chip" = "$host" ]
