// open3d.cpp: bench_compare_open3d, open3d::geometry::TriangleMesh::ComputeVertexNormals against
// shadetool on the same mesh in the same process.
//
// Open3D (0.16) sums the unnormalised triangle normals into the vertices (area weighting) and
// normalises (NormalizeNormals). It reuses existing triangle normals and accumulates into an
// existing vertex-normal array, so both are cleared (untimed) before every run. Doubles
// (Eigen::Vector3d) throughout; OpenMP threads set with omp_set_num_threads.
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <omp.h>
#include <open3d/geometry/TriangleMesh.h>

#include "ours_rows.h"

using namespace shadetool;
using namespace shadetool::bench;

namespace {

std::vector<Case> open3d_cases(const BenchMesh& b, const std::vector<int>& threads) {
  auto m = std::make_shared<open3d::geometry::TriangleMesh>();
  const Mesh& in = b.am.mesh;
  m->vertices_.resize(in.num_vertices());
  for (std::size_t v = 0; v < in.num_vertices(); ++v)
    m->vertices_[v] = Eigen::Vector3d(in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]);
  m->triangles_.resize(in.num_faces());
  for (std::size_t f = 0; f < in.num_faces(); ++f)
    m->triangles_[f] = Eigen::Vector3i(int(in.corner_vertex[3 * f]), int(in.corner_vertex[3 * f + 1]), int(in.corner_vertex[3 * f + 2]));
  std::vector<Case> cases;
  for (int t : threads) {
    Case c;
    c.row = Row{"open3d", "Open3D ComputeVertexNormals", "area", "double", "", t};
    c.reset = [m] {
      m->triangle_normals_.clear(); m->vertex_normals_.clear();
      m->triangle_normals_.shrink_to_fit(); m->vertex_normals_.shrink_to_fit();
    };
    c.run = [m, t] { omp_set_num_threads(t); m->ComputeVertexNormals(true); };
    c.error = [m, &b] {
      return angular_error(b, [&](std::size_t v, Vec3d& n) {
        if (v >= m->vertex_normals_.size()) return false;
        n = {m->vertex_normals_[v](0), m->vertex_normals_[v](1), m->vertex_normals_[v](2)};
        return true;
      });
    };
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse_options(argc, argv);
    if (o.header) std::puts(csv_header());
    for (const std::string& name : o.meshes) {
      const BenchMesh b = load_bench_mesh(name);
      std::vector<Case> cases = ours_vertex_cases("open3d", b, {Weighting::Area}, {Precision::Double, Precision::Float}, o.threads);
      append(cases, ours_vertex_cases("open3d", b, {Weighting::Area}, {Precision::Double, Precision::Float}, o.threads,
                                      /*prepared=*/true));
      append(cases, open3d_cases(b, o.threads));
      run_cases(b, cases, repeats_for(b, o.repeats));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_compare_open3d: %s\n", e.what());
    return 1;
  }
}
