#!/usr/bin/env bash
# Runs antkit's controllers on an emulated Cortex-M4 (issue 27): QEMU's netduinoplus2 (an
# STM32F405, the nearest model QEMU has to the e-puck2's STM32F407), the image built from mcu/ with
# Debian's gcc-arm-none-eabi, its input and output through semihosting.
#
#   scripts/run-on-mcu.sh stc --map F --variant ant|ant-edge|online [--start X,Y] [--noise P]
#                         [--seed S]
#
# prints one JSON object whose hash, covered, repeats and returned_to_start equal those of
# `antkit stc --format json` with the same arguments.
#
#   scripts/run-on-mcu.sh buffon --arena SPEC|FILE.wkt --steps N [--seed S] [--width W] [--noise X]
#
# prints one JSON object whose trials[0] has the hash, bc, crossings_exact and blocked of
# `antkit buffon --trials 1 --format json`'s trial with the same arguments. The host prepares the
# input (`antkit dev buffon-mcu-input`: the arena built with CGAL and sent as its Q15.16 walls, the
# options checked as `antkit buffon` checks them); the exploration behaviour, the world's steps,
# the pheromone raster, the detector, the exact crossing count and the hash run on the chip. A
# trial whose walls, buckets, raster, visit 1's trail and crossing index exceed the image's
# 112 KiB arena is refused (exit 2) with the sizes and the limit in the message: the paper's
# circles (256 walls, about 130 KiB of wall buckets) do not fit; squares and polygons of a few
# dozen walls do, with a few thousand steps per visit. The host prepares the input (`antkit
# dev stc-mcu-input`: the map read, the start chosen and checked, the map's free sub-cells as bits);
# the controller, the floor's steps and the hash run on the emulated chip. Bad input is refused by
# the host as `antkit stc` refuses it, exit 2 with a located message; a map whose floor exceeds the
# image's 112 KiB arena (online: with its memory of the cells seen) is refused with both sizes in
# the message.
#
#   scripts/run-on-mcu.sh rs --arena SPEC|FILE.wkt --steps N [--seed S] [--noise X]
#
# runs one Randomized Search walk (paper 000, Section 8.1: visit 3 of trial 0's streams, marking the
# 0.1 x 0.1 cells under the body) and prints one JSON object whose hash, cells, length_raw and
# blocked equal those of `antkit dev rs-mcu-input --host` with the same arguments (the host's
# run_rs). The host sends the arena's walls (`antkit dev rs-mcu-input`); the behaviour, the world's
# steps, RS's raster and the hash run on the chip, in the same 112 KiB arena: walls, wall buckets
# and a byte per raster cell of the walls' box, refused with the sizes and the limit when they
# exceed it.
#
#   scripts/run-on-mcu.sh wanderer (--map F | --size WxH --density P) [--seed S] [--trial K]
#                         [--sensor R] [--limit T]
#
# runs paper 004's Random Wanderer for one robot that only steps and turns (uniform/step_turn.hpp)
# and prints one JSON object whose hash, viewed, viewable, movements, moves and stop equal those of
# `antkit cover --algo rw --robots 1 --format json` with the same arguments. The host reads the map,
# places the robot, counts the viewable cells and computes the sensor's footprint (`antkit dev
# wanderer-mcu-input`); the wanderer, the world's ticks (moves, line-of-sight views) and the hash
# run on the chip, in the same 112 KiB arena: 2 bits per map cell and the footprint, refused with
# the sizes and the limit when they exceed it.
#
#   scripts/run-on-mcu.sh decide [--first N] [--count N] [--flip K]
#
# runs the ant-like STC decision as the chip compiles it (the C API's antkit_ant_stc_step) on
# inputs [N, N + COUNT) of its whole domain (default: all 134 217 728, 4 quadrants x 2 done x 16^6
# masks, numbered as proofs/tie/ant_stc_tie.cpp enumerates them) and prints one JSON object whose
# digest of every answer equals that of `proof_tie_ant_decide_digest AntDecide.out` with the same
# range, computed from the Coq table (mcu/src/decide_run.cpp). --flip K changes the chip's answer
# on input K (the tooth). Nothing is read from the host but the command line; a full run takes
# about 20 s (15.5 G emulated instructions).
#
# Options before the subcommand:
#   --icount   run QEMU with -icount shift=0 (its virtual clock advances 1 ns per instruction, and
#              the emulated STM32F405's SysTick counts 168 per us of it) and add to the JSON
#              "instructions" (of the tour: ticks x 125 / 21) and "instructions_per_move". An
#              estimate of cycles, not a measurement: QEMU counts instructions, while a real
#              Cortex-M4 takes more than one cycle for loads, taken branches and flash wait states.
#
# Builds what it needs on first use: build/mcu (the image) and, unless ANTKIT_EXE names an antkit
# binary, build/release's antkit. Exit: 0 ran, 2 bad input, 1 any other failure, 77 the cross
# compiler or QEMU is missing (scripts/bootstrap.sh installs them).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

usage() {
  echo "usage: scripts/run-on-mcu.sh [--icount] stc --map F --variant ant|ant-edge|online [--start X,Y]" \
    "[--noise P] [--seed S]" >&2
  echo "       scripts/run-on-mcu.sh [--icount] buffon --arena SPEC --steps N [--seed S] [--width W]" \
    "[--noise X]" >&2
  echo "       scripts/run-on-mcu.sh [--icount] rs --arena SPEC --steps N [--seed S] [--noise X]" >&2
  echo "       scripts/run-on-mcu.sh [--icount] wanderer (--map F | --size WxH --density P) [--seed S]" \
    "[--trial K] [--sensor R] [--limit T]" >&2
  echo "       scripts/run-on-mcu.sh [--icount] decide [--first N] [--count N] [--flip K]" >&2
  exit 2
}

icount=0
while [ $# -gt 0 ] && [ "${1#--}" != "$1" ]; do
  case "$1" in
  --icount) icount=1 ;;
  *) usage ;;
  esac
  shift
done
[ $# -ge 1 ] || usage
command=$1
shift
case "$command" in
stc | buffon | rs | wanderer | decide) ;;
*)
  echo "run-on-mcu.sh: unknown command '$command' (stc, buffon, rs, wanderer, decide)" >&2
  exit 2
  ;;
esac

missing=()
for tool in arm-none-eabi-g++ qemu-system-arm cmake ninja; do
  command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "run-on-mcu.sh: missing ${missing[*]}: run scripts/bootstrap.sh (as root it installs" \
    "gcc-arm-none-eabi, libstdc++-arm-none-eabi-newlib and qemu-system-arm)" >&2
  exit 77
fi

export CCACHE_BASEDIR=$here CCACHE_NOHASHDIR=1
log=$here/build/mcu.build.log
mkdir -p "$here/build"
# ANTKIT_MCU_IMAGE: an image already built (ctest passes the build tree's, which the build made).
image=${ANTKIT_MCU_IMAGE:-$here/build/mcu/antkit_mcu.elf}
if [ -z "${ANTKIT_MCU_IMAGE:-}" ]; then
  if [ ! -f "$here/build/mcu/build.ninja" ]; then
    cmake -S "$here/mcu" -B "$here/build/mcu" -G Ninja \
      "-DCMAKE_TOOLCHAIN_FILE=$here/cmake/arm-none-eabi.cmake" >"$log" 2>&1 ||
      { cat "$log" >&2; exit 1; }
  fi
  cmake --build "$here/build/mcu" >"$log" 2>&1 || { cat "$log" >&2; exit 1; }
fi

antkit=${ANTKIT_EXE:-$here/build/release/cli/antkit}
if [ -z "${ANTKIT_EXE:-}" ] && [ "$command" != decide ]; then
  if [ ! -f "$here/build/release/build.ninja" ]; then
    (cd "$here" && cmake --preset release) >"$log" 2>&1 || { cat "$log" >&2; exit 1; }
  fi
  cmake --build "$here/build/release" --target antkit >"$log" 2>&1 || { cat "$log" >&2; exit 1; }
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "$command" = decide ]; then
  # No input file: the range (and the tooth's input) on the semihosting command line.
  first=0 count="" flip=""
  while [ $# -gt 0 ]; do
    [ $# -ge 2 ] || usage
    [[ "$2" =~ ^[0-9]+$ ]] || usage
    case "$1" in
    --first) first=$2 ;;
    --count) count=$2 ;;
    --flip) flip=",arg=$2" ;;
    *) usage ;;
    esac
    shift 2
  done
  count=${count:-$((134217728 - first))}
  config="enable=on,target=native,arg=antkit_mcu,arg=decide,arg=$first,arg=$count$flip"
else
  # Bad input: antkit's located message on stderr and its exit status 2, nothing on stdout.
  "$antkit" dev "$command-mcu-input" "$@" --out "$work/input.bin" >/dev/null
  config="enable=on,target=native,arg=antkit_mcu,arg=$work/input.bin"
fi

qemu=(qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none
  -semihosting-config "$config" -kernel "$image")
[ $icount -eq 1 ] && qemu+=(-icount shift=0)
status=0
timeout 600 "${qemu[@]}" >"$work/out" 2>"$work/err" || status=$?
if [ $status -eq 2 ]; then
  sed 's/^error: /run-on-mcu.sh: the chip refused its input: /' "$work/out" >&2
  exit 2
elif [ $status -ne 0 ]; then
  echo "run-on-mcu.sh: the image failed (QEMU exit $status)" >&2
  cat "$work/out" "$work/err" >&2
  exit 1
fi
if [ $icount -eq 1 ]; then
  ticks=$(jq -r .ticks "$work/out")
  # A tour's moves (stc: its positions less the start), the steps (buffon: both visits', rs: the
  # walk's; "moves"), the ticks (wanderer: "movements") or the inputs (decide).
  moves=$(jq -r 'if .movements then .movements elif .moves then .moves
    elif .inputs then .inputs else .positions - 1 end' \
    "$work/out")
  instructions=$((ticks * 125 / 21))
  jq -c --argjson i "$instructions" --argjson m "$moves" \
    '. + {instructions: $i, instructions_per_move: (if $m > 0 then ($i / $m | floor) else 0 end)}' \
    "$work/out"
else
  cat "$work/out"
fi
