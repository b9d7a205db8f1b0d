#!/usr/bin/env bash
# .ci/sanitizers.sh: the whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer
# (CMake option SHADETOOL_SANITIZE=ON) in its own build directory, then ctest. Every CLI test runs
# the sanitized binary, so the error paths of the readers and the driver are checked too.
#
# Kept fast for CI (2 cores, the whole CI under 20 minutes): -O0 with line tables only (-g1) and
# benchmarks off. Measured on the 2-core development VM (lightly loaded): -O0 builds in 3 min and
# the tests take 2 min; -O1 halves the test time but doubles every heavy translation unit's
# compile time (14 s vs 7 s for cli/cmd_transform.cpp), a net loss. Needs only what the main build
# needs (gcc's libasan and libubsan come with g++).
#
# Not run here: sh_install_consumer, which builds an outside project against the installed
# library; that project is not compiled with the sanitizers, so it cannot link an instrumented
# library (undefined __asan_* symbols). It runs in the ordinary build.
#
# Environment: SANITIZE_BUILD (default build-sanitize), JOBS (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SANITIZE_BUILD:-build-sanitize}
jobs=${JOBS:-2}
start=$(date +%s)
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g1" \
  -DSHADETOOL_SANITIZE=ON -DSHADETOOL_BUILD_TESTS=ON -DSHADETOOL_BUILD_BENCH=OFF -DSHADETOOL_PYTHON=OFF
cmake --build "$build" -j "$jobs"
built=$(date +%s)
# Any report stops the program with a non-zero status (the CMake option also passes
# -fno-sanitize-recover=undefined), so ctest sees it as a failure.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# render_srgb8_exhaustive (a billion pow calls, the table against its formula) runs in the plain build;
# the sanitized render tests read the same table.
ctest --test-dir "$build" --output-on-failure -j "$jobs" -E '^(sh_install_consumer|render_srgb8_exhaustive)$'
echo "sanitizers: build $((built - start)) s, tests $(($(date +%s) - built)) s"
