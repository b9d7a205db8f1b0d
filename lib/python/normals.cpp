// normals.cpp: face_normals, vertex_normals, corner_normals, tangents on NumPy arrays: the
// library's calls (normals/face_normals.h, vertex_normals.h, corner_normals.h, tangents.h), with
// the GIL released.
#include <cmath>

#include <shadetool/core/validate.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/tangents.h>
#include <shadetool/normals/vertex_normals.h>

#include "arrays.h"
#include "bindings.h"

namespace shadetool_python {

namespace {

constexpr const char* kMeshArgs = R"doc(
  V  (n, 3) float64 or float32 vertex positions, or a shadetool.Mesh (then F is None: no copy)
  F  (m, k) integer faces (triangles: (m, 3); int32, int64, uint32, ...) or a tuple
     (indices, offsets) for polygons: face f is indices[offsets[f]:offsets[f + 1]]
  No copy where the layout allows: float64 C-contiguous V and int32/uint32 C-contiguous F are
  read in place (every index checked first). Other dtypes and layouts (float32, int64, strided)
  are converted once into the library's arrays (float64, uint32; float32 widened exactly).
  ValueError for a wrong shape, dtype or an index outside [0, n). Do not write into V or F from
  another thread during the call (the GIL is released while the library reads them).)doc";

}  // namespace

void init_normals(py::module_& m) {
  m.def(
      "face_normals",
      [](py::object V, py::object F, const std::string& precision) {
        const MeshViewInput in = mesh_view_input(V, F, "face_normals");
        shadetool::require_finite_positions(in.view, "face_normals: V");  // the CLI's rule: refused, not (0, 0, 1)
        const shadetool::Precision p = parse_precision(precision, "face_normals");
        std::vector<double> normals;
        {
          py::gil_scoped_release nogil;
          normals = shadetool::face_normals(in.view, p);
        }
        const py::ssize_t rows = py::ssize_t(normals.size() / 3);
        return to_numpy(std::move(normals), {rows, 3});
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("precision") = "double",
      (std::string(R"doc(face_normals(V, F=None, precision="double") -> (m, 3) float64

One unit normal per face: triangles by the cross product of their two shortest edges, polygons by
Newell's method; a face without area (zero area to 64 eps, fewer than 3 corners) gets (0, 0, 0),
never NaN. A NaN or infinite position raises ValueError naming the first such vertex (as the CLI). The library's normals/face_normals.h.
)doc") + kMeshArgs + "\n  precision  \"double\" or \"float\": the accumulation precision (output float64 either way)\n")
          .c_str());

  m.def(
      "vertex_normals",
      [](py::object V, py::object F, const std::string& weight, const std::string& precision) {
        const MeshViewInput in = mesh_view_input(V, F, "vertex_normals");
        shadetool::require_finite_positions(in.view, "vertex_normals: V");  // the CLI's rule: refused, not (0, 0, 1)
        const shadetool::Weighting w = parse_weighting(weight, "vertex_normals");
        const shadetool::Precision p = parse_precision(precision, "vertex_normals");
        shadetool::VertexNormals result;
        {
          py::gil_scoped_release nogil;
          shadetool::vertex_normals(in.view, w, p, result);
        }
        const py::ssize_t rows = py::ssize_t(in.view.num_vertices());
        return to_numpy(std::move(result.normals), {rows, 3});
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("weight") = "angle", py::arg("precision") = "double",
      (std::string(R"doc(vertex_normals(V, F=None, weight="angle", precision="double") -> (n, 3) float64

One unit normal per vertex, the normalised weighted sum of the normals of its faces (the library's
normals/vertex_normals.h, bitwise what `shadetool normals --weight W` writes):
  weight  "angle" (interior angle, Thuermer & Wuethrich 1998; default), "area" (face area, as
          Open3D's compute_vertex_normals and OpenMesh), "uniform" (Gouraud 1971) or "max"
          (Max 1999: exact on a sphere)
  precision  "double" or "float": the accumulation precision (output float64 either way)
A vertex with no valid face (isolated, only degenerate faces) gets the documented fallback
((0, 0, 1), or its first face's normal when its contributions cancel), never NaN. A NaN or
infinite position raises ValueError naming the first such vertex (as the CLI refuses it). Threads: TBB,
the GIL released; the result is bitwise the same for any thread count.
)doc") + kMeshArgs + "\n")
          .c_str());

  m.def(
      "corner_normals",
      [](py::object V, py::object F, py::object crease_deg, const std::string& weight, const std::string& precision) {
        if (crease_deg.is_none()) throw py::value_error("corner_normals: crease_deg is required (degrees, 0..180)");
        const double deg = crease_deg.cast<double>();
        if (!(deg >= 0.0 && deg <= 180.0))
          throw py::value_error("corner_normals: crease_deg must be in [0, 180] degrees, got " + py::repr(crease_deg).cast<std::string>());
        const MeshViewInput in = mesh_view_input(V, F, "corner_normals");
        shadetool::require_finite_positions(in.view, "corner_normals: V");  // the CLI's rule: refused, not (0, 0, 1)
        const shadetool::Weighting w = parse_weighting(weight, "corner_normals");
        const shadetool::Precision p = parse_precision(precision, "corner_normals");
        shadetool::CornerNormals result;
        {
          py::gil_scoped_release nogil;
          result = shadetool::corner_normals(in.view, deg * shadetool::kRadiansPerDegree, w, p);
        }
        const py::ssize_t rows = py::ssize_t(result.normals.size() / 3);
        py::array normals = to_numpy(std::move(result.normals), {rows, 3});
        return py::make_tuple(normals, per_corner(std::move(result.corner_index), in.layout));
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("crease_deg") = py::none(), py::arg("weight") = "angle",
      py::arg("precision") = "double",
      (std::string(R"doc(corner_normals(V, F=None, crease_deg, weight="angle", precision="double") -> (normals, corner_index)

One normal per face corner, smooth across edges whose faces meet at less than crease_deg degrees
and split at sharper ones (boundary, non-manifold and inconsistently wound edges always split):
the library's normals/corner_normals.h, what `shadetool normals --crease DEG` writes.
  normals       (p, 3) float64: the pool of unit normals, one per (vertex, smooth group)
  corner_index  uint32 row of `normals` for every corner, shaped like F: (m, k), or (C,) for
                (indices, offsets) polygons
)doc") + kMeshArgs + "\n  crease_deg  degrees in [0, 180] (required)\n")
          .c_str());

  m.def(
      "tangents",
      [](py::object V, py::object F, py::object N, py::object UV) {
        std::shared_ptr<const shadetool::Mesh> mesh = as_mesh(V);
        FaceLayout layout;
        if (mesh) {
          if (!F.is_none() || !N.is_none() || !UV.is_none())
            throw py::value_error("tangents: with a shadetool.Mesh, F, N and UV must be None (the mesh's own are used)");
          layout = layout_of(*mesh);
        } else {
          if (N.is_none() || UV.is_none()) throw py::value_error("tangents: N (n, 3) and UV (n, 2) are required with arrays");
          auto owned = std::make_shared<shadetool::Mesh>(owned_mesh(V, F, "tangents", layout));
          const std::size_t n = owned->num_vertices();
          owned->vertex_normals = read_double_rows(N, n, 3, "tangents: N");
          owned->texcoords = read_double_rows(UV, n, 2, "tangents: UV");
          owned->texcoord_dims = 2;
          owned->corner_texcoord_index = owned->corner_vertex;
          mesh = owned;
        }
        shadetool::TangentFrames frames;
        {
          py::gil_scoped_release nogil;
          frames = shadetool::mikktspace_tangents(*mesh);  // shadetool::Error -> ValueError (module.cpp)
        }
        const py::ssize_t C = py::ssize_t(frames.tangents.size() / 4);
        if (layout.corners_per_face == 0) return to_numpy(std::move(frames.tangents), {C, 4});
        const py::ssize_t k = py::ssize_t(layout.corners_per_face);
        return to_numpy(std::move(frames.tangents), {C / k, k, 4});
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("N") = py::none(), py::arg("UV") = py::none(),
      (std::string(R"doc(tangents(V, F=None, N=None, UV=None) -> (m, k, 4) or (C, 4) float64

MikkTSpace tangent frames per face corner (the library's normals/tangents.h, what
`shadetool normals --tangents` writes): xyz a unit tangent, w = +1 or -1 the handedness
(bitangent = w * cross(normal, tangent)), exactly the reference implementation's frames (Blender,
Substance, xNormal, glTF), computed in float from the inputs rounded to float.
  N   (n, 3) float vertex normals (unit)
  UV  (n, 2) float texture coordinates per vertex (v up; for glTF's TEXCOORD_0 negate w)
  or V a shadetool.Mesh with normals and texture coordinates (F, N, UV None).
ValueError when the mesh has no texture coordinates or no normals.
)doc") + kMeshArgs + "\n")
          .c_str());
}

}  // namespace shadetool_python
