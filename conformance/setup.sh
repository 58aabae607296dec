#!/usr/bin/env bash
# Installs what the conformance table needs beyond the library's own packages: the pinned npm
# libraries (npm ci from package-lock.json, no install scripts) and the Vulkan runner with its
# shaders (conformance/vulkan, built into $1, default build/conformance-vk). The Debian packages
# (Qt 5, OpenSceneGraph, glslang, glslc, Mesa's lavapipe, the Vulkan loader) are in
# scripts/debian-packages.txt and installed by scripts/setup.sh.
# Usage: conformance/setup.sh [vulkan-build-dir]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
vk_build="${1:-$here/../build/conformance-vk}"
"$here/../scripts/setup.sh"
command -v npm >/dev/null || { echo "conformance/setup.sh: npm is missing (it comes with nodejs)" >&2; exit 2; }
# npm ci reinstalls from the lock file; skip it when node_modules already matches the lock.
if ! cmp -s "$here/js/package-lock.json" "$here/js/node_modules/.package-lock.json.installed" 2>/dev/null; then
  (cd "$here/js" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error)
  cp "$here/js/package-lock.json" "$here/js/node_modules/.package-lock.json.installed"
fi
cmake -S "$here/vulkan" -B "$vk_build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$vk_build" -j"$(nproc)" >/dev/null
echo "conformance/setup.sh: npm libraries installed, Vulkan runner in $vk_build"
