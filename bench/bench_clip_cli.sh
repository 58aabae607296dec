#!/usr/bin/env bash
# `shadowproof clip` end to end: the median of 5 runs of wall time, CPU time (user + system) and
# the largest peak resident memory, measured with GNU time, on
# - the armadillo of Debian's libcgal-demo (26,002 vertices, 52,000 triangles, decimal
#   coordinates read exactly) over a ground plane under a directional light;
# - the 1M-triangle sphere of bench_clip (499,850 vertices, 999,696 triangles, a 51 MB OFF file
#   of exact decimals that `bench_clip --write-off` writes) over z = 0, light (1, 2, 5, 0).
# Usage: bench/bench_clip_cli.sh BUILD_DIR [DATA_DIR]   (DATA_DIR from scripts/bench-data.sh;
#        BUILD_DIR configured with -DSHADOWPROOF_BUILD_BENCH=ON)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:?usage: bench/bench_clip_cli.sh BUILD_DIR [DATA_DIR]}"
data="${2:-${SHADOWPROOF_BENCH_DATA:-$root/build/bench-data}}"
[ -f "$data/armadillo.json" ] || "$root/scripts/bench-data.sh" "$data"
[ -f "$data/sphere-1M.json" ] || "$build/bench/bench_clip" --write-off "$data"
median() { printf '%s\n' "$@" | sort -g | sed -n 3p; }
for name in armadillo sphere-1M; do
  walls=() cpus=() peak=0
  for i in 1 2 3 4 5; do
    out="$(/usr/bin/time -f '%e %U %S %M' "$build/shadowproof" clip "$data/$name.json" 2>&1 >/dev/null | tail -1)"
    read -r wall user sys rss <<<"$out"
    walls+=("$wall")
    cpus+=("$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')")
    [ "$rss" -gt "$peak" ] && peak="$rss"
  done
  echo "$name, shadowproof clip end to end: median wall $(median "${walls[@]}") s," \
       "median CPU $(median "${cpus[@]}") s, peak memory $((peak / 1024)) MB (5 runs)"
done
