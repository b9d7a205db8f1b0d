#!/usr/bin/env bash
# `cmake --install` exports shadetool::shadetool: a tiny consumer project finds it with
# find_package(shadetool), builds, and computes the normals of a mesh from data/.
set -euo pipefail
bin=$1 src=$2
build_dir=$(dirname "$bin")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cmake --install "$build_dir" --prefix "$tmp/prefix" > /dev/null
mkdir "$tmp/consumer"
cat > "$tmp/consumer/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(consumer CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(shadetool REQUIRED)
add_executable(consumer main.cpp)
target_link_libraries(consumer PRIVATE shadetool::shadetool)
CM
cat > "$tmp/consumer/main.cpp" <<'CPP'
#include <cmath>
#include <cstdio>
#include <shadetool/io/mesh_io.h>
#include <shadetool/normals/vertex_normals.h>
int main(int argc, char** argv) {
  shadetool::Mesh mesh = shadetool::read_mesh(argv[1]);
  shadetool::VertexNormals n = shadetool::vertex_normals(mesh, shadetool::Weighting::Angle);
  // Every normal of a closed torus is a unit vector.
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double* p = &n.normals[3 * v];
    if (std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1) > 1e-12) return 1;
  }
  std::printf("%zu vertices\n", mesh.num_vertices());
  return 0;
}
CPP
cmake -S "$tmp/consumer" -B "$tmp/consumer/build" -DCMAKE_PREFIX_PATH="$tmp/prefix" > /dev/null
cmake --build "$tmp/consumer/build" > /dev/null
out=$("$tmp/consumer/build/consumer" "$src/data/torus.obj")
[ "$out" = "1152 vertices" ] || { echo "consumer printed: $out"; echo "0 passed, 1 failed"; exit 1; }
test -x "$tmp/prefix/bin/shadetool" && ls "$tmp/prefix/share/man/man1/shadetool.1" > /dev/null
echo "1 passed, 0 failed"
