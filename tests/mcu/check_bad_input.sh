#!/usr/bin/env bash
# check_bad_input.sh MAPS: bad input to scripts/run-on-mcu.sh is refused with exit 2 and a located
# message, on the host (the options, as antkit stc and antkit buffon refuse them) and on the chip
# (an input file it cannot read: QEMU run directly on a corrupt file).
set -uo pipefail
[ -z "${ANTKIT_MCU_MISSING:-}" ] || { echo "skipped: no arm-none-eabi-g++ or qemu-system-arm"; exit 77; }
here=$(cd "$(dirname "$0")/../.." && pwd)
maps=$1
run=$here/scripts/run-on-mcu.sh
failed=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
expect() { # expect NAME PATTERN COMMAND...: exit 2, stderr matching PATTERN, nothing on stdout
  local name=$1 pattern=$2
  shift 2
  local out err status
  err=$work/expect.err
  out=$("$@" 2>"$err")
  status=$?
  if [ $status -eq 2 ] && [ -z "$out" ] && grep -Eq "$pattern" "$err"; then
    echo "ok   $name: $(head -1 "$err")"
  else
    echo "FAIL $name: exit $status, stdout '$out', stderr '$(cat "$err")'"
    failed=1
  fi
  rm -f "$err"
}
den=$maps/movingai/den312d.map
expect missing-map "error: .*nope\.map: cannot open" "$run" stc --map nope.map --variant ant
expect start-in-wall "error: --start: .*inside an obstacle" "$run" stc --map "$den" --variant ant --start 0,0
expect start-off-map "error: --start: .*outside the map" "$run" stc --map "$den" --variant ant --start 900,2
expect bad-variant "error: --variant" "$run" stc --map "$den" --variant sideways
expect host-only-variant "error: --variant: .*host only" "$run" stc --map "$den" --variant offline
expect bad-noise "error: --noise" "$run" stc --map "$den" --variant ant --noise 2
expect unknown-command "unknown command" "$run" sweep --map "$den"
expect buffon-bad-arena "error: --arena" "$run" buffon --arena circle:d=-3 --steps 100
expect buffon-missing-wkt "error: .*nope\.wkt" "$run" buffon --arena nope.wkt --steps 100
expect buffon-bad-steps "error: --steps: the steps per visit must be in" "$run" buffon --arena square:area=25 --steps 0
expect buffon-bad-width "error: --width" "$run" buffon --arena square:area=25 --steps 100 --width 0
expect buffon-bad-noise "error: --noise" "$run" buffon --arena square:area=25 --steps 100 --noise 3
expect rs-bad-arena "error: --arena" "$run" rs --arena circle:d=-3 --steps 100
expect rs-bad-steps "error: --steps: the steps must be in" "$run" rs --arena square:area=25 --steps 0
expect rs-bad-noise "error: --noise" "$run" rs --arena square:area=25 --steps 100 --noise 3
expect wanderer-missing-map "error: .*nope\.map: cannot open" "$run" wanderer --map nope.map
expect wanderer-bad-sensor "error: --sensor" "$run" wanderer --map "$den" --sensor -1
expect wanderer-bad-density "error: .*density" "$run" wanderer --size 20x20 --density 2
expect wanderer-no-map "error: .*give either --map" "$run" wanderer --seed 3

# The chip's own refusals: a file that is not an input, and one cut short.
chip() { # chip FILE: the image on FILE, its exit status and output
  timeout 60 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
    -semihosting-config "enable=on,target=native,arg=antkit_mcu,arg=$1" -kernel "$ANTKIT_MCU_IMAGE"
}
printf 'this is not an antkit input, but it is long enough to hold a header\n' >"$work/text"
"$ANTKIT_EXE" dev stc-mcu-input --map "$den" --variant ant --out "$work/good" >/dev/null
head -c 100 "$work/good" >"$work/short"
# A Buffon input cut inside its walls, and one whose header asks for 0 steps.
"$ANTKIT_EXE" dev buffon-mcu-input --arena square:area=25 --steps 100 --out "$work/buffon" >/dev/null
head -c 60 "$work/buffon" >"$work/buffon-short"
{ head -c 16 "$work/buffon"; printf '\0\0\0\0\0\0\0\0'; tail -c +25 "$work/buffon"; } >"$work/buffon-steps"
# An RS input cut inside its walls, and one whose header asks for 0 steps.
"$ANTKIT_EXE" dev rs-mcu-input --arena square:area=25 --steps 100 --out "$work/rs" >/dev/null
head -c 60 "$work/rs" >"$work/rs-short"
{ head -c 16 "$work/rs"; printf '\0\0\0\0\0\0\0\0'; tail -c +25 "$work/rs"; } >"$work/rs-steps"
# A wanderer input cut inside its map, and one whose start lies off the map.
"$ANTKIT_EXE" dev wanderer-mcu-input --map "$den" --out "$work/wanderer" >/dev/null
head -c 200 "$work/wanderer" >"$work/wanderer-short"
{ head -c 48 "$work/wanderer"; printf '\377\377\0\0'; tail -c +53 "$work/wanderer"; } >"$work/wanderer-start"
for f in text short buffon-short buffon-steps rs-short rs-steps wanderer-short wanderer-start; do
  out=$(chip "$work/$f")
  status=$?
  if [ $status -eq 2 ] && [[ "$out" == "error: $work/$f: "* ]]; then
    echo "ok   chip-$f: $out"
  else
    echo "FAIL chip-$f: exit $status: $out"
    failed=1
  fi
done
exit $failed
