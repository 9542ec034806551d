#!/usr/bin/env bash
# check_sim.sh SIM ANTKIT MAP: the example loop run on the simulated floor (SIM, from the start
# `antkit stc` chooses) gives antkit stc --variant ant-edge's tour: the same hash, covered and
# repeats, and never a refused move.
set -euo pipefail
sim=$1 antkit=$2 map=$3
host=$("$antkit" stc --map "$map" --variant ant-edge --format json)
read -r x y < <(jq -r '.start | "\(.[0]) \(.[1])"' <<<"$host")
loop=$("$sim" "$map" "$x" "$y")
echo "antkit stc: $(jq -c '{hash, covered, repeats}' <<<"$host")"
echo "example:    $loop"
[ "$(jq -c '{hash, covered, repeats}' <<<"$host")" = "$(jq -c '{hash, covered, repeats}' <<<"$loop")" ]
[ "$(jq -r .refused <<<"$loop")" = false ]
