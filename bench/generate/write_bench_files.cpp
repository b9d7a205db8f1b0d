// write_bench_files.cpp: see write_bench_files.h.
#include "write_bench_files.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

namespace shadetool::bench {
namespace {

struct File {
  std::FILE* f;
  std::string path;
  File(const std::string& p, const char* mode) : f(std::fopen(p.c_str(), mode)), path(p) {
    if (!f) throw std::runtime_error(path + ": cannot open for writing");
  }
  ~File() { if (f) std::fclose(f); }
  void write(const void* data, std::size_t n) {
    if (n && std::fwrite(data, 1, n, f) != n) throw std::runtime_error(path + ": write failed");
  }
  void close() {
    const int rc = std::fclose(f);
    f = nullptr;
    if (rc != 0) throw std::runtime_error(path + ": write failed on close");
  }
};

// Little-endian store (the only byte order on the machines this runs on, checked at compile time).
static_assert(sizeof(float) == 4 && sizeof(double) == 8, "IEEE float/double expected");
template <class T>
void put(std::vector<char>& buf, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  buf.insert(buf.end(), bytes, bytes + sizeof(T));
}

}  // namespace

void write_binary_ply(const Mesh& mesh, const std::string& path, bool double_positions) {
  if (!mesh.all_triangles()) throw std::runtime_error(path + ": the generator writes triangle meshes only");
  File out(path, "wb");
  const char* type = double_positions ? "double" : "float";
  const std::string header = fmt::format(
      "ply\nformat binary_little_endian 1.0\ncomment shadetool bench/generate\n"
      "element vertex {}\nproperty {} x\nproperty {} y\nproperty {} z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      mesh.num_vertices(), type, type, type, mesh.num_faces());
  out.write(header.data(), header.size());
  std::vector<char> buf;
  buf.reserve(1 << 22);
  auto flush = [&] { out.write(buf.data(), buf.size()); buf.clear(); };
  for (double x : mesh.positions) {
    if (double_positions) put(buf, x); else put(buf, float(x));
    if (buf.size() > (1 << 22) - 64) flush();
  }
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    put(buf, std::uint8_t(3));
    for (int k = 0; k < 3; ++k) put(buf, std::int32_t(mesh.corner_vertex[3 * f + k]));
    if (buf.size() > (1 << 22) - 64) flush();
  }
  flush();
  out.close();
}

void write_obj(const Mesh& mesh, const std::string& path, bool double_positions) {
  if (!mesh.all_triangles()) throw std::runtime_error(path + ": the generator writes triangle meshes only");
  File out(path, "wb");
  fmt::memory_buffer buf;
  auto flush = [&] { out.write(buf.data(), buf.size()); buf.clear(); };
  fmt::format_to(std::back_inserter(buf), "# shadetool bench/generate: {} vertices, {} triangles\n",
                 mesh.num_vertices(), mesh.num_faces());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double* p = &mesh.positions[3 * v];
    if (double_positions) fmt::format_to(std::back_inserter(buf), "v {:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
    else fmt::format_to(std::back_inserter(buf), "v {:.9g} {:.9g} {:.9g}\n", float(p[0]), float(p[1]), float(p[2]));
    if (buf.size() > (1 << 22)) flush();
  }
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const std::uint32_t* c = &mesh.corner_vertex[3 * f];
    fmt::format_to(std::back_inserter(buf), "f {} {} {}\n", c[0] + 1, c[1] + 1, c[2] + 1);
    if (buf.size() > (1 << 22)) flush();
  }
  flush();
  out.close();
}

void write_normals_f64(const std::vector<Vec3d>& normals, const std::string& path) {
  File out(path, "wb");
  std::vector<char> buf;
  buf.reserve(24 * normals.size());
  for (const Vec3d& n : normals) { put(buf, n.x); put(buf, n.y); put(buf, n.z); }
  out.write(buf.data(), buf.size());
  out.close();
}

}  // namespace shadetool::bench
