// repair_mesh.h's progress (RepairOptions::progress, core/progress.h): the stage "repair" counts
// its seven named passes once each, with or without welding, so its fraction never falls and ends
// at exactly 1; and listening changes no face.
#include <catch2/catch.hpp>

#include <shadetool/repair/repair_mesh.h>
#include "support/analytic_meshes.h"
#include "support/recording_progress.h"

using namespace shadetool;

TEST_CASE("repair reports its seven passes once each, ending at exactly 1, and listening changes nothing",
          "[repair][progress]") {
  for (const double weld : {-1.0, 1e-9}) {
    INFO("weld_eps " << weld);
    Mesh quiet_mesh = testing::torus(24, 12).mesh;
    // Every other face reversed: repair has work to do.
    for (std::size_t f = 0; f < quiet_mesh.num_faces(); f += 2)
      std::swap(quiet_mesh.corner_vertex[quiet_mesh.face_start[f] + 1], quiet_mesh.corner_vertex[quiet_mesh.face_start[f] + 2]);
    Mesh listened_mesh = quiet_mesh;
    RepairOptions quiet;
    quiet.weld_eps = weld;
    testing::RecordingProgress rec;
    RepairOptions listened = quiet;
    listened.progress = &rec;
    const RepairReport a = repair_mesh(quiet_mesh, quiet);
    const RepairReport b = repair_mesh(listened_mesh, listened);
    CHECK(a.faces_flipped == b.faces_flipped);
    CHECK(quiet_mesh.corner_vertex == listened_mesh.corner_vertex);
    CHECK(quiet_mesh.vertex_normals == listened_mesh.vertex_normals);
    REQUIRE(rec.stages().size() == 1);
    CHECK(rec.stages()[0].name == "repair");
    CHECK(rec.stages()[0].total == 7);
    CHECK(rec.stages()[0].advances == 7);
    CHECK(rec.every_stage_monotone_and_complete());
  }
}
