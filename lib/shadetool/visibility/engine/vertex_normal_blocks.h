// vertex_normal_blocks.h: the library's vertex normals (normals/vertex_normals.h, angle-weighted,
// summed in double) for one block of consecutive vertices at a time, so that a caller that reads
// each vertex's normal once (ambient occlusion's ray axes) holds B rows instead of #V (machinery:
// at 1M triangles the #V rows were 6 MB of the occlusion command's peak even in float;
// bench/visibility/results.md, Memory).
//
// Inputs:  mesh   positions #V by 3, faces (triangles or polygons); outlives the blocks, unchanged
//          block_log2  B = 2^block_log2 vertices per block: block k is vertices [kB, min((k+1)B, #V))
// Output:  compute(k, out): out.normals rows 0 .. (end - begin - 1) are the normals of the block's
//          vertices begin .. end - 1 (later rows belong to neighbours outside the block and are not
//          their normals); fallback and degenerate counts are the sub-mesh's.
// Method:  block k's sub-mesh is every face with a corner in the block, in face order, over the
//          block's vertices (first, in order: row v - begin) and the other vertices those faces use
//          (after them, ascending); vertex_normals of the sub-mesh gives the block's rows.
// Why these are the full mesh's normals, bit for bit: a vertex's normal depends only on its own
//          faces. Its sum adds its corners' contributions in ascending corner order
//          (normals/engine/accumulate_by_vertex.h), each contribution depends only on its face's
//          positions (copied exactly), the degenerate-face rule is per face, and the fallback takes
//          its lowest valid face or (0, 0, 1) when it has none; the sub-mesh keeps every face of a
//          block vertex, in the same relative order. The one input that looks beyond a vertex's
//          faces, the power-of-two scale of meshes outside [2^-32, 2^32) (normals/engine/
//          mesh_scale.h), may differ between a block and the mesh; that scale changes no bit while
//          the kernels stay in range (the same file), which every test mesh, 1e-3 to 1e8, does.
// Face ranges: one pass over the corners at construction records, per block, the lowest and
//          highest face with a corner in it, so compute(k) scans only those faces (meshes stored
//          with locality: about the block's own faces; faces in random order: all faces per block,
//          slower but the same bits).
// Memory:  8 B per block for the ranges; while a block is computed, about 110 B per block vertex
//          (its faces' corners and starts, its vertices' positions, their double normals).
// Threads: compute(k) runs on the caller (vertex_normals splits sub-meshes of 32768+ faces over
//          TBB itself); the result is the same for any thread count (vertex_normals.h).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool::visibility_engine {

class VertexNormalBlocks {
 public:
  VertexNormalBlocks(const Mesh& mesh, unsigned block_log2) : mesh_(mesh), log2_(block_log2), block_(std::size_t(1) << block_log2) {
    const std::size_t nv = mesh.num_vertices(), nf = mesh.num_faces();
    blocks_ = (nv + block_ - 1) >> log2_;
    first_face_.assign(blocks_, std::numeric_limits<std::uint32_t>::max());
    last_face_.assign(blocks_, 0);
    for (std::size_t f = 0; f < nf; ++f)
      for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
        const std::size_t k = mesh.corner_vertex[c] >> log2_;
        first_face_[k] = std::min(first_face_[k], std::uint32_t(f));
        last_face_[k] = std::max(last_face_[k], std::uint32_t(f));
      }
  }

  std::size_t blocks() const { return blocks_; }
  std::size_t begin(std::size_t k) const { return k * block_; }
  std::size_t end(std::size_t k) const { return std::min((k + 1) * block_, mesh_.num_vertices()); }

  void compute(std::size_t k, VertexNormals& out) {
    const std::uint32_t vb = std::uint32_t(begin(k)), nb = std::uint32_t(end(k) - begin(k));
    corners_.clear();
    starts_.assign(1, 0);
    outside_.clear();
    if (first_face_[k] <= last_face_[k])
      for (std::size_t f = first_face_[k]; f <= last_face_[k]; ++f) {
        const std::uint32_t cb = mesh_.face_start[f], ce = mesh_.face_start[f + 1];
        bool touches = false;
        for (std::uint32_t c = cb; c < ce; ++c) touches |= mesh_.corner_vertex[c] - vb < nb;  // unsigned: in block
        if (!touches) continue;
        for (std::uint32_t c = cb; c < ce; ++c) {
          const std::uint32_t v = mesh_.corner_vertex[c];
          corners_.push_back(v);
          if (v - vb >= nb) outside_.push_back(v);
        }
        starts_.push_back(std::uint32_t(corners_.size()));
      }
    std::sort(outside_.begin(), outside_.end());
    outside_.erase(std::unique(outside_.begin(), outside_.end()), outside_.end());
    for (std::uint32_t& v : corners_)  // global index -> sub-mesh row
      v = v - vb < nb ? v - vb
                      : nb + std::uint32_t(std::lower_bound(outside_.begin(), outside_.end(), v) - outside_.begin());
    positions_.resize(3 * (std::size_t(nb) + outside_.size()));
    std::copy(mesh_.positions.begin() + 3 * std::size_t(vb), mesh_.positions.begin() + 3 * (std::size_t(vb) + nb),
              positions_.begin());
    for (std::size_t i = 0; i < outside_.size(); ++i)
      std::copy_n(mesh_.positions.begin() + 3 * std::size_t(outside_[i]), 3, positions_.begin() + 3 * (nb + i));
    const MeshView sub = MeshView::polygons(positions_.data(), nb + outside_.size(), corners_.data(), starts_.data(),
                                            starts_.size() - 1);
    vertex_normals(sub, Weighting::Angle, Precision::Double, out);
  }

 private:
  const Mesh& mesh_;
  unsigned log2_;
  std::size_t block_, blocks_ = 0;
  std::vector<std::uint32_t> first_face_, last_face_;  // per block: faces with a corner in it lie in this range
  std::vector<std::uint32_t> corners_, starts_, outside_;  // the current block's sub-mesh (reused)
  std::vector<double> positions_;
};

}  // namespace shadetool::visibility_engine
