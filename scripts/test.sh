#!/usr/bin/env bash
# Installs what is missing, builds everything under AddressSanitizer and
# UndefinedBehaviorSanitizer (preset asan-ubsan) and runs the whole test suite through ctest.
# Usage: scripts/test.sh [build-dir]   (default: build/asan-ubsan)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build/asan-ubsan}"
"$root/scripts/setup.sh"
# The conformance table's adapters (npm ci of the pinned libraries, the Vulkan runner): ctest
# runs a sample of every one (label conformance).
"$root/conformance/setup.sh" "$root/build/conformance-vk"
(cd "$root" && cmake --preset asan-ubsan -B "$build")
cmake --build "$build" -j"$(nproc)"
# A sanitizer report fails the test that triggered it.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)"

# The oracle's exact arithmetic on an FMA target (preset fma, -march=x86-64-v3 -O2): the
# error-free transformations' own tests and the agreement tests of the dedicated kernels with
# the rational oracle, where the compiler could contract a*b+c. Needs a CPU with AVX2 and FMA;
# skipped (and said so) on one without.
if grep -qw fma /proc/cpuinfo && grep -qw avx2 /proc/cpuinfo; then
  (cd "$root" && cmake --preset fma -B "$root/build/fma" >/dev/null)
  cmake --build "$root/build/fma" -j"$(nproc)" --target test_verify test_oracle_kernels test_batch test_number test_ulp
  ctest --test-dir "$root/build/fma" -R "^test_(verify|oracle_kernels|batch|number|ulp):" --output-on-failure -j"$(nproc)"
else
  echo "test.sh: this CPU has no FMA/AVX2; the fma preset's tests were not run"
fi
