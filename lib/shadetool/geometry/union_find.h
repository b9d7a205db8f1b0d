// union_find.h: disjoint sets over 0..n-1 in one flat array — the one union-find of the library
// (Tarjan 1975; path halving, Tarjan & van Leeuwen 1984).
//
// Inputs:  parent  n uint32, parent[x] == x for a root; callers own the array (a vector, a slice of
//                  scratch memory) so that one pass can keep several sets side by side.
// Rules:   union by lower index: the root of every set is its smallest element, so the sets, their
//          roots and every later labelling are independent of the order the unions come in.
//          find halves the path as it walks (each node visited points to its grandparent).
// With parity (for orientation): node[x] = (parent << 1) | parity, the parity of x relative to its
// parent; path halving XORs the two parities it skips, so parities to the root stay exact.
// Limits: n < 2^32 (2^31 with parity, which spends a bit). Not thread-safe: one writer at a time.
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// The root of x's set, halving the path on the way.
inline std::uint32_t union_find_root(std::uint32_t* parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Joins the sets of a and b; the lower root becomes the root. Returns it.
inline std::uint32_t union_find_unite(std::uint32_t* parent, std::uint32_t a, std::uint32_t b) {
  a = union_find_root(parent, a);
  b = union_find_root(parent, b);
  if (a == b) return a;
  if (a < b) return parent[b] = a;
  return parent[a] = b;
}

// The same over a vector, for callers who want no raw array.
class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::uint32_t(0)); }
  std::uint32_t find(std::uint32_t x) { return union_find_root(parent_.data(), x); }
  std::uint32_t unite(std::uint32_t a, std::uint32_t b) { return union_find_unite(parent_.data(), a, b); }

 private:
  std::vector<std::uint32_t> parent_;
};

// With parity: the root of x, and in `parity` x's parity relative to it. Path halving keeps the
// parities: a node moved to its grandparent takes the XOR of the two links it skips.
inline std::uint32_t union_find_root_with_parity(std::uint32_t* node, std::uint32_t x, std::uint32_t& parity) {
  parity = 0;
  for (;;) {
    const std::uint32_t nx = node[x], px = nx >> 1;
    if (px == x) return x;
    const std::uint32_t ny = node[px], py = ny >> 1;
    if (py == px) {
      parity ^= nx & 1u;
      return px;
    }
    const std::uint32_t to_grandparent = (nx ^ ny) & 1u;
    node[x] = (py << 1) | to_grandparent;
    parity ^= to_grandparent;
    x = py;
  }
}

}  // namespace shadetool
#pragma GCC visibility pop
