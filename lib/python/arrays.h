// arrays.h: NumPy arrays in and out of the library's Mesh, for the Python module (not installed).
//
// In, for the normals (mesh_view_input): a view over V and F in place where their layout allows
// (float64 V, int32/uint32 F, C-contiguous: no copy, one min/max pass over the indices), else
// over copies converted as below. In, for the calls that change or keep the mesh (repair,
// transform, lighting, shadetool.Mesh): the library's Mesh owns its arrays (std::vector<double>
// positions, std::vector<uint32_t> corners and face starts), so V and F are copied ONCE into it,
// converted on the way:
//   V  (n, 3) float64 or float32, any strides (float32 widened exactly; no intermediate copy)
//   F  (m, k) integer array of any integer dtype (int32, int64, uint32, ...): m faces of k >= 3
//      corners each (triangles: k = 3), any strides; or a pair (indices, offsets): C corner indices
//      and m + 1 offsets from 0 to C, face f using indices[offsets[f]:offsets[f+1]], at least 3
//      (polygons of mixed sizes; fewer than 3 corners is refused, as the file readers refuse it). Every index is checked: 0 <= i < n, else ValueError naming the
//      face and corner. n and C must fit the library's uint32 indices.
// A Python list or other sequence is first turned into an array by numpy.asarray (a copy).
// The copy and the index check run with the GIL released: contiguous aligned arrays in one
// converting pass into capacity reserved by core/bulk_reserve.h (huge pages), after one min/max
// pass over the indices; strided or unaligned arrays element by element over TBB ranges
// (core/engine/parallel.h). The view skips that copy (its cost: bench/python/results.md). Arrays in a non-native byte order are converted to native first (a copy).
// Out: a result std::vector is moved into a capsule that owns it and viewed as a NumPy array:
// no copy.
// Errors: py::value_error with one line `FUNCTION: ARG: what is wrong` (shape, dtype, index).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/weighting.h>

namespace shadetool_python {

namespace py = pybind11;

// How F was given, so that results per corner come back in the same layout.
struct FaceLayout {
  std::size_t corners_per_face = 3;  // k of an (m, k) array; 0 for (indices, offsets) polygons
};

// A mesh argument: the library Mesh to compute on (built from V and F, or a shadetool.Mesh's own,
// shared and not copied) and F's layout.
struct MeshInput {
  std::shared_ptr<const shadetool::Mesh> mesh;
  FaceLayout layout;
};

// The wrapper of shadetool.Mesh: the mesh is shared with every array view handed out, and replaced
// (copy on write) when an attribute is assigned, so no view ever dangles.
struct PyMesh {
  std::shared_ptr<shadetool::Mesh> mesh = std::make_shared<shadetool::Mesh>();
};

// V may be a shadetool.Mesh (then F must be None) or an (n, 3) array; F as above.
MeshInput mesh_input(py::handle V, py::handle F, const std::string& fn);

// A mesh argument as a view (core/mesh_view.h) for the calls that only read it (the normals):
// the caller's arrays are used IN PLACE where their layout allows, with no copy:
//   V  float64 (n, 3), C-contiguous, aligned
//   F  int32 or uint32 (m, k), C-contiguous, aligned, every index in [0, n) (one min/max pass;
//      (m, 3): nothing else is made; other k: the F + 1 face starts k f are), or a tuple
//      (indices, offsets) of such 1-D arrays (offsets checked as above)
// Everything else (float32, int64 and other integer types, strided or unaligned arrays, lists)
// is converted into `storage` as mesh_input does. A shadetool.Mesh is viewed, not copied.
// The view reads the arrays during the call with the GIL released: another Python thread must
// not write into them meanwhile (as for any NumPy buffer handed to C code that releases the GIL).
struct MeshViewInput {
  shadetool::MeshView view;
  FaceLayout layout;
  std::shared_ptr<const shadetool::Mesh> storage;  // converted arrays, or the shadetool.Mesh viewed
  std::vector<py::object> keep;                     // the arrays read in place (alive for the call)
};
MeshViewInput mesh_view_input(py::handle V, py::handle F, const std::string& fn);

// A mesh of its own for a call that changes it: built from V and F, or a copy of a shadetool.Mesh's.
shadetool::Mesh owned_mesh(py::handle V, py::handle F, const std::string& fn, FaceLayout& layout);

// Reads V into mesh.positions (and sets mesh.precision from its dtype).
void read_positions(py::handle V, const std::string& what, shadetool::Mesh& mesh);
// Reads F into mesh.face_start / corner_vertex, checking indices against mesh.num_vertices().
FaceLayout read_faces(py::handle F, const std::string& what, shadetool::Mesh& mesh);
// An (rows, cols) float array (float64 or float32) into doubles; rows checked.
std::vector<double> read_double_rows(py::handle A, std::size_t rows, std::size_t cols, const std::string& what);
// An (rows, cols) float array into floats (colours).
std::vector<float> read_float_rows(py::handle A, std::size_t rows, std::size_t cols, const std::string& what);
// The layout of a library mesh's faces (k when every face has k corners, else polygons).
FaceLayout layout_of(const shadetool::Mesh& mesh);
// A shadetool.Mesh's mesh, or nullptr when `obj` is not one.
std::shared_ptr<shadetool::Mesh> as_mesh(py::handle obj);

// The vector, moved into a capsule that owns it, as an array of `shape` (product = v.size()).
template <class T, class Alloc>
py::array_t<T> to_numpy(std::vector<T, Alloc>&& v, std::vector<py::ssize_t> shape) {
  auto* owner = new std::vector<T, Alloc>(std::move(v));
  py::capsule base(owner, [](void* p) { delete static_cast<std::vector<T, Alloc>*>(p); });
  return py::array_t<T>(std::move(shape), owner->data(), base);
}

// Corner-indexed values (#C) shaped as F was given: (m, k), or flat (C,) for polygons.
template <class T>
py::array_t<T> per_corner(std::vector<T>&& v, const FaceLayout& layout) {
  if (layout.corners_per_face == 0) return to_numpy(std::move(v), {py::ssize_t(v.size())});
  const py::ssize_t k = py::ssize_t(layout.corners_per_face);
  const py::ssize_t m = py::ssize_t(v.size()) / k;
  return to_numpy(std::move(v), {m, k});
}

// Faces of a library mesh (moved out, no copy) in the layout asked for: (m, k) uint32, or the pair
// (indices, offsets) of uint32 arrays.
py::object faces_out(shadetool::Mesh&& mesh, const FaceLayout& layout);

// "uniform" | "area" | "angle" | "max"; "double" | "float". ValueError naming fn otherwise.
shadetool::Weighting parse_weighting(const std::string& value, const std::string& fn);
shadetool::Precision parse_precision(const std::string& value, const std::string& fn);

}  // namespace shadetool_python
