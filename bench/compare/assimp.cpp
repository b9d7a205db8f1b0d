// assimp.cpp: bench_compare_assimp, assimp's aiProcess_GenSmoothNormals against shadetool on the
// same mesh in the same process.
//
// assimp's GenVertexNormalsProcess (5.2) writes each face's unit normal to the face's vertices,
// then sums, for every vertex, the normals of all vertices at the same position (SpatialSort,
// no angle limit at the default 175 degrees): the `uniform` weighting, in float. It expects one
// vertex per face corner, as its OBJ importer produces (on an indexed mesh each shared vertex would
// keep only its last face's normal), so the mesh is handed to assimp as OBJ text in memory, imported
// once with no post-processing (untimed), and only ApplyPostProcessing(aiProcess_GenSmoothNormals)
// is timed; the normals are deleted (untimed) before each run, since assimp skips meshes that have
// them. Vertex v's normal is read at its first corner. Vertices no face uses are dropped by the
// importer: counted as `missing`.
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include "ours_rows.h"

using namespace shadetool;
using namespace shadetool::bench;

namespace {

std::string obj_text(const Mesh& m) {
  fmt::memory_buffer buf;
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    fmt::format_to(std::back_inserter(buf), "v {:.9g} {:.9g} {:.9g}\n", m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    fmt::format_to(std::back_inserter(buf), "f {} {} {}\n", m.corner_vertex[3 * f] + 1, m.corner_vertex[3 * f + 1] + 1, m.corner_vertex[3 * f + 2] + 1);
  return std::string(buf.data(), buf.size());
}

Case assimp_case(const BenchMesh& b) {
  const Mesh& in = b.am.mesh;
  auto importer = std::make_shared<Assimp::Importer>();
  const std::string text = obj_text(in);
  const aiScene* scene = importer->ReadFileFromMemory(text.data(), text.size(), 0, "obj");
  if (!scene || scene->mNumMeshes != 1) throw std::runtime_error(std::string("assimp import failed: ") + importer->GetErrorString());
  aiMesh* am = scene->mMeshes[0];
  std::string note;
  if (am->mNumFaces != in.num_faces()) note = fmt::format("assimp kept {} of {} faces; ", am->mNumFaces, in.num_faces());
  note += fmt::format("{} unjoined vertices", am->mNumVertices);
  Case c;
  c.row = Row{"assimp", "assimp GenSmoothNormals", "uniform", "float", note, 1};
  c.reset = [importer, am] { delete[] am->mNormals; am->mNormals = nullptr; };
  c.run = [importer] { importer->ApplyPostProcessing(aiProcess_GenSmoothNormals); };
  c.error = [importer, am, &b] {
    const Mesh& in = b.am.mesh;
    if (!am->mNormals) throw std::runtime_error("assimp produced no normals");
    // Our vertex -> assimp vertex at its first corner (faces keep their order through the importer).
    std::vector<std::int64_t> first(in.num_vertices(), -1);
    if (am->mNumFaces == in.num_faces())
      for (std::size_t f = 0; f < in.num_faces(); ++f)
        for (unsigned k = 0; k < 3 && k < am->mFaces[f].mNumIndices; ++k)
          if (first[in.corner_vertex[3 * f + k]] < 0) first[in.corner_vertex[3 * f + k]] = am->mFaces[f].mIndices[k];
    return angular_error(b, [&](std::size_t v, Vec3d& n) {
      if (first[v] < 0) return false;
      const aiVector3D& x = am->mNormals[first[v]];
      n = {double(x.x), double(x.y), double(x.z)};
      return true;
    });
  };
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
      std::vector<Case> cases = ours_vertex_cases("assimp", b, {Weighting::Area, Weighting::Uniform},
                                                  {Precision::Double, Precision::Float}, {1});
      cases.push_back(assimp_case(b));
      run_cases(b, cases, repeats_for(b, o.repeats));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_compare_assimp: %s\n", e.what());
    return 1;
  }
}
