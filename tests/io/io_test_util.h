// io_test_util.h: shared helpers of the io tests: a mesh with every attribute, a scratch
// directory, file helpers and a way to run the CLI.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "support/run_process.h"

#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/files/mesh_files.h>

namespace shadetool::iotest {

namespace fs = std::filesystem;

// A fresh directory under the system temp dir, removed at the end of the test.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::random_device rd;
    path = fs::temp_directory_path() / ("shadetool-io-" + std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

inline void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), std::streamsize(bytes.size()));
}

inline std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// The round-trip contract of the text writers (io/engine/number_text.h), checked value by value: a value
// that is exactly a float (double(float(x)) == x, e.g. read from binary PLY) is printed as the
// float's shortest text, which reads back as the double nearest to that decimal: it comes back as
// the same float. Any other value comes back bitwise. NaN comes back as NaN.
inline bool same_after_text(double orig, double back) {
  if (std::isnan(orig)) return std::isnan(back);
  if (double(float(orig)) == orig) {
    const float a = float(orig), b = float(back);
    return std::memcmp(&a, &b, sizeof a) == 0;
  }
  return std::memcmp(&orig, &back, sizeof orig) == 0;
}
inline bool same_after_text(const std::vector<double>& orig, const std::vector<double>& back) {
  if (orig.size() != back.size()) return false;
  for (std::size_t i = 0; i < orig.size(); ++i)
    if (!same_after_text(orig[i], back[i])) return false;
  return true;
}

// The message of the Error thrown by `f`, or "" when none was thrown.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

inline Mesh read_text(const std::string& text, Format format, ReadInfo* info = nullptr, const std::string& name = "t") {
  return read_mesh_from_memory(text, format, name, info);
}

// A small mesh with everything a reader can keep: a triangle, a quad and a pentagon sharing
// edges (consistently wound, manifold, with a boundary), values that are not exact in binary
// (0.1), per-corner normals (a pool shared by some corners), per-corner texcoords, vertex
// colours and face colours. Values are floats (precision Float) so every format can carry them
// exactly.
inline Mesh rich_mesh() {
  Mesh m;
  const double P[7][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0.1}, {2.5, 0.5, 0.1}, {0.5, 2, 1e-3}};
  for (auto& p : P) m.add_vertex({double(float(p[0])), double(float(p[1])), double(float(p[2]))});
  m.add_face({0, 1, 3});
  m.add_face({1, 4, 5, 2});
  m.add_face({3, 1, 2, 5, 6});
  const double N[3][3] = {{0, 0, 1}, {0.6, 0, 0.8}, {0, -0.28, 0.96}};
  for (auto& n : N)
    for (double x : n) m.corner_normals.push_back(double(float(x)));
  m.corner_normal_index = {0, 0, 0, 0, 1, 1, 0, 2, 2, 2, 2, 0};
  for (double t : {0.0, 0.0, 1.0, 0.0, 0.5, 0.25, 0.1, 0.9}) m.texcoords.push_back(double(float(t)));
  m.corner_texcoord_index = {0, 1, 2, 1, 3, 2, 0, 1, 2, 3, 0, 1};
  m.color_channels = 3;
  m.colors_are_float = false;
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k) m.vertex_colors.push_back(float((v * 37 + std::size_t(k) * 91) % 256) / 255.0f);
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) m.face_colors.push_back(float((f * 53 + std::size_t(k) * 17 + 5) % 256) / 255.0f);
  m.precision = ValuePrecision::Float;
  return m;
}

// Runs the shadetool binary through the shell (tests/support/run_process.h).
using Run = shadetool_test::ProcessResult;
inline Run run_cli(const std::string& args) { return shadetool_test::run_shadetool(args); }

template <class T>
inline bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every array and field a reader fills, compared bit for bit (NaN included): the meshes two
// readings of one content give (chunks or one pass; a file and its rewritten twin).
inline void require_same_mesh(const Mesh& a, const Mesh& b) {
  CHECK(same_bits(a.positions, b.positions));
  CHECK(a.face_start == b.face_start);
  CHECK(a.corner_vertex == b.corner_vertex);
  CHECK(same_bits(a.vertex_normals, b.vertex_normals));
  CHECK(same_bits(a.corner_normals, b.corner_normals));
  CHECK(a.corner_normal_index == b.corner_normal_index);
  CHECK(same_bits(a.face_normals, b.face_normals));
  CHECK(same_bits(a.texcoords, b.texcoords));
  CHECK(a.texcoord_dims == b.texcoord_dims);
  CHECK(a.corner_texcoord_index == b.corner_texcoord_index);
  CHECK(same_bits(a.vertex_colors, b.vertex_colors));
  CHECK(same_bits(a.face_colors, b.face_colors));
  CHECK(same_bits(a.vertex_quality, b.vertex_quality));
  CHECK(same_bits(a.face_quality, b.face_quality));
  CHECK(a.texcoord_names == b.texcoord_names);
  REQUIRE(a.vertex_properties.size() == b.vertex_properties.size());
  for (std::size_t i = 0; i < a.vertex_properties.size(); ++i) {
    CHECK(a.vertex_properties[i].name == b.vertex_properties[i].name);
    CHECK(same_bits(a.vertex_properties[i].values, b.vertex_properties[i].values));
  }
  REQUIRE(a.face_properties.size() == b.face_properties.size());
  for (std::size_t i = 0; i < a.face_properties.size(); ++i) {
    CHECK(a.face_properties[i].name == b.face_properties[i].name);
    CHECK(same_bits(a.face_properties[i].values, b.face_properties[i].values));
  }
  CHECK(a.color_channels == b.color_channels);
  CHECK(a.colors_are_float == b.colors_are_float);
  CHECK(a.group_statements == b.group_statements);
  CHECK(a.face_group_run == b.face_group_run);
  CHECK(a.comments == b.comments);
  CHECK(a.precision == b.precision);
}

inline std::string data_path(const std::string& name) { return std::string(SHADETOOL_SOURCE_DIR) + "/data/" + name; }

}  // namespace shadetool::iotest
