#!/usr/bin/env bash
# check_wanderer.sh [refused] antkit-cover-options...: scripts/run-on-mcu.sh wanderer's JSON against
# `antkit cover --algo rw --robots 1 --format json`'s for the same options (hash, viewed, viewable,
# movements, moves, stop). With "refused" first, the run must instead be refused (exit 2, nothing on
# stdout) with the chip's limit (114688 bytes) in the message, while antkit cover runs it.
set -euo pipefail
[ -z "${ANTKIT_MCU_MISSING:-}" ] || { echo "skipped: no arm-none-eabi-g++ or qemu-system-arm"; exit 77; }
here=$(cd "$(dirname "$0")/../.." && pwd)
refused=0
[ "${1:-}" = refused ] && { refused=1; shift; }
err=$(mktemp)
trap 'rm -f "$err"' EXIT
fields='{hash, viewed, viewable, movements, moves, stop}'
host=$("$ANTKIT_EXE" cover --algo rw --robots 1 "$@" --format json | jq -c "$fields")
echo "host: $host"
status=0
chip=$("$here/scripts/run-on-mcu.sh" wanderer "$@" 2>"$err") || status=$?
if [ $refused -eq 1 ]; then
  echo "chip: exit $status: $(cat "$err")"
  [ $status -eq 2 ] && [ -z "$chip" ] && grep -Eq "^antkit: error: .*holds 114688 bytes" "$err"
  exit
fi
[ $status -eq 0 ] || { echo "run-on-mcu.sh failed ($status): $(cat "$err")"; exit 1; }
chip=$(jq -c "$fields" <<<"$chip")
echo "chip: $chip"
# The robot must have moved and viewed beyond its start.
[ "$(jq .moves <<<"$chip")" -gt 0 ]
[ "$chip" = "$host" ]
