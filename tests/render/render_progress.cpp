// render_mesh.h's progress (RenderOptions::progress, core/progress.h): the stage "render" counts
// every tile of the image once, whatever the shading and thread count, so its fraction never falls
// and ends at exactly 1; and listening changes no pixel.
#include <catch2/catch.hpp>

#include <cstring>

#include "render_test_util.h"
#include "support/analytic_meshes.h"
#include "support/recording_progress.h"

using namespace shadetool;
using namespace shadetool::render_testing;

TEST_CASE("render reports every tile once, ending at exactly 1, and listening changes no pixel", "[render][progress]") {
  const Mesh mesh = shadetool::testing::torus(48, 24).mesh;
  const Scene s = lit_scene({0, 0, 4});
  RenderOptions quiet;
  quiet.width = 200;  // not a multiple of a tile: the edge tiles count too
  quiet.height = 150;
  for (RenderShading shading : {RenderShading::Flat, RenderShading::Gouraud, RenderShading::Phong}) {
    INFO(render_shading_name(shading));
    quiet.shading = shading;
    shadetool::testing::RecordingProgress rec;
    RenderOptions listened = quiet;
    listened.progress = &rec;
    const RenderResult a = render_mesh(mesh, s, quiet);
    const RenderResult b = render_mesh(mesh, s, listened);
    REQUIRE(a.image.rgb.size() == b.image.rgb.size());
    CHECK(std::memcmp(a.image.rgb.data(), b.image.rgb.data(), a.image.rgb.size() * sizeof(a.image.rgb[0])) == 0);
    REQUIRE(rec.stages().size() == 1);
    CHECK(rec.stages()[0].name == "render");
    // Tiles of 64 pixels for flat and Gouraud at one sample per pixel, else 32 (tile_raster.cpp's
    // tile_pixels): ceil(200 / 64) by ceil(150 / 64), or ceil(200 / 32) by ceil(150 / 32).
    CHECK(rec.stages()[0].total == (shading == RenderShading::Phong ? 7 * 5 : 4 * 3));
    CHECK(rec.overshoots() == 0);
    CHECK(rec.every_stage_monotone_and_complete());
  }
}
