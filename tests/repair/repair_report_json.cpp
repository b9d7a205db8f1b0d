// repair_report_json: the report's JSON carries the repair's counts under the CLI's key names.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <shadetool/repair/repair_mesh.h>
#include <shadetool/repair/repair_report_json.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

TEST_CASE("repair_report_json: an inverted sphere's report, key for key", "[repair][report]") {
  Mesh m = icosphere(2).mesh;
  const std::size_t F = m.num_faces();
  invert_all(m);
  const RepairReport r = repair_mesh(m);
  const nlohmann::json j = nlohmann::json::parse(repair_report_json(r, -1, "angle"));
  // Truth from the mesh, not from the report: one closed component, every face reversed.
  CHECK(j.at("faces_in") == F);
  CHECK(j.at("faces_out") == F);
  CHECK(j.at("components") == 1);
  CHECK(j.at("closed_components") == 1);
  CHECK(j.at("components_inverted") == 1);
  CHECK(j.at("faces_flipped") == F);
  CHECK(j.at("orientation").at("by_volume") == 1);
  CHECK(j.at("degenerate_by_kind").at("zero_area") == 0);
  CHECK(j.at("weld_eps").is_null());
  CHECK(j.at("weighting") == "angle");
  CHECK(j.at("changes") == r.changes());
  CHECK(j.at("changes").get<std::size_t>() > 0);
  CHECK(nlohmann::json::parse(repair_report_json(r, 0.25, "max")).at("weld_eps") == 0.25);
}
