#!/usr/bin/env bash
# fuzz/run.sh SECONDS [TARGET...]: builds the libFuzzer targets (clang, own build dir) and runs
# each for SECONDS, one after the other (the machine has 2 cores shared with others), seeded with
# data/ (files of the target's format), tests/bad_inputs/ and fuzz/corpus/TARGET/.
#
# New interesting inputs go to build-fuzz/work/TARGET/ (not committed); crashes, leaks, timeouts
# and out-of-memory inputs to build-fuzz/artifacts/. Exit status 1 when any target found one.
# Executions per target are printed at the end (and kept in build-fuzz/logs/TARGET.log).
#
# Environment: FUZZ_BUILD (default build-fuzz), FUZZ_SOURCE_ROOT (tree whose lib/ is fuzzed,
# default this checkout), FUZZ_JOBS (build parallelism, default 2),
# FUZZ_MALLOC_MB (largest single allocation allowed, default 512: inputs are at most 1 MiB, so a
# bigger allocation means a count was trusted), FUZZ_TIMEOUT (seconds for one input, default 10).
set -uo pipefail
if [ $# -lt 1 ] || ! [[ $1 =~ ^[0-9]+$ ]]; then
  echo "usage: fuzz/run.sh SECONDS [TARGET...]   (targets: obj ply off stl scene)" >&2
  exit 2
fi
seconds=$1; shift
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD:-$root/build-fuzz}
case $build in /*) ;; *) build=$root/$build ;; esac

if ! command -v clang++ > /dev/null; then
  echo "fuzz/run.sh: clang++ not found (apt-get install -y clang libclang-rt-14-dev)" >&2
  exit 1
fi
mkdir -p "$build"
cmake -S "$root/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DSHADETOOL_ROOT="${FUZZ_SOURCE_ROOT:-$root}" > "$build/cmake.log" 2>&1 ||
  { cat "$build/cmake.log" >&2; exit 1; }
cmake --build "$build" -j "${FUZZ_JOBS:-2}" > "$build/build.log" 2>&1 ||
  { tail -50 "$build/build.log" >&2; exit 1; }

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for exe in "$build"/fuzz_*; do
    [ -x "$exe" ] && [ -f "$exe" ] && targets+=("$(basename "$exe")")
  done
fi

mkdir -p "$build/artifacts" "$build/logs"
status=0
summary=""
for t in "${targets[@]}"; do
  exe=""
  for cand in "$build/$t" "$build/fuzz_$t" "$build/fuzz_read_$t"; do
    [ -f "$cand" ] && [ -x "$cand" ] && { exe=$cand; break; }
  done
  [ -n "$exe" ] || { echo "fuzz/run.sh: no target '$t'" >&2; status=1; continue; }
  name=$(basename "$exe"); short=${name#fuzz_}; short=${short#read_}
  # Seeds: files of this format (scene: JSON) from data/, the bad-input corpus, fuzz/corpus/.
  seeds=$build/seeds/$name; rm -rf "$seeds"; mkdir -p "$seeds" "$build/work/$name"
  ext=$short; [ "$short" = scene ] && ext=json
  find "$root/data" "$root/tests/bad_inputs" "$root/tests/stress" -type f -iname "*.$ext" \
    -size -1024k -exec cp -t "$seeds" {} + 2> /dev/null
  dirs=("$build/work/$name" "$seeds")
  [ -d "$root/fuzz/corpus/$name" ] && dirs+=("$root/fuzz/corpus/$name")
  dict=$root/fuzz/$short.dict; dictopt=(); [ -f "$dict" ] && dictopt=(-dict="$dict")
  echo "fuzz/run.sh: $name for ${seconds}s"
  "$exe" "${dirs[@]}" "${dictopt[@]}" -max_total_time="$seconds" -max_len=65536 \
    -timeout="${FUZZ_TIMEOUT:-10}" -malloc_limit_mb="${FUZZ_MALLOC_MB:-512}" -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/artifacts/$name-" > "$build/logs/$name.log" 2>&1
  rc=$?
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/logs/$name.log" | grep -o '[0-9]*$' | tail -1)
  if [ $rc -ne 0 ]; then
    status=1
    summary+="$name: FAILED after ${execs:-?} executions (exit $rc), see $build/logs/$name.log"$'\n'
    grep -E '^(==[0-9]+==ERROR|SUMMARY|fuzz:|.*runtime error|artifact_prefix|Test unit written)' "$build/logs/$name.log" | head -8 >&2
  else
    summary+="$name: ${execs:-?} executions in ${seconds}s, no failure"$'\n'
  fi
done
printf '%s' "$summary"
ls "$build/artifacts" 2> /dev/null | sed 's/^/artifact: /'
exit $status
