// pipeline.cpp: repair and transform on NumPy arrays: the library's repair/repair_mesh.h and
// transform/transform_mesh.h on a mesh of the call's own, with the GIL released.
#include <shadetool/core/validate.h>
#include <shadetool/repair/repair_mesh.h>
#include <shadetool/repair/repair_report_json.h>
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/transform_mesh.h>

#include "arrays.h"
#include "bindings.h"

namespace shadetool_python {
namespace {

// The report as `shadetool repair --report` writes it, key for key (repair/repair_report_json.h).
py::dict report_dict(const shadetool::RepairReport& r, const std::string& weight) {
  return py::module_::import("json").attr("loads")(shadetool::repair_report_json(r, -1, weight));
}

shadetool::NormalsPolicy parse_policy(const std::string& s) {
  return shadetool::parse_normals_policy(s, "transform: normals");  // transform_mesh.h's vocabulary
}

}  // namespace

void init_pipeline(py::module_& m) {
  m.def(
      "repair",
      [](py::object V, py::object F, const std::string& weight, bool remove_degenerate, bool return_normals) {
        FaceLayout layout;
        shadetool::Mesh mesh = owned_mesh(V, F, "repair", layout);
        shadetool::RepairOptions options;
        options.weighting = parse_weighting(weight, "repair");
        options.remove_degenerate = remove_degenerate;
        shadetool::RepairReport report;
        {
          py::gil_scoped_release nogil;
          shadetool::require_finite_positions(mesh, "repair: V");
          shadetool::require_faces(mesh, "repair: F");
          report = shadetool::repair_mesh(mesh, options);
        }
        py::dict d = report_dict(report, weight);
        if (!return_normals) return py::make_tuple(faces_out(std::move(mesh), layout), d);
        py::object N = py::none();
        if (mesh.has_vertex_normals()) N = to_numpy(std::move(mesh.vertex_normals), {py::ssize_t(mesh.num_vertices()), 3});
        return py::make_tuple(faces_out(std::move(mesh), layout), N, d);
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("weight") = "angle", py::arg("remove_degenerate") = false,
      py::arg("return_normals") = false,
      R"doc(repair(V, F=None, weight="angle", remove_degenerate=False, return_normals=False) -> (F, report)

Orients the faces consistently and outward (the library's repair/repair_mesh.h, what
`shadetool repair` does): consistent winding per component, outward by signed volume (closed),
nesting parity (shells in shells) or the generalised winding number (open); degenerate faces
counted, and removed with remove_degenerate. Positions are not changed.
  V  (n, 3) float64/float32 (finite), or a shadetool.Mesh (F None; the Mesh is not changed)
  F  (m, k) integers or (indices, offsets); copied once into uint32
Returns F repaired, uint32, in F's layout ((m', k), or (indices, offsets)), and the report: a dict
with the keys of `shadetool repair --report` (faces_flipped, components, orientation, ...).
return_normals=True returns (F, N, report): N the repaired vertex normals (n, 3) float64 (the
mesh's own, fixed where NaN, zero or flipped; computed where missing), as `shadetool repair` writes.
ValueError for bad shapes, dtypes or indices, non-finite positions, no faces.
)doc");

  m.def(
      "transform",
      [](py::object V, py::object F, py::object N, py::object matrix, const std::string& normals) {
        FaceLayout layout;
        shadetool::Mesh mesh = owned_mesh(V, F, "transform", layout);
        if (!N.is_none()) {
          if (as_mesh(V)) throw py::value_error("transform: N must be None when the first argument is a shadetool.Mesh");
          mesh.vertex_normals = read_double_rows(N, mesh.num_vertices(), 3, "transform: N");
        }
        if (matrix.is_none()) throw py::value_error("transform: matrix is required ((3, 4) [A|t] or (4, 4) with last row 0 0 0 1)");
        py::array_t<double, py::array::c_style | py::array::forcecast> mat = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(matrix);
        if (!mat || !((mat.ndim() == 2 && mat.shape(1) == 4 && (mat.shape(0) == 3 || mat.shape(0) == 4)))) {
          PyErr_Clear();
          throw py::value_error("transform: matrix must have shape (3, 4) or (4, 4)");
        }
        const std::vector<double> values(mat.data(), mat.data() + mat.size());
        const shadetool::Affine3d map = shadetool::affine_from_row_major(values, "transform: matrix");
        shadetool::TransformOptions options;
        options.normals = parse_policy(normals);
        {
          py::gil_scoped_release nogil;
          shadetool::transform_mesh(mesh, map, options, "transform: V");
        }
        const py::ssize_t n = py::ssize_t(mesh.num_vertices());
        py::object N_out = py::none();
        if (mesh.has_vertex_normals()) N_out = to_numpy(std::move(mesh.vertex_normals), {n, 3});
        py::array V_out = to_numpy(std::move(mesh.positions), {n, 3});
        return py::make_tuple(V_out, faces_out(std::move(mesh), layout), N_out);
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("N") = py::none(), py::arg("matrix") = py::none(),
      py::arg("normals") = "transform",
      R"doc(transform(V, F, N, matrix, normals="transform") -> (V, F, N)

Applies the affine map p -> A p + t (the library's transform/transform_mesh.h, what
`shadetool transform --matrix` does): positions A p + t; normals by sign(det A) cof(A), normalised
(rotations and uniform scales exactly, without renormalising); a mirror (det A < 0) reverses the
faces' winding so that they keep their orientation.
  V       (n, 3) float64/float32 (finite), or a shadetool.Mesh (F and N None; its own vertex normals)
  F       (m, k) integers or (indices, offsets)
  N       (n, 3) float vertex normals, or None
  matrix  (3, 4) rows of [A | t], or (4, 4) with last row 0 0 0 1 (array-like of floats)
  normals "transform" (default), "recompute" (from the new faces) or "drop"
Returns V float64 (n, 3), F uint32 in F's layout, N float64 (n, 3) or None.
ValueError: bad shapes, dtypes or indices, a non-finite or projective matrix, a singular map with
normals to transform.
)doc");
}

}  // namespace shadetool_python
