#!/usr/bin/env bash
# check_footprint.sh IMAGE: the Cortex-M image links no allocator (no malloc, free, _sbrk: the step
# path and everything else run without a heap), the ant-like STC step stays within issue 27's
# budget of 8 KiB of flash (the C API's step functions, ant_decide inlined in them, and the floor's
# step), and the Buffon behaviour with its detector within 16 KiB. The controllers' state sizes (2 bytes) are static_asserts in stc/ant.hpp and c/src/antkit.cpp.
set -euo pipefail
[ -z "${ANTKIT_MCU_MISSING:-}" ] || { echo "skipped: no arm-none-eabi-g++ or qemu-system-arm"; exit 77; }
image=$1
symbols=$(arm-none-eabi-nm -S -C "$image")
if grep -Eq ' (malloc|free|_sbrk|_malloc_r|operator new)' <<<"$symbols"; then
  echo "FAIL: the image links an allocator:"
  grep -E ' (malloc|free|_sbrk|_malloc_r|operator new)' <<<"$symbols"
  exit 1
fi
size_of() { # the bytes of the symbols matching a pattern (nm -S: address, size, type, name)
  local total=0 address size rest
  while read -r address size rest; do
    total=$((total + 16#$size))
  done < <(grep -E "$1" <<<"$symbols")
  echo $total
}
ant=$(size_of ' antkit_ant_stc_step$')
edge=$(size_of ' antkit_ant_edge_stc_step$')
[ "$ant" -gt 0 ] && [ "$edge" -gt 0 ] || { echo "FAIL: step functions not found"; exit 1; }
echo "antkit_ant_stc_step: $ant bytes, antkit_ant_edge_stc_step: $edge bytes (budget 8192 each)"
[ "$ant" -le 8192 ] && [ "$edge" -le 8192 ]
# The Buffon behaviour with its detector (issue 27's budget: 16 KiB): ExplorationBehaviour::step
# and the stream's refill (what antkit_buffon_behaviour_step runs), the detector inlined in the
# visit loop. Both visit loops must be there (the trial runs on the chip).
behaviour=$(size_of 'ExplorationBehaviour::step|BufferedStream::refill')
loops=$(size_of 'visit<antkit::buffon::run_fixed_trial')
[ "$behaviour" -gt 0 ] && [ "$loops" -gt 0 ] || { echo "FAIL: Buffon step functions not found"; exit 1; }
echo "Buffon behaviour step: $behaviour bytes (budget 16384)"
[ "$behaviour" -le 16384 ]
