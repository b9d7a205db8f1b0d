#!/usr/bin/env bash
# The library's module graph, read from the sources as the compiler resolves them: every
# `#include <shadetool/MODULE/...>` is the file lib/shadetool/MODULE/... (lib/ is the include path),
# so the graph needs no build. Checks:
#   - every such include names a file that exists (includes are real paths);
#   - each module includes only the modules its layer allows (the table below, lowest first), so
#     there is no circle, io/ depends on core and geometry only, and nothing in lib/ reaches up
#     into the CLI;
#   - no module includes another module's engine/ folder (machinery stays inside its module), but
#     for core/engine/: the one parallel policy and thread count every module shares.
# A new module or a new arrow is a line in the table, reviewed like code.
set -uo pipefail
src=$2
lib=$src/lib/shadetool
pass=0 fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# module: the modules it may include (besides itself)
declare -A allowed=(
  [core]=""
  [geometry]="core"
  [io]="core geometry"
  [normals]="core geometry"
  [transform]="core geometry normals"
  [info]="core geometry"
  [repair]="core geometry normals"
  [fit]="core geometry"
  [visibility]="core geometry normals fit"
  [lighting]="core geometry normals fit visibility"
  [render]="core geometry io normals fit lighting visibility"
  [gltf]="core geometry io normals transform fit lighting visibility"
  [files]="core geometry io gltf"
)

for dir in "$lib"/*/; do
  m=$(basename "$dir")
  [ -n "${allowed[$m]+x}" ] || { bad "module $m is not in tests/module_graph.sh's table"; allowed[$m]=""; continue; }
done

while IFS= read -r line; do
  file=${line%%:*}
  inc=$(sed -E 's/.*#include <shadetool\/([^>]+)>.*/\1/' <<<"$line")
  [ "$inc" = "shadetool.h" ] && continue
  if [ ! -f "$lib/$inc" ]; then bad "$file includes <shadetool/$inc>, which is no file under lib/shadetool/"; continue; fi
  rel=${file#"$lib"/}
  from=${rel%%/*}
  to=${inc%%/*}
  [ "$from" = "$to" ] && { pass=$((pass + 1)); continue; }
  case "$inc" in core/engine/*) ;; */engine/*) bad "$file reaches into another module's engine/: <shadetool/$inc>"; continue;; esac
  if [[ " ${allowed[$from]} " == *" $to "* ]]; then pass=$((pass + 1)); else bad "$file: $from may not include $to (<shadetool/$inc>)"; fi
done < <(grep -rHE '^\s*#\s*include <shadetool/' "$lib" --include=*.h --include=*.cpp)

# Outside the library (CLI, Python, tests, bench, fuzz, examples) every include must name a file too.
while IFS= read -r line; do
  file=${line%%:*}
  inc=$(sed -E 's/.*#include <shadetool\/([^>]+)>.*/\1/' <<<"$line")
  [ "$inc" = "shadetool.h" ] && continue
  if [ -f "$lib/$inc" ]; then pass=$((pass + 1)); else bad "$file includes <shadetool/$inc>, which is no file under lib/shadetool/"; fi
done < <(grep -rHE '^\s*#\s*include <shadetool/' "$src/cli" "$src/lib/python" "$src/tests" "$src/bench" "$src/fuzz" "$src/examples" \
           --include=*.h --include=*.cpp --include=*.cc 2>/dev/null)

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
