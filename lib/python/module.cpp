// module.cpp: the Python module `shadetool`: the library's public API on NumPy arrays.
// Each function's binding lives in the file named in bindings.h; conversions in arrays.h.
// Errors: the library's shadetool::Error (its one-line message) becomes ValueError; shapes,
// dtypes and indices are checked at the boundary (arrays.cpp) and raise ValueError, so no bad
// input reaches a kernel; missing files raise FileNotFoundError.
#include <cerrno>

#include <shadetool/core/error.h>

#include "bindings.h"

namespace shadetool_python {

void throw_file_not_found(const std::string& path, const std::string& what) {
  py::object error = py::module_::import("builtins").attr("FileNotFoundError")(ENOENT, what, path);
  PyErr_SetObject(PyExc_FileNotFoundError, error.ptr());
  throw py::error_already_set();
}

}  // namespace shadetool_python

namespace py = pybind11;

PYBIND11_MODULE(_shadetool, m) {  // the package shadetool re-exports it (package/__init__.py)
  namespace sp = shadetool_python;
  m.doc() = R"doc(shadetool: mesh normals, repair, transforms, lighting, occlusion and rendering on NumPy arrays.

The functions are the shadetool C++ library's own (the same code and bits as the `shadetool`
command line), on the arrays you hold:

  V  vertex positions, (n, 3) float64 or float32
  F  faces: (m, 3) integers for triangles ((m, k) for k-gons; int32, int64, uint32, ...), or a
     tuple (indices, offsets) for polygons of mixed sizes (face f = indices[offsets[f]:offsets[f+1]])
  N  vertex normals, (n, 3) float

Functions: face_normals, vertex_normals, corner_normals, repair, transform, bake_lighting,
occlusion, render, read_mesh, write_mesh, and the Mesh class (arrays of a mesh read from or
written to OBJ, PLY, OFF, STL). Any function taking (V, F) also takes a Mesh in place of V (F None),
computing on the mesh's own arrays without a copy.

Copies: face_normals, vertex_normals and corner_normals read a C-contiguous float64 V and a
C-contiguous int32 or uint32 F in place (every index checked first; do not write into them from
another thread during the call). Otherwise, and for the other functions, the library's mesh stores
float64 positions and uint32 indices in arrays it owns, so V and F are copied once into it (float32
widened exactly, int64 checked and narrowed, any strides; no second copy). Results are returned without a copy (the library's output array becomes
the NumPy array's memory).

Threads: the library's (TBB); the GIL is released while it computes. Errors: ValueError with the
library's one-line message for a wrong shape, dtype or index, bad options or bad file content;
FileNotFoundError for a missing file. Example:

    import numpy as np, shadetool
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)
    N = shadetool.vertex_normals(V, F, weight="angle")      # (4, 3) float64
    shadetool.write_mesh("tetra.ply", V, F, vertex_normals=N)
)doc";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const shadetool::Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  sp::init_mesh(m);
  sp::init_normals(m);
  sp::init_pipeline(m);
  sp::init_lighting(m);
  m.attr("__version__") = "0.1.0";
}
