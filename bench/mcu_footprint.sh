#!/usr/bin/env bash
# The Cortex-M image's footprint (issue 27), as a Markdown table for the README: flash of each
# controller's step path (from the image's symbol table: nm -S), the stack of each function on it
# (gcc -fstack-usage), the controllers' state, the whole image (size), and the instructions per move
# of a tour on den312d under QEMU with -icount (an estimate of cycles: see scripts/run-on-mcu.sh);
# then Buffon, Randomized Search and the step-turn wanderer the same way.
#
#   bench/mcu_footprint.sh        builds build/mcu if needed (through scripts/run-on-mcu.sh)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
map=data/maps/movingai/den312d.map
ant=$(scripts/run-on-mcu.sh --icount stc --map $map --variant ant)
edge=$(scripts/run-on-mcu.sh --icount stc --map $map --variant ant-edge)
online=$(scripts/run-on-mcu.sh --icount stc --map $map --variant online)
buffon=$(scripts/run-on-mcu.sh --icount buffon --arena square:area=25 --steps 3000 --seed 1)
rs=$(scripts/run-on-mcu.sh --icount rs --arena square:area=25 --steps 3000 --seed 1)
wanderer=$(scripts/run-on-mcu.sh --icount wanderer --map $map)
image=build/mcu/antkit_mcu.elf
symbols=$(arm-none-eabi-nm -S -C "$image")
stack=$(cat $(find build/mcu -name '*.su'))
size_of() { # flash bytes of the symbols whose demangled name matches the pattern
  local total=0 address size rest
  while read -r address size rest; do total=$((total + 16#$size)); done < <(grep -E "$1" <<<"$symbols")
  echo $total
}
stack_of() { # the largest frame of the functions matching the pattern
  grep -E "$1" <<<"$stack" | awk -F'\t' '{ if ($2 > m) m = $2 } END { print m + 0 }'
}
ctl_ant=$(size_of ' antkit_ant_stc_step$')
ctl_edge=$(size_of ' antkit_ant_edge_stc_step$')
ctl_online=$(size_of ' antkit_online_stc_step$')
loop_online=$(size_of 'tour<\(anonymous namespace\)::OnlineController')
loop_ant=$(size_of 'tour<\(anonymous namespace\)::AntController')
loop_edge=$(size_of 'tour<\(anonymous namespace\)::AntEdgeController')
apply=$(size_of 'Floor::apply')
light=$(size_of 'Floor::light_edge')
hash=$(size_of 'TraceHash::add_u32')
read -r text data bss _ < <(arm-none-eabi-size "$image" | tail -1)
echo "Cortex-M4 (arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion), -O2, hard float), image $image:"
echo
echo "| | ant (sub-cell marks) | ant-edge (lit edges) | online (memory of cells seen) |"
echo "|---|---|---|---|"
echo "| controller step (C API: \`antkit_*_stc_step\`, the decision inlined) | $ctl_ant B flash, $(stack_of 'antkit_ant_stc_step') B stack | $ctl_edge B flash, $(stack_of 'antkit_ant_edge_stc_step') B stack | $ctl_online B flash, $(stack_of 'antkit_online_stc_step') B stack |"
echo "| controller state | 2 B (\`antkit_ant_stc\`) | 2 B (\`antkit_ant_edge_stc\`) | 128 B (\`antkit_online_stc\`) + a buffer you give it, 256 B per 16 x 16-cell tile seen ($(jq -r '"\(.memory_tiles) tiles on den312d"' <<<"$online")) |"
echo "| the world's step (tour loop with observation and hash inlined, \`Floor::apply\`, \`light_edge\`, \`TraceHash::add_u32\`) | $((loop_ant + apply + hash)) B flash | $((loop_edge + apply + light + hash)) B flash | $((loop_online + apply + hash)) B flash |"
echo "| floor (RAM, per map; den312d) | 2 bits per sub-cell + 1 B per cell ($(jq .floor_bytes <<<"$ant") B) | 2 bits per sub-cell + 2 B per cell ($(jq .floor_bytes <<<"$edge") B) | as ant ($(jq .floor_bytes <<<"$online") B) |"
echo "| instructions per move, den312d (QEMU -icount; controller, floor and hash) | $(jq .instructions_per_move <<<"$ant") | $(jq .instructions_per_move <<<"$edge") | $(jq .instructions_per_move <<<"$online") |"
echo
echo "Whole image: $text B flash (text), $data B data, $bss B bss (of which the floor arena $(jq .floor_limit <<<"$ant") B)."
echo
# Buffon (one trial of square:area=25, 3000 steps per visit). The step path by name: the visit loops
# (the detector, the raster's lay and at, the crossing count inlined), visit_step, the behaviour,
# the world's sensing and collisions, the trace hash, the sine table, and the 64/128-bit helpers
# a 32-bit core needs for them.
behaviour=$(size_of 'ExplorationBehaviour::step|BufferedStream::refill')
# TraceHash::add_u64 is out of line once per translation unit that calls it (buffon_run's and
# rs_run's, the same code): one copy is counted.
hash64=$((16#$(grep -E 'TraceHash::add_u64' <<<"$symbols" | head -1 | awk '{ print $2 }')))
world=$(($(size_of 'visit<antkit::buffon::run_fixed_trial|buffon::visit_step|WorldCore::sense_walls|WorldCore::clear_walls|closer_than|kernel::uniform<long, 16>|RasterCore::lay|RasterCore::at_exact|orientation_in<|soft::Int<true>::divmod|div_round_half_up<|__udivmoddi4') + hash64))
table=$(size_of 'kSineQ30')
echo "| Buffon | flash | stack | RAM |"
echo "|---|---|---|---|"
echo "| behaviour + detector step (\`ExplorationBehaviour::step\`, its stream's refill; the detector inlined) | $behaviour B | $(stack_of 'ExplorationBehaviour::step') + $(stack_of 'BufferedStream::refill') B | 136 B behaviour + 8 B detector (C structs: 160 B, 8 B) |"
echo "| the world's step (visit loops, \`visit_step\`, sensing, collisions, raster, crossing count, hash, 64/128-bit helpers) | $world B + $table B sine table | $(stack_of 'sense_walls') B (sense_walls) | $(jq .arena_bytes <<<"$buffon") B of the arena for square:area=25, 3000 steps |"
echo "| instructions per step (QEMU -icount; both visits of square:area=25, 3000 steps) | $(jq .instructions_per_move <<<"$buffon") | | |"
echo
# Randomized Search (one walk of square:area=25, 3000 steps) and the step-turn wanderer (den312d,
# sensor 5, to antkit cover's default limit of 10 W H ticks). RS's controller is the Buffon
# behaviour (above); its world's step is run_fixed_rs's loop (RS's marking inlined but for the
# disk stamp), visit_step and the world's sensing and collisions as Buffon's. The wanderer's
# controller is the C API's step (StepTurnCore, its stream's draw and refill inlined); its world's
# step is the tick loop (turns and moves inlined), the view and the hash of the state.
rs_world=$(size_of 'buffon::run_fixed_rs|ByteRasterCore::disk<antkit::buffon::rs_mark|buffon::visit_step|WorldCore::sense_walls|WorldCore::clear_walls|closer_than|kernel::uniform<long, 16>|orientation_in<|soft::Int<true>::divmod|div_round_half_up<|__udivmoddi4')
w_ctl=$(size_of ' antkit_step_turn_wanderer_step$')
w_world=$(size_of 'wander\(antkit::uniform::StepTurnWorld|StepTurnWorld::view|StepTurnWorld::can_step|StepTurnWorld::hash_state')
echo "| Randomized Search, step-turn wanderer | flash | stack | RAM |"
echo "|---|---|---|---|"
echo "| RS: controller step | the Buffon behaviour's (above; C API \`antkit_buffon_behaviour_step\`) | | 136 B (C struct 160 B) |"
echo "| RS: the world's step (\`run_fixed_rs\`'s loop, RS's disk stamp, \`visit_step\`, sensing, collisions, hash, 64/128-bit helpers) | $((rs_world + hash64)) B + the $table B sine table | $(stack_of 'sense_walls') B (sense_walls) | $(jq .arena_bytes <<<"$rs") B of the arena for square:area=25 (walls, buckets, 1 B per 0.1 x 0.1 cell) |"
echo "| RS: instructions per step (QEMU -icount; square:area=25, 3000 steps) | $(jq .instructions_per_move <<<"$rs") | | |"
echo "| wanderer: controller step (C API: \`antkit_step_turn_wanderer_step\`, the draw inlined) | $w_ctl B | $(stack_of 'antkit_step_turn_wanderer_step') B | 56 B (\`antkit_step_turn_wanderer\`: 64 B) |"
echo "| wanderer: the world's step (tick loop, \`StepTurnWorld::view\`, \`can_step\`, \`hash_state\`) | $w_world B | $(stack_of 'wander\(') + $(stack_of 'StepTurnWorld::view') B (loop, view) | $(jq .arena_bytes <<<"$wanderer") B for den312d: 2 bits per cell, 12 B per sensor ray and 4 B per cell between (sensor 5: 81 rays) |"
echo "| wanderer: instructions per tick, den312d (QEMU -icount; controller, world, view and hash) | $(jq .instructions_per_move <<<"$wanderer") | | |"
