// read_scene.cpp: JSON -> Scene with one-line errors `FILE: $.json.path: problem` (see read_scene.h).
#include <shadetool/lighting/read_scene.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadetool/core/error.h>
#include <shadetool/core/affine.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/area_light.h>
#include <shadetool/lighting/environment_map.h>
#include <shadetool/lighting/look_at.h>
#include <shadetool/lighting/validate_scene.h>

namespace shadetool {

namespace {

using json = nlohmann::json;

// JSONPath step for an object key: .name for identifiers, ["odd key"] otherwise.
std::string key_step(const std::string& key) {
  bool identifier = !key.empty() && !std::isdigit(static_cast<unsigned char>(key[0]));
  for (char c : key)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) identifier = false;
  return identifier ? "." + key : "[" + json(key).dump() + "]";
}

std::string describe(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return j.get<bool>() ? "true" : "false";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array of " + std::to_string(j.size());
    case json::value_t::object: return "an object";
    case json::value_t::number_integer: case json::value_t::number_unsigned: case json::value_t::number_float:
    case json::value_t::binary: case json::value_t::discarded: break;
  }
  return "a number";
}

std::string number_text(double x) {
  std::ostringstream s;
  s.precision(12);
  s << x;
  return s.str();
}

// One scene file being read: its name for messages, and typed accessors that fail with the path.
class SceneReader {
 public:
  // base_dir: where relative paths in the scene (an environment's image) start: the scene file's folder.
  SceneReader(std::string file, std::string base_dir) : file_(std::move(file)), base_dir_(std::move(base_dir)) {}

  [[noreturn]] void bad(const std::string& path, const std::string& problem) const {
    fail(file_, 0, path + ": " + problem);
  }

  void require_object(const json& j, const std::string& path) const {
    if (!j.is_object()) bad(path, "must be an object, got " + describe(j));
  }

  void check_keys(const json& obj, const std::string& path, std::initializer_list<const char*> allowed,
                  const std::string& what) const {
    check_keys(obj, path, std::vector<const char*>(allowed), what);
  }
  void check_keys(const json& obj, const std::string& path, const std::vector<const char*>& allowed,
                  const std::string& what) const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const bool known = std::any_of(allowed.begin(), allowed.end(), [&](const char* k) { return it.key() == k; });
      if (known) continue;
      std::string list;
      for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
      bad(path + key_step(it.key()), "unknown key in " + what + " (expected one of: " + list + ")");
    }
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) bad(path, "must be a number, got " + describe(j));
    const double x = j.get<double>();
    if (!std::isfinite(x)) bad(path, "must be a finite number");
    return x;
  }

  double non_negative(const json& j, const std::string& path) const {
    const double x = number(j, path);
    if (x < 0) bad(path, "must be >= 0, got " + number_text(x));
    return x;
  }

  bool boolean(const json& j, const std::string& path) const {
    if (!j.is_boolean()) bad(path, "must be true or false, got " + describe(j));
    return j.get<bool>();
  }

  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) bad(path, "must be a string, got " + describe(j));
    return j.get<std::string>();
  }

  Vec3d vec3(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) bad(path, "must be an array of 3 numbers, got " + describe(j));
    return {number(j[0], path + "[0]"), number(j[1], path + "[1]"), number(j[2], path + "[2]")};
  }

  Vec3d colour(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3)
      bad(path, "must be a colour [r, g, b] (3 numbers >= 0), got " + describe(j));
    Vec3d c;
    for (int i = 0; i < 3; ++i) {
      const std::string p = path + "[" + std::to_string(i) + "]";
      c[i] = number(j[i], p);
      if (c[i] < 0) bad(p, "colour channels must be >= 0, got " + number_text(c[i]));
    }
    return c;
  }

  Vec3d direction(const json& j, const std::string& path) const {
    const Vec3d d = vec3(j, path);
    if (!(length(d) > 0)) bad(path, "zero-length direction");
    return d;
  }

  // 16 numbers, row-major 4x4, bottom row exactly 0 0 0 1, invertible 3x3 part.
  Affine3d affine(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 16)
      bad(path, "must be a 4x4 matrix as an array of 16 numbers (row-major), got " + describe(j));
    double m[16];
    for (int i = 0; i < 16; ++i) m[i] = number(j[i], path + "[" + std::to_string(i) + "]");
    if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
      bad(path, "bottom row must be 0 0 0 1 (an affine map; projections are not supported), got " +
                    number_text(m[12]) + " " + number_text(m[13]) + " " + number_text(m[14]) + " " +
                    number_text(m[15]));
    Affine3d M;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) M.A.m[r][c] = m[4 * r + c];
      M.t[r] = m[4 * r + 3];
    }
    Affine3d unused;
    if (!invert_affine(M, unused)) bad(path, "the 3x3 part is singular (determinant 0): the map has no inverse");
    return M;
  }

  const json* find(const json& obj, const char* key) const {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }
  const json& need(const json& obj, const std::string& path, const char* key, const std::string& what) const {
    const json* j = find(obj, key);
    if (!j) bad(path, what + " needs '" + key + "'");
    return *j;
  }

  ShadingModel model(const json& j, const std::string& path) const {
    return parse_shading_model(string(j, path), located(file_, 0, path));  // scene.h's vocabulary
  }

  void camera(const json& j, const std::string& path, Scene& scene) const {
    require_object(j, path);
    check_keys(j, path, {"eye", "target", "up", "view", "fov_y", "near", "far", "orthographic"}, "camera");
    lens(j, path, scene.lens);
    if (const json* v = find(j, "view")) {
      if (find(j, "eye") || find(j, "target") || find(j, "up"))
        bad(path, "give either \"view\" or \"eye\"/\"target\"/\"up\", not both");
      scene.camera_from_world = affine(*v, path + ".view");
    } else {
      const Vec3d eye = vec3(need(j, path, "eye", "a camera"), path + ".eye");
      const Vec3d target = vec3(need(j, path, "target", "a camera"), path + ".target");
      const json* up_json = find(j, "up");
      const Vec3d up = up_json ? direction(*up_json, path + ".up") : Vec3d{0, 1, 0};
      if (eye == target) bad(path + ".target", "equals the eye: no view direction");
      if (!look_at(eye, target, up, scene.camera_from_world))
        bad(path + ".up", "is parallel to the view direction (target - eye)");
    }
    scene.has_camera = true;
  }

  // The projection fields of a camera (render/ reads them; see scene.h CameraLens).
  void lens(const json& j, const std::string& path, CameraLens& lens) const {
    if (const json* v = find(j, "fov_y")) {
      lens.fov_y_degrees = number(*v, path + ".fov_y");
      if (!(lens.fov_y_degrees > 0 && lens.fov_y_degrees < 180))
        bad(path + ".fov_y", "must be in (0, 180) degrees, got " + number_text(lens.fov_y_degrees));
    }
    if (const json* v = find(j, "orthographic")) {
      lens.orthographic_height = number(*v, path + ".orthographic");
      if (!(lens.orthographic_height > 0)) bad(path + ".orthographic", "must be a height > 0 (world units)");
      if (find(j, "fov_y")) bad(path, "give either \"fov_y\" (perspective) or \"orthographic\", not both");
    }
    const json* n = find(j, "near");
    const json* f = find(j, "far");
    if (n) lens.near = number(*n, path + ".near");
    if (f) lens.far = number(*f, path + ".far");
    if (n && !(lens.near > 0)) bad(path + ".near", "must be > 0, got " + number_text(lens.near));
    if (f && !(lens.far > lens.near)) bad(path + ".far", "must be greater than near, got " + number_text(lens.far));
  }

  Material material(const json& j, const std::string& path) const {
    require_object(j, path);
    check_keys(j, path, {"ambient", "diffuse", "specular", "emission", "shininess"}, "material");
    Material m;
    if (const json* v = find(j, "ambient")) m.ambient = colour(*v, path + ".ambient");
    if (const json* v = find(j, "diffuse")) m.diffuse = colour(*v, path + ".diffuse");
    if (const json* v = find(j, "specular")) m.specular = colour(*v, path + ".specular");
    if (const json* v = find(j, "emission")) m.emission = colour(*v, path + ".emission");
    if (const json* v = find(j, "shininess")) m.shininess = non_negative(*v, path + ".shininess");
    return m;
  }

  // The light-type table: one entry per kind, with its JSON name, its keys and its parser. A kind
  // is reached only through its own entry (an unknown "type" is an error naming every entry).
  struct LightKindEntry {
    const char* name;  // the JSON "type"
    LightType type;
    std::vector<const char*> keys;
    void (SceneReader::*parse)(const json&, const std::string&, Light&) const;
  };
  static const std::vector<LightKindEntry>& light_kinds() {
    static const std::vector<LightKindEntry> kinds = {
        {"ambient", LightType::Ambient, {"type", "color", "intensity"}, &SceneReader::ambient_light},
        {"directional", LightType::Directional,
         {"type", "direction", "color", "intensity", "ambient", "diffuse", "specular"}, &SceneReader::directional_light},
        {"point", LightType::Point,
         {"type", "position", "attenuation", "color", "intensity", "ambient", "diffuse", "specular"},
         &SceneReader::point_light},
        {"spot", LightType::Spot,
         {"type", "position", "direction", "cutoff", "exponent", "attenuation", "color", "intensity", "ambient",
          "diffuse", "specular"},
         &SceneReader::spot_light},
        {"area", LightType::Area,
         {"type", "shape", "center", "u", "v", "vertices", "radius", "two_sided", "color", "intensity", "ambient"},
         &SceneReader::area_light},
        {"sky", LightType::Sky, {"type", "up", "sky", "ground", "intensity", "ambient"}, &SceneReader::sky_light},
        {"environment", LightType::Environment, {"type", "image", "rotation", "intensity", "ambient"},
         &SceneReader::environment_light},
    };
    return kinds;
  }

  Light light(const json& j, const std::string& path) const {
    require_object(j, path);
    const std::string type = string(need(j, path, "type", "a light"), path + ".type");
    const auto& kinds = light_kinds();
    const auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const LightKindEntry& k) { return type == k.name; });
    if (kind == kinds.end()) {
      std::string names;
      for (std::size_t i = 0; i < kinds.size(); ++i)
        names += std::string(i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + "\"" + kinds[i].name + "\"";
      bad(path + ".type", "must be " + names + ", got \"" + type + "\"");
    }
    check_keys(j, path, kind->keys, (std::string("aeiou").find(type[0]) != std::string::npos ? "an " : "a ") + type + " light");
    Light L;
    L.type = kind->type;
    (this->*kind->parse)(j, path, L);
    return L;
  }

  // color (default [1,1,1]) times intensity (default 1).
  Vec3d color_times_intensity(const json& j, const std::string& path) const {
    Vec3d color{1, 1, 1};
    double intensity = 1;
    if (const json* v = find(j, "color")) color = colour(*v, path + ".color");
    if (const json* v = find(j, "intensity")) intensity = non_negative(*v, path + ".intensity");
    return scaled_colour(color, intensity, path + (find(j, "intensity") ? ".intensity" : ".color"));
  }

  // color * intensity, refused when a channel overflows (issue 21: Inf would reach the equation).
  Vec3d scaled_colour(const Vec3d& color, double intensity, const std::string& path) const {
    const Vec3d c = color * intensity;
    if (!is_finite(c))
      bad(path, "color x intensity overflows (" + number_text(std::fmax(color.x, std::fmax(color.y, color.z))) +
                    " x " + number_text(intensity) + " is beyond double's range)");
    return c;
  }

  void ambient_light(const json& j, const std::string& path, Light& L) const {
    L.ambient = color_times_intensity(j, path);
    L.diffuse = L.specular = {0, 0, 0};
  }

  // OpenGL's a_i, d_i, s_i: ambient black, diffuse and specular color * intensity, each overridable.
  void light_colours(const json& j, const std::string& path, Light& L) const {
    L.ambient = {0, 0, 0};
    L.diffuse = L.specular = color_times_intensity(j, path);
    if (const json* v = find(j, "ambient")) L.ambient = colour(*v, path + ".ambient");
    if (const json* v = find(j, "diffuse")) L.diffuse = colour(*v, path + ".diffuse");
    if (const json* v = find(j, "specular")) L.specular = colour(*v, path + ".specular");
  }

  void attenuation(const json& j, const std::string& path, Light& L) const {
    if (const json* v = find(j, "attenuation")) {
      const std::string p = path + ".attenuation";
      if (!v->is_array() || v->size() != 3) bad(p, "must be [kc, kl, kq] (3 numbers >= 0), got " + describe(*v));
      for (int i = 0; i < 3; ++i) L.attenuation[i] = non_negative((*v)[i], p + "[" + std::to_string(i) + "]");
      if (L.attenuation == Vec3d{0, 0, 0}) bad(p, "is [0, 0, 0]: 1/(kc + kl d + kq d^2) has no finite value");
    }
  }

  void directional_light(const json& j, const std::string& path, Light& L) const {
    light_colours(j, path, L);
    L.direction = direction(need(j, path, "direction", "a directional light"), path + ".direction");
  }

  void point_light(const json& j, const std::string& path, Light& L) const {
    light_colours(j, path, L);
    L.position = vec3(need(j, path, "position", "a point light"), path + ".position");
    attenuation(j, path, L);
  }

  // Area lights (issue 16): emitted radiance L = color * intensity in diffuse and specular.
  void area_light(const json& j, const std::string& path, Light& L) const {
    const std::string shape = string(need(j, path, "shape", "an area light"), path + ".shape");
    if (shape == "rect") {
      check_keys(j, path, {"type", "shape", "center", "u", "v", "two_sided", "color", "intensity", "ambient"},
                 "a rect area light");
    } else if (shape == "polygon") {
      check_keys(j, path, {"type", "shape", "vertices", "two_sided", "color", "intensity", "ambient"},
                 "a polygon area light");
    } else if (shape == "sphere") {
      check_keys(j, path, {"type", "shape", "center", "radius", "color", "intensity", "ambient"}, "a sphere area light");
    } else {
      bad(path + ".shape", "must be \"rect\", \"polygon\" or \"sphere\", got \"" + shape + "\"");
    }
    L.ambient = {0, 0, 0};
    L.diffuse = L.specular = color_times_intensity(j, path);
    if (const json* v = find(j, "ambient")) L.ambient = colour(*v, path + ".ambient");
    if (const json* v = find(j, "two_sided")) L.two_sided = boolean(*v, path + ".two_sided");
    const std::string what = "a " + shape + " area light";
    if (shape == "sphere") {
      L.shape = AreaShape::Sphere;
      L.center = vec3(need(j, path, "center", what), path + ".center");
      L.radius = number(need(j, path, "radius", what), path + ".radius");
      if (!(L.radius > 0)) bad(path + ".radius", "must be > 0, got " + number_text(L.radius));
      return;
    }
    L.shape = AreaShape::Polygon;
    if (shape == "rect") {
      const Vec3d c = vec3(need(j, path, "center", what), path + ".center");
      const Vec3d u = direction(need(j, path, "u", what), path + ".u");
      const Vec3d v = direction(need(j, path, "v", what), path + ".v");
      L.vertices = {c - u - v, c + u - v, c + u + v, c - u + v};
      for (int i = 0; i < 4; ++i)
        if (!is_finite(L.vertices[i])) bad(path, "a corner center +- u +- v is beyond double's range");
      const Vec3d uu = normalized_or(u, Vec3d{0, 0, 0}), vv = normalized_or(v, Vec3d{0, 0, 0});
      if (!(length(cross(uu, vv)) > 1e-12)) bad(path + ".v", "is parallel to u: the rect has no area");
      return;
    }
    const std::string p = path + ".vertices";
    const json& vs = need(j, path, "vertices", what);
    if (!vs.is_array() || vs.size() < 3 || vs.size() > std::size_t(kMaxAreaVertices))
      bad(p, "must be an array of 3 to " + std::to_string(kMaxAreaVertices) + " points, got " + describe(vs));
    for (std::size_t i = 0; i < vs.size(); ++i) L.vertices.push_back(vec3(vs[i], p + "[" + std::to_string(i) + "]"));
    polygon_shape(L.vertices, p);
  }

  // A polygon light must be planar, convex and non-degenerate (its closed forms assume it).
  void polygon_shape(const std::vector<Vec3d>& v, const std::string& p) const {
    const std::size_t k = v.size();
    double size = 0;  // largest distance from v[0]: the scale for the tolerances below
    for (const Vec3d& x : v) size = std::fmax(size, length(x - v[0]));
    if (!(size > 0) || !std::isfinite(size)) bad(p, "degenerate polygon: every vertex is the same point");
    Vec3d normal{0, 0, 0};  // Newell, relative to v[0], on coordinates scaled by 1/size
    const double inv = 1.0 / size;  // size > 0 checked
    for (std::size_t i = 1; i + 1 < k; ++i) normal += cross((v[i] - v[0]) * inv, (v[i + 1] - v[0]) * inv);
    const double area2 = length(normal);
    if (!(area2 > 1e-12)) bad(p, "degenerate polygon: its vertices are collinear (zero area)");
    const Vec3d n = normal * (1.0 / area2);
    for (std::size_t i = 0; i < k; ++i) {
      const double off = std::fabs(dot(v[i] - v[0], n)) * inv;
      if (off > 1e-9)
        bad(p + "[" + std::to_string(i) + "]", "not planar: " + number_text(off) +
                                                   " of the polygon's size off the plane of the others");
    }
    double turning = 0;  // sum of exterior angles: 2 pi for a convex simple polygon
    for (std::size_t i = 0; i < k; ++i) {
      const Vec3d a = v[(i + 1) % k] - v[i], b = v[(i + 2) % k] - v[(i + 1) % k];
      if (!(length(a) > 0)) bad(p + "[" + std::to_string((i + 1) % k) + "]", "repeats the previous vertex");
      const double turn = dot(cross(a * inv, b * inv), n);
      if (turn < -1e-12 * length(a * inv) * length(b * inv))
        bad(p + "[" + std::to_string((i + 1) % k) + "]", "not convex: the polygon turns the other way here");
      turning += std::atan2(turn, dot(a * inv, b * inv));
    }
    if (std::fabs(turning - 2 * kPi) > 1e-6) bad(p, "not convex: the polygon winds around more than once");
  }

  void sky_light(const json& j, const std::string& path, Light& L) const {
    double intensity = 1;
    if (const json* v = find(j, "intensity")) intensity = non_negative(*v, path + ".intensity");
    Vec3d sky{1, 1, 1}, ground{0, 0, 0};
    if (const json* v = find(j, "sky")) sky = colour(*v, path + ".sky");
    if (const json* v = find(j, "ground")) ground = colour(*v, path + ".ground");
    if (const json* v = find(j, "up")) L.up = direction(*v, path + ".up");
    L.ambient = {0, 0, 0};
    if (const json* v = find(j, "ambient")) L.ambient = colour(*v, path + ".ambient");
    const std::string at = path + (find(j, "intensity") ? ".intensity" : ".sky");
    L.diffuse = L.specular = scaled_colour(sky, intensity, at);
    L.ground = scaled_colour(ground, intensity, path + (find(j, "intensity") ? ".intensity" : ".ground"));
  }

  // An equirectangular Radiance .hdr (lighting/environment_map.h), path relative to the scene
  // file, rotated by "rotation": [degrees, ax, ay, az] (axis non-zero). The image is read here, so
  // that an unreadable one fails with the scene's other errors, before any mesh is read.
  void environment_light(const json& j, const std::string& path, Light& L) const {
    double intensity = 1;
    if (const json* v = find(j, "intensity")) intensity = non_negative(*v, path + ".intensity");
    L.ambient = {0, 0, 0};
    if (const json* v = find(j, "ambient")) L.ambient = colour(*v, path + ".ambient");
    L.diffuse = L.specular = {intensity, intensity, intensity};
    if (const json* v = find(j, "rotation")) {
      const std::string p = path + ".rotation";
      if (!v->is_array() || v->size() != 4)
        bad(p, "must be [degrees, ax, ay, az] (an angle and a non-zero axis), got " + describe(*v));
      const double degrees = number((*v)[0], p + "[0]");
      const Vec3d axis{number((*v)[1], p + "[1]"), number((*v)[2], p + "[2]"), number((*v)[3], p + "[3]")};
      if (!(length(axis) > 0)) bad(p, "the axis [ax, ay, az] is zero");
      L.world_from_map = environment_rotation(degrees, axis);
    }
    const std::string p = path + ".image";
    const std::string name = string(need(j, path, "image", "an environment light"), p);
    if (name.empty()) bad(p, "is empty (expected a .hdr file, relative to the scene file)");
    const std::filesystem::path image = std::filesystem::path(base_dir_) / name;  // absolute names stay absolute
    std::error_code ec;
    if (std::filesystem::is_directory(image, ec)) bad(p, "'" + image.string() + "' is a directory");
    try {
      L.environment = read_environment_map(image.string());
    } catch (const Error& e) {
      bad(p, "'" + image.string() + "': " + e.what());
    }
  }

  void spot_light(const json& j, const std::string& path, Light& L) const {
    const std::string what = "a spot light";
    light_colours(j, path, L);
    L.direction = direction(need(j, path, "direction", what), path + ".direction");
    L.position = vec3(need(j, path, "position", what), path + ".position");
    attenuation(j, path, L);
    const std::string p = path + ".cutoff";
    L.cutoff_degrees = number(need(j, path, "cutoff", what), p);
    if (!((L.cutoff_degrees >= 0 && L.cutoff_degrees <= 90) || L.cutoff_degrees == 180))
      bad(p, "must be in [0, 90] degrees or 180 (no cone), got " + number_text(L.cutoff_degrees));
    if (const json* v = find(j, "exponent")) L.exponent = non_negative(*v, path + ".exponent");
  }

  Scene scene(const json& root) const {
    const std::string path = "$";
    require_object(root, path);
    check_keys(root, path, {"model", "world_from_object", "camera", "view", "ambient", "two_sided", "material", "lights"},
               "a scene");
    Scene s;
    if (const json* v = find(root, "model")) {
      s.model = model(*v, "$.model");
      s.model_given = true;
    }
    if (const json* v = find(root, "world_from_object")) s.world_from_object = affine(*v, "$.world_from_object");
    if (find(root, "camera") && find(root, "view")) bad(path, "give either \"camera\" or \"view\", not both");
    if (const json* v = find(root, "camera")) camera(*v, "$.camera", s);
    if (const json* v = find(root, "view")) {
      s.camera_from_world = affine(*v, "$.view");
      s.has_camera = true;
    }
    if (const json* v = find(root, "ambient")) s.global_ambient = colour(*v, "$.ambient");
    if (const json* v = find(root, "two_sided")) s.two_sided = boolean(*v, "$.two_sided");
    if (const json* v = find(root, "material")) s.material = material(*v, "$.material");
    if (const json* v = find(root, "lights")) {
      if (!v->is_array()) bad("$.lights", "must be an array of lights, got " + describe(*v));
      for (std::size_t i = 0; i < v->size(); ++i) s.lights.push_back(light((*v)[i], "$.lights[" + std::to_string(i) + "]"));
    }
    return s;
  }

 private:
  std::string file_;
  std::string base_dir_;
};

// Tracks the JSON path while nlohmann parses, to report duplicate keys (which nlohmann would
// otherwise resolve silently to the last value).
class DuplicateKeyFinder {
 public:
  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        step_into_element();
        frames_.push_back({event == json::parse_event_t::array_start, 0, {}, {}});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!frames_.empty()) frames_.pop_back();
        break;
      case json::parse_event_t::key:
        if (!frames_.empty()) {
          Frame& top = frames_.back();
          top.key = parsed.get<std::string>();
          if (!top.keys.insert(top.key).second && first_duplicate.empty())
            first_duplicate = path_to_top() + ": duplicate key \"" + top.key + "\"";
        }
        break;
      case json::parse_event_t::value:
        step_into_element();
        break;
    }
    return true;
  }
  std::string first_duplicate;

 private:
  struct Frame {
    bool is_array;
    std::size_t count;  // elements seen so far (arrays)
    std::string key;    // current key (objects)
    std::set<std::string> keys;
  };
  void step_into_element() {
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().count;
  }
  std::string path_to_top() const {
    std::string p = "$";
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
      p += frames_[i].is_array ? "[" + std::to_string(frames_[i].count - 1) + "]" : key_step(frames_[i].key);
    return p;
  }
  std::vector<Frame> frames_;
};

// "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error ..." ->
// `NAME:3: invalid JSON at column 7: syntax error ...`.
[[noreturn]] void fail_json(const std::string& name, const json::exception& e) {
  const std::string what = e.what();
  const std::size_t bracket = what.find("] ");
  std::string message = bracket == std::string::npos ? what : what.substr(bracket + 2);
  const std::size_t at = message.find("at line ");
  const std::size_t column = message.find(", column ");
  const std::size_t colon = column == std::string::npos ? std::string::npos : message.find(": ", column);
  if (at != std::string::npos && colon != std::string::npos) {
    const std::size_t line = std::stoul(message.substr(at + 8, column - at - 8));
    const std::string col = message.substr(column + 9, colon - column - 9);
    fail(name, line, "invalid JSON at column " + col + ": " + message.substr(colon + 2));
  }
  fail(name, 0, "invalid JSON: " + message);
}

}  // namespace

Scene parse_scene(std::string_view json_text, const std::string& name) {
  json root;
  DuplicateKeyFinder duplicates;
  try {
    root = json::parse(json_text.begin(), json_text.end(),
                       [&duplicates](int depth, json::parse_event_t event, json& parsed) {
                         return duplicates(depth, event, parsed);
                       });
  } catch (const json::exception& e) {
    fail_json(name, e);
  }
  if (!duplicates.first_duplicate.empty()) fail(name, 0, duplicates.first_duplicate);
  const Scene scene = SceneReader(name, std::filesystem::path(name).parent_path().string()).scene(root);
  validate_scene(scene, name);  // the reader checked each field on the way; this is every door's check
  return scene;
}

Scene read_scene(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, 0, "cannot read scene file: is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, 0, std::string("cannot read scene file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(path, 0, "cannot read scene file: read error");
  return parse_scene(text.str(), path);
}

}  // namespace shadetool
