// cpp_vertex_normals: the C++ side of bench_normals.py: shadetool::vertex_normals on the same arrays
// the Python bench holds (raw little-endian files: V as n x 3 float64, F as m x 3 int32), timed in
// this process. Compiled by bench_normals.py against the build's libshadetool.a.
//
// Usage: cpp_vertex_normals V.f64 F.i32 WEIGHT REPS OUT.f64
// Prints one JSON object: per-repetition milliseconds of
//   call         vertex_normals(mesh, weight, Double) on a Mesh built beforehand (a fresh result each
//                time, as the Python call returns a fresh array)
//   view_call    vertex_normals(MeshView::triangles(V, F), weight, Double) on the arrays in place
//                (core/mesh_view.h: what a C++ caller holding its own arrays does; the int32 indices
//                are read as uint32, no index check, which the Python binding adds)
// and writes the normals of the last call to OUT.f64 (the bench checks they equal Python's, bit for
// bit); exits 1 when the view's normals differ from the Mesh's.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/vertex_normals.h>

namespace {

template <class T>
std::vector<T> read_raw(const char* path) {
  std::vector<T> v;
  FILE* f = std::fopen(path, "rb");
  if (!f) return v;
  std::fseek(f, 0, SEEK_END);
  const long bytes = std::ftell(f);
  std::fseek(f, 0, SEEK_SET);
  v.resize(std::size_t(bytes) / sizeof(T));
  const std::size_t got = std::fread(v.data(), sizeof(T), v.size(), f);
  std::fclose(f);
  v.resize(got);
  return v;
}

shadetool::Mesh mesh_from(const std::vector<double>& V, const std::vector<std::int32_t>& F) {
  shadetool::Mesh mesh;
  mesh.precision = shadetool::ValuePrecision::Double;
  mesh.positions = V;
  mesh.corner_vertex.assign(F.begin(), F.end());  // one converting pass, as lib/python/arrays.cpp
  mesh.face_start.resize(F.size() / 3 + 1);
  for (std::size_t f = 0; f < mesh.face_start.size(); ++f) mesh.face_start[f] = std::uint32_t(3 * f);
  return mesh;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: cpp_vertex_normals V.f64 F.i32 WEIGHT REPS OUT.f64\n");
    return 2;
  }
  const std::vector<double> V = read_raw<double>(argv[1]);
  const std::vector<std::int32_t> F = read_raw<std::int32_t>(argv[2]);
  const std::string w = argv[3];
  const shadetool::Weighting weighting = w == "area" ? shadetool::Weighting::Area
                                         : w == "uniform" ? shadetool::Weighting::Uniform
                                         : w == "max" ? shadetool::Weighting::Max
                                                      : shadetool::Weighting::Angle;
  const int reps = std::stoi(argv[4]);
  const shadetool::Mesh mesh = mesh_from(V, F);
  // int32 indices >= 0 have the bits of the same uint32 (the bench's F is in range).
  const shadetool::MeshView view = shadetool::MeshView::triangles(
      V.data(), V.size() / 3, reinterpret_cast<const std::uint32_t*>(F.data()), F.size() / 3);
  std::vector<double> call, view_call;
  shadetool::VertexNormals from_view;
  shadetool::VertexNormals last = shadetool::vertex_normals(mesh, weighting);  // warm-up
  for (int r = 0; r < reps; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    last = shadetool::vertex_normals(mesh, weighting);
    call.push_back(ms_since(t0));
    t0 = std::chrono::steady_clock::now();
    from_view = shadetool::vertex_normals(view, weighting);
    view_call.push_back(ms_since(t0));
  }
  if (from_view.normals.size() != last.normals.size() ||
      std::memcmp(from_view.normals.data(), last.normals.data(), last.normals.size() * sizeof(double)) != 0) {
    std::fprintf(stderr, "cpp_vertex_normals: the view's normals differ from the Mesh's\n");
    return 1;
  }
  FILE* out = std::fopen(argv[5], "wb");
  if (!out || std::fwrite(last.normals.data(), sizeof(double), last.normals.size(), out) != last.normals.size()) return 1;
  std::fclose(out);
  auto list = [](const std::vector<double>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
    return s + "]";
  };
  std::printf("{\"call\": %s, \"view_call\": %s}\n", list(call).c_str(), list(view_call).c_str());
  return 0;
}
