#!/usr/bin/env bash
# The oracle's exact arithmetic on an FMA target (preset fma, -march=x86-64-v3 -O2): builds the
# error-free transformations' tests and the agreement tests of the dedicated kernels with the
# rational oracle where the compiler could contract a*b+c into a fused multiply-add, and runs
# them. Skipped, and said so, on a CPU without AVX2 and FMA. Usage: scripts/test-fma.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if ! grep -qw fma /proc/cpuinfo || ! grep -qw avx2 /proc/cpuinfo; then
  echo "test-fma.sh: this CPU has no FMA/AVX2; the fma preset's tests were not run"
  exit 0
fi
(cd "$root" && cmake --preset fma -B "$root/build/fma" >/dev/null)
cmake --build "$root/build/fma" -j"$(nproc)" --target test_verify test_oracle_kernels test_batch test_number test_ulp
ctest --test-dir "$root/build/fma" -R "^test_(verify|oracle_kernels|batch|number|ulp):" --output-on-failure -j"$(nproc)"
