// transform_mesh.cpp: see transform_mesh.h.
#include <shadetool/transform/transform_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include <shadetool/core/vocabulary.h>
#include <shadetool/core/engine/parallel.h>
#include <shadetool/geometry/scaled_length.h>
#include <shadetool/normals/tangent_vertices.h>
#include <shadetool/transform/recompute_normals.h>
#include <shadetool/transform/reverse_winding.h>
#include <shadetool/transform/transform_normals.h>

namespace shadetool {

namespace {
const NamedValue<NormalsPolicy> kNormalsPolicies[] = {
    {NormalsPolicy::Transform, "transform"},
    {NormalsPolicy::Recompute, "recompute"},
    {NormalsPolicy::Drop, "drop"},
};
}  // namespace

NormalsPolicy parse_normals_policy(std::string_view text, const std::string& what) {
  return parse_named(kNormalsPolicies, text, what);
}
const char* normals_policy_name(NormalsPolicy policy) { return name_of(kNormalsPolicies, policy); }
std::vector<std::string> normals_policy_names() { return names_of(kNormalsPolicies); }

namespace {

// Returns how many coordinates came out non-finite: a finite map can send finite positions
// beyond double's range (1e30 scaled by 1e300). Counted per range right after it is written
// (still in cache), not in another pass over the array.
std::size_t transform_positions(Mesh& mesh, const Affine3d& M, bool translate_only) {
  double* data = mesh.positions.data();
  const Affine3d map = M;  // by value: the loop reads locals, not through a reference
  return engine::count_over_ranges(mesh.num_vertices(), [&](std::size_t begin, std::size_t end) {
    double* p = data + 3 * begin;
    if (translate_only) {
      for (std::size_t v = begin; v < end; ++v, p += 3) {
        p[0] += map.t.x;
        p[1] += map.t.y;
        p[2] += map.t.z;
      }
    } else {
      const auto& A = map.A.m;
      for (std::size_t v = begin; v < end; ++v, p += 3) {
        const double x = p[0], y = p[1], z = p[2];
        p[0] = A[0][0] * x + A[0][1] * y + A[0][2] * z + map.t.x;
        p[1] = A[1][0] * x + A[1][1] * y + A[1][2] * z + map.t.y;
        p[2] = A[2][0] * x + A[2][1] * y + A[2][2] * z + map.t.z;
      }
    }
    std::size_t overflowed = 0;
    for (const double* q = data + 3 * begin; q < data + 3 * end; ++q) overflowed += !std::isfinite(*q);
    return overflowed;
  });
}

bool has_any_normals(const Mesh& mesh) {
  return mesh.has_vertex_normals() || mesh.has_corner_normals() || mesh.has_face_normals();
}

}  // namespace

std::string singular_map_message(const AffineClass& c) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "det A = %.3g, |det A| / (|A|_F / sqrt 3)^3 = %.3g < %g", c.det, c.relative_det,
                kSingularTolerance);
  return std::string("the transform is singular or nearly so (") + buf +
         "): normals have no reliable transform; drop or recompute them (--normals drop | --normals recompute)";
}

namespace {

// Vertex properties tx ty tz tw (transform_mesh.h): mapped by A with w flipped under a mirror, or
// removed when they no longer belong to the normals.
void transform_tangent_properties(Mesh& mesh, const Affine3d& M, const AffineClass& c, NormalsPolicy policy,
                                  TransformReport& report) {
  const std::array<MeshProperty*, 4> t4 = tangent_properties(mesh);  // tx ty tz tw, null where absent
  if (!t4[0] || !t4[1] || !t4[2]) return;
  if (c.path == TransformPath::Identity || c.path == TransformPath::Translation) {
    report.tangents = "untouched";
    return;
  }
  if (c.path == TransformPath::Singular || policy != NormalsPolicy::Transform) {
    remove_tangent_properties(mesh);
    report.tangents = "dropped";
    return;
  }
  std::vector<double>& tx = t4[0]->values;
  std::vector<double>& ty = t4[1]->values;
  std::vector<double>& tz = t4[2]->values;
  const std::size_t n = std::min({tx.size(), ty.size(), tz.size()});
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3d t{tx[v], ty[v], tz[v]};
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) || (t.x == 0 && t.y == 0 && t.z == 0)) continue;
    const Vec3d a = M.A * t;
    double o[3];
    if (!normalise_checked(a.x, a.y, a.z, o)) continue;  // geometry/scaled_length.h: A t = 0 or not finite
    tx[v] = o[0];
    ty[v] = o[1];
    tz[v] = o[2];
    ++report.tangents_mapped;
  }
  if (t4[3] && c.mirror)
    for (double& w : t4[3]->values) w = -w;
  report.tangents = "mapped";
}

}  // namespace

TransformReport transform_mesh(Mesh& mesh, const Affine3d& M, const TransformOptions& options, const std::string& name) {
  TransformReport report;
  report.affine = classify_affine(M);
  const AffineClass& c = report.affine;
  require_finite_positions(mesh, name);
  const bool had_normals = has_any_normals(mesh);
  if (c.path == TransformPath::Singular && options.normals == NormalsPolicy::Transform)
    fail(name, 0, singular_map_message(c));

  if (c.path != TransformPath::Identity) {
    // Refuse rather than return Inf (the mesh is then partly transformed; the CLI discards it).
    const std::size_t overflowed = transform_positions(mesh, M, c.path == TransformPath::Translation);
    if (overflowed > 0)
      fail(name, 0, "the transform sends " + std::to_string(overflowed) + (overflowed == 1 ? " coordinate" : " coordinates") +
                        " beyond the range of double (about 1.8e308)");
  }

  switch (options.normals) {
    case NormalsPolicy::Drop:
      mesh.vertex_normals.clear();
      mesh.corner_normals.clear();
      mesh.corner_normal_index.clear();
      mesh.face_normals.clear();
      report.normals = had_normals ? "dropped" : "none";
      break;
    case NormalsPolicy::Transform: {
      if (!had_normals) break;
      const NormalMap nm = normal_map(M, c);
      if (nm.untouched) {
        report.normals = "untouched";
        break;
      }
      for (auto* a : {&mesh.vertex_normals, &mesh.corner_normals, &mesh.face_normals}) {
        report.normals_left += transform_normals(*a, nm);
        report.normals_mapped += a->size() / 3;
      }
      report.normals_mapped -= report.normals_left;
      report.normals = "transformed";
      break;
    }
    case NormalsPolicy::Recompute:
      break;  // after the winding
  }

  if (c.mirror) {
    reverse_winding(mesh);
    report.winding_reversed = mesh.num_faces() > 0;  // a point cloud has nothing to re-wind
  }

  if (options.normals == NormalsPolicy::Recompute && had_normals) {
    report.fallback_normals = recompute_normals(mesh);
    report.normals = "recomputed";
  }
  transform_tangent_properties(mesh, M, c, options.normals, report);
  return report;
}

}  // namespace shadetool
