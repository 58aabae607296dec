#!/usr/bin/env bash
# Opt-in, for benchmarks only (no test needs it): installs Debian's libcgal-demo and extracts
# the meshes bench/bench_clip.cpp and bench/bench_clip_cli.sh use (armadillo, bunny00,
# elephant, ChineseDragon-10kv) into DIR, with bench/scenes/armadillo.json next to them.
# Usage: scripts/bench-data.sh [DIR]   (default: build/bench-data; then
#        SHADOWPROOF_BENCH_DATA=DIR build/bench/bench_clip)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${1:-$root/build/bench-data}"
tarball=/usr/share/doc/libcgal-demo/data.tar.gz
if [ ! -f "$tarball" ]; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  echo "bench-data: installing libcgal-demo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends libcgal-demo
fi
mkdir -p "$dir"
meshes=(armadillo.off bunny00.off elephant.off ChineseDragon-10kv.off)
tar -xzf "$tarball" -C "$dir" --strip-components=2 "${meshes[@]/#/data/meshes/}"
cp "$root/bench/scenes/armadillo.json" "$dir/"
echo "bench-data: ${meshes[*]} and armadillo.json in $dir"
