// repeated_index.h: whether a face uses one vertex index at two or more of its corners.
//
// The one test behind both uses of the rule: geometry/degenerate_face.h's RepeatedIndex kind (info
// counts such faces, repair removes them) and core/edge_adjacency.h's unwound faces (a face with
// fewer than 3 corners or a repeated index has no winding of its own; repair's pairing leaves them
// out). A repeated index need not be adjacent: (a, b, a, c) repeats a.
//
// Inputs:  corner_vertex  the face's n vertex indices; n may be 0
//          scratch        reused buffer (faces of more than 16 corners are sorted in it)
// Output:  true when two of the n indices are equal
// Method: all pairs for n <= 16 (at most 120 compares, no allocation); sort and compare
// neighbours beyond.
#pragma once

#include <cstdint>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

bool has_repeated_index(const std::uint32_t* corner_vertex, std::uint32_t n, std::vector<std::uint32_t>& scratch);

}  // namespace shadetool
#pragma GCC visibility pop
