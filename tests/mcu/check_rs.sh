#!/usr/bin/env bash
# check_rs.sh ARENA STEPS SEED [options...]: scripts/run-on-mcu.sh rs's Randomized Search walk
# against the host's (`antkit dev rs-mcu-input --host`, buffon::run_rs) for the same arguments
# (hash, cells, length_raw, blocked), both the chip's walk through the core and through the C API.
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
  out=$("$here/scripts/run-on-mcu.sh" rs --arena "$arena" --steps "$steps" --seed "$seed" "$@" \
    2>"$err") || status=$?
  echo "chip: exit $status: $(cat "$err")"
  [ $status -eq 2 ] && [ -z "$out" ] && grep -Eq "^antkit: error: .*holds 114688 bytes" "$err"
  exit
fi
fields='{hash, cells, length_raw, blocked}'
host=$("$ANTKIT_EXE" dev rs-mcu-input --arena "$arena" --steps "$steps" --seed "$seed" "$@" --host |
  jq -c "$fields")
echo "host: $host"
status=0
chip=$("$here/scripts/run-on-mcu.sh" rs --arena "$arena" --steps "$steps" --seed "$seed" "$@" \
  2>"$err") || status=$?
[ $status -eq 0 ] || { echo "run-on-mcu.sh failed ($status): $(cat "$err")"; exit 1; }
# The walk twice on the chip: through the core (run_fixed_rs) and through the C API's behaviour.
chip_c_api=$(jq -c ".c_api | $fields" <<<"$chip")
chip=$(jq -c "$fields" <<<"$chip")
echo "chip: $chip"
echo "chip, C API: $chip_c_api"
[ "$chip_c_api" = "$host" ]
# The walk must have done something: cells marked beyond the start's footprint.
[ "$(jq .cells <<<"$chip")" -gt 80 ]
[ "$chip" = "$host" ]
