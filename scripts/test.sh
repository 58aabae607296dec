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
# the rational oracle, where the compiler could contract a*b+c. A second build of the library:
# run with SHADOWPROOF_TEST_FMA=1 (scripts/test-fma.sh alone runs just this part). Needs a CPU
# with AVX2 and FMA.
if [ "${SHADOWPROOF_TEST_FMA:-0}" = 1 ]; then
  "$root/scripts/test-fma.sh"
fi
