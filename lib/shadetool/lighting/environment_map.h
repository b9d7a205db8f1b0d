// environment_map.h: an environment light's image and what the lighting equation reads from it
// (issue 16): the projected-solid-angle integral P and the specular integral S of
// lighting/area_light.h, per colour channel, for radiance given by an equirectangular map.
//
//   P(n) = integral of L(w) max(n.w, 0) dw        (steradians times radiance; no 1/pi)
//   S(n) = integral of L(w) [n.w > 0] spec(w) dw   (spec: area_light.h's SpecularLobe)
//
// Map convention (the image as stored, before the light's rotation): row 0 is the top, +y; row j
// covers polar angles theta in [pi j / H, pi (j+1) / H) from +y; column i covers azimuths
// phi in [2 pi i / W, 2 pi (i+1) / W), and
//   w(theta, phi) = (-sin(theta) sin(phi), cos(theta), sin(theta) cos(phi)),
// so the image's centre column looks along -z with +x to its right (u = 0.5 + atan2(x, -z) / 2pi,
// as most renderers' equirectangular maps). A texel is a constant radiance over its
// latitude-longitude rectangle; its solid angle is exact: (phi step) * (cos theta0 - cos theta1).
//
// Diffuse, P: Ramamoorthi & Hanrahan (2001), "An efficient representation for irradiance
// environment maps": the nine spherical-harmonic coefficients L_lm (l <= 2) of the map and
//   P(n) = sum_lm A_l L_lm Y_lm(n),   A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4
// (their eq. 7-8 without the 1/pi of radiosity: A_l are the clamped cosine's coefficients). The
// L_lm are integrated exactly over each texel's rectangle (the Y_lm are polynomials of degree
// <= 2 in w: closed forms in theta and phi, see environment_map.cpp), so a constant map gives
// pi L and a map that is one colour above the horizon and another below gives the sky light's
// pi (1 +- n.up) / 2 exactly (its odd bands l >= 3 have A_l = 0). The truncation to l <= 2 is
// the only approximation: measured against the full sum below in tests/lighting and
// bench/lighting (R&H bound it by about 3% of the average irradiance for natural lighting; a
// single bright texel is the worst case).
//
// Specular, S: the sum over the texels of a down-sampled copy of the map (levels: 2x2 box
// filters weighted by solid angle, so each level holds the same integral of L) of
//   L_t [n.w_t > 0] spec(w_t) dOmega_t,  w_t the texel's centre direction.
// The level is chosen by the lobe's width (environment_specular_level); its error against the
// full-resolution sum is measured in bench/lighting and bounded in tests/lighting. Texels where
// spec(w) < 2^-40 are skipped (and, for Phong, the rows that cannot reach R's cap): the omitted
// part is below 2^-40 of the integral of L over the hemisphere. spec is the point light's
// formula (lighting_equation.h: R.w, and n.H from n.w, n.V, w.V).
//
// Radiance values: Radiance RGBE (.hdr) decoded by stb_image (libstb-dev), which maps a texel
// (m, e) to m * 2^(e - 136) WITHOUT the +0.5 that Radiance's own reader and Blender add: a file
// written by a truncating RGBE writer reads up to half a quantisation step (<= 1/256 relative)
// lower here. We follow stb's convention (the values are what the library returns; our test
// images use mantissas whose values are exact in it).
//
// Precision: the map is stored as float (the file holds 8-bit mantissas); every sum accumulates
// in double. Degenerate input: an image of zero radiance gives P = S = 0; a zero normal is the
// caller's (engine/area_point.cpp adds only ambient).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <shadetool/core/affine.h>
#include <shadetool/core/vec3.h>
#include <shadetool/lighting/area_light.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// One resolution of the map: width x height texels, RGB radiance, row 0 = top (+y).
struct EnvironmentLevel {
  int width = 0, height = 0;
  std::vector<float> rgb;               // width * height * 3, row-major
  std::vector<double> row_solid_angle;  // height: one texel's solid angle in row j (exact)
  std::vector<Vec3d> direction;         // width * height texel-centre unit directions (map space)
};

struct EnvironmentMap {
  std::vector<EnvironmentLevel> levels;  // levels[0] the image; each next one half as wide and tall
  Vec3d sh[9];                           // L_lm per channel, order (0,0) (1,-1) (1,0) (1,1) (2,-2) ... (2,2)
};

// Builds the map from RGB radiance (width * height * 3 values, row 0 at the top, every value
// finite and >= 0): the levels down to a height of 4 (or an odd size) and the SH coefficients.
// Throws shadetool::Error for an empty or mis-sized input.
std::shared_ptr<const EnvironmentMap> make_environment_map(int width, int height, const std::vector<float>& rgb);

// Reads a Radiance .hdr (RGBE) file with stb_image and builds the map. Throws shadetool::Error
// with the reason (no file name: the caller names the file and the JSON path).
std::shared_ptr<const EnvironmentMap> read_environment_map(const std::string& path);

// The map's texel-centre direction and its solid angle, for row j and column i of a level.
Vec3d environment_direction(int width, int height, int row, int column);
double environment_row_solid_angle(int width, int height, int row);

// The nine real spherical harmonics Y_lm(w) (w unit), in EnvironmentMap::sh's order.
void spherical_harmonics_9(const Vec3d& w, double y[9]);

// P(n) by the nine coefficients (n unit, map space). Per channel.
Vec3d environment_irradiance_sh(const EnvironmentMap& map, const Vec3d& n);

// P(n) by summing every texel of a level: sum_t L_t max(n.w_t, 0) dOmega_t (the reference).
Vec3d environment_irradiance_sum(const EnvironmentMap& map, const Vec3d& n, int level = 0);

// S by summing a level's texels (lobe in map space; `normal` the point's unit normal there).
Vec3d environment_specular_sum(const EnvironmentMap& map, const Vec3d& normal, const SpecularLobe& lobe, int level);

// The coarsest level whose texel height pi / H is at most 1 / (texels_per_lobe) of the lobe's
// half-width 1.18 / sqrt(shininess) (the angle where cos^s = 1/2), and no coarser than
// kEnvironmentMinHeight rows (the horizon cut on coarse texels). Shininess 0: the coarsest such level.
constexpr int kEnvironmentMinHeight = 16;
constexpr double kEnvironmentTexelsPerLobe = 2;
int environment_specular_level(const EnvironmentMap& map, double shininess,
                               double texels_per_lobe = kEnvironmentTexelsPerLobe);

// The map's radiance at a direction (map space, unit): the level-0 texel containing it.
Vec3d environment_radiance(const EnvironmentMap& map, const Vec3d& w);

// The rotation of the light's "rotation": [degrees, ax, ay, az] (axis non-zero): world_from_map.
// Exact at multiples of 90 degrees.
Mat3d environment_rotation(double degrees, const Vec3d& axis);

}  // namespace shadetool
#pragma GCC visibility pop
