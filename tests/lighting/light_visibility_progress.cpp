// light_visibility.h's progress (ShadowOptions::progress, core/progress.h): the stage "shadows"
// counts rays per point planned (1 per point for a hard light, N for an area light, 2N for a
// sky), so its total is known before the first ray, its fraction never falls and ends at exactly
// 1; and listening changes no colour.
#include <catch2/catch.hpp>

#include <cstring>

#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/light_visibility.h>
#include "lighting_test_util.h"
#include "support/analytic_meshes.h"
#include "support/recording_progress.h"

using namespace shadetool;

TEST_CASE("shadows report every planned ray once, ending at exactly 1, and listening changes no colour",
          "[lighting][shadows][progress]") {
  Scene scene = testing::dark_scene(ShadingModel::Lambert);
  scene.material.diffuse = {0.8, 0.8, 0.8};  // lit: no light is dropped from the plan as dark
  scene.lights.push_back(testing::directional({-1, -2, -3}));
  scene.lights.push_back(testing::point_light({2, 3, 4}));
  Light sky;
  sky.type = LightType::Sky;
  sky.up = {0, 0, 1};
  sky.diffuse = sky.specular = {0.25, 0.5, 1};
  sky.ground = {0.3, 0.2, 0.1};
  scene.lights.push_back(sky);
  const Mesh mesh = testing::torus(32, 16).mesh;  // 512 vertices
  ShadowOptions quiet;
  quiet.enabled = true;
  quiet.samples = 16;
  testing::RecordingProgress rec;
  ShadowOptions listened = quiet;
  listened.progress = &rec;
  const BakeResult a = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, quiet);
  const BakeResult b = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, listened);
  REQUIRE(a.rgb.size() == b.rgb.size());
  CHECK(std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(a.rgb[0])) == 0);
  REQUIRE(rec.stages().size() == 1);
  CHECK(rec.stages()[0].name == "shadows");
  // Two hard lights (one ray per vertex each) and a sky (16 sky and 16 ground rays per vertex).
  CHECK(rec.stages()[0].total == 512u * (1 + 1 + 2 * 16));
  CHECK(rec.stages()[0].advances > 2);
  CHECK(rec.overshoots() == 0);
  CHECK(rec.every_stage_monotone_and_complete());
}
