// weighting.h: how face normals are weighted into vertex normals, and the accumulation precision.
#pragma once

namespace shadetool {

enum class Weighting {
  Uniform,  // mean of unit face normals (Gouraud 1971)
  Area,     // sum of unnormalised face normals: weight = face area
  Angle,    // unit face normal times the interior angle at the vertex (Thürmer & Wüthrich 1998)
  Max,      // sin(angle) / (|e1| |e2|) (Max 1999), exact when the neighbours lie on a sphere
};

// Precision the kernels accumulate in (inputs and outputs are double arrays either way).
enum class Precision { Double, Float };

}  // namespace shadetool
