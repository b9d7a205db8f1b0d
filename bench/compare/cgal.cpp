// cgal.cpp: bench_compare_cgal, CGAL::Polygon_mesh_processing::compute_vertex_normals on a
// Surface_mesh with the Epick kernel (double), against shadetool on the same mesh in one process.
//
// CGAL's vertex normal (compute_normal.h, CGAL 5.5) is the "most visible" normal: the direction
// that maximises the smallest angle to the incident face normals (a min-circle problem on the
// sphere of directions), falling back to the sine-weighted sum when there is none. It computes the
// face normals first (inside the timed region, as a user calling it gets). add_face refuses faces
// that would make the mesh non-manifold; faces with a repeated index are left out; both counted.
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>

#include "ours_rows.h"

using namespace shadetool;
using namespace shadetool::bench;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
using VertexIndex = SurfaceMesh::Vertex_index;

Case cgal_case(const BenchMesh& b) {
  auto m = std::make_shared<SurfaceMesh>();
  const Mesh& in = b.am.mesh;
  for (std::size_t v = 0; v < in.num_vertices(); ++v)
    m->add_vertex(K::Point_3(in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]));
  std::size_t refused = 0, repeated = 0;
  for (std::size_t f = 0; f < in.num_faces(); ++f) {
    if (has_repeated_index(in, f)) { ++repeated; continue; }
    const std::uint32_t* c = &in.corner_vertex[3 * f];
    if (m->add_face(VertexIndex(c[0]), VertexIndex(c[1]), VertexIndex(c[2])) == SurfaceMesh::null_face()) ++refused;
  }
  auto vnormals = m->add_property_map<VertexIndex, K::Vector_3>("v:bench_normals", CGAL::NULL_VECTOR).first;
  std::string note;
  if (repeated) note = std::to_string(repeated) + " faces with a repeated index left out";
  if (refused) note += (note.empty() ? "" : "; ") + std::to_string(refused) + " faces refused by add_face";
  Case c;
  c.row = Row{"cgal", "CGAL PMP::compute_vertex_normals", "most-visible", "double", note, 1};
  c.reset = [m, vnormals] { for (VertexIndex v : m->vertices()) vnormals[v] = CGAL::NULL_VECTOR; };
  c.run = [m, vnormals] { CGAL::Polygon_mesh_processing::compute_vertex_normals(*m, vnormals); };
  c.error = [m, vnormals, &b] {
    return angular_error(b, [&](std::size_t v, Vec3d& n) {
      const K::Vector_3 x = vnormals[VertexIndex(std::uint32_t(v))];
      n = {x.x(), x.y(), x.z()};
      return true;
    });
  };
  // Large meshes: one run, no warm-up. The cost grows with the cube of a vertex's valence (the
  // most-visible normal tries triples of incident face normals), and the UV sphere's poles have
  // valence ~1000 at 1M triangles: ~30 s per call there, ~1 s on the 1M icosphere or torus.
  if (in.num_faces() > 100000) { c.max_repeats = 1; c.warmup = false; }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    Options o = parse_options(argc, argv);
    o.repeats = std::min(o.repeats, 5);
    if (o.header) std::puts(csv_header());
    for (const std::string& name : o.meshes) {
      const BenchMesh b = load_bench_mesh(name);
      std::vector<Case> cases = ours_vertex_cases("cgal", b, {Weighting::Area, Weighting::Angle}, {Precision::Double}, {1});
      cases.push_back(cgal_case(b));
      run_cases(b, cases, repeats_for(b, o.repeats));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_compare_cgal: %s\n", e.what());
    return 1;
  }
}
