// environment_map.cpp: see environment_map.h.
#include <shadetool/lighting/environment_map.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/lighting_equation.h>

// stb_image, HDR decoder only, with every function static to this file: no symbol can clash with
// another copy of stb in the process (tinygltf's, libstb's).
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_HDR
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace shadetool {

namespace {

// Levels small enough to keep every texel's direction (the specular sum reads them per point).
constexpr long kStoredDirections = 1L << 16;

double polar_angle(int height, int row) { return kPi * double(row) / double(height); }  // height > 0
double azimuth(int width, int column) { return kTwoPi * double(column) / double(width); }  // width > 0

// The nine Y_lm integrated exactly over a texel [theta0, theta1] x [phi0, phi1] (dw = sin dtheta dphi):
// the monomials 1, x, y, z, xy, yz, xz, x^2, y^2, z^2 of w = (-s sin phi, c, s cos phi), with
// c = cos theta, s = sin theta, are products of a theta integral and a phi integral.
struct TexelMoments {
  double one, x, y, z, xy, yz, xz, xx, yy, zz;
};
struct RowIntegrals {
  double R0, Rc, Rcc, Rs, Rcs, Rss;  // of sin, c sin, c^2 sin, s^2, c s^2, s^3 over theta
};
struct ColumnIntegrals {
  double C0, Cs, Cc, Css, Ccc, Csc;  // of 1, sin, cos, sin^2, cos^2, sin cos over phi
};
RowIntegrals row_integrals(double t0, double t1) {
  const double c0 = std::cos(t0), c1 = std::cos(t1), s0 = std::sin(t0), s1 = std::sin(t1);
  RowIntegrals r;
  r.R0 = c0 - c1;
  r.Rc = (c0 * c0 - c1 * c1) / 2;
  r.Rcc = (c0 * c0 * c0 - c1 * c1 * c1) / 3;
  r.Rs = (t1 - t0) / 2 - (std::sin(2 * t1) - std::sin(2 * t0)) / 4;
  r.Rcs = (s1 * s1 * s1 - s0 * s0 * s0) / 3;
  r.Rss = r.R0 - r.Rcc;
  return r;
}
ColumnIntegrals column_integrals(double p0, double p1) {
  ColumnIntegrals c;
  c.C0 = p1 - p0;
  c.Cs = std::cos(p0) - std::cos(p1);
  c.Cc = std::sin(p1) - std::sin(p0);
  c.Css = c.C0 / 2 - (std::sin(2 * p1) - std::sin(2 * p0)) / 4;
  c.Ccc = c.C0 - c.Css;
  c.Csc = (std::sin(p1) * std::sin(p1) - std::sin(p0) * std::sin(p0)) / 2;
  return c;
}

// Y_lm's constants (real, orthonormal): Y00 = k0, Y1m = k1 (y, z, x), Y2-2 = k2 xy, Y2-1 = k2 yz,
// Y20 = k3 (3 z^2 - 1), Y21 = k2 xz, Y22 = k4 (x^2 - y^2).
const double k0 = 0.5 / std::sqrt(kPi);
const double k1 = std::sqrt(3 / (4 * kPi));
const double k2 = 0.5 * std::sqrt(15 / kPi);
const double k3 = 0.25 * std::sqrt(5 / kPi);
const double k4 = 0.25 * std::sqrt(15 / kPi);

// Integrals of the nine Y_lm over one texel.
void texel_harmonics(const RowIntegrals& r, const ColumnIntegrals& c, double y[9]) {
  const double one = r.R0 * c.C0, x = -r.Rs * c.Cs, yy1 = r.Rc * c.C0, z = r.Rs * c.Cc;
  const double xy = -r.Rcs * c.Cs, yz = r.Rcs * c.Cc, xz = -r.Rss * c.Csc;
  const double xx = r.Rss * c.Css, yy = r.Rcc * c.C0, zz = r.Rss * c.Ccc;
  y[0] = k0 * one;
  y[1] = k1 * yy1;
  y[2] = k1 * z;
  y[3] = k1 * x;
  y[4] = k2 * xy;
  y[5] = k2 * yz;
  y[6] = k3 * (3 * zz - one);
  y[7] = k2 * xz;
  y[8] = k4 * (xx - yy);
}

void fill_level_geometry(EnvironmentLevel& level) {
  level.row_solid_angle.resize(level.height);
  for (int j = 0; j < level.height; ++j) level.row_solid_angle[j] = environment_row_solid_angle(level.width, level.height, j);
  if (long(level.width) * level.height > kStoredDirections) return;
  level.direction.resize(std::size_t(level.width) * level.height);
  for (int j = 0; j < level.height; ++j)
    for (int i = 0; i < level.width; ++i)
      level.direction[std::size_t(j) * level.width + i] = environment_direction(level.width, level.height, j, i);
}

// The next level: 2x2 texels merged, radiance weighted by solid angle (the two rows differ).
EnvironmentLevel half_level(const EnvironmentLevel& a) {
  EnvironmentLevel b;
  b.width = a.width / 2;
  b.height = a.height / 2;
  b.rgb.resize(std::size_t(b.width) * b.height * 3);
  for (int j = 0; j < b.height; ++j) {
    const double w0 = a.row_solid_angle[2 * j], w1 = a.row_solid_angle[2 * j + 1];
    const double total = 2 * (w0 + w1);  // > 0: every row of a map has a positive solid angle
    for (int i = 0; i < b.width; ++i)
      for (int k = 0; k < 3; ++k) {
        auto at = [&](int jj, int ii) { return double(a.rgb[(std::size_t(jj) * a.width + ii) * 3 + k]); };
        const double sum = w0 * (at(2 * j, 2 * i) + at(2 * j, 2 * i + 1)) + w1 * (at(2 * j + 1, 2 * i) + at(2 * j + 1, 2 * i + 1));
        b.rgb[(std::size_t(j) * b.width + i) * 3 + k] = float(sum / total);
      }
  }
  fill_level_geometry(b);
  return b;
}

Vec3d texel_rgb(const EnvironmentLevel& level, std::size_t t) {
  return {level.rgb[3 * t], level.rgb[3 * t + 1], level.rgb[3 * t + 2]};
}

}  // namespace

Vec3d environment_direction(int width, int height, int row, int column) {
  const double theta = kPi * (row + 0.5) / height, phi = kTwoPi * (column + 0.5) / width;  // sizes > 0
  const double s = std::sin(theta);
  return {-s * std::sin(phi), std::cos(theta), s * std::cos(phi)};
}

double environment_row_solid_angle(int width, int height, int row) {
  // (phi step) (cos theta0 - cos theta1) = (2 pi / W) * 2 sin((t0 + t1) / 2) sin((t1 - t0) / 2):
  // the product form has no cancellation near the poles.
  const double t0 = polar_angle(height, row), t1 = polar_angle(height, row + 1);
  return (kTwoPi / width) * 2 * std::sin((t0 + t1) / 2) * std::sin((t1 - t0) / 2);  // width > 0
}

void spherical_harmonics_9(const Vec3d& w, double y[9]) {
  y[0] = k0;
  y[1] = k1 * w.y;
  y[2] = k1 * w.z;
  y[3] = k1 * w.x;
  y[4] = k2 * w.x * w.y;
  y[5] = k2 * w.y * w.z;
  y[6] = k3 * (3 * w.z * w.z - 1);
  y[7] = k2 * w.x * w.z;
  y[8] = k4 * (w.x * w.x - w.y * w.y);
}

std::shared_ptr<const EnvironmentMap> make_environment_map(int width, int height, const std::vector<float>& rgb) {
  if (width < 1 || height < 1) throw Error("environment map: empty image");
  if (rgb.size() != std::size_t(width) * height * 3) throw Error("environment map: pixel count does not match its size");
  for (float v : rgb)
    if (!(v >= 0) || !std::isfinite(v)) throw Error("environment map: a radiance value is negative or not finite");
  auto map = std::make_shared<EnvironmentMap>();
  EnvironmentLevel level0;
  level0.width = width;
  level0.height = height;
  level0.rgb = rgb;
  fill_level_geometry(level0);
  map->levels.push_back(std::move(level0));
  while (map->levels.back().height > 4 && map->levels.back().height % 2 == 0 && map->levels.back().width % 2 == 0)
    map->levels.push_back(half_level(map->levels.back()));

  // L_lm = sum over texels of L_t * integral of Y_lm over the texel (exact per texel).
  std::vector<ColumnIntegrals> columns(width);
  for (int i = 0; i < width; ++i) columns[i] = column_integrals(azimuth(width, i), azimuth(width, i + 1));
  for (int m = 0; m < 9; ++m) map->sh[m] = {0, 0, 0};
  for (int j = 0; j < height; ++j) {
    const RowIntegrals r = row_integrals(polar_angle(height, j), polar_angle(height, j + 1));
    for (int i = 0; i < width; ++i) {
      double y[9];
      texel_harmonics(r, columns[i], y);
      const Vec3d L = texel_rgb(map->levels[0], std::size_t(j) * width + i);
      for (int m = 0; m < 9; ++m) map->sh[m] += L * y[m];
    }
  }
  return map;
}

namespace {

// The file's bytes handed to stb through callbacks that notice a read past the end: stb's decoder
// reads zeros there instead of failing, so a truncated file would otherwise decode as black rows.
struct ByteSource {
  const std::vector<unsigned char>* bytes;
  std::size_t position = 0;
  bool overrun = false;
};
int read_bytes(void* user, char* data, int size) {
  ByteSource& s = *static_cast<ByteSource*>(user);
  if (s.position >= s.bytes->size()) {
    s.overrun = true;
    return 0;
  }
  const std::size_t n = std::min(std::size_t(size), s.bytes->size() - s.position);
  std::memcpy(data, s.bytes->data() + s.position, n);
  s.position += n;
  return int(n);
}
void skip_bytes(void* user, int n) {
  ByteSource& s = *static_cast<ByteSource*>(user);
  s.position = n < 0 ? s.position - std::min(s.position, std::size_t(-n)) : s.position + std::size_t(n);
}
int at_end(void* user) {
  const ByteSource& s = *static_cast<ByteSource*>(user);
  return s.position >= s.bytes->size();
}

}  // namespace

std::shared_ptr<const EnvironmentMap> read_environment_map(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(std::string("cannot open the image: ") + std::strerror(errno));
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error("cannot read the image: read error");
  const int size = bytes.size() > std::size_t(1) << 30 ? 0 : int(bytes.size());  // stb takes an int
  if (bytes.empty() || !stbi_is_hdr_from_memory(bytes.data(), size)) throw Error("not a Radiance .hdr (RGBE) image");
  ByteSource source{&bytes};
  const stbi_io_callbacks callbacks{read_bytes, skip_bytes, at_end};
  int w = 0, h = 0, channels = 0;
  float* data = stbi_loadf_from_callbacks(&callbacks, &source, &w, &h, &channels, 3);
  if (!data) throw Error(std::string("cannot decode the image: ") + stbi_failure_reason());
  std::vector<float> rgb(data, data + std::size_t(w) * h * 3);
  stbi_image_free(data);
  if (source.overrun) throw Error("cannot decode the image: the pixel data ends early (truncated file)");
  return make_environment_map(w, h, rgb);
}

Vec3d environment_irradiance_sh(const EnvironmentMap& map, const Vec3d& n) {
  double y[9];
  spherical_harmonics_9(n, y);
  const double A[9] = {kPi, 2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4, kPi / 4, kPi / 4, kPi / 4, kPi / 4};
  Vec3d P{0, 0, 0};
  for (int m = 0; m < 9; ++m) P += map.sh[m] * (A[m] * y[m]);
  return P;
}

Vec3d environment_irradiance_sum(const EnvironmentMap& map, const Vec3d& n, int level_index) {
  const EnvironmentLevel& level = map.levels[level_index];
  Vec3d P{0, 0, 0};
  for (int j = 0; j < level.height; ++j) {
    Vec3d row{0, 0, 0};
    for (int i = 0; i < level.width; ++i) {
      const std::size_t t = std::size_t(j) * level.width + i;
      const Vec3d w = level.direction.empty() ? environment_direction(level.width, level.height, j, i) : level.direction[t];
      const double c = dot(n, w);
      if (c > 0) row += texel_rgb(level, t) * c;
    }
    P += row * level.row_solid_angle[j];
  }
  return P;
}

Vec3d environment_specular_sum(const EnvironmentMap& map, const Vec3d& normal, const SpecularLobe& lobe, int level_index) {
  const EnvironmentLevel& level = map.levels[level_index];
  const double s = lobe.shininess;
  // The lobe's base b (R.w for Phong, n.H for Blinn-Phong; spec = b^s) below `cut` gives
  // spec < 2^-40: such texels are skipped, so the omitted part of S is below 2^-40 of the
  // integral of L over the hemisphere. Shininess 0 (spec = 1 everywhere): nothing is skipped.
  const double cut = s > 0 ? std::exp2(-40.0 / s) : 0.0;  // s > 0 checked
  int j0 = 0, j1 = level.height - 1;
  Vec3d V = lobe.view;
  double n_dot_v = 0, v_unit = 0;
  switch (lobe.kind) {
    case LobeKind::None: return {0, 0, 0};
    case LobeKind::Phong:
      if (cut > 0) {  // only rows whose centres can be within acos(cut) of R (one row of margin)
        const double theta_r = std::acos(std::fmax(-1.0, std::fmin(1.0, lobe.reflected.y)));
        const double alpha = std::acos(cut), row = kPi / level.height;
        j0 = std::max(0, int(std::floor((theta_r - alpha) / row - 0.5)) - 1);
        j1 = std::min(level.height - 1, int(std::ceil((theta_r + alpha) / row - 0.5)) + 1);
      }
      break;
    case LobeKind::BlinnPhong:
      n_dot_v = dot(normal, V);
      v_unit = V == Vec3d{0, 0, 0} ? 0.0 : 1.0;  // at the eye H = w (lighting_equation.h)
      break;
  }
  Vec3d S{0, 0, 0};
  for (int j = j0; j <= j1; ++j) {
    Vec3d row{0, 0, 0};
    for (int i = 0; i < level.width; ++i) {
      const std::size_t t = std::size_t(j) * level.width + i;
      const Vec3d w = level.direction.empty() ? environment_direction(level.width, level.height, j, i) : level.direction[t];
      const double n_dot_w = dot(normal, w);
      if (!(n_dot_w > 0)) continue;
      const double b = positive_part(lobe.kind == LobeKind::Phong ? dot(lobe.reflected, w)
                                                                  : blinn_phong_n_dot_h(n_dot_w, n_dot_v, dot(w, V), v_unit));
      if (b < cut) continue;
      row += texel_rgb(level, t) * std::pow(b, s);
    }
    S += row * level.row_solid_angle[j];
  }
  return S;
}

int environment_specular_level(const EnvironmentMap& map, double shininess, double texels_per_lobe) {
  const double half_width = shininess > 0 ? 1.18 / std::sqrt(shininess) : kPi;  // shininess > 0 checked
  int best = 0;
  for (int k = 1; k < int(map.levels.size()); ++k) {
    const EnvironmentLevel& L = map.levels[k];
    if (L.height < kEnvironmentMinHeight || kPi / L.height > half_width / texels_per_lobe) break;
    best = k;
  }
  return best;
}

Vec3d environment_radiance(const EnvironmentMap& map, const Vec3d& w) {
  const EnvironmentLevel& L = map.levels[0];
  const double theta = std::acos(std::fmax(-1.0, std::fmin(1.0, w.y)));
  double phi = std::atan2(-w.x, w.z);  // w = (-s sin phi, c, s cos phi)
  if (phi < 0) phi += kTwoPi;
  int row = int(theta / kPi * L.height), col = int(phi / kTwoPi * L.width);
  row = row < 0 ? 0 : row >= L.height ? L.height - 1 : row;
  col = col < 0 ? 0 : col >= L.width ? L.width - 1 : col;
  return texel_rgb(L, std::size_t(row) * L.width + col);
}

Mat3d environment_rotation(double degrees, const Vec3d& axis) {
  const Vec3d k = normalized_or(axis, Vec3d{0, 1, 0});
  // cos and sin exact at multiples of 90 degrees (a quarter turn must not leave 6e-17 behind).
  const double r = std::fmod(degrees, 360.0);
  const double q = r / 90.0;
  double c, s;
  if (q == std::floor(q)) {
    const int quarter = ((int(q) % 4) + 4) % 4;
    const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    c = cs[quarter][0];
    s = cs[quarter][1];
  } else {
    c = std::cos(r * kRadiansPerDegree);
    s = std::sin(r * kRadiansPerDegree);
  }
  const double t = 1 - c;
  Mat3d R;  // Rodrigues
  R.m = {{{t * k.x * k.x + c, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y},
          {t * k.x * k.y + s * k.z, t * k.y * k.y + c, t * k.y * k.z - s * k.x},
          {t * k.x * k.z - s * k.y, t * k.y * k.z + s * k.x, t * k.z * k.z + c}}};
  return R;
}

}  // namespace shadetool
