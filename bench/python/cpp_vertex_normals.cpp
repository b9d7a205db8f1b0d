// cpp_vertex_normals: the C++ side of bench_normals.py: shadetool::vertex_normals on the same arrays
// the Python bench holds (raw little-endian files: V as n x 3 float64, F as m x 3 int32), timed in
// this process. Compiled by bench_normals.py against the build's libshadetool.a.
//
// Usage: cpp_vertex_normals V.f64 F.i32 WEIGHT REPS OUT.f64
// Prints one JSON object: per-repetition milliseconds of
//   call         vertex_normals(mesh, weight, Double) on a Mesh built beforehand (a fresh result each
//                time, as the Python call returns a fresh array)
//   arrays_call  the same plus building the Mesh from the arrays (what a C++ caller holding arrays
//                in another layout does: positions copied, int32 corners converted, face starts;
//                no index check, which the Python binding adds)
// and writes the normals of the last call to OUT.f64 (the bench checks they equal Python's, bit for bit).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>
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
  std::vector<double> call, arrays_call;
  shadetool::VertexNormals last = shadetool::vertex_normals(mesh, weighting);  // warm-up
  for (int r = 0; r < reps; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    last = shadetool::vertex_normals(mesh, weighting);
    call.push_back(ms_since(t0));
    t0 = std::chrono::steady_clock::now();
    const shadetool::Mesh built = mesh_from(V, F);
    const shadetool::VertexNormals n = shadetool::vertex_normals(built, weighting);
    arrays_call.push_back(ms_since(t0));
  }
  FILE* out = std::fopen(argv[5], "wb");
  if (!out || std::fwrite(last.normals.data(), sizeof(double), last.normals.size(), out) != last.normals.size()) return 1;
  std::fclose(out);
  auto list = [](const std::vector<double>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
    return s + "]";
  };
  std::printf("{\"call\": %s, \"arrays_call\": %s}\n", list(call).c_str(), list(arrays_call).c_str());
  return 0;
}
