// invalid_normals.h: counting normals that cannot be used as they are.
//
// Inputs:  normals  N by 3 flat array
// Output:  how many rows have a NaN or Inf component or zero length (all three components 0).
//          Rows that are finite and non-zero but not of unit length are valid (the lighting
//          normalises them, and every writer writes them divided by their length:
//          files/mesh_files.h); only NaN, Inf and zero carry no direction.
#pragma once

#include <cstddef>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::size_t count_invalid_normals(const std::vector<double>& normals);

}  // namespace shadetool
#pragma GCC visibility pop
