#!/usr/bin/env bash
# Regenerates the sample meshes in data/ from data/generate/make_data.cpp (needs g++ and
# libfast-float-dev; uses shadetool's own writers, nothing else).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
g++ -std=c++17 -O2 -I"$root/lib" -I"$root/tests" "$root/data/generate/make_data.cpp" "$root"/lib/shadetool/io/*.cpp -o "$tmp/make_data"
"$tmp/make_data" "$root/data"
