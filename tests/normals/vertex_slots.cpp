// Tests of normals/engine/vertex_slots.h: the ring tests of the one-thread corner-normal path
// (one_smooth_ring, and smooth_rings8, its 8-lane AVX2 form) against a plain statement of what a
// ring is, written here: the corners' (next, prev) pairs form one closed ring when the map
// "corner i -> the corner j whose prev is i's next" is a permutation of the d corners with a
// single cycle and no corner leaves to the vertex itself. The corner-normal tests check the path's
// output on meshes; these check the verdicts themselves on slots no mesh of the tests produces
// (duplicate ids, pinches of two rings, rings through the vertex itself, ids near 2^32, junk beyond d, d at and past
// kSlotPairs), and the 8-lane form on every lane position.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include <shadetool/normals/engine/vertex_slots.h>

using shadetool::normals_detail::kSlotPairs;
using shadetool::normals_detail::one_smooth_ring;
using Slot = shadetool::normals_detail::VertexSlot<double>;

namespace {

// The truth: sigma(i) = the unique j with prev[j] == next[i]; one ring when sigma is defined for
// every i (exactly one such j), is a permutation, has one cycle through all d corners, and no
// next is v itself.
bool ring_by_definition(std::uint32_t v, const Slot& s) {
  const std::uint32_t d = s.d;
  if (d < 1 || d > kSlotPairs) return false;
  std::vector<int> sigma(d, -1);
  for (std::uint32_t i = 0; i < d; ++i) {
    if (s.next[i] == v) return false;
    int found = 0;
    for (std::uint32_t j = 0; j < d; ++j)
      if (s.prev[j] == s.next[i]) {
        sigma[i] = int(j);
        ++found;
      }
    if (found != 1) return false;
  }
  std::vector<bool> seen(d, false);
  std::uint32_t k = 0, steps = 0;
  do {
    if (seen[k]) return false;
    seen[k] = true;
    k = std::uint32_t(sigma[k]);
    ++steps;
  } while (k != 0 && steps <= d);
  return k == 0 && steps == d;
}

// A slot for vertex v with d corners: one ring of distinct far ids in a random cyclic order, the
// corners stored in a random order, then (by `kind`) broken or split; lanes past d hold junk.
Slot make_slot(std::uint32_t v, std::uint32_t d, int kind, std::mt19937& rng) {
  Slot s{};
  s.d = d;
  std::uniform_int_distribution<std::uint32_t> junk;
  for (std::uint32_t i = 0; i < kSlotPairs; ++i) {
    s.next[i] = junk(rng);
    s.prev[i] = junk(rng);
  }
  const std::uint32_t n = std::min(d, kSlotPairs);
  std::vector<std::uint32_t> far;
  while (far.size() < n) {  // distinct far ids near v (wrapping past 2^32), never v
    const std::uint32_t w = v + std::uint32_t(std::uniform_int_distribution<int>(-40, 40)(rng));
    if (w != v && std::find(far.begin(), far.end(), w) == far.end()) far.push_back(w);
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), rng);
  // Ring: triangle k = (v, far[k], far[k + 1]): next far[k], prev far[k + 1]. A pinch (kind 1):
  // two rings of the first m and the other n - m far ids.
  const std::uint32_t m = (kind == 1 && n >= 4) ? 2 + rng() % (n - 3) : n;
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t lo = k < m ? 0 : m, len = k < m ? m : n - m;
    s.next[order[k]] = far[k];
    s.prev[order[k]] = far[lo + (k - lo + 1) % len];
  }
  if (n == 0) return s;
  const std::uint32_t c = rng() % n, c2 = rng() % n;
  switch (kind) {
    case 2: s.prev[c] = s.prev[c2]; break;         // a far vertex arrived from twice (or nothing changes)
    case 3: s.next[c] = s.next[c2]; break;         // left to twice
    case 4: s.next[c] = v; break;                  // a corner leaving to the vertex itself
    case 5: s.prev[c] = v + 1000; break;           // an open fan (a boundary)
    case 6: std::swap(s.next[c], s.prev[c]); break;  // a flipped face
    case 7: {  // a far vertex that is the vertex itself: a closed ring through v (both ends of it)
      const std::uint32_t x = s.next[c];
      for (std::uint32_t i = 0; i < n; ++i) {
        if (s.next[i] == x) s.next[i] = v;
        if (s.prev[i] == x) s.prev[i] = v;
      }
      break;
    }
    default: break;                                // 0: a ring; 1: a pinch
  }
  return s;
}

}  // namespace

TEST_CASE("one_smooth_ring: the verdict of the definition on rings, pinches, duplicates, boundaries and flips", "[normals][vertex_slots]") {
  std::mt19937 rng(31);
  std::size_t rings = 0, not_rings = 0;
  for (int t = 0; t < 200000; ++t) {
    const std::uint32_t v = (t % 3 == 0) ? std::uint32_t(-1) - std::uint32_t(rng() % 64) : std::uint32_t(rng());
    const std::uint32_t d = 1 + rng() % kSlotPairs;
    std::vector<Slot> pair(2);  // one_smooth_ring reads one lane past prev: the next slot's, masked
    pair[0] = make_slot(v, d, int(rng() % 8), rng);
    const Slot& s = pair[0];
    const bool truth = ring_by_definition(v, s);
    (truth ? rings : not_rings) += 1;
    if (one_smooth_ring(v, s) != truth) {
      INFO("v " << v << " d " << d);
      CHECK(one_smooth_ring(v, s) == truth);
    }
  }
  // Both verdicts are common, so neither answer passes by default.
  CHECK(rings > 40000);
  CHECK(not_rings > 40000);
}

#if defined(SHADETOOL_SLOT_RING_LANES)
TEST_CASE("smooth_rings8: one_smooth_ring's verdict in each of the 8 lanes, d past kSlotPairs never a ring", "[normals][vertex_slots]") {
  using shadetool::normals_detail::slot_ring_lanes_available;
  using shadetool::normals_detail::smooth_rings8;
  if (!slot_ring_lanes_available()) {
    WARN("no AVX2 on this CPU: smooth_rings8 is not used here, and not tested");
    return;
  }
  std::mt19937 rng(37);
  std::size_t lanes = 0, rings = 0;
  for (int t = 0; t < 20000; ++t) {
    const std::uint32_t v0 = (t % 4 == 0) ? std::uint32_t(-9) - std::uint32_t(rng() % 32) : std::uint32_t(rng() % 100000);
    std::vector<Slot> slots(9);  // the ninth: the slot after the block, which the eighth lane may read
    std::uniform_int_distribution<std::uint32_t> junk;
    for (auto& s : slots) {
      for (std::uint32_t i = 0; i < kSlotPairs; ++i) s.next[i] = junk(rng), s.prev[i] = junk(rng);
      s.d = junk(rng);
    }
    for (std::uint32_t k = 0; k < 8; ++k) {
      const std::uint32_t d = 1 + rng() % (kSlotPairs + 2);  // kSlotPairs + 1, + 2: too many corners
      slots[k] = make_slot(v0 + k, d, int(rng() % 8), rng);
    }
    const std::uint32_t got = smooth_rings8(v0, slots.data());
    for (std::uint32_t k = 0; k < 8; ++k) {
      const Slot& s = slots[k];
      const bool truth = s.d <= kSlotPairs && one_smooth_ring(v0 + k, s);
      REQUIRE(truth == ring_by_definition(v0 + k, s));
      ++lanes;
      rings += truth;
      if (bool((got >> k) & 1u) != truth) {
        INFO("v0 " << v0 << " lane " << k << " d " << s.d);
        CHECK(bool((got >> k) & 1u) == truth);
      }
    }
  }
  CHECK(rings > lanes / 5);
  CHECK(lanes - rings > lanes / 5);
}
#endif
