// pipeline.cpp: repair and transform on NumPy arrays: the library's repair/repair_mesh.h and
// transform/transform_mesh.h on a mesh of the call's own, with the GIL released.
#include <shadetool/core/validate.h>
#include <shadetool/repair/repair_mesh.h>
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/transform_mesh.h>

#include "arrays.h"
#include "bindings.h"

namespace shadetool_python {
namespace {

// The report as `shadetool repair --report` writes it (cli/cmd_repair.cpp), key for key.
py::dict report_dict(const shadetool::RepairReport& r, const std::string& weight) {
  py::dict d;
  d["faces_in"] = r.faces_in;
  d["faces_out"] = r.faces_out;
  d["components"] = r.components;
  d["closed_components"] = r.closed_components;
  d["open_components"] = r.open_components;
  d["faces_flipped"] = r.faces_flipped;
  d["faces_flipped_for_consistency"] = r.faces_flipped_for_consistency;
  d["components_inverted"] = r.components_inverted;
  d["nested_shells"] = r.nested_shells;
  py::dict orientation;
  orientation["by_volume"] = r.oriented_by_volume;
  orientation["by_vote"] = r.oriented_by_vote;
  orientation["by_normals"] = r.oriented_by_normals;
  orientation["by_majority"] = r.oriented_by_majority;
  orientation["open_component_method"] = "generalized winding number";
  d["orientation"] = orientation;
  d["non_manifold_edges"] = r.non_manifold_edges;
  d["duplicate_faces"] = r.duplicate_faces;
  d["non_orientable_components"] = r.non_orientable_components;
  d["inconsistent_edges"] = r.inconsistent_edges;
  d["boundary_loops"] = r.boundary_loops;
  d["degenerate_faces"] = r.degenerate_faces;
  py::dict by_kind;
  by_kind["zero_area"] = r.degenerate_zero_area;
  by_kind["repeated_index"] = r.degenerate_repeated_index;
  by_kind["too_few_corners"] = r.degenerate_too_few_corners;
  by_kind["non_finite"] = r.degenerate_non_finite;
  d["degenerate_by_kind"] = by_kind;
  d["degenerate_faces_removed"] = r.degenerate_faces_removed;
  d["vertices_welded"] = r.vertices_welded;
  d["seam_vertices_joined"] = r.seam_vertices_joined;
  d["weld_eps"] = py::none();
  py::dict normals;
  normals["nan"] = r.normals.nan;
  normals["inf"] = r.normals.inf;
  normals["zero"] = r.normals.zero;
  normals["flipped"] = r.normals.flipped;
  normals["missing"] = r.normals.missing;
  normals["total"] = r.normals.total();
  d["normals_recomputed"] = normals;
  py::dict by_normal_kind;
  by_normal_kind["vertex"] = r.normals.vertex;
  by_normal_kind["corner"] = r.normals.corner;
  by_normal_kind["face"] = r.normals.face;
  d["normals_recomputed_by_kind"] = by_normal_kind;
  d["weighting"] = weight;
  d["changes"] = r.changes();
  return d;
}

shadetool::NormalsPolicy parse_policy(const std::string& s) {
  if (s == "transform") return shadetool::NormalsPolicy::Transform;
  if (s == "recompute") return shadetool::NormalsPolicy::Recompute;
  if (s == "drop") return shadetool::NormalsPolicy::Drop;
  throw py::value_error("transform: normals: '" + s + "' is not one of transform, recompute, drop");
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
