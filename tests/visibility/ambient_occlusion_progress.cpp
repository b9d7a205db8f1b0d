// ambient_occlusion.h's progress (AmbientOcclusionOptions::progress, core/progress.h): the stage
// "occlusion" counts every point once, so its fraction never falls and ends at exactly 1, in many
// advances (a display can show it moving); and listening changes no bit of the result.
#include <catch2/catch.hpp>

#include <cstring>

#include <shadetool/visibility/ambient_occlusion.h>
#include "support/analytic_meshes.h"
#include "support/recording_progress.h"

using namespace shadetool;

namespace {

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void check_one_complete_stage(const testing::RecordingProgress& rec, std::uint64_t points) {
  REQUIRE(rec.stages().size() == 1);
  const auto& s = rec.stages()[0];
  CHECK(s.name == "occlusion");
  CHECK(s.total == points);
  CHECK(s.advances > 1);
  CHECK(rec.overshoots() == 0);
  CHECK(rec.advances_outside_a_stage() == 0);
  CHECK(rec.every_stage_monotone_and_complete());
}

}  // namespace

TEST_CASE("occlusion reports every vertex and face once, ending at exactly 1, and listening changes nothing",
          "[visibility][progress]") {
  const Mesh mesh = testing::torus(64, 32).mesh;  // 2048 vertices, 4096 triangles
  AmbientOcclusionOptions quiet;
  quiet.samples = 64;
  for (const bool per_face : {false, true}) {
    INFO((per_face ? "per face" : "per vertex (computed normals)"));
    testing::RecordingProgress rec;
    AmbientOcclusionOptions listened = quiet;
    listened.progress = &rec;
    const MeshOcclusion a = mesh_occlusion(mesh, per_face, quiet, "torus");
    const MeshOcclusion b = mesh_occlusion(mesh, per_face, listened, "torus");
    CHECK(same_bits(a.ao.open_fraction, b.ao.open_fraction));
    check_one_complete_stage(rec, per_face ? mesh.num_faces() : mesh.num_vertices());
  }
  SECTION("the mesh's own vertex normals, and points with their own normals") {
    Mesh with_normals = mesh;
    for (const Vec3d& n : testing::torus(64, 32).exact_normals) with_normals.vertex_normals.insert(with_normals.vertex_normals.end(), {n.x, n.y, n.z});
    testing::RecordingProgress rec;
    AmbientOcclusionOptions listened = quiet;
    listened.progress = &rec;
    const MeshOcclusion b = mesh_occlusion(with_normals, false, listened, "torus");
    CHECK(same_bits(mesh_occlusion(with_normals, false, quiet, "torus").ao.open_fraction, b.ao.open_fraction));
    check_one_complete_stage(rec, mesh.num_vertices());

    testing::RecordingProgress at_points;
    listened.progress = &at_points;
    const VisibilityScene scene(mesh);
    const AmbientOcclusion c = ambient_occlusion_at_points(scene, mesh.positions, with_normals.vertex_normals, {}, listened);
    CHECK(same_bits(ambient_occlusion_at_points(scene, mesh.positions, with_normals.vertex_normals, {}, quiet).open_fraction,
                    c.open_fraction));
    check_one_complete_stage(at_points, mesh.num_vertices());
  }
}
