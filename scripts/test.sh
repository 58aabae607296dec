#!/usr/bin/env bash
# Installs what is missing, builds everything under AddressSanitizer and
# UndefinedBehaviorSanitizer (preset asan-ubsan) and runs the whole test suite through ctest.
# Usage: scripts/test.sh [build-dir]   (default: build/asan-ubsan)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build/asan-ubsan}"
"$root/scripts/setup.sh"
(cd "$root" && cmake --preset asan-ubsan -B "$build")
cmake --build "$build" -j"$(nproc)"
# A sanitizer report fails the test that triggered it.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
