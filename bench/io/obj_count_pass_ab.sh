#!/usr/bin/env bash
# Times the OBJ counting pass (io/engine/obj_statement_counts.cpp) of a past commit against the
# work tree's, in one program, interleaved run by run (alternating which goes first), process CPU
# medians, each mask build (Best = AVX2 here, SSE2, plain C++); exits non-zero if the counts differ.
# Usage: bench/io/obj_count_pass_ab.sh COMMIT FILE.obj [REPS]    (results: bench/io/results.md)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
git -C "$root" show "$1:lib/shadetool/io/engine/obj_statement_counts.cpp" > "$tmp/old_counts.cpp"
printf '#define shadetool shadetool_old\n#include "%s"\n' "$tmp/old_counts.cpp" > "$tmp/tu_old.cpp"
printf '#define shadetool shadetool_new\n#include "%s"\n' "$root/lib/shadetool/io/engine/obj_statement_counts.cpp" > "$tmp/tu_new.cpp"
g++ -std=c++17 -O3 -DNDEBUG -I"$root/lib" "$root/bench/io/obj_count_pass_ab.cpp" "$tmp/tu_old.cpp" "$tmp/tu_new.cpp" -o "$tmp/ab"
echo "load $(cut -d' ' -f1-3 /proc/loadavg)"
"$tmp/ab" "$2" "${3:-15}"
echo "load $(cut -d' ' -f1-3 /proc/loadavg)"
