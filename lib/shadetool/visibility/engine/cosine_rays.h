// cosine_rays.h: the hits among the rays of points' scrambled Sobol sequences, cosine-distributed
// about their unit axes (sample_sequence.h; directions by engine/cosine_directions.h, the same
// bits), traced by Embree's stream call rtcOccluded1M (machinery shared by ambient_occlusion.cpp
// and occlusion_to_error.cpp).
//
// count_cosine_hits: rays first .. first + count - 1 of one point, traced 64 at a time (a batch of
//   occlusion_to_error continues the sequence where the last one stopped, so k batches of n rays
//   are the same rays as one of k n).
// CosineRayBatch: rays 0 .. N - 1 of consecutive points queued into one stream of up to
//   kBatchRays rays, traced when it is full and at finish(), each point's hit count handed back
//   in the order the points were added (a point larger than the stream spans several). The same
//   rays and answers as count_cosine_hits point by point (each ray's answer is its own), at a
//   lower cost: Embree's per-call cost (about 1.4 us) is paid per 2048 rays, not per 64
//   (bench/visibility/results.md, "Occlusion loop"). 2048 rays = kRaysPerTask, about one TBB
//   task's rays: a 98 KB buffer per thread, under glibc's mmap threshold (on the 1M knot the
//   command's peak RSS was 100-400 KiB above main's with it, 300-550 KiB with 4096).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <shadetool/core/vec3.h>
#include <shadetool/visibility/engine/cosine_directions.h>
#include <shadetool/visibility/engine/embree_scene.h>
#include <shadetool/visibility/ray_offset.h>
#include <shadetool/visibility/sample_sequence.h>

namespace shadetool::visibility_engine {

inline std::uint32_t count_cosine_hits(RTCScene scene, const Vec3f& p_local, const Vec3d& n, std::uint32_t seed,
                                       std::uint32_t first, std::uint32_t count, float tfar_local) {
  CosineFrame frame;
  frame.seed = seed;
  frame.n = n;
  visibility::orthonormal_basis(n, frame.t, frame.b);
  const Vec3f origin = visibility::offset_ray_origin(p_local, Vec3f(n));
  constexpr std::uint32_t kStream = kDirectionBlock;  // rays made, then traced together
  RTCRay rays[kStream];
  float dx[kStream], dy[kStream], dz[kStream];
  std::uint32_t hits = 0;
  const std::uint32_t end = first + count;
  for (std::uint32_t begin = first; begin < end; begin += kStream) {
    const std::uint32_t k = std::min(kStream, end - begin);
    cosine_directions(frame, begin, k, dx, dy, dz);
    for (std::uint32_t j = 0; j < k; ++j) rays[j] = make_ray(origin, Vec3f(dx[j], dy[j], dz[j]), tfar_local);
    hits += count_occluded(scene, rays, k);
  }
  return hits;
}

constexpr std::uint32_t kBatchRays = 2048;

class CosineRayBatch {
 public:
  // capacity_rays: the stream's size, at most kBatchRays (a caller with fewer rays in all asks for
  // fewer); at least 1.
  CosineRayBatch(RTCScene scene, float tfar_local, std::size_t capacity_rays)
      : scene_(scene), tfar_(tfar_local),
        capacity_(std::uint32_t(std::max<std::size_t>(1, std::min<std::size_t>(kBatchRays, capacity_rays)))),
        rays_(new RTCRay[capacity_]) {}

  // Point `slot`'s rays 0 .. samples - 1 about unit axis n from p_local (scene frame; offset by
  // ray_offset.h). n is the same in the world and scene frames: the scale is uniform and positive.
  // done(slot, hits) is called for every point whose rays a full stream completes.
  template <class Done>
  void add(std::size_t slot, const Vec3f& p_local, const Vec3d& n, std::uint32_t seed, std::uint32_t samples,
           const Done& done) {
    CosineFrame frame;
    frame.seed = seed;
    frame.n = n;
    visibility::orthonormal_basis(n, frame.t, frame.b);
    const Vec3f origin = visibility::offset_ray_origin(p_local, Vec3f(n));
    float dx[kDirectionBlock], dy[kDirectionBlock], dz[kDirectionBlock];
    for (std::uint32_t begin = 0; begin < samples;) {
      if (used_ == capacity_) trace(done);
      const std::uint32_t k = std::min({kDirectionBlock, samples - begin, capacity_ - used_});
      cosine_directions(frame, begin, k, dx, dy, dz);
      for (std::uint32_t j = 0; j < k; ++j) rays_[used_ + j] = make_ray(origin, Vec3f(dx[j], dy[j], dz[j]), tfar_);
      used_ += k;
      begin += k;
    }
    queued_.push_back({slot, used_});
  }

  // Traces what is queued: every added point's done() has been called when it returns.
  template <class Done>
  void finish(const Done& done) {
    if (used_ > 0 || !queued_.empty()) trace(done);
  }

 private:
  struct Queued {
    std::size_t slot;
    std::uint32_t end;  // the point's last ray in the stream, + 1
  };

  std::uint32_t blocked(std::uint32_t b, std::uint32_t e) const {
    std::uint32_t hits = 0;
    for (std::uint32_t i = b; i < e; ++i) hits += rays_[i].tfar < 0.0f ? 1u : 0u;  // Embree: tfar = -inf on a hit
    return hits;
  }

  template <class Done>
  void trace(const Done& done) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1M(scene_, &context, rays_.get(), used_, sizeof(RTCRay));
    std::uint32_t b = 0;
    for (const Queued& q : queued_) {
      done(q.slot, carry_ + blocked(b, q.end));  // carry_: the first point's hits from earlier streams
      carry_ = 0;
      b = q.end;
    }
    carry_ += blocked(b, used_);  // the point being added when the stream filled
    queued_.clear();
    used_ = 0;
  }

  RTCScene scene_;
  float tfar_;
  std::uint32_t capacity_, used_ = 0, carry_ = 0;
  std::unique_ptr<RTCRay[]> rays_;
  std::vector<Queued> queued_;
};

}  // namespace shadetool::visibility_engine
