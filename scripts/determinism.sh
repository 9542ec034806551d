#!/usr/bin/env bash
# The determinism matrix (issue 16): builds antkit_determinism (determinism/main.cpp running the
# scenarios of determinism/scenarios.cpp: the kernel and the algorithms only,
# ANTKIT_DETERMINISM_ONLY) in several configurations and requires
# every one of them to print every golden hash of determinism/golden.txt at 1, 2 and 8 threads.
#
#   scripts/determinism.sh            the whole matrix: gcc-12 -O0 and -O3, clang-14 -O0 and -O3,
#                                     s390x (big-endian, g++-s390x-linux-gnu, run under qemu-s390x),
#                                     armhf (32-bit ARM Linux, g++-arm-linux-gnueabihf, run under
#                                     qemu-arm), cortex-m4 (the Cortex-M image of mcu/ under QEMU's
#                                     netduinoplus2, issue 27: every scenario that runs on the chip)
#   scripts/determinism.sh --ci       what .ci/run runs: clang-14 -O0, s390x and cortex-m4, at 8
#                                     threads only (the default gcc -O2 build checks the same golden
#                                     file at 1, 2 and 8 threads under ctest, label determinism)
#   scripts/determinism.sh CONFIG...  the named configurations only
#
# Every configuration compiles with -ffp-contract=off (the kernel's rule 7, also carried by
# antkit::kernel). A mismatch prints the scenario, the configuration, and the first step at which
# its trace (--trace: each step's state and a chained hash of the states so far) differs from the
# reference build's, with both states. Each configuration also prints the STC tours of every shared
# map (--stc-tours: ant, ant-edge and online from `antkit stc`'s start, 17 maps), and must print the
# first configuration's bytes. The teeth: the s390x build's native-endian hash must differ
# from the little-endian golden value, and the script shows where its trace first parts.
#
# cortex-m4 is not a build of antkit_determinism: the chip runs the STC scenarios of ant and
# ant-edge (with and without marker noise) and online, on the three maps, Buffon's on the square
# with a pillar (seeds 1 to 3: four trials each, their digest) and the lone step-turn wanderer's
# (uniform/rw/1robots, on the three coverage maps), from inputs the clang-O0 build writes
# (--mcu-inputs, through the library's writers: the same map, start and noise; the same walls, body
# and steps; the same placement, sensor and ticks), and must print their golden hashes. The other
# scenarios (Buffon on the circle, whose 256 walls do not fit the chip, and with the precision
# rules, LOS, offline and full STC, coverage by several robots or by the planners, the marker-floor
# robot) do not run on the chip; the configuration names how many ran.
#
# Builds go to build/determinism/<config> (ccache when installed). Exit status: 0 every
# configuration gives every golden hash and the teeth bite, 1 otherwise, 2 bad usage.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
# ccache keys on paths relative to the checkout, so a clean clone (CI) reuses earlier compiles.
export CCACHE_BASEDIR=$here CCACHE_NOHASHDIR=1

golden=determinism/golden.txt
maps=${ANTKIT_MAPS:-$here/data/maps}
jobs=${JOBS:-$(nproc)}
all_configs=(gcc-O0 gcc-O3 clang-O0 clang-O3 s390x armhf cortex-m4)
ci_configs=(clang-O0 s390x cortex-m4)
thread_counts=(1 2 8)

configs=()
if [ $# -eq 0 ]; then
  configs=("${all_configs[@]}")
elif [ "$1" = "--ci" ] && [ $# -eq 1 ]; then
  configs=("${ci_configs[@]}")
  # One thread count in CI: these configurations are there for the compiler, the optimiser and
  # the byte order; that the hashes do not depend on the thread count is the code's, and CI's first
  # pass checks it on the default build at 1, 2 and 8 threads (ctest determinism.golden.threads*).
  # 8 threads: the parallel paths with the most interleaving. (-O0 and qemu runs are minutes each.)
  thread_counts=(8)
else
  for c in "$@"; do
    case " ${all_configs[*]} " in
    *" $c "*) configs+=("$c") ;;
    *)
      echo "determinism.sh: unknown configuration '$c' (known: ${all_configs[*]}, or --ci)" >&2
      exit 2
      ;;
    esac
  done
fi
if [ ! -d "$maps/movingai" ]; then
  echo "determinism.sh: $maps/movingai: not found (data/maps in the checkout, or ANTKIT_MAPS)" >&2
  exit 2
fi

# config_args CONFIG: sets compiler, flags and extra (the CMake arguments of a configuration).
config_args() {
  extra=()
  case "$1" in
  gcc-O0 | gcc-O3) compiler=g++-12 flags="-${1#gcc-} -ffp-contract=off" ;;
  clang-O0 | clang-O3) compiler=clang++-14 flags="-${1#clang-} -ffp-contract=off" ;;
  s390x)
    compiler=s390x-linux-gnu-g++-12 flags="-O2 -ffp-contract=off"
    extra=(-DCMAKE_SYSTEM_NAME=Linux -DCMAKE_SYSTEM_PROCESSOR=s390x -DCMAKE_EXE_LINKER_FLAGS=-static)
    ;;
  armhf)
    compiler=arm-linux-gnueabihf-g++-12 flags="-O2 -ffp-contract=off"
    extra=(-DCMAKE_SYSTEM_NAME=Linux -DCMAKE_SYSTEM_PROCESSOR=arm -DCMAKE_EXE_LINKER_FLAGS=-static)
    ;;
  cortex-m4) compiler=arm-none-eabi-g++ flags="-O2 (mcu/CMakeLists.txt)" ;;
  esac
}

# run CONFIG ARGS...: the configuration's runner (s390x under qemu-s390x).
run() {
  local config=$1
  shift
  local exe=build/determinism/$config/determinism/antkit_determinism
  if [ "$config" = s390x ]; then
    qemu-s390x "$exe" "$@"
  elif [ "$config" = armhf ]; then
    qemu-arm "$exe" "$@"
  else
    "$exe" "$@"
  fi
}

build() {
  local dir=build/determinism/$1
  config_args "$1"
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S . -B "$dir" -G Ninja -DANTKIT_DETERMINISM_ONLY=ON -DCMAKE_BUILD_TYPE=None \
      "-DCMAKE_CXX_COMPILER=$compiler" "-DCMAKE_CXX_FLAGS=$flags" "${extra[@]}" \
      >"$dir.configure.log" 2>&1 || { cat "$dir.configure.log"; return 1; }
  fi
  cmake --build "$dir" -j "$jobs" --target antkit_determinism >"$dir.build.log" 2>&1 ||
    { tail -40 "$dir.build.log"; return 1; }
}

# first_difference CONFIG SCENARIO REFERENCE: the first step where CONFIG's trace of SCENARIO and
# REFERENCE's differ, with both states.
first_difference() {
  local config=$1 scenario=$2 reference=$3 mode=(--maps "$maps" --trace "$2")
  [ "$scenario" = teeth/native-endian ] && mode=(--teeth native-endian --trace "$2")
  local a=build/determinism/$config.trace b=build/determinism/$reference.trace
  run "$config" "${mode[@]}" >"$a"
  run "$reference" "${mode[@]}" >"$b"
  local line
  line=$(cmp "$a" "$b" 2>/dev/null | sed -n 's/.* line \([0-9]*\)$/\1/p' || true)
  echo "   $scenario, $config against $reference:"
  if [ -z "$line" ]; then
    if cmp -s "$a" "$b"; then
      echo "     the per-step traces agree ($(wc -l <"$a") steps): only the hashed result differs"
    else
      echo "     one trace is a prefix of the other: $config has $(wc -l <"$a") steps," \
        "$reference $(wc -l <"$b")"
    fi
    return
  fi
  echo "     first differing step: $(sed -n "${line}p" "$a" | cut -d' ' -f1)" \
    "(each line: step, chained hash of the states so far, state)"
  echo "     $config: $(sed -n "${line}p" "$a" | cut -d' ' -f2-)"
  echo "     $reference: $(sed -n "${line}p" "$b" | cut -d' ' -f2-)"
}

# cortex_m4: the chip's configuration (see the top). Prints a line per scenario run, "MISMATCH"
# lines for a hash that is not golden; returns 1 on a mismatch or a failure.
cortex_m4() {
  local dir=build/determinism/cortex-m4 host=clang-O0
  if ! command -v arm-none-eabi-g++ >/dev/null || ! command -v qemu-system-arm >/dev/null; then
    echo "   arm-none-eabi-g++ or qemu-system-arm is missing (scripts/bootstrap.sh installs them)"
    return 1
  fi
  build "$host" || { echo "   the host build ($host) that writes the inputs failed"; return 1; }
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S mcu -B "$dir" -G Ninja "-DCMAKE_TOOLCHAIN_FILE=$here/cmake/arm-none-eabi.cmake" \
      >"$dir.configure.log" 2>&1 || { cat "$dir.configure.log"; return 1; }
  fi
  cmake --build "$dir" >"$dir.build.log" 2>&1 || { tail -40 "$dir.build.log"; return 1; }
  mkdir -p "$dir/inputs"
  local list bad=0 ran=0 name file out hash golden_hash
  list=$(run "$host" --maps "$maps" --mcu-inputs "$dir/inputs") || return 1
  while read -r name file; do
    out=$(timeout 300 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
      -semihosting-config "enable=on,target=native,arg=antkit_mcu,arg=$file" \
      -kernel "$dir/antkit_mcu.elf") || { echo "   $name: the image failed: $out"; bad=1; continue; }
    hash=$(sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p' <<<"$out")
    golden_hash=$(awk -v n="$name" '$1 == n { print $2 }' "$golden")
    ran=$((ran + 1))
    if [ -z "$hash" ] || [ "$hash" != "$golden_hash" ]; then
      echo "   MISMATCH $name: golden $golden_hash, the chip ${hash:-printed no hash}"
      bad=1
    fi
  done <<<"$list"
  echo "   $ran scenarios on the chip (of $(grep -cvE '^(#|$)' "$golden") golden lines;" \
    "the rest do not run on it yet)"
  [ $bad -eq 0 ] && [ $ran -gt 0 ]
}

failed=0
reference=""
tours_reference="" # the first configuration whose every-map STC listing ran
declare -A verdict
pending=() # "config scenario": a mismatch to locate once a reference build is known
start_all=$SECONDS
mkdir -p build/determinism
for config in "${configs[@]}"; do
  t0=$SECONDS
  config_args "$config"
  echo "== $config: $compiler $flags ${extra[*]}"
  if [ "$config" = cortex-m4 ]; then
    if cortex_m4; then
      verdict[$config]="every scenario the chip runs (STC; Buffon on the square with a pillar; the lone wanderer), hash for hash ($((SECONDS - t0)) s)"
    else
      verdict[$config]="MISMATCH or failure (above)"
      failed=1
    fi
    continue
  fi
  if ! build "$config"; then
    echo "   BUILD FAILED"
    verdict[$config]="build failed"
    failed=1
    continue
  fi
  ok=1
  for threads in "${thread_counts[@]}"; do
    out=$(run "$config" --maps "$maps" --check "$golden" --threads "$threads") && status=0 || status=$?
    echo "   threads $threads: $(echo "$out" | tail -1)"
    if [ "$status" -ne 0 ]; then
      ok=0
      echo "$out" | grep -E '^(MISMATCH|MISSING)' | sed "s/^/   [$config, threads $threads] /" || true
      while read -r tag scenario _; do
        [ "$tag" = MISMATCH ] && pending+=("$config ${scenario%:}")
      done <<<"$out"
    fi
  done
  # The teeth: native-endian bytes give the golden value on little-endian CPUs only.
  teeth=$(run "$config" --teeth native-endian --check "$golden") && tstatus=0 || tstatus=$?
  if [ "$config" = s390x ]; then
    if [ "$tstatus" -eq 1 ] && echo "$teeth" | grep -q MISMATCH; then
      echo "   teeth: the native-endian hash differs on s390x, as it must:"
      echo "$teeth" | sed 's/^/     /'
      pending+=("$config teeth/native-endian")
    else
      echo "   TEETH MISSING: the native-endian hash matched on a big-endian CPU"
      ok=0
    fi
  elif [ "$tstatus" -ne 0 ]; then
    echo "   teeth: the native-endian hash should match on this little-endian build: $teeth"
    ok=0
  fi
  # Every shared map's STC tours (--stc-tours; issue 27): the first configuration's listing is the
  # reference, every later one must print the same bytes (ctest's determinism.stc_tours test holds
  # the listing to `antkit stc`'s own on the default build).
  tours=build/determinism/$config.stc-tours
  if ! run "$config" --maps "$maps" --stc-tours >"$tours"; then
    echo "   STC TOURS FAILED: the every-map listing did not run"
    ok=0
  elif [ -z "$tours_reference" ]; then
    tours_reference=$config
    echo "   stc tours: $(wc -l <"$tours") tours on every shared map (the listing the others must repeat)"
  elif cmp -s "$tours" "build/determinism/$tours_reference.stc-tours"; then
    echo "   stc tours: all $(wc -l <"$tours") as $tours_reference's"
  else
    echo "   STC TOURS MISMATCH against $tours_reference:"
    diff "build/determinism/$tours_reference.stc-tours" "$tours" | head -10 | sed 's/^/     /'
    ok=0
  fi
  if [ $ok -eq 1 ]; then
    verdict[$config]="every golden hash at ${thread_counts[*]} threads ($((SECONDS - t0)) s with the build)"
    [ -n "$reference" ] || reference=$config
  else
    verdict[$config]="MISMATCH"
    failed=1
  fi
done

if [ ${#pending[@]} -gt 0 ]; then
  if [ -z "$reference" ] || [ "$reference" = s390x ]; then
    # A little-endian build that gives every golden hash: the one the teeth are compared with.
    for c in gcc-O3 clang-O3 gcc-O0 clang-O0; do
      [ "${verdict[$c]:-}" = MISMATCH ] && continue
      if [ -z "${verdict[$c]:-}" ]; then
        build "$c" && run "$c" --maps "$maps" --check "$golden" >/dev/null && reference=$c && break
      elif [ "${verdict[$c]}" != "build failed" ]; then
        reference=$c && break
      fi
    done
  fi
  echo "== where the traces part:"
  declare -A seen
  for p in "${pending[@]}"; do
    [ -n "${seen[$p]:-}" ] && continue
    seen[$p]=1
    if [ -z "$reference" ]; then
      echo "   ${p#* }, ${p%% *}: no build matched every golden hash, so there is no reference trace"
    else
      first_difference "${p%% *}" "${p#* }" "$reference"
    fi
  done
fi

echo "== determinism matrix ($((SECONDS - start_all)) s):"
for config in "${configs[@]}"; do echo "   $config: ${verdict[$config]}"; done
exit $failed
