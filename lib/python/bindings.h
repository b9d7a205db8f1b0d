// bindings.h: the parts of the Python module, each defined in its own file (not installed).
//   mesh_class.cpp   shadetool.Mesh, read_mesh, write_mesh
//   normals.cpp      face_normals, vertex_normals, corner_normals
//   pipeline.cpp     repair, transform
//   lighting.cpp     bake_lighting, occlusion, render
#pragma once

#include <string>

#include <pybind11/pybind11.h>

namespace shadetool_python {

namespace py = pybind11;

void init_mesh(py::module_& m);
void init_normals(py::module_& m);
void init_pipeline(py::module_& m);
void init_lighting(py::module_& m);

// Raises FileNotFoundError(errno.ENOENT, what, PATH): "[Errno 2] what: 'PATH'".
[[noreturn]] void throw_file_not_found(const std::string& path, const std::string& what);

}  // namespace shadetool_python
