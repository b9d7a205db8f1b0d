// transform_bench.cpp: normals under a non-uniform scale, shadetool against Open3D's
// TriangleMesh::Transform and assimp's aiProcess_PreTransformVertices.
//
// Mesh: a unit icosphere whose vertex normals are exact (n = p). Map: the same for every tool,
// A = diag(1, 2, 3) (the non-uniform scale), A = R diag(1, 2, 3) with R = 30 degrees
// about (1, 1, 1), and A = R alone (where applying A to normals is right: a control). Truth: the
// image of the sphere under R diag(a, b, c) is R applied to the ellipsoid x^2/a^2 + y^2/b^2 +
// z^2/c^2 = 1; its exact normal at the image of p is R (p.x/a, p.y/b, p.z/c)/|.| (the gradient of
// the implicit function: no cofactor involved). Reported: max and mean angle (degrees) between each tool's vertex
// normals and the truth, whether the tool's normals are unit, and which rule it follows (its
// output compared with normalize(A n) and with normalize(A^-T n)).
// Time: median of `reps` runs of the transform call alone (positions + vertex normals; copies
// excluded); shadetool and Open3D alternate run by run and the ratio is the median of the per-run
// ratios (the machine is shared and noisy). assimp's time covers its whole post-processing
// step (scene graph flattening included), so it is shown but is not like for like.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <thread>
#include <vector>

#include <Eigen/Core>
#include <open3d/geometry/TriangleMesh.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "support/analytic_meshes.h"
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/transform_mesh.h>

using namespace shadetool;

namespace {

struct Errors {
  double max_deg = 0, mean_deg = 0, max_unit_defect = 0;
};

template <class GetNormal>
Errors angular_errors(std::size_t n, const std::vector<Vec3d>& truth, GetNormal get) {
  Errors e;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d g = get(i);
    const double a = testing::angle_degrees(g, truth[i]);
    e.max_deg = std::max(e.max_deg, a);
    sum += a;
    e.max_unit_defect = std::max(e.max_unit_defect, std::fabs(length(g) - 1));
  }
  e.mean_deg = n ? sum / double(n) : 0;
  return e;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

float f32(double x) { return static_cast<float>(x); }

// A scene with one triangle mesh under a root node carrying `A`, round-tripped through assimp's
// own binary format so that the Importer owns it (post-processing needs an imported scene).
std::string assbin_blob(const Mesh& m, const Affine3d& M) {
  aiScene* scene = new aiScene();
  scene->mRootNode = new aiNode();
  const auto& A = M.A.m;
  scene->mRootNode->mTransformation = aiMatrix4x4(f32(A[0][0]), f32(A[0][1]), f32(A[0][2]), f32(M.t.x), f32(A[1][0]),
                                                  f32(A[1][1]), f32(A[1][2]), f32(M.t.y), f32(A[2][0]), f32(A[2][1]),
                                                  f32(A[2][2]), f32(M.t.z), 0, 0, 0, 1);
  scene->mRootNode->mNumMeshes = 1;
  scene->mRootNode->mMeshes = new unsigned[1]{0};
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{new aiMaterial()};
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1];
  aiMesh* mesh = scene->mMeshes[0] = new aiMesh();
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mMaterialIndex = 0;
  mesh->mNumVertices = unsigned(m.num_vertices());
  mesh->mVertices = new aiVector3D[mesh->mNumVertices];
  mesh->mNormals = new aiVector3D[mesh->mNumVertices];
  for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
    mesh->mVertices[v] = aiVector3D(f32(m.positions[3 * v]), f32(m.positions[3 * v + 1]), f32(m.positions[3 * v + 2]));
    mesh->mNormals[v] = aiVector3D(f32(m.vertex_normals[3 * v]), f32(m.vertex_normals[3 * v + 1]), f32(m.vertex_normals[3 * v + 2]));
  }
  mesh->mNumFaces = unsigned(m.num_faces());
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    mesh->mFaces[f].mNumIndices = 3;
    mesh->mFaces[f].mIndices = new unsigned[3]{m.corner_vertex[3 * f], m.corner_vertex[3 * f + 1], m.corner_vertex[3 * f + 2]};
  }
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene, "assbin");
  if (!blob) {
    std::fprintf(stderr, "assimp export failed: %s\n", exporter.GetErrorString());
    std::exit(1);
  }
  std::string bytes(static_cast<const char*>(blob->data), blob->size);
  delete scene;
  return bytes;
}

struct ToolResult {
  explicit ToolResult(std::string n) : name(std::move(n)) {}
  std::string name;
  Errors err;
  double vs_A_n = 0, vs_inverse_transpose = 0;  // max angle (deg) to normalize(A n) / normalize(A^-T n)
  double median_ms = 0;
  double ratio = 0;  // median of per-run time ratios to Open3D (assimp: ratio of medians)
};

void print(const ToolResult& r, double open3d_ms) {
  std::printf("  %-34s max %.3e  mean %.3e  |n|-1 max %.1e   vs A n %.2e  vs A^-T n %.2e   %8.2f ms  x%.2f\n",
              r.name.c_str(), r.err.max_deg, r.err.mean_deg, r.err.max_unit_defect, r.vs_A_n, r.vs_inverse_transpose,
              r.median_ms, r.ratio > 0 ? r.ratio : (open3d_ms > 0 ? r.median_ms / open3d_ms : 0.0));
}

void run_case(const char* title, const testing::AnalyticMesh& sphere, const Mat3d& R, const Vec3d& scale, int reps) {
  const Affine3d M = compose_in_order({scale_map(scale), Affine3d{R, Vec3d{0, 0, 0}}});
  const std::size_t V = sphere.mesh.num_vertices();
  std::vector<Vec3d> truth(V), by_A(V), by_inverse_transpose(V);
  // The image of the unit sphere under R S, S = diag(a, b, c), is R applied to the ellipsoid
  // x^2/a^2 + y^2/b^2 + z^2/c^2 = 1; at the image of p its gradient is R (p.x/a, p.y/b, p.z/c).
  for (std::size_t v = 0; v < V; ++v) {
    const Vec3d p = sphere.mesh.position(v);
    truth[v] = normalized_or(R * Vec3d{p.x / scale.x, p.y / scale.y, p.z / scale.z}, Vec3d{0, 0, 0});
    by_inverse_transpose[v] = truth[v];
    by_A[v] = normalized_or(M.A * sphere.exact_normals[v], Vec3d{0, 0, 0});
  }
  std::printf("%s: %zu vertices, %zu faces, %d runs; angle to the exact ellipsoid normal in degrees\n", title, V,
              sphere.mesh.num_faces(), reps);
  std::printf("  %-34s %-41s %-34s %s\n", "tool", "error vs exact", "which rule it follows", "median time, ratio to Open3D");

  Mesh input = sphere.mesh;
  input.vertex_normals.clear();
  for (const Vec3d& n : sphere.exact_normals) input.vertex_normals.insert(input.vertex_normals.end(), {n.x, n.y, n.z});

  // ---- Open3D and shadetool, alternating run by run so that load from other processes hits both
  // alike; the ratio reported is the median of the per-run ratios.
  ToolResult o3d("Open3D TriangleMesh::Transform");
  ToolResult st("shadetool transform_mesh"), st_float("shadetool, float in and out");
  {
    open3d::geometry::TriangleMesh base;
    for (std::size_t v = 0; v < V; ++v) {
      base.vertices_.emplace_back(input.positions[3 * v], input.positions[3 * v + 1], input.positions[3 * v + 2]);
      base.vertex_normals_.emplace_back(input.vertex_normals[3 * v], input.vertex_normals[3 * v + 1], input.vertex_normals[3 * v + 2]);
    }
    for (std::size_t f = 0; f < input.num_faces(); ++f)
      base.triangles_.emplace_back(input.corner_vertex[3 * f], input.corner_vertex[3 * f + 1], input.corner_vertex[3 * f + 2]);
    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) T(r, c) = M.A.m[r][c];
      T(r, 3) = M.t[r];
    }
    std::vector<double> o3d_times, st_times, ratios;
    open3d::geometry::TriangleMesh o3d_out;
    Mesh st_out;
    for (int k = 0; k < reps; ++k) {
      open3d::geometry::TriangleMesh om = base;
      auto t0 = std::chrono::steady_clock::now();
      om.Transform(T);
      o3d_times.push_back(ms_since(t0));
      Mesh sm = input;
      t0 = std::chrono::steady_clock::now();
      transform_mesh(sm, M);
      st_times.push_back(ms_since(t0));
      ratios.push_back(st_times.back() / o3d_times.back());
      if (k == 0) {
        o3d_out = std::move(om);
        st_out = std::move(sm);
      }
    }
    o3d.median_ms = median(o3d_times);
    o3d.ratio = 1;
    auto get_o3d = [&](std::size_t i) { const auto& n = o3d_out.vertex_normals_[i]; return Vec3d{n.x(), n.y(), n.z()}; };
    o3d.err = angular_errors(V, truth, get_o3d);
    o3d.vs_A_n = angular_errors(V, by_A, get_o3d).max_deg;
    o3d.vs_inverse_transpose = angular_errors(V, by_inverse_transpose, get_o3d).max_deg;

    st.median_ms = median(st_times);
    st.ratio = median(ratios);
    auto get = [&](std::size_t i) { return get3(st_out.vertex_normals, i); };
    st.err = angular_errors(V, truth, get);
    st.vs_A_n = angular_errors(V, by_A, get).max_deg;
    st.vs_inverse_transpose = angular_errors(V, by_inverse_transpose, get).max_deg;

    // shadetool with float input and output, as a float file would hold them.
    Mesh fin = input;
    for (auto& x : fin.positions) x = f32(x);
    for (auto& x : fin.vertex_normals) x = f32(x);
    transform_mesh(fin, M);
    auto getf = [&](std::size_t i) {
      return Vec3d{f32(fin.vertex_normals[3 * i]), f32(fin.vertex_normals[3 * i + 1]), f32(fin.vertex_normals[3 * i + 2])};
    };
    st_float.err = angular_errors(V, truth, getf);
    st_float.vs_A_n = angular_errors(V, by_A, getf).max_deg;
    st_float.vs_inverse_transpose = angular_errors(V, by_inverse_transpose, getf).max_deg;
  }

  // ---- assimp (float throughout: ai_real is float in Debian's build)
  ToolResult as("assimp PreTransformVertices (float)");
  {
    const std::string blob = assbin_blob(input, M);
    std::vector<double> times;
    std::vector<Vec3d> normals;
    for (int k = 0; k < reps; ++k) {
      Assimp::Importer importer;
      const aiScene* s = importer.ReadFileFromMemory(blob.data(), blob.size(), 0, "assbin");
      if (!s) {
        std::fprintf(stderr, "assimp import failed: %s\n", importer.GetErrorString());
        std::exit(1);
      }
      const auto t0 = std::chrono::steady_clock::now();
      s = importer.ApplyPostProcessing(aiProcess_PreTransformVertices);
      times.push_back(ms_since(t0));
      if (k == 0) {
        if (!s || s->mNumMeshes != 1 || s->mMeshes[0]->mNumVertices != V || !s->mMeshes[0]->mNormals) {
          std::fprintf(stderr, "assimp: unexpected scene after PreTransformVertices\n");
          std::exit(1);
        }
        for (unsigned v = 0; v < V; ++v) {
          const aiVector3D& n = s->mMeshes[0]->mNormals[v];
          normals.push_back({n.x, n.y, n.z});
        }
      }
    }
    as.median_ms = median(times);
    auto get = [&](std::size_t i) { return normals[i]; };
    as.err = angular_errors(V, truth, get);
    as.vs_A_n = angular_errors(V, by_A, get).max_deg;
    as.vs_inverse_transpose = angular_errors(V, by_inverse_transpose, get).max_deg;
  }

  print(st, o3d.median_ms);
  std::printf("  %-34s max %.3e  mean %.3e  |n|-1 max %.1e   vs A n %.2e  vs A^-T n %.2e\n", st_float.name.c_str(),
              st_float.err.max_deg, st_float.err.mean_deg, st_float.err.max_unit_defect, st_float.vs_A_n,
              st_float.vs_inverse_transpose);
  print(o3d, o3d.median_ms);
  print(as, o3d.median_ms);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const int level = argc > 1 ? std::atoi(argv[1]) : 7;  // icosphere level: 7 -> 163842 vertices
  const int reps = argc > 2 ? std::atoi(argv[2]) : 15;
  std::printf("bench/transform: icosphere level %d, %u hardware threads\n\n", level, std::thread::hardware_concurrency());
  const testing::AnalyticMesh sphere = testing::icosphere(level, 0.3, 11);
  const Mat3d R = rotation_map(30, {1, 1, 1}).A;
  run_case("A = diag(1,2,3)", sphere, Mat3d::identity(), {1, 2, 3}, reps);
  run_case("A = R diag(1,2,3), R = 30 degrees about (1,1,1)", sphere, R, {1, 2, 3}, reps);
  run_case("A = R (a rotation: every tool is right up to rounding; time of the fast path)", sphere, R, {1, 1, 1}, reps);
  return 0;
}
