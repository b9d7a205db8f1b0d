// embree_scene.h: the Embree objects behind a VisibilityScene, and the one ray query every
// visibility estimate is built from (machinery; not installed for users, no Embree in the public
// headers).
//
// make_ray(origin, direction, tfar): an RTCRay for the segment origin + t * direction, 0 <= t <= tfar.
// occluded(origin, direction, tfar): true when the segment origin + t * direction, 0 < t <= tfar,
// meets a triangle of the scene (rtcOccluded1; Embree reports a hit by setting tfar to -inf).
// The ray mask is all ones: Debian builds Embree with ray masks, and a ray with mask 0 (a
// zero-initialised RTCRay) hits nothing, silently.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <embree3/rtcore.h>

#include <shadetool/core/vec3.h>
#include <shadetool/visibility/visibility_scene.h>

namespace shadetool {

struct VisibilityScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<float> vertices;             // 3 per vertex + 1 padding float (Embree reads 16 bytes)
  std::vector<std::uint32_t> triangles;    // 3 per triangle
  std::int64_t allocated_bytes = 0;        // running total from the memory monitor
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace visibility_engine {

inline RTCRay make_ray(const Vec3f& origin, const Vec3f& direction, float tfar) {
  RTCRay ray;
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.tnear = 0.0f;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.time = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

inline bool occluded(RTCScene scene, const Vec3f& origin, const Vec3f& direction, float tfar) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, tfar);
  rtcOccluded1(scene, &context, &ray);
  return ray.tfar < 0.0f;
}

// The rays of one point traced as a stream (rtcOccluded1M: Embree groups them into packets where
// its ISA allows); returns how many were blocked. The answers are rtcOccluded1's for each ray
// alone: bench/visibility checks that both count the same hits (4000 vertices x N = 4..1024 rays).
inline std::uint32_t count_occluded(RTCScene scene, RTCRay* rays, unsigned count) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1M(scene, &context, rays, count, sizeof(RTCRay));
  std::uint32_t hits = 0;
  for (unsigned i = 0; i < count; ++i) hits += rays[i].tfar < 0.0f ? 1u : 0u;
  return hits;
}

}  // namespace visibility_engine
}  // namespace shadetool
