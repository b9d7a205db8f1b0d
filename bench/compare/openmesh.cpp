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
#include <memory>
#include <string>
#include <vector>

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
std::vector<Case> openmesh_cases(const BenchMesh& b, const char* precision) {
  auto m = std::make_shared<M>();
  const std::string note = build(b.am.mesh, *m);
  m->request_face_normals();
  m->request_vertex_normals();
  auto zero_normals = [m] {
    for (auto v : m->vertices()) m->set_normal(v, typename M::Normal(0, 0, 0));
  };
  auto error = [m, &b] {
    return angular_error(b, [&](std::size_t v, Vec3d& n) {
      const auto& x = m->normal(typename M::VertexHandle(int(v)));
      n = {double(x[0]), double(x[1]), double(x[2])};
      return true;
    });
  };
  std::vector<Case> cases(3);
  cases[0].row = Row{"openmesh", "OpenMesh update_face_normals", "face", precision, note, 1};
  cases[0].run = [m] { m->update_face_normals(); };
  // update_vertex_normals uses the face normals already stored (the previous case left them).
  cases[1].row = Row{"openmesh", "OpenMesh update_vertex_normals", "uniform", precision,
                     note + (note.empty() ? "" : "; ") + "face normals precomputed", 1};
  cases[1].reset = zero_normals;
  cases[1].run = [m] { m->update_vertex_normals(); };
  cases[1].error = error;
  cases[2].row = Row{"openmesh", "OpenMesh update_normals", "uniform", precision, note, 1};
  cases[2].reset = zero_normals;
  cases[2].run = [m] { m->update_normals(); };
  cases[2].error = error;
  return cases;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse_options(argc, argv);
    if (o.header) std::puts(csv_header());
    for (const std::string& name : o.meshes) {
      const BenchMesh b = load_bench_mesh(name);
      std::vector<Case> cases = ours_vertex_cases("openmesh", b, {Weighting::Area, Weighting::Uniform},
                                                  {Precision::Double, Precision::Float}, {1});
      append(cases, ours_vertex_cases("openmesh", b, {Weighting::Area, Weighting::Uniform},
                                      {Precision::Double, Precision::Float}, {1}, /*prepared=*/true));
      append(cases, ours_face_cases("openmesh", b, {1}));
      append(cases, openmesh_cases<TriMeshF>(b, "float"));
      append(cases, openmesh_cases<TriMeshD>(b, "double"));
      // Each case's error is read after all rounds: the update_normals case runs last per mesh
      // type, so the vertex normals it is scored on are its own (update_vertex_normals gives the
      // same ones from the same face normals).
      run_cases(b, cases, repeats_for(b, o.repeats));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_compare_openmesh: %s\n", e.what());
    return 1;
  }
}
