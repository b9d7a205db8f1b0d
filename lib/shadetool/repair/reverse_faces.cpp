// reverse_faces.cpp: winding reversal keeping the first corner (see the header).
#include <shadetool/core/engine/parallel.h>
#include <shadetool/repair/reverse_faces.h>

#include <algorithm>
#include <functional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <shadetool/core/error.h>

namespace shadetool {

std::size_t reverse_faces(Mesh& mesh, const std::vector<std::uint8_t>& reverse) {
  const std::size_t F = mesh.num_faces();
  if (reverse.size() != F) fail("reverse_faces", 0, "flag array size differs from the face count");
  const bool normals = mesh.has_corner_normals(), texcoords = mesh.has_texcoords();
  std::size_t count = 0;
  if (mesh.all_triangles() && !normals && !texcoords) {
    // Triangles with nothing else per corner: swap corners 1 and 2 by a mask, not by a branch
    // (the flags of a damaged mesh are as good as random; a mispredicted branch per face cost
    // more than writing every face back; `r ? b : a` was compiled to such a branch). Blocks of
    // faces in parallel (TBB) above 32768 faces; each block writes only its own faces.
    std::uint32_t* cv = mesh.corner_vertex.data();
    const std::uint8_t* flag = reverse.data();
    auto swap_range = [cv, flag](std::size_t f0, std::size_t f1) {
      std::size_t n = 0;
      for (std::size_t f = f0; f < f1; ++f) {
        const std::uint32_t r = flag[f] != 0, mask = 0u - r;  // all ones: swap
        const std::uint32_t a = cv[3 * f + 1], b = cv[3 * f + 2], x = (a ^ b) & mask;
        cv[3 * f + 1] = a ^ x;
        cv[3 * f + 2] = b ^ x;
        n += r;
      }
      return n;
    };
    if (F < engine::kSerialBelow) return swap_range(0, F);
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, F, std::size_t(1) << 14), std::size_t(0),
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t n) { return n + swap_range(r.begin(), r.end()); },
        std::plus<std::size_t>());
  }
  for (std::size_t f = 0; f < F; ++f) {
    if (!reverse[f]) continue;
    ++count;
    const std::uint32_t b = mesh.face_start[f] + 1, e = mesh.face_start[f + 1];
    if (e <= b) continue;  // an empty face has nothing to reverse
    std::reverse(mesh.corner_vertex.begin() + b, mesh.corner_vertex.begin() + e);
    if (normals) std::reverse(mesh.corner_normal_index.begin() + b, mesh.corner_normal_index.begin() + e);
    if (texcoords) std::reverse(mesh.corner_texcoord_index.begin() + b, mesh.corner_texcoord_index.begin() + e);
  }
  return count;
}

}  // namespace shadetool
