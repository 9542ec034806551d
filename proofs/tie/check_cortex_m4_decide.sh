#!/usr/bin/env bash
# check_cortex_m4_decide.sh DIGEST GOLDEN [--first N] [--count N] [--flip K]
#
# The ant-like STC decision as the Cortex-M4 image compiles it (the C API's antkit_ant_stc_step,
# run under QEMU by scripts/run-on-mcu.sh decide) against AntDecide.v's `decide`: the chip's digest
# of its answers on inputs [N, N + COUNT) (default: the whole domain, 134 217 728 inputs) must
# equal the one DIGEST (proof_tie_ant_decide_digest) computes from the Coq table GOLDEN over the
# same inputs (issue 41; mcu/src/decide_run.cpp defines the numbering and the digest).
#
# --flip K: the tooth. The chip changes its answer on input K; the digests must then differ, and
# the check passes only when it reports that MISMATCH.
#
# Exit: 0 pass, 1 fail, 77 skipped (no cross compiler or QEMU: ANTKIT_MCU_MISSING).
set -euo pipefail
[ -z "${ANTKIT_MCU_MISSING:-}" ] || { echo "skipped: no arm-none-eabi-g++ or qemu-system-arm"; exit 77; }
here=$(cd "$(dirname "$0")/../.." && pwd)
digest=$1 golden=$2
shift 2
range=() flip=()
while [ $# -gt 0 ]; do
  case "$1" in
  --first | --count) range+=("$1" "$2") ;;
  --flip) flip=(--flip "$2") ;;
  *)
    echo "usage: check_cortex_m4_decide.sh DIGEST GOLDEN [--first N] [--count N] [--flip K]" >&2
    exit 1
    ;;
  esac
  shift 2
done
fields='{first, inputs, bytes, digest}'
host=$("$digest" "$golden" "${range[@]}" | jq -c "$fields")
echo "Coq table: $host"
start=$(date +%s.%N)
status=0
chip_json=$("$here/scripts/run-on-mcu.sh" decide "${range[@]}" "${flip[@]}") || status=$?
[ $status -ne 77 ] || { echo "skipped: run-on-mcu.sh: no cross compiler or QEMU"; exit 77; }
[ $status -eq 0 ] || { echo "run-on-mcu.sh failed ($status)"; exit 1; }
end=$(date +%s.%N)
chip=$(jq -c "$fields" <<<"$chip_json")
seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')
echo "chip:      $chip ($seconds s under QEMU)"
if [ "$chip" = "$host" ]; then
  if [ ${#flip[@]} -eq 0 ]; then
    echo "the chip's answers are the Coq table's"
    exit 0
  fi
  echo "FAIL: the chip's answer on input ${flip[1]} was flipped, and the digests still agree"
  exit 1
fi
echo "MISMATCH cortex-m4 decide: the chip's digest is not the Coq table's"
if [ ${#flip[@]} -gt 0 ]; then
  echo "(the tooth: the chip's answer on input ${flip[1]} was flipped)"
  exit 0
fi
exit 1
