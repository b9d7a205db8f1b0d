// shading_space.h: the space the lighting equation is evaluated in, and everything brought into it.
//
// The equation is defined in world space (lighting/lighting_equation.h). Any space S with an
// invertible affine map world_from_S (x_w = B x_s + b) gives the same colours if lengths and
// angles are measured in the world's metric, pulled back to S (the first fundamental form):
//
//   vectors v (L, V, H, spot axis)     |v|_w^2 = v^T G v,       G = B^T B
//   normals n (covectors: n_w ~ B^-T n) |n|_w^2 = n^T G^-1 n
//   pairing n.v (normal with vector)   n_w . v_w = n . v        (B^-T n . B v = n . v: no metric)
//
// so n.L, n.V, n.H, R.V, the spot cosine and the distance for attenuation are all computed from
// S-coordinates exactly (to rounding), for any B: non-uniform scale, shear, mirror. The spaces:
//
//   world   B = I.          Points by M, normals by sign(det A) cof(A) (A = M's 3x3 part).
//   camera  B = V_A^-1.     Points by V M, normals by sign(det) cof(V_A A); lights by V. The eye is
//                           the origin. A rigid V (look_at) has G = I.
//   object  B = A.          Nothing per point is transformed; lights and eye by M^-1 once.
//                           G = A^T A: the identity for a rotation, s^2 I for a similarity.
//
// Metric kinds: Identity (G = I: plain dot products), Scaled (G = s^2 I: one scale factor),
// General (B and B^-T as matrices). A metric is taken as Identity/Scaled when G differs from
// s^2 I by at most 1e-12 s^2 per entry (relative colour error below 1e-11).
//
// Cost model for `auto` (flops per point, beyond what every space does): a point transform costs
// 18, a normal transform 15 (skipped when the object-to-space map is exactly the identity, and the
// point transform when no position is read); a General metric costs 15 for the normal's length,
// 45 for V (|B V| and B^T B V) and 15 per point/spot light (|B L|). Scaled and Identity metrics cost
// nothing. The cheapest space wins; ties go to object, then world, then camera. bench/lighting
// measures the spaces against this model.
//
// Precision: everything in double. G is never formed for the General metric (it would square
// cond(A)): |v|_G = |B v|, |n|_{G^-1} = |B^-T n| and G v = B^T (B v), so the relative error is
// about cond(A) * 2^-53, as world space's own normal transform.
#pragma once

#include <memory>
#include <string>

#include <shadetool/core/affine.h>
#include <shadetool/lighting/lighting_equation.h>
#include <shadetool/lighting/lighting_plan.h>
#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class ShadingSpace { Auto, World, Camera, Object };
// Its vocabulary (core/vocabulary.h): "auto", "world", "camera", "object".
ShadingSpace parse_shading_space(std::string_view text, const std::string& what);
const char* shading_space_name(ShadingSpace space);
std::vector<std::string> shading_space_names();

enum class MetricKind { Identity, Scaled, General };

struct SpaceMetric {
  MetricKind kind = MetricKind::Identity;
  double scale2 = 1;            // s^2 for Scaled (G = s^2 I)
  Mat3d B;                      // General: world_from_S's linear part; |v|_G = |B v|
  Mat3d B_inverse_transpose;    // General: B^-T; |n|_{G^-1} = |B^-T n|
};

// The metric G = B^T B of a linear map B (world_from_S), classified as above. B invertible.
SpaceMetric metric_of(const Mat3d& world_from_space_linear);

// A light as the equation in space S reads it (material products folded in).
struct SpaceLight {
  LightType type = LightType::Directional;  // Directional, Point or Spot (ambient is folded into the base)
  Vec3d position{0, 0, 0};       // Point/Spot, in S
  Vec3d to_light{0, 0, 0};       // Directional: unit (in G) vector toward the light, in S; Sky: up, in S
  Vec3d axis_lowered{0, 0, 0};   // Spot: G * axis, axis the unit (in G) spot direction in S
  bool cone = false;             // Spot with cutoff != 180
  double cos_cutoff = -1;        // cos(cutoff); exactly 0 for 90 and 1 for 0
  double exponent = 0;
  double kc = 1, kl = 0, kq = 0;
  LightProducts products;        // ka * a_i, kd * d_i, ks * s_i
  bool has_ambient = false;
  bool has_specular = false;

  // Area and Sky (issue 16): evaluated in WORLD space, where their closed forms are exact for
  // every world_from_object (the point and normal are mapped back by the frame, when needed).
  AreaShape shape = AreaShape::Polygon;
  std::vector<Vec3d> vertices;    // Area Polygon, world
  Vec3d emit_normal{0, 0, 0};     // Area Polygon: unit normal of the emitting side (Newell), world
  bool two_sided = false;         // Area Polygon
  Vec3d center{0, 0, 0};          // Area Sphere, world
  double radius = 0;              // Area Sphere
  Vec3d up{0, 1, 0};              // Sky: unit, world
  LightProducts ground_products;  // Sky: kd * ground, ks * ground (ambient in `products`)
  std::shared_ptr<const EnvironmentMap> environment;  // Environment: the map (products hold kd, ks * intensity)
  Mat3d map_from_world;                               // Environment: the inverse of its rotation
};

struct ShadingFrame {
  ShadingSpace space = ShadingSpace::World;
  Affine3d space_from_object;       // applied to points
  Mat3d normal_to_space;            // sign(det) cof(linear part): applied to normals
  bool transform = true;            // false: space_from_object is exactly the identity (or skipped)
  SpaceMetric metric;
  Vec3d eye{0, 0, 0};               // in S
  // For area and sky lights (world space): S -> world for points and normals, and the eye.
  bool space_is_world = true;       // world_from_space is exactly the identity
  Affine3d world_from_space;
  Mat3d normal_to_world;            // sign(det) cof(world_from_space's linear part)
  Vec3d eye_world{0, 0, 0};
  std::vector<SpaceLight> lights;   // the plan's lights, in S
};

// Brings the plan's lights and the eye into `space` (not Auto) and sets the per-point maps.
ShadingFrame make_frame(const Scene& scene, const LightingPlan& plan, ShadingSpace space);

struct SpaceChoice {
  ShadingSpace space = ShadingSpace::Object;
  double cost[3] = {0, 0, 0};  // world, camera, object (model above)
  std::string reason;          // one line, for --stats and notes
};

// The cheapest space that is exact for this scene and plan (all three are exact; see above).
SpaceChoice choose_space(const Scene& scene, const LightingPlan& plan);

// cos of an angle in degrees, exact at 0, 90 and 180 (the values that decide cone membership at
// the cone's edge for the common cutoffs).
double cos_degrees(double degrees);

}  // namespace shadetool
#pragma GCC visibility pop
