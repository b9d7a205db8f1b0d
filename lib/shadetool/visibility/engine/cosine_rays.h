// cosine_rays.h: the hits among rays first .. first + count - 1 of one point's scrambled Sobol
// sequence, cosine-distributed about its unit axis (sample_sequence.h), traced 64 at a time
// (machinery shared by ambient_occlusion.cpp, from ray 0, and occlusion_to_error.cpp, batch by
// batch: a batch continues the sequence where the last one stopped, so k batches of n rays are
// the same rays as one of k n).
#pragma once

#include <algorithm>
#include <cstdint>

#include <shadetool/core/vec3.h>
#include <shadetool/visibility/engine/embree_scene.h>
#include <shadetool/visibility/ray_offset.h>
#include <shadetool/visibility/sample_sequence.h>

namespace shadetool::visibility_engine {

inline std::uint32_t count_cosine_hits(RTCScene scene, const Vec3f& p_local, const Vec3d& n, std::uint32_t seed,
                                       std::uint32_t first, std::uint32_t count, float tfar_local) {
  Vec3d t, b;
  visibility::orthonormal_basis(n, t, b);
  const Vec3f origin = visibility::offset_ray_origin(p_local, Vec3f(n));
  constexpr std::uint32_t kStream = 64;  // rays made, then traced together
  RTCRay rays[kStream];
  std::uint32_t hits = 0;
  const std::uint32_t end = first + count;
  for (std::uint32_t begin = first; begin < end; begin += kStream) {
    const std::uint32_t k = std::min(kStream, end - begin);
    for (std::uint32_t j = 0; j < k; ++j) {
      const visibility::UnitSquarePoint s = visibility::scrambled_sobol_2d(begin + j, seed);
      const Vec3d w = visibility::cosine_hemisphere(s.u, s.v);
      rays[j] = make_ray(origin, Vec3f(t * w.x + b * w.y + n * w.z), tfar_local);
    }
    hits += count_occluded(scene, rays, k);
  }
  return hits;
}

}  // namespace shadetool::visibility_engine
