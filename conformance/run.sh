#!/usr/bin/env bash
# Regenerates docs/conformance.md: installs what is missing (conformance/setup.sh), builds
# shadowproof (optimised, build/release unless $SHADOWPROOF_BUILD names another tree), and
# grades every adapter on 3000 cases (conformance/run.mjs). Takes about 5 minutes on 2 cores.
# Usage: conformance/run.sh [--sample | --cases N]   (--sample: a few cases each, no table written)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SHADOWPROOF_BUILD:-$root/build/release}"
vk_build="$root/build/conformance-vk"
"$root/conformance/setup.sh" "$vk_build"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADOWPROOF_BUILD_PROOFS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target shadowproof_cli
# Mesa's CPU driver, lavapipe, runs the shaders (the machine may have no GPU at all).
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
node "$root/conformance/run.mjs" --shadowproof "$build/shadowproof" --vk-build "$vk_build" "$@"
