// fuzz_scene.cpp: libFuzzer target for bake-lighting's scene parser (lighting/read_scene.h).
//
// Arbitrary bytes must either throw shadetool::Error (one line naming the problem) or give a Scene
// that satisfies what read_scene.h promises: every number finite, colours, intensities, shininess,
// exponents and attenuation >= 0, attenuation not all zero, light directions of non-zero length,
// spot cutoff in [0, 90] or 180; area lights with finite vertices (3 to 64) or a positive radius,
// sky lights with a non-zero up. Such a scene must then light a small mesh (a tetrahedron with an
// isolated vertex and a degenerate face, per vertex and per face, every shading model) with
// colours that are all finite: a scene the parser accepts may not produce NaN downstream.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/lighting/area_light.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/read_scene.h>

namespace {

[[noreturn]] void bug(const char* what) {
  std::fprintf(stderr, "fuzz: scene invariant broken: %s\n", what);
  std::abort();
}

bool finite(const shadetool::Vec3d& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool non_negative(const shadetool::Vec3d& v) { return v.x >= 0 && v.y >= 0 && v.z >= 0; }

const shadetool::Mesh& test_mesh() {
  static const shadetool::Mesh mesh = [] {
    shadetool::Mesh m;
    m.add_vertex({0, 0, 0});
    m.add_vertex({1, 0, 0});
    m.add_vertex({0, 1, 0});
    m.add_vertex({0, 0, 1});
    m.add_vertex({5, 5, 5});  // isolated
    m.add_face({0, 2, 1});
    m.add_face({0, 1, 3});
    m.add_face({0, 3, 2});
    m.add_face({1, 2, 3});
    m.add_face({0, 0, 1});  // degenerate
    return m;
  }();
  return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  shadetool::Scene scene;
  try {
    scene = shadetool::parse_scene(text, "fuzz.json");
  } catch (const shadetool::Error&) {
    return 0;
  }
  const auto& mat = scene.material;
  const shadetool::Vec3d* const colours[] = {&mat.ambient, &mat.diffuse, &mat.specular, &mat.emission,
                                             &scene.global_ambient};
  for (const auto* v : colours)
    if (!finite(*v) || !non_negative(*v)) bug("material or global ambient colour not finite and >= 0");
  if (!std::isfinite(mat.shininess) || mat.shininess < 0) bug("shininess");
  for (const auto& l : scene.lights) {
    for (const auto* v : {&l.ambient, &l.diffuse, &l.specular, &l.attenuation})
      if (!finite(*v) || !non_negative(*v)) bug("light colour or attenuation not finite and >= 0");
    if (!finite(l.position) || !finite(l.direction)) bug("light position or direction not finite");
    if (l.type == shadetool::LightType::Directional || l.type == shadetool::LightType::Spot)
      if (l.direction.x == 0 && l.direction.y == 0 && l.direction.z == 0) bug("zero light direction accepted");
    if ((l.type == shadetool::LightType::Point || l.type == shadetool::LightType::Spot) &&
        l.attenuation.x == 0 && l.attenuation.y == 0 && l.attenuation.z == 0)
      bug("attenuation 0 0 0 accepted");
    if (!(l.cutoff_degrees >= 0 && l.cutoff_degrees <= 90) && l.cutoff_degrees != 180) bug("cutoff out of range");
    if (!std::isfinite(l.exponent) || l.exponent < 0) bug("spot exponent");
    // Area and sky lights (issue 16)
    if (!finite(l.ground) || !non_negative(l.ground)) bug("sky ground radiance not finite and >= 0");
    if (l.type == shadetool::LightType::Sky && l.up.x == 0 && l.up.y == 0 && l.up.z == 0) bug("zero sky up accepted");
    if (l.type == shadetool::LightType::Area && l.shape == shadetool::AreaShape::Sphere &&
        !(l.radius > 0 && std::isfinite(l.radius) && finite(l.center)))
      bug("sphere light radius not > 0 or centre not finite");
    if (l.type == shadetool::LightType::Area && l.shape == shadetool::AreaShape::Polygon) {
      if (l.vertices.size() < 3 || l.vertices.size() > std::size_t(shadetool::kMaxAreaVertices))
        bug("polygon light vertex count out of range");
      for (const auto& v : l.vertices)
        if (!finite(v)) bug("polygon light vertex not finite");
    }
  }
  // Lighting with an accepted scene never yields NaN. (Inf can only come from colours or
  // intensities near the top of double's range; the equation's terms are sums of products of
  // such values, so an accepted scene with values below 1e100 must give finite colours.)
  bool huge = false;
  auto big = [](const shadetool::Vec3d& v) { return std::fabs(v.x) > 1e100 || std::fabs(v.y) > 1e100 || std::fabs(v.z) > 1e100; };
  for (const auto* v : colours) huge = huge || big(*v);
  for (const auto& l : scene.lights)
    for (const auto* v : {&l.ambient, &l.diffuse, &l.specular, &l.ground}) huge = huge || big(*v);
  for (auto freq : {shadetool::ShadingFrequency::PerVertex, shadetool::ShadingFrequency::PerFace})
    for (auto model : {shadetool::ShadingModel::Lambert, shadetool::ShadingModel::Phong, shadetool::ShadingModel::BlinnPhong}) {
      shadetool::ShadeOptions options;
      options.model = model;
      options.parallel = false;
      shadetool::BakeResult baked;
      try {
        baked = shadetool::bake_lighting(test_mesh(), scene, freq, options);
      } catch (const shadetool::Error&) {
        continue;  // refused with a message (e.g. a map that sends the mesh out of range)
      }
      for (double c : baked.rgb) {
        if (std::isnan(c)) bug("NaN colour from an accepted scene");
        if (!huge && !std::isfinite(c)) bug("infinite colour from an accepted scene with colours below 1e100");
      }
    }
  return 0;
}
