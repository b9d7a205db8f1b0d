// openmesh.cpp: bench_compare_openmesh, OpenMesh's update_face_normals, update_vertex_normals and
// update_normals against shadetool on the same mesh in the same process.
//
// OpenMesh's vertex normal (PolyMeshT::calc_vertex_normal_fast) is the normalised sum of the unit
// normals of the incident faces: the `uniform` weighting. It runs with the default TriMesh traits
// (float points and normals) and with double traits. The mesh is built with add_vertex/add_face
// outside the timed region; add_face refuses faces that would make the mesh non-manifold, and
// aborts on a face with a repeated index, which is therefore left out; both are counted in `note`.
#include <cstdio>
#include <exception>
#include <string>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "ours_rows.h"

using namespace shadetool;
using namespace shadetool::bench;

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TriMeshF = OpenMesh::TriMesh_ArrayKernelT<>;
using TriMeshD = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

template <class M>
std::string build(const Mesh& in, M& m) {
  using P = typename M::Point;
  using S = typename P::value_type;
  for (std::size_t v = 0; v < in.num_vertices(); ++v)
    m.add_vertex(P(S(in.positions[3 * v]), S(in.positions[3 * v + 1]), S(in.positions[3 * v + 2])));
  std::size_t refused = 0, repeated = 0;
  std::vector<typename M::VertexHandle> face(3);
  for (std::size_t f = 0; f < in.num_faces(); ++f) {
    if (has_repeated_index(in, f)) { ++repeated; continue; }
    for (int k = 0; k < 3; ++k) face[k] = typename M::VertexHandle(int(in.corner_vertex[3 * f + k]));
    if (!m.add_face(face).is_valid()) ++refused;
  }
  std::string note;
  if (repeated) note = std::to_string(repeated) + " faces with a repeated index left out";
  if (refused) note += (note.empty() ? "" : "; ") + std::to_string(refused) + " faces refused by add_face";
  return note;
}

template <class M>
void run(const BenchMesh& b, const Options& o, const char* precision) {
  M m;
  const std::string note = build(b.am.mesh, m);
  m.request_face_normals();
  m.request_vertex_normals();
  auto zero_normals = [&] {
    for (auto v : m.vertices()) m.set_normal(v, typename M::Normal(0, 0, 0));
  };
  auto error = [&] {
    return angular_error(b, [&](std::size_t v, Vec3d& n) {
      const auto& x = m.normal(typename M::VertexHandle(int(v)));
      n = {double(x[0]), double(x[1]), double(x[2])};
      return true;
    });
  };
  const int reps = repeats_for(b, o.repeats);
  Timing t = time_median(reps, [] {}, [&] { m.update_face_normals(); });
  print_row(b, Row{"openmesh", "OpenMesh update_face_normals", "face", precision, note, 1}, t, ErrorStats{});
  t = time_median(reps, zero_normals, [&] { m.update_vertex_normals(); });
  print_row(b, Row{"openmesh", "OpenMesh update_vertex_normals", "uniform", precision, note + (note.empty() ? "" : "; ") + "face normals precomputed", 1}, t, error());
  t = time_median(reps, zero_normals, [&] { m.update_normals(); });
  print_row(b, Row{"openmesh", "OpenMesh update_normals", "uniform", precision, note, 1}, t, error());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse_options(argc, argv);
    if (o.header) std::puts(csv_header());
    for (const std::string& name : o.meshes) {
      const BenchMesh b = load_bench_mesh(name);
      ours_vertex_rows("openmesh", b, o.repeats, {Weighting::Area, Weighting::Uniform}, {Precision::Double, Precision::Float}, {1});
      ours_face_rows("openmesh", b, o.repeats, {1});
      run<TriMeshF>(b, o, "float");
      run<TriMeshD>(b, o, "double");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_compare_openmesh: %s\n", e.what());
    return 1;
  }
}
