#!/usr/bin/env bash
# `make demo`: the main job on a built-in default. Grows with the kit: today it shows the kernel's
# arenas and maps; later issues add the papers' reproductions.
set -euo pipefail
antkit=${1:-build/release/cli/antkit}
"$antkit" --version
