// visibility_scene.cpp
#include <shadetool/visibility/visibility_scene.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include <shadetool/core/error.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/polygon_triangles.h>
#include <shadetool/visibility/engine/embree_scene.h>

namespace shadetool {

namespace {

bool count_bytes(void* user, ssize_t bytes, bool /*post*/) {
  // Called from Embree's build threads: the total is only read after rtcCommitScene returns.
  __atomic_add_fetch(&static_cast<VisibilityScene::Impl*>(user)->allocated_bytes, std::int64_t(bytes),
                     __ATOMIC_RELAXED);
  return true;
}

void check_device(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE)
    throw Error(std::string("visibility: Embree failed to ") + what + " (error " + std::to_string(int(e)) + ")");
}

}  // namespace

VisibilityScene::VisibilityScene(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  const auto start = std::chrono::steady_clock::now();
  // 1. Which faces take part (geometry/degenerate_face.h, the library's one rule), and their box.
  std::vector<std::uint32_t> kept;
  kept.reserve(mesh.num_faces());
  std::vector<std::uint32_t> scratch;
  Vec3d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3d hi = -lo;
  std::size_t corners = 0;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    switch (face_degenerate_kind(mesh, f, scratch)) {
      case DegenerateKind::None: break;
      case DegenerateKind::TooFewCorners:
      case DegenerateKind::RepeatedIndex:
      case DegenerateKind::ZeroArea: ++stats_.degenerate_faces; continue;
      case DegenerateKind::NonFinite: ++stats_.nonfinite_faces; continue;
    }
    kept.push_back(std::uint32_t(f));
    corners += mesh.face_size(f);
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      const Vec3d p = mesh.position(mesh.corner_vertex[c]);
      lo = {std::fmin(lo.x, p.x), std::fmin(lo.y, p.y), std::fmin(lo.z, p.z)};
      hi = {std::fmax(hi.x, p.x), std::fmax(hi.y, p.y), std::fmax(hi.z, p.z)};
    }
  }
  stats_.faces_used = kept.size();

  // 2. The frame: centre of the box, scale 2^-e with 2^e >= the half extent (exact).
  if (!kept.empty()) {
    centre_ = {lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2};  // halves first: no overflow
    const double half = std::fmax(hi.x / 2 - lo.x / 2, std::fmax(hi.y / 2 - lo.y / 2, hi.z / 2 - lo.z / 2));
    if (half > 0) {
      int e = 0;
      std::frexp(half, &e);  // half = m 2^e, 0.5 <= m < 1
      scale_ = std::ldexp(1.0, -e);
    }
  }

  // 3. Buffers: float vertices, every vertex (so vertex ids index them directly); the kept faces'
  // triangles.
  Impl& s = *impl_;
  const std::size_t nv = mesh.num_vertices();
  s.vertices.assign(3 * nv + 1, 0.0f);
  for (std::size_t v = 0; v < nv; ++v) {
    // Kept faces' corners lie in the box (|local| <= 1); others (non-finite, or isolated far
    // away) are used by no triangle and stay 0.
    const Vec3f l((mesh.position(v) - centre_) * scale_);
    if (!is_finite(l)) continue;
    s.vertices[3 * v] = l.x;
    s.vertices[3 * v + 1] = l.y;
    s.vertices[3 * v + 2] = l.z;
  }
  // Index buffer: when every face is a kept triangle, the mesh's corner array already is Embree's
  // UINT3 layout and is shared (no copy: 12 B per triangle saved); otherwise (a degenerate face
  // to leave out, a polygon to split) a filtered, split copy owned here.
  const bool all_triangles = kept.size() == mesh.num_faces() && corners == 3 * kept.size();
  const std::uint32_t* indices = mesh.corner_vertex.data();
  stats_.triangles = kept.size();
  stats_.shared_indices = all_triangles;
  if (!all_triangles) {
    s.triangles.reserve(3 * (corners - 2 * kept.size()));
    std::vector<std::uint32_t> split;  // one face's triangles as corner positions, reused
    for (const std::uint32_t f : kept) {
      const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
      // Triangles and convex quads: the fan from corner 0 (a quad on its 0-2 diagonal, as render
      // rasterises it); a concave quad (geometry/polygon_triangles.h quad_is_concave) and 5+
      // corners: polygon_triangles, inside the outline, as render draws it and the glTF/STL
      // writers write it (a concave quad through its reflex corner; a convex polygon: the fan).
      split.clear();
      if (e - b <= 3 || (e - b == 4 && !quad_is_concave(mesh.positions.data(), mesh.corner_vertex.data() + b))) {
        for (std::uint32_t c = 1; c + 1 < e - b; ++c) split.insert(split.end(), {0u, c, c + 1});
      } else {
        polygon_triangles(mesh.positions.data(), mesh.corner_vertex.data() + b, e - b, split);
      }
      for (const std::uint32_t k : split) s.triangles.push_back(mesh.corner_vertex[b + k]);
    }
    indices = s.triangles.data();
    stats_.triangles = s.triangles.size() / 3;
  }
  stats_.buffer_bytes = s.vertices.size() * sizeof(float) + s.triangles.size() * sizeof(std::uint32_t);
  // The kept faces' list (4 B per face) is done with: freed before Embree's build, whose end is
  // the command's peak memory (bench/visibility/results.md).
  std::vector<std::uint32_t>().swap(kept);

  // 4. Embree: one device per scene (its memory monitor then counts this scene alone).
  s.device = rtcNewDevice(nullptr);
  if (!s.device) throw Error("visibility: Embree could not create a device");
  rtcSetDeviceMemoryMonitorFunction(s.device, count_bytes, &s);
  s.scene = rtcNewScene(s.device);
  rtcSetSceneFlags(s.scene, RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT));  // no shortcuts that lose accuracy (watertight)
  if (stats_.triangles > 0) {
    RTCGeometry g = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, s.vertices.data(), 0,
                               3 * sizeof(float), nv);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices, 0,
                               3 * sizeof(std::uint32_t), stats_.triangles);
    rtcCommitGeometry(g);
    rtcAttachGeometry(s.scene, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(s.scene);
  check_device(s.device, "build the BVH");
  stats_.bvh_bytes = std::size_t(std::max<std::int64_t>(0, __atomic_load_n(&s.allocated_bytes, __ATOMIC_RELAXED)));
  stats_.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

VisibilityScene::~VisibilityScene() = default;
VisibilityScene::VisibilityScene(VisibilityScene&&) noexcept = default;
VisibilityScene& VisibilityScene::operator=(VisibilityScene&&) noexcept = default;

Vec3f VisibilityScene::to_local(const Vec3d& world) const {
  const Vec3d l = (world - centre_) * scale_;
  const Vec3f f(l);
  if (!is_finite(f))
    throw Error("visibility: a point lies beyond float range of the mesh's frame (coordinates too far apart)");
  return f;
}

}  // namespace shadetool
