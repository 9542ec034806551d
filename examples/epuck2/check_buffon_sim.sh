#!/usr/bin/env bash
# check_buffon_sim.sh SIM ANTKIT ARENA STEPS SEED NOISE: the Buffon example loop (buffon_loop.c) run on
# the simulated board (SIM, buffon_board_sim.cpp) gives trial 0 of `antkit buffon --trials 1`: the
# same Buffon count, blocked steps and trail lengths (raw Q15.16, exact).
set -euo pipefail
sim=$1 antkit=$2 arena=$3 steps=$4 seed=$5 noise=$6
host=$("$antkit" buffon --arena "$arena" --trials 1 --steps "$steps" --seed "$seed" \
  --noise "$noise" --format json |
  jq -c '.trials[0] | {bc, blocked, length1_raw: (.length1 * 65536), length2_raw: (.length2 * 65536)}')
loop=$("$sim" "$arena" "$steps" "$seed" "$noise")
echo "antkit buffon: $host"
echo "example:       $loop"
[ "$host" = "$(jq -c '{bc, blocked, length1_raw, length2_raw}' <<<"$loop")" ]
