// unit_normals.h: the one rule for stored normals that are finite and non-zero but off unit length
// by more than kUnitNormalTolerance (an OBJ's `vn 0 0 -6.283185`, a glTF NORMAL of length 0.1 as in
// Khronos' BoxBadNormals): every writer (files/mesh_files.h for OBJ/PLY/OFF/STL, gltf/gltf_write for
// glTF) writes them divided by their length, the same direction, and says so in one note. Normals
// are directions: glTF requires unit NORMAL (the validator's ACCESSOR_VECTOR3_NON_UNIT) and a
// fixed-function renderer or a reader that does not normalise would shade with the length.
//
// Inputs:  rows  a flat #N by 3 array of normals (double).
// Output:  the off-unit rows divided by their length in place; OffUnitNormals counts them and keeps
//          the shortest and longest length seen, for the note.
// Degenerate rows: zero or non-finite rows are not touched here (they are refused or replaced
// elsewhere: normals/replace_invalid_normals.h); the division is by a length checked > 0.
// Precision: double.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace shadetool {

constexpr double kUnitNormalTolerance = 1e-3;

struct OffUnitNormals {
  std::size_t rows = 0;
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
};

// True for a finite row whose length is > 0 and off 1 by more than the tolerance; `length` is set.
inline bool off_unit_normal(const double* n, double& length) {
  if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]))) return false;
  length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return length > 0.0 && std::fabs(length - 1.0) > kUnitNormalTolerance;
}

inline bool any_off_unit_normal(const std::vector<double>& rows) {
  double length = 0.0;
  for (std::size_t i = 0; i + 2 < rows.size(); i += 3)
    if (off_unit_normal(&rows[i], length)) return true;
  return false;
}

// Divides each off-unit row by its length (checked > 0 by off_unit_normal) and counts it.
inline void normalise_off_unit_normals(std::vector<double>& rows, OffUnitNormals& found) {
  for (std::size_t i = 0; i + 2 < rows.size(); i += 3) {
    double length = 0.0;
    if (!off_unit_normal(&rows[i], length)) continue;
    ++found.rows;
    found.shortest = std::min(found.shortest, length);
    found.longest = std::max(found.longest, length);
    for (std::size_t k = 0; k < 3; ++k) rows[i + k] /= length;
  }
}

// "3 normals not of unit length (0.1 to 0.5) written divided by their length: the same directions";
// empty when found.rows == 0.
inline std::string off_unit_normals_note(const OffUnitNormals& found) {
  if (found.rows == 0) return std::string();
  auto number = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return std::string(buf);
  };
  return std::to_string(found.rows) + (found.rows == 1 ? " normal" : " normals") + " not of unit length (" +
         number(found.shortest) + (found.longest != found.shortest ? " to " + number(found.longest) : std::string()) +
         ") written divided by their length: the same directions";
}

}  // namespace shadetool
