#!/usr/bin/env bash
# Installs the Debian packages antkit needs, or says exactly how to; then the node packages the
# interop tests read antkit's files with (package-lock.json, by `npm ci`).
#
# Run by `make demo` and `make test` before they configure. As root it installs whatever is missing
# with apt-get; as anyone else it prints the one command to run and exits 1. It changes nothing when
# every package is already there, so it is cheap to run on every build.
#
# `scripts/bootstrap.sh --node-packages` (run by `make test` and `make check`, not by the demo, which
# needs none) installs the node packages alone: `npm ci` runs only when node_modules is missing or
# was installed from another package-lock.json (the lock's hash is kept in node_modules/.antkit-lock),
# and is left out where node or npm is not installed (the interop tests then skip, saying so).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache git
  clang-14 libclang-rt-14-dev clang-format
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-hypothesis
  catch2 librapidcheck-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev jq
  libz3-dev coq libcairo2-dev
  libsqlite3-dev libzstd-dev liblz4-dev
  libcoq-interval
  g++-s390x-linux-gnu qemu-user
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm
  g++-arm-linux-gnueabihf
  libopenmpi-dev openmpi-bin
  cvc5
  time
)

node_packages() {
  local root lock stamp want
  root=$(cd "$(dirname "$0")/.." && pwd)
  lock="$root/package-lock.json"
  stamp="$root/node_modules/.antkit-lock"
  [ -f "$lock" ] || return 0
  # Without node the interop tests skip, saying so; nothing to do here.
  command -v node >/dev/null && command -v npm >/dev/null || return 0
  want=$(sha256sum "$lock" | cut -d' ' -f1)
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
    return 0
  fi
  echo "bootstrap: npm ci (node packages for the interop tests)" >&2
  (cd "$root" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
  echo "$want" >"$stamp"
}

if [ "${1:-}" = "--node-packages" ]; then
  node_packages
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "bootstrap: missing Debian packages: ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
  echo "bootstrap: installed ${#missing[@]} package(s)" >&2
else
  echo "bootstrap: run this, then try again:" >&2
  echo "  sudo apt-get update && sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
  exit 1
fi
