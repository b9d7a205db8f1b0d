#!/usr/bin/env bash
# .ci/sanitizers.sh: the whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer
# (CMake option SHADETOOL_SANITIZE=ON) in its own build directory, then ctest. Every CLI test runs
# the sanitized binary, so the error paths of the readers and the driver are checked too.
#
# Kept fast for CI (2 cores, the whole CI under 20 minutes): -O1 (sanitizers need no more to find
# what they find, and it compiles much faster than -O3), line tables only (-g1) for readable
# reports, benchmarks off. Needs only what the main build needs (gcc's libasan/libubsan come with g++).
#
# Environment: SANITIZE_BUILD (default build-sanitize), JOBS (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SANITIZE_BUILD:-build-sanitize}
jobs=${JOBS:-2}
start=$(date +%s)
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DSHADETOOL_SANITIZE=ON -DSHADETOOL_BUILD_TESTS=ON -DSHADETOOL_BUILD_BENCH=OFF
cmake --build "$build" -j "$jobs"
built=$(date +%s)
# Any report stops the program with a non-zero status (the CMake option also passes
# -fno-sanitize-recover=undefined), so ctest sees it as a failure.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j "$jobs"
echo "sanitizers: build $((built - start)) s, tests $(($(date +%s) - built)) s"
