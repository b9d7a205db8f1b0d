// gltf_morph_normals.h: NORMAL deltas of a primitive's morph targets, recomputed from the
// displaced positions after its base normals were computed.
//
// Inputs:  primitive  mesh with vertex normals #V by 3 (just computed), targets with POSITION
//                     deltas #V by 3
//          compute    the caller's normals computation (the one that made the base normals),
//                     applied to a copy of the mesh whose positions are p + d and which has no
//                     normals; it must leave #V by 3 vertex normals
// Output:  every target that moves positions gets NORMAL deltas n(p + d) - n(p) (#V by 3, added
//          when it had none); returns how many targets were recomputed. Targets without POSITION
//          deltas keep theirs. Only vertex normals: with corner or face normals nothing is done
//          (returns 0) and the caller says so.
// Precision: whatever `compute` uses; the difference in double.
#pragma once

#include <cstddef>
#include <functional>

#include <shadetool/gltf/gltf_document.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::size_t recompute_morph_normal_deltas(GltfPrimitive& primitive, const std::function<void(Mesh&)>& compute);

}  // namespace shadetool
#pragma GCC visibility pop
