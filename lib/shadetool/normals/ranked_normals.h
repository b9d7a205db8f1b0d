// ranked_normals.h: normals as Blender's Weighted Normal modifier computes them (its modes Face
// Area, Corner Angle and Face Area And Angle, its Weight, Threshold and Keep Sharp): large faces
// dominate, so that the flat faces of a bevelled hard-surface model shade flat.
//
// Inputs:  mesh     positions #V by 3, faces (triangles or polygons)
//          options  mode (normals/weighting.h RankedWeighting), strength W in [1, 100] (Blender's
//                   Weight, default 50), threshold T >= 0 (default 0.01), crease_angle (radians;
//                   < 0: one normal per vertex; >= 0: Keep Sharp, one per smooth group of
//                   corner_normals(mesh, crease_angle))
// Output:  CornerNormals (normals/corner_normals.h): one row per item (vertex, or smooth group)
//          and corner_index; fallback_corners, degenerate_faces.
//
// Formula (MOD_weighted_normal.cc, aggregate_item_normal): every corner has a value v (face
// area, corner angle, or their product) and its face's unit normal n. At each item, the corners
// are taken by decreasing v (ties: corner order); the rank k starts at 0 and goes up by one
// whenever v differs from the value that last set the rank by more than T. The item's normal is
// the normalised sum of n v / w^k, with w from W: W/50, except 32767 at W = 100, 1/32767 at W = 1,
// and 25 (W/50 - 1) when that exceeds 1 (so W = 50 weighs every rank alike: plain area or angle
// weighting; W > 50 favours the largest values).
// Corner angle: the angle between the corner's two edges, in [0, pi] (as Blender's poly angles).
// Face area: |N| / 2 of geometry/face_area_vector.h. Precision: double (Blender computes in float:
// expect agreement to about 1e-5 degrees on well-shaped meshes, and a different rank where two
// values differ by T to within float rounding). tests/blender_normals.sh compares with Blender
// 3.4's modifier on every mode: within 0.035 degrees (its 16-bit custom normals), except at W = 1,
// where Blender's float sum overflows from rank 5 on and it falls back to its default normal; we
// keep the ranked result.
// Degenerate faces (geometry/degenerate_face.h) contribute nothing and do not rank; an item whose
// sum is zero gets the normal of its first valid face, else (0, 0, 1) (counted as fallback).
#pragma once

#include <shadetool/core/mesh.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct RankedWeightingOptions {
  RankedWeighting mode = RankedWeighting::FaceArea;
  int strength = 50;          // 1..100
  double threshold = 0.01;    // >= 0
  double crease_angle = -1;   // radians; >= 0: keep sharp
};

// Blender's w for a strength W in [1, 100] (Error outside).
double ranked_weight_base(int strength);

CornerNormals ranked_normals(const Mesh& mesh, const RankedWeightingOptions& options);

}  // namespace shadetool
#pragma GCC visibility pop
