#!/usr/bin/env bash
# The installed library, as a consumer outside the source tree sees it (issue 15):
#  1. `cmake --install` of this build (static libshadetool.a): a consumer finds it with
#     find_package(shadetool) and, separately, with pkg-config (--static), and computes normals.
#  2. The same sources configured with -DBUILD_SHARED_LIBS=ON (library target only): the installed
#     libshadetool.so exports the public API and nothing else (no engine:: or *_detail:: symbol),
#     and the same consumer builds and runs against it through CMake and through pkg-config.
#  Consumers include <shadetool/...> only; <core/...>, <io/...> and engine/ headers are not installed.
#  3. (issue 28, item 10) A C++20 consumer that writes a PNG through the library (libpng is the
#     library's private dependency) builds static and shared through pkg-config and CMake; no
#     installed header includes a package the consumer was not told about (fast_float, fmt, tinygltf,
#     embree, TBB: the .pc file and the CMake config list exactly what a consumer links).
set -euo pipefail
bin=$1 src=$2
build_dir=$(dirname "$bin")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
passed=0
ok() { echo "ok: $1"; passed=$((passed + 1)); }
fail() { echo "FAIL: $1"; echo "$passed passed, 1 failed"; exit 1; }

mkdir "$tmp/consumer"
cat > "$tmp/consumer/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(consumer CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(shadetool REQUIRED)
add_executable(consumer main.cpp umbrella.cpp)
target_link_libraries(consumer PRIVATE shadetool::shadetool)
CM
# The program is the README's "Using the library" example, verbatim; a second file includes the
# umbrella header, so every installed header must compile on its own terms.
sed -n '/^\/\/ my_app.cpp/,/^```$/p' "$src/README.md" | sed '$d' > "$tmp/consumer/main.cpp"
grep -q 'int main' "$tmp/consumer/main.cpp" || fail "README has no my_app.cpp example"
printf '#include <shadetool/shadetool.h>\nint umbrella_compiles = 1;\n' > "$tmp/consumer/umbrella.cpp"
mkdir "$tmp/consumer20"
cat > "$tmp/consumer20/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(consumer20 CXX)
set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
find_package(shadetool REQUIRED)
add_executable(picture picture.cpp)
target_link_libraries(picture PRIVATE shadetool::shadetool)
CM
cat > "$tmp/consumer20/picture.cpp" <<'CPP'
// A C++20 program (std::span) that writes a 4x2 PNG gradient through the library.
#include <cstdio>
#include <span>
#include <shadetool/shadetool.h>
int main(int argc, char** argv) {
  if (argc != 2) return 2;
  shadetool::Image image;
  image.width = 4;
  image.height = 2;
  image.u8.resize(4 * 2 * 3);
  std::span<std::uint8_t> pixels(image.u8);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::uint8_t(i * 10);
  shadetool::write_image(image, argv[1], "");
  std::printf("%zu bytes of pixels\n", pixels.size());
}
CPP

expected="1152 vertices, 2304 faces"
check_prefix() {  # kind prefix
  local kind=$1 prefix=$2
  [ -f "$prefix/include/shadetool/shadetool.h" ] || fail "$kind: no umbrella header"
  for d in core io normals; do [ ! -e "$prefix/include/$d" ] || fail "$kind: include/$d installed"; done
  if find "$prefix/include" -path '*engine*' | grep -q .; then fail "$kind: engine/ headers installed"; fi
  # via CMake
  cmake -S "$tmp/consumer" -B "$tmp/b-$kind" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
  cmake --build "$tmp/b-$kind" > /dev/null
  out=$(LD_LIBRARY_PATH="$prefix/lib" "$tmp/b-$kind/consumer" "$src/data/torus.obj" "$tmp/out-$kind.ply")
  [ "$out" = "$expected" ] || fail "$kind CMake consumer printed: $out"
  "$bin" info "$tmp/out-$kind.ply" | grep -q 'vertex normals' || fail "$kind: the written PLY has no normals"
  ok "$kind library through find_package(shadetool)"
  # via pkg-config
  local pc="$prefix/lib/pkgconfig"; [ -d "$pc" ] || pc=$(dirname "$(find "$prefix" -name shadetool.pc | head -n 1)")
  local flags; flags=$(PKG_CONFIG_PATH="$pc" pkg-config --cflags --libs $3 shadetool)
  # shellcheck disable=SC2086
  g++ "$tmp/consumer/main.cpp" "$tmp/consumer/umbrella.cpp" -o "$tmp/pc-$kind" $flags
  out=$(LD_LIBRARY_PATH="$(dirname "$pc")" "$tmp/pc-$kind" "$src/data/torus.obj" "$tmp/pc-$kind.ply")
  [ "$out" = "$expected" ] || fail "$kind pkg-config consumer printed: $out"
  ok "$kind library through pkg-config ($flags)"
  # a C++20 consumer writing a PNG, through pkg-config (no -std from the .pc file) and CMake
  # shellcheck disable=SC2086
  g++ -std=c++20 "$tmp/consumer20/picture.cpp" -o "$tmp/pic-$kind" $flags || fail "$kind: C++20 consumer does not build through pkg-config ($flags)"
  LD_LIBRARY_PATH="$(dirname "$pc")" "$tmp/pic-$kind" "$tmp/pic-$kind.png" > /dev/null
  [ "$(head -c 8 "$tmp/pic-$kind.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$kind: C++20 consumer wrote no PNG"
  cmake -S "$tmp/consumer20" -B "$tmp/b20-$kind" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
  cmake --build "$tmp/b20-$kind" > /dev/null || fail "$kind: C++20 consumer does not build through find_package"
  LD_LIBRARY_PATH="$prefix/lib" "$tmp/b20-$kind/picture" "$tmp/pic20-$kind.png" > /dev/null
  ok "$kind library: a C++20 consumer writes a PNG through pkg-config and through find_package"
  # installed headers include only the standard library and shadetool's own headers
  local foreign
  # (the OpenMesh adapter is for OpenMesh users and says so; sys/ is the C library's)
  foreign=$(grep -rhoE '^\s*#\s*include\s*<[^>]+>' "$prefix/include/shadetool" --exclude=openmesh_adapter.h | sed -E 's/.*<([^>]+)>.*/\1/' | grep '/' | grep -Ev '^(shadetool|sys)/' | sort -u || true)
  [ -z "$foreign" ] || fail "$kind: installed headers include other packages' headers: $(echo $foreign)"
  ok "$kind: installed headers include no other package's header"
}

# 1. this build (static)
cmake --install "$build_dir" --prefix "$tmp/static" > /dev/null
test -x "$tmp/static/bin/shadetool" && ls "$tmp/static/share/man/man1/shadetool.1" > /dev/null
check_prefix static "$tmp/static" --static

# 2. a shared build of the library alone
launcher=$(grep -m1 '^CMAKE_CXX_COMPILER_LAUNCHER:' "$build_dir/CMakeCache.txt" 2>/dev/null | cut -d= -f2 || true)
cmake -S "$src" -B "$tmp/shared-build" -DBUILD_SHARED_LIBS=ON -DSHADETOOL_BUILD_TESTS=OFF \
  -DCMAKE_BUILD_TYPE=Release ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher} > /dev/null
cmake --build "$tmp/shared-build" --target shadetool -j2 > /dev/null
cmake --install "$tmp/shared-build" --prefix "$tmp/shared" --component library > /dev/null
so=$(find "$tmp/shared-build" -name 'libshadetool.so*' -type f | head -n 1)
[ -n "$so" ] || fail "no libshadetool.so built"
exports=$(nm -DC --defined-only "$so" | grep ' [TWVu] ' | grep 'shadetool::' || true)
echo "$exports" | grep -q 'shadetool::vertex_normals' || fail "libshadetool.so does not export vertex_normals"
echo "$exports" | grep -q 'shadetool::read_mesh' || fail "libshadetool.so does not export read_mesh"
# Internal functions and objects: names that start in an engine or *_detail namespace (a standard
# template instantiated over an internal type, e.g. a shared_ptr's control block, is the standard
# library's vague-linkage symbol, not our API).
leaked=$(echo "$exports" | awk '{ $1 = ""; $2 = ""; print }' | sed 's/^ *//' | grep -E '^(typeinfo( name)? for |vtable for )?shadetool::(engine|[a-z_]*_detail)::' || true)
[ -z "$leaked" ] || fail "libshadetool.so exports internals: $(echo "$leaked" | head -n 3)"
ok "libshadetool.so exports $(echo "$exports" | wc -l) public symbols and no engine::/_detail:: symbol"
check_prefix shared "$tmp/shared" ""
echo "$passed passed, 0 failed"
