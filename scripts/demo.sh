#!/usr/bin/env bash
# Installs what is missing, builds the shadowproof executable and runs its bundled demo.
# Usage: scripts/demo.sh [build-dir]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j"$(nproc)" --target shadowproof_cli
"$build/shadowproof" demo --svg "$build/demo-shadow.svg"
"$build/shadowproof" check --impl all
