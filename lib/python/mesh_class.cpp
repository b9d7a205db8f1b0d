// mesh_class.cpp: shadetool.Mesh (the library's Mesh behind NumPy views), read_mesh, write_mesh.
#include <filesystem>
#include <string>

#include <pybind11/stl/filesystem.h>

#include <shadetool/files/mesh_files.h>

#include "arrays.h"
#include "bindings.h"

namespace shadetool_python {
namespace {

using shadetool::Mesh;
namespace fs = std::filesystem;

// A view of one of the mesh's arrays (no copy); the view keeps the mesh alive. Writing through it
// changes the mesh in place.
template <class T>
py::object view(const std::shared_ptr<Mesh>& mesh, std::vector<T>& v, std::vector<py::ssize_t> shape) {
  auto* keep = new std::shared_ptr<Mesh>(mesh);
  py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<Mesh>*>(p); });
  return py::array_t<T>(std::move(shape), v.data(), base);
}

// {name: (n,) float64 view} of a mesh's extra properties (Mesh::vertex_properties / face_properties).
py::dict property_views(const std::shared_ptr<Mesh>& mesh, std::vector<shadetool::MeshProperty>& props) {
  py::dict d;
  for (auto& p : props) d[py::str(p.name)] = view(mesh, p.values, {py::ssize_t(p.values.size())});
  return d;
}

py::ssize_t rows(const std::vector<double>& v) { return py::ssize_t(v.size() / 3); }

// Copy on write: views handed out keep the old mesh; the wrapper takes a changed copy.
template <class Change>
void change(PyMesh& self, Change&& f) {
  auto fresh = std::make_shared<Mesh>(*self.mesh);
  f(*fresh);
  self.mesh = std::move(fresh);
}

std::vector<float> read_colors(py::handle A, std::size_t rows, const std::string& what, int& channels) {
  py::array a = py::array::ensure(A);
  const std::size_t cols = a && a.ndim() == 2 && a.shape(1) == 4 ? 4 : 3;
  channels = int(cols);
  return read_float_rows(A, rows, cols, what);
}

void set_faces(Mesh& m, py::handle F) {
  Mesh staged;  // positions are needed only for the index check
  staged.positions.resize(m.positions.size());
  read_faces(F, "Mesh.faces", staged);
  if (staged.num_faces() != m.num_faces()) {  // per-face data no longer matches
    m.face_normals.clear();
    m.face_colors.clear();
    m.face_quality.clear();
    m.face_group_run.clear();
  }
  if (staged.num_corners() != m.num_corners()) {  // per-corner data no longer matches
    m.corner_normal_index.clear();
    m.corner_normals.clear();
    m.corner_texcoord_index.clear();
  }
  m.face_start = std::move(staged.face_start);
  m.corner_vertex = std::move(staged.corner_vertex);
}

fs::path parent_of(const std::string& path) {
  const fs::path p = fs::absolute(fs::path(path));
  return p.parent_path();
}

}  // namespace

void init_mesh(py::module_& m) {
  py::class_<PyMesh>(m, "Mesh", R"doc(
A mesh as the library holds it: indexed flat arrays, read from or written to OBJ, PLY, OFF, STL.

Mesh(vertices, faces, vertex_normals=None, face_normals=None, vertex_colors=None, face_colors=None)

  vertices        (n, 3) float64 or float32: copied once into the mesh's float64 store
                  (float32 widened exactly; the mesh remembers float32 and writes float32 again)
  faces           (m, k) integers (k corners per face; triangles (m, 3)), any integer dtype, or a
                  tuple (indices, offsets) for polygons of mixed sizes: copied into uint32
  vertex_normals  (n, 3) float, face_normals (m, 3) float (stored float64)
  vertex_colors   (n, 3) or (n, 4) float, linear, nominally in [0, 1]; face_colors (m, 3|4)

Attributes read back are NumPy views of the mesh's own arrays (no copy; writing into them changes
the mesh in place): vertices (n, 3) float64, faces (m, k) uint32 (ValueError when face sizes
differ: use face_indices / face_offsets), face_indices (C,) uint32, face_offsets (m + 1,) uint32,
vertex_normals (n, 3) float64 or None, face_normals (m, 3) float64 or None, corner_normals
(p, 3) float64 pool or None with corner_normal_index (C,) uint32, vertex_colors / face_colors
(rows, 3 or 4) float32 or None, vertex_quality (n,) / face_quality (m,) float32 or None. Assigning an attribute copies the whole mesh once (views taken
before keep the old arrays, so none dangles). Do not write into a view while another thread
computes on the same Mesh (the library reads it without the GIL).
)doc")
      .def(py::init([](py::object vertices, py::object faces, py::object vertex_normals, py::object face_normals,
                       py::object vertex_colors, py::object face_colors) {
             PyMesh self;
             Mesh& mesh = *self.mesh;
             read_positions(vertices, "Mesh: vertices", mesh);
             read_faces(faces, "Mesh: faces", mesh);
             if (!vertex_normals.is_none())
               mesh.vertex_normals = read_double_rows(vertex_normals, mesh.num_vertices(), 3, "Mesh: vertex_normals");
             if (!face_normals.is_none())
               mesh.face_normals = read_double_rows(face_normals, mesh.num_faces(), 3, "Mesh: face_normals");
             int channels = 3;
             if (!vertex_colors.is_none())
               mesh.vertex_colors = read_colors(vertex_colors, mesh.num_vertices(), "Mesh: vertex_colors", channels);
             if (!face_colors.is_none()) {
               int face_channels = 3;
               mesh.face_colors = read_colors(face_colors, mesh.num_faces(), "Mesh: face_colors", face_channels);
               if (!vertex_colors.is_none() && face_channels != channels)
                 throw py::value_error("Mesh: vertex_colors and face_colors must have the same number of channels (3 or 4)");
               channels = face_channels;
             }
             mesh.color_channels = channels;
             mesh.colors_are_float = true;
             return self;
           }),
           py::arg("vertices"), py::arg("faces"), py::arg("vertex_normals") = py::none(),
           py::arg("face_normals") = py::none(), py::arg("vertex_colors") = py::none(), py::arg("face_colors") = py::none())
      .def_property_readonly("num_vertices", [](const PyMesh& s) { return s.mesh->num_vertices(); })
      .def_property_readonly("num_faces", [](const PyMesh& s) { return s.mesh->num_faces(); })
      .def_property(
          "vertices", [](PyMesh& s) { return view(s.mesh, s.mesh->positions, {rows(s.mesh->positions), 3}); },
          [](PyMesh& s, py::object V) {
            change(s, [&](Mesh& m) {
              const std::size_t n = m.num_vertices();
              m.positions = read_double_rows(V, n, 3, "Mesh.vertices (same vertex count; build a new Mesh to change it)");
            });
          },
          "(n, 3) float64 view of the positions")
      .def_property(
          "faces",
          [](PyMesh& s) {
            const FaceLayout layout = layout_of(*s.mesh);
            if (layout.corners_per_face == 0)
              throw py::value_error("Mesh.faces: faces of different sizes; use face_indices and face_offsets");
            return view(s.mesh, s.mesh->corner_vertex,
                        {py::ssize_t(s.mesh->num_faces()), py::ssize_t(layout.corners_per_face)});
          },
          [](PyMesh& s, py::object F) { change(s, [&](Mesh& m) { set_faces(m, F); }); },
          "(m, k) uint32 view of the faces' vertex indices (every face with k corners)")
      .def_property_readonly(
          "face_indices", [](PyMesh& s) { return view(s.mesh, s.mesh->corner_vertex, {py::ssize_t(s.mesh->num_corners())}); },
          "(C,) uint32 view: the vertex index of every corner, face after face")
      .def_property_readonly(
          "face_offsets", [](PyMesh& s) { return view(s.mesh, s.mesh->face_start, {py::ssize_t(s.mesh->face_start.size())}); },
          "(m + 1,) uint32 view: face f uses face_indices[face_offsets[f]:face_offsets[f + 1]]")
      .def_property(
          "vertex_normals",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_vertex_normals()) return py::none();
            return view(s.mesh, s.mesh->vertex_normals, {rows(s.mesh->vertex_normals), 3});
          },
          [](PyMesh& s, py::object N) {
            change(s, [&](Mesh& m) {
              if (N.is_none()) m.vertex_normals.clear();
              else m.vertex_normals = read_double_rows(N, m.num_vertices(), 3, "Mesh.vertex_normals");
            });
          },
          "(n, 3) float64 view or None; assigning (n, 3) floats or None")
      .def_property(
          "face_normals",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_face_normals()) return py::none();
            return view(s.mesh, s.mesh->face_normals, {rows(s.mesh->face_normals), 3});
          },
          [](PyMesh& s, py::object N) {
            change(s, [&](Mesh& m) {
              if (N.is_none()) m.face_normals.clear();
              else m.face_normals = read_double_rows(N, m.num_faces(), 3, "Mesh.face_normals");
            });
          },
          "(m, 3) float64 view or None")
      .def_property_readonly(
          "corner_normals",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_corner_normals()) return py::none();
            return view(s.mesh, s.mesh->corner_normals, {rows(s.mesh->corner_normals), 3});
          },
          "(p, 3) float64 view of the corner normal pool (OBJ vn, creases) or None")
      .def_property_readonly(
          "corner_normal_index",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_corner_normals()) return py::none();
            return view(s.mesh, s.mesh->corner_normal_index, {py::ssize_t(s.mesh->corner_normal_index.size())});
          },
          "(C,) uint32 view: each corner's row of corner_normals, or None")
      .def_property(
          "vertex_colors",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_vertex_colors()) return py::none();
            const py::ssize_t ch = s.mesh->color_channels;
            return view(s.mesh, s.mesh->vertex_colors, {py::ssize_t(s.mesh->vertex_colors.size()) / ch, ch});
          },
          [](PyMesh& s, py::object C) {
            change(s, [&](Mesh& m) {
              if (C.is_none()) {
                m.vertex_colors.clear();
                return;
              }
              int ch = 3;
              m.vertex_colors = read_colors(C, m.num_vertices(), "Mesh.vertex_colors", ch);
              if (m.has_face_colors() && ch != m.color_channels)
                throw py::value_error("Mesh.vertex_colors: must have as many channels as face_colors (" +
                                      std::to_string(m.color_channels) + ")");
              m.color_channels = ch;
              m.colors_are_float = true;
            });
          },
          "(n, 3|4) float32 view (linear colours) or None")
      .def_property(
          "face_colors",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_face_colors()) return py::none();
            const py::ssize_t ch = s.mesh->color_channels;
            return view(s.mesh, s.mesh->face_colors, {py::ssize_t(s.mesh->face_colors.size()) / ch, ch});
          },
          [](PyMesh& s, py::object C) {
            change(s, [&](Mesh& m) {
              if (C.is_none()) {
                m.face_colors.clear();
                return;
              }
              int ch = 3;
              m.face_colors = read_colors(C, m.num_faces(), "Mesh.face_colors", ch);
              if (m.has_vertex_colors() && ch != m.color_channels)
                throw py::value_error("Mesh.face_colors: must have as many channels as vertex_colors (" +
                                      std::to_string(m.color_channels) + ")");
              m.color_channels = ch;
              m.colors_are_float = true;
            });
          },
          "(m, 3|4) float32 view (linear colours) or None")
      .def_property_readonly(
          "vertex_quality",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_vertex_quality()) return py::none();
            return view(s.mesh, s.mesh->vertex_quality, {py::ssize_t(s.mesh->vertex_quality.size())});
          },
          "(n,) float32 view of a scalar per vertex (PLY `quality`; occlusion's output) or None")
      .def_property_readonly(
          "face_quality",
          [](PyMesh& s) -> py::object {
            if (!s.mesh->has_face_quality()) return py::none();
            return view(s.mesh, s.mesh->face_quality, {py::ssize_t(s.mesh->face_quality.size())});
          },
          "(m,) float32 view of a scalar per face (PLY face `quality`) or None")
      .def_property_readonly(
          "vertex_properties",
          [](PyMesh& s) { return property_views(s.mesh, s.mesh->vertex_properties); },
          "{name: (n,) float64 view}: the PLY file's other scalar vertex properties (a scanner's confidence, "
          "intensity, ...), kept and written back to PLY in their declared types")
      .def_property_readonly(
          "face_properties",
          [](PyMesh& s) { return property_views(s.mesh, s.mesh->face_properties); },
          "{name: (m,) float64 view}: the PLY file's other scalar face properties (flags, ...)")
      .def_property_readonly(
          "comments",
          [](const PyMesh& s) {
            py::list l;
            for (const auto& c : s.mesh->comments) l.append(py::str(c));
            return l;
          },
          "The file's comment lines (PLY header `comment` / `obj_info` lines, keyword included)")
      .def("clear_normals",
           [](PyMesh& s) {
             change(s, [](Mesh& m) {
               m.vertex_normals.clear();
               m.corner_normals.clear();
               m.corner_normal_index.clear();
               m.face_normals.clear();
             });
           },
           "Removes every normal (vertex, corner, face), as `shadetool normals --recompute` does first.")
      .def_property(
          "precision",
          [](const PyMesh& s) { return shadetool::value_precision_name(s.mesh->precision); },
          [](PyMesh& s, const std::string& p) {
            const shadetool::ValuePrecision precision = shadetool::parse_value_precision(p, "Mesh.precision");
            change(s, [&](Mesh& m) { m.precision = precision; });
          },
          "'float' or 'double': the number type a writer uses (as read, or as the vertices' dtype)")
      .def("copy", [](const PyMesh& s) { PyMesh c; c.mesh = std::make_shared<Mesh>(*s.mesh); return c; },
           "A deep copy.")
      .def("__repr__", [](const PyMesh& s) {
        const Mesh& m = *s.mesh;
        std::string r = "<shadetool.Mesh " + std::to_string(m.num_vertices()) + " vertices, " +
                        std::to_string(m.num_faces()) + " faces";
        if (m.has_vertex_normals()) r += ", vertex normals";
        if (m.has_corner_normals()) r += ", corner normals";
        if (m.has_face_normals()) r += ", face normals";
        if (m.has_vertex_colors()) r += ", vertex colors";
        if (m.has_face_colors()) r += ", face colors";
        return r + ">";
      });

  m.def(
      "read_mesh",
      [](const fs::path& path, const std::string& format) {
        const std::string p = path.string();
        if (!fs::exists(path)) throw_file_not_found(p, "no such file");
        const shadetool::Format f = format.empty() ? shadetool::Format::Auto : shadetool::parse_format_name(format, "format");
        PyMesh out;
        {
          py::gil_scoped_release nogil;
          *out.mesh = shadetool::read_mesh(p, f);
        }
        return out;
      },
      py::arg("path"), py::arg("format") = "", R"doc(
read_mesh(path, format="") -> Mesh

Reads an OBJ, PLY, OFF, STL or glTF 2.0 file (format from the extension unless given: "obj",
"ply", "off", "stl", "gltf"/"glb") with the library's readers: nothing read is dropped (polygons,
normals, colours, quality). A glTF file's triangle primitives come as one mesh in world space,
placed by the scene's nodes as assimp and Blender place them (a mesh shown by two nodes twice;
mirrored nodes re-wound; TEXCOORD_0 with v flipped; notes in the C++ header gltf/gltf_scene.h); the
command line processes them one by one in object space and keeps the rest of the document.
FileNotFoundError when the file does not exist; ValueError with the reader's `FILE:LINE: what`
message for bad content.
)doc");

  m.def(
      "write_mesh",
      [](const fs::path& path, py::object mesh, py::object F, py::object vertex_normals, bool binary,
         const std::string& format) {
        std::shared_ptr<const Mesh> to_write;
        if (std::shared_ptr<Mesh> given = as_mesh(mesh)) {
          if (!F.is_none() || !vertex_normals.is_none())
            throw py::value_error("write_mesh: F and vertex_normals must be None when a shadetool.Mesh is given");
          to_write = given;
        } else {
          auto built = std::make_shared<Mesh>();
          if (F.is_none()) throw py::value_error("write_mesh: F: is required when V is an array");
          read_positions(mesh, "write_mesh: V", *built);
          read_faces(F, "write_mesh: F", *built);
          if (!vertex_normals.is_none())
            built->vertex_normals = read_double_rows(vertex_normals, built->num_vertices(), 3, "write_mesh: vertex_normals");
          to_write = built;
        }
        const std::string p = path.string();
        const fs::path dir = parent_of(p);
        if (!fs::is_directory(dir)) throw_file_not_found(p, "directory " + dir.string() + " does not exist");
        shadetool::WriteOptions options;
        options.format = format.empty() ? shadetool::Format::Auto : shadetool::parse_format_name(format, "format");
        options.binary = binary;
        py::gil_scoped_release nogil;
        shadetool::write_mesh(*to_write, p, options);
      },
      py::arg("path"), py::arg("mesh"), py::arg("F") = py::none(), py::kw_only(),
      py::arg("vertex_normals") = py::none(), py::arg("binary") = true, py::arg("format") = "", R"doc(
write_mesh(path, mesh, F=None, *, vertex_normals=None, binary=True, format="") -> None

Writes a Mesh, or arrays V (n, 3) float, F (m, k) integers or (indices, offsets) with optional
vertex_normals (n, 3), with the library's writers, atomically (a temporary file renamed into
place: on any error no file is left and an existing one is untouched). binary: PLY and STL as
binary (default) or text. Format from the extension unless given. FileNotFoundError when the
directory does not exist; ValueError with the writer's message (e.g. NaN coordinates).
)doc");
}

}  // namespace shadetool_python
