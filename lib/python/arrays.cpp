// arrays.cpp: NumPy arrays into the library's Mesh and back (arrays.h states the contract).
#include "arrays.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/engine/parallel.h>

namespace shadetool_python {
namespace {

using shadetool::Mesh;
namespace engine = shadetool::engine;

constexpr std::size_t kMaxIndex = std::numeric_limits<std::uint32_t>::max();

[[noreturn]] void bad(const std::string& what, const std::string& message) { throw py::value_error(what + ": " + message); }

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

// Any array-like as an ndarray (numpy.asarray: no copy for an ndarray).
py::array as_array(py::handle obj, const std::string& what) {
  if (obj.is_none()) bad(what, "is None; expected a NumPy array");
  py::array a = py::array::ensure(obj);
  if (!a) {
    PyErr_Clear();
    bad(what, "cannot be converted to a NumPy array");
  }
  // Non-native byte order ('>f8' on x86): converted to native first (a copy), so that every path
  // below reads the values, not their swapped bytes.
  // (NumPy reports a native order as '=', an explicit non-native one as '>' or '<'.)
  const std::uint16_t probe = 1;
  const bool little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
  if (a.dtype().byteorder() == (little ? '>' : '<'))
    a = py::array::ensure(a.attr("astype")(a.dtype().attr("newbyteorder")("=")));
  return a;
}

// Element (i, k) of a 2-D array of T at any strides (bytes).
template <class T>
T load(const char* base, py::ssize_t s0, py::ssize_t s1, std::size_t i, std::size_t k) {
  T v;
  std::memcpy(&v, base + py::ssize_t(i) * s0 + py::ssize_t(k) * s1, sizeof(T));
  return v;
}

// rows x cols values of a 2-D float array (float64 or float32) into `out` (resized). Contiguous
// input: one converting pass (assign: no zero-fill first, vectorised), serial: it is bound by
// memory and page faults, and a second thread on a busy 2-core machine costs more than it brings.
// Strided or unaligned input: element by element (memcpy loads) over TBB ranges.
template <class Out>
void copy_float_rows(const py::array& a, std::size_t rows, std::size_t cols, std::vector<Out>& out) {
  const char* base = static_cast<const char*>(a.data());
  const py::ssize_t s0 = a.strides(0), s1 = a.strides(1);
  const bool f64 = a.itemsize() == 8;
  const bool aligned = reinterpret_cast<std::uintptr_t>(base) % std::uintptr_t(a.itemsize()) == 0;
  const bool contiguous = aligned && s1 == a.itemsize() && s0 == py::ssize_t(cols) * a.itemsize();
  py::gil_scoped_release nogil;
  if (contiguous || rows == 0) {
    shadetool::reserve_bulk(out, rows * cols);  // huge pages for fresh large arrays, as the readers do
    if (f64) {
      const double* p = reinterpret_cast<const double*>(base);
      out.assign(p, p + rows * cols);
    } else {
      const float* p = reinterpret_cast<const float*>(base);
      out.assign(p, p + rows * cols);
    }
    return;
  }
  out.resize(rows * cols);
  Out* o = out.data();
  engine::parallel_ranges(rows, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i)
      for (std::size_t k = 0; k < cols; ++k)
        o[i * cols + k] = f64 ? Out(load<double>(base, s0, s1, i, k)) : Out(load<float>(base, s0, s1, i, k));
  });
}

py::array float_rows(py::handle A, std::size_t rows, std::size_t cols, const std::string& what) {
  py::array a = as_array(A, what);
  if (a.ndim() != 2 || (rows != std::size_t(-1) && std::size_t(a.shape(0)) != rows) || std::size_t(a.shape(1)) != cols) {
    const std::string want = rows == std::size_t(-1) ? "n" : std::to_string(rows);
    bad(what, "must have shape (" + want + ", " + std::to_string(cols) + "), got " + shape_text(a));
  }
  if (a.dtype().kind() != 'f' || (a.itemsize() != 8 && a.itemsize() != 4))
    bad(what, "dtype " + dtype_text(a) + " not supported; expected float64 or float32");
  return a;
}

// Integer arrays of any width and sign: values read as int64 (uint64 above 2^63 - 1 saturate to
// int64 max, which every range check refuses).
template <class F>
void with_integer_type(const py::array& a, const std::string& what, F&& f) {
  const char kind = a.dtype().kind();
  const auto size = a.itemsize();
  if (kind == 'i') {
    if (size == 1) return f(std::int8_t{});
    if (size == 2) return f(std::int16_t{});
    if (size == 4) return f(std::int32_t{});
    if (size == 8) return f(std::int64_t{});
  } else if (kind == 'u') {
    if (size == 1) return f(std::uint8_t{});
    if (size == 2) return f(std::uint16_t{});
    if (size == 4) return f(std::uint32_t{});
    if (size == 8) return f(std::uint64_t{});
  }
  bad(what, "dtype " + dtype_text(a) + " not supported; expected an integer array (int32, int64, uint32, ...)");
}

template <class I>
std::int64_t as_int64(I v) {
  if constexpr (std::is_same_v<I, std::uint64_t>)
    return v > std::uint64_t(std::numeric_limits<std::int64_t>::max()) ? std::numeric_limits<std::int64_t>::max()
                                                                        : std::int64_t(v);
  else
    return std::int64_t(v);
}

// Copies rows x cols integers of `a` (2-D, or 1-D with cols = 1) into `out` (resized) as uint32,
// checking 0 <= value < limit; returns how many are out of range (the first is found by the
// caller). Contiguous input: the range check is one read-only pass of min and max (vectorised), then
// one converting assign; strided input: element by element over TBB ranges.
std::size_t copy_indices(const py::array& a, std::size_t rows, std::size_t cols, std::uint64_t limit,
                         std::vector<std::uint32_t>& out, const std::string& what) {
  const char* base = static_cast<const char*>(a.data());
  const py::ssize_t s0 = a.ndim() >= 1 ? a.strides(0) : 0, s1 = a.ndim() == 2 ? a.strides(1) : 0;
  const bool aligned = reinterpret_cast<std::uintptr_t>(base) % std::uintptr_t(a.itemsize()) == 0;
  const bool contiguous = aligned && ((a.ndim() == 1 && s0 == a.itemsize()) ||
                                      (a.ndim() == 2 && s1 == a.itemsize() && s0 == py::ssize_t(cols) * a.itemsize()));
  std::size_t bad_count = 0;
  with_integer_type(a, what, [&](auto tag) {
    using I = decltype(tag);
    py::gil_scoped_release nogil;
    const std::size_t total = rows * cols;
    if (contiguous || total == 0) {
      const I* p = reinterpret_cast<const I*>(base);
      I lo = total ? p[0] : I(0), hi = lo;
      for (std::size_t i = 0; i < total; ++i) {
        lo = p[i] < lo ? p[i] : lo;
        hi = p[i] > hi ? p[i] : hi;
      }
      if (total == 0 || (as_int64(lo) >= 0 && std::uint64_t(as_int64(hi)) < limit)) {
        shadetool::reserve_bulk(out, total);
        if constexpr (sizeof(I) == sizeof(std::uint32_t)) {
          // int32 / uint32 in [0, limit): the same bits as uint32, so a plain copy (memmove).
          const std::uint32_t* q = reinterpret_cast<const std::uint32_t*>(p);
          out.assign(q, q + total);
        } else {
          out.assign(p, p + total);
        }
        return;
      }
    }
    out.resize(total);
    std::uint32_t* o = out.data();
    bad_count = engine::count_over_ranges(rows, [&](std::size_t b, std::size_t e) {
      std::size_t n_bad = 0;
      for (std::size_t i = b; i < e; ++i)
        for (std::size_t k = 0; k < cols; ++k) {
          const std::int64_t v = as_int64(load<I>(base, s0, s1, i, k));
          const bool ok = v >= 0 && std::uint64_t(v) < limit;
          n_bad += !ok;
          o[i * cols + k] = ok ? std::uint32_t(v) : 0;
        }
      return n_bad;
    });
  });
  return bad_count;
}

// The first (row, col) of `a` whose value is outside [0, limit) (serial; only on the error path).
std::pair<std::size_t, std::size_t> first_out_of_range(const py::array& a, std::size_t rows, std::size_t cols,
                                                       std::uint64_t limit, std::int64_t& value, const std::string& what) {
  const char* base = static_cast<const char*>(a.data());
  const py::ssize_t s0 = a.strides(0), s1 = a.ndim() == 2 ? a.strides(1) : 0;
  std::pair<std::size_t, std::size_t> at{0, 0};
  with_integer_type(a, what, [&](auto tag) {
    using I = decltype(tag);
    for (std::size_t i = 0; i < rows; ++i)
      for (std::size_t k = 0; k < cols; ++k) {
        const std::int64_t v = as_int64(load<I>(base, s0, s1, i, k));
        if (!(v >= 0 && std::uint64_t(v) < limit)) {
          value = v;
          at = {i, k};
          return;
        }
      }
  });
  return at;
}

std::string plural(std::size_t n, const char* one, const char* many) { return std::to_string(n) + (n == 1 ? one : many); }

// Whether `a` (2-D rows x cols, or 1-D) is C-contiguous and aligned to its element size: then a
// pointer of its element type reads it in place.
bool contiguous_aligned(const py::array& a, std::size_t cols) {
  const bool aligned = reinterpret_cast<std::uintptr_t>(a.data()) % std::uintptr_t(a.itemsize()) == 0;
  if (a.ndim() == 1) return aligned && a.strides(0) == a.itemsize();
  return aligned && a.ndim() == 2 && a.strides(1) == a.itemsize() && a.strides(0) == py::ssize_t(cols) * a.itemsize();
}

// The rows x cols indices of `a` in place, as uint32, when the layout allows: int32 or uint32,
// C-contiguous, aligned, every value in [0, limit) (one counting pass over the threads, GIL
// released; an int32 in that range has the bits of the same uint32). Null otherwise (also when empty): the caller copies
// (copy_indices converts any integer type and names a bad index).
const std::uint32_t* indices_in_place(const py::array& a, std::size_t rows, std::size_t cols, std::uint64_t limit) {
  const char kind = a.dtype().kind();
  const std::size_t total = rows * cols;
  if (total == 0 || a.itemsize() != 4 || (kind != 'i' && kind != 'u') || !contiguous_aligned(a, cols)) return nullptr;
  // Counted over the threads: one comparison per index on its uint32 bits (a negative int32 is
  // >= 2^31 there, and an int32 is in range only below 2^31).
  const std::uint64_t below = kind == 'i' ? std::min<std::uint64_t>(limit, std::uint64_t(1) << 31) : limit;
  bool in_range = true;
  if (below <= 0xFFFFFFFFull) {
    py::gil_scoped_release nogil;
    const std::uint32_t* p = static_cast<const std::uint32_t*>(a.data());
    const std::uint32_t lim = std::uint32_t(below);
    in_range = shadetool::engine::count_over_ranges(total, [p, lim](std::size_t b, std::size_t e) {
                 std::size_t out = 0;
                 for (std::size_t i = b; i < e; ++i) out += p[i] >= lim;
                 return out;
               }, std::size_t(1) << 16) == 0;
  }
  return in_range ? static_cast<const std::uint32_t*>(a.data()) : nullptr;
}

// face_start = 0, k, 2k, ... (faces + 1 values; faces k < 2^32, checked by the caller).
void fill_face_starts(std::size_t faces, std::size_t k, std::vector<std::uint32_t>& face_start) {
  shadetool::reserve_bulk(face_start, faces + 1);
  face_start.resize(faces + 1);
  std::uint32_t* starts = face_start.data();
  const std::uint32_t step = std::uint32_t(k);
  for (std::size_t f = 0; f <= faces; ++f) starts[f] = std::uint32_t(f) * step;
}

// Positions as the library reads them: in place in V's array, or in storage.positions.
struct PositionArray {
  const double* data;
  std::size_t vertices;
};
// Faces as the library reads them: corners (and polygon offsets) in place in F's arrays, or in
// storage.corner_vertex (storage.face_start); face_start null for (m, 3) triangles.
struct FaceArrays {
  const std::uint32_t* corners = nullptr;
  const std::uint32_t* face_start = nullptr;
  std::size_t faces = 0, corner_count = 0;
  FaceLayout layout;
};

}  // namespace

shadetool::Weighting parse_weighting(const std::string& value, const std::string& fn) {
  return shadetool::parse_weighting(value, fn + ": weight");  // normals/weighting.h's vocabulary
}

shadetool::Precision parse_precision(const std::string& value, const std::string& fn) {
  return shadetool::parse_precision(value, fn + ": precision");
}

namespace {

PositionArray positions_in_place_or_copied(py::handle V, const std::string& what, Mesh& storage,
                                           std::vector<py::object>& keep) {
  py::array a = float_rows(V, std::size_t(-1), 3, what);
  const std::size_t n = std::size_t(a.shape(0));
  if (n > kMaxIndex) bad(what, plural(n, " vertex", " vertices") + ": more than the library's 2^32 - 1");
  storage.precision = a.itemsize() == 8 ? shadetool::ValuePrecision::Double : shadetool::ValuePrecision::Float;
  if (n > 0 && a.itemsize() == 8 && contiguous_aligned(a, 3)) {  // float64 (n, 3) C-contiguous: in place
    keep.push_back(a);
    return {static_cast<const double*>(a.data()), n};
  }
  copy_float_rows(a, n, 3, storage.positions);
  return {storage.positions.data(), n};
}

FaceArrays faces_in_place_or_copied(py::handle F, const std::string& what, std::size_t n, Mesh& storage,
                                    std::vector<py::object>& keep) {
  auto index_error = [&](const py::array& a, std::size_t rows, std::size_t cols, std::size_t count,
                         const std::string& where) {
    std::int64_t value = 0;
    const auto at = first_out_of_range(a, rows, cols, n, value, what);
    const std::string first = cols == 1 ? where + " " + std::to_string(at.first)
                                        : "face " + std::to_string(at.first) + " corner " + std::to_string(at.second);
    bad(what, plural(count, " vertex index", " vertex indices") + " out of range [0, " + std::to_string(n) +
                  ") (first: " + first + " is " + std::to_string(value) + ")");
  };
  // The indices of `a` in place when the layout allows, else copied (and checked) into `into`.
  auto indices = [&](const py::array& a, std::size_t rows, std::size_t cols, std::uint64_t limit,
                     std::vector<std::uint32_t>& into, const std::string& arg, std::size_t& bad_count) {
    bad_count = 0;
    if (const std::uint32_t* p = indices_in_place(a, rows, cols, limit)) {
      keep.push_back(a);
      return p;
    }
    bad_count = copy_indices(a, rows, cols, limit, into, arg);
    return static_cast<const std::uint32_t*>(into.data());
  };
  FaceArrays out;
  if (py::isinstance<py::tuple>(F) && py::len(F) == 2) {  // polygons: (indices, offsets)
    py::tuple pair = F.cast<py::tuple>();
    py::array index_array = as_array(pair[0], what + "[0] (indices)");
    py::array offsets = as_array(pair[1], what + "[1] (offsets)");
    if (index_array.ndim() != 1) bad(what + "[0] (indices)", "must be 1-D, got shape " + shape_text(index_array));
    if (offsets.ndim() != 1 || offsets.shape(0) < 1)
      bad(what + "[1] (offsets)", "must be 1-D with m + 1 >= 1 entries, got shape " + shape_text(offsets));
    const std::size_t corners = std::size_t(index_array.shape(0));
    const std::size_t faces = std::size_t(offsets.shape(0)) - 1;
    if (corners > kMaxIndex) bad(what, std::to_string(corners) + " corners: more than the library's 2^32 - 1");
    // Offsets within [0, C]: checked with limit C + 1, then their order.
    std::size_t bad_count = 0;
    const std::uint32_t* starts =
        indices(offsets, faces + 1, 1, std::uint64_t(corners) + 1, storage.face_start, what + "[1] (offsets)", bad_count);
    if (bad_count > 0) bad(what + "[1] (offsets)", plural(bad_count, " offset", " offsets") + " outside [0, " + std::to_string(corners) + "]");
    if (starts[0] != 0) bad(what + "[1] (offsets)", "must start at 0, got " + std::to_string(starts[0]));
    if (starts[faces] != corners)
      bad(what + "[1] (offsets)", "must end at len(indices) = " + std::to_string(corners) + ", got " + std::to_string(starts[faces]));
    // Faces of fewer than 3 corners are refused, as the file readers refuse them (and a mix of
    // them with larger faces could otherwise total 3 corners per face and pass for triangles).
    for (std::size_t f = 0; f < faces; ++f) {
      if (starts[f + 1] < starts[f])
        bad(what + "[1] (offsets)", "must be non-decreasing (offsets[" + std::to_string(f + 1) + "] < offsets[" + std::to_string(f) + "])");
      if (starts[f + 1] - starts[f] < 3)
        bad(what + "[1] (offsets)", "face " + std::to_string(f) + " has " + std::to_string(starts[f + 1] - starts[f]) +
                                        " corners (a face needs at least 3)");
    }
    out.corners = indices(index_array, corners, 1, n, storage.corner_vertex, what + "[0] (indices)", bad_count);
    if (bad_count > 0) index_error(index_array, corners, 1, bad_count, "indices");
    out.face_start = starts;
    out.faces = faces;
    out.corner_count = corners;
    out.layout = FaceLayout{0};
    return out;
  }
  py::array a = as_array(F, what);
  if (a.ndim() != 2 || a.shape(1) < 3)
    bad(what, "must have shape (m, k) (k >= 3 corners per face; triangles: (m, 3)) or be a tuple (indices, offsets), got shape " +
                  shape_text(a));
  const std::size_t faces = std::size_t(a.shape(0)), k = std::size_t(a.shape(1));
  if (faces * k > kMaxIndex) bad(what, std::to_string(faces * k) + " corners: more than the library's 2^32 - 1");
  std::size_t bad_count = 0;
  out.corners = indices(a, faces, k, n, storage.corner_vertex, what, bad_count);
  if (bad_count > 0) index_error(a, faces, k, bad_count, "");
  out.faces = faces;
  out.corner_count = faces * k;
  out.layout = FaceLayout{k};
  if (k != 3) {  // face starts k f (small: F + 1 values); triangles need none (corner = 3 f + j)
    py::gil_scoped_release nogil;
    fill_face_starts(faces, k, storage.face_start);
    out.face_start = storage.face_start.data();
  }
  return out;
}

}  // namespace

void read_positions(py::handle V, const std::string& what, Mesh& mesh) {
  std::vector<py::object> keep;
  const PositionArray p = positions_in_place_or_copied(V, what, mesh, keep);
  if (p.data != mesh.positions.data()) {  // read in place: the Mesh needs its own copy
    py::gil_scoped_release nogil;
    shadetool::reserve_bulk(mesh.positions, 3 * p.vertices);
    mesh.positions.assign(p.data, p.data + 3 * p.vertices);
  }
}

FaceLayout read_faces(py::handle F, const std::string& what, Mesh& mesh) {
  std::vector<py::object> keep;
  const FaceArrays f = faces_in_place_or_copied(F, what, mesh.num_vertices(), mesh, keep);
  py::gil_scoped_release nogil;
  if (f.corners != mesh.corner_vertex.data()) {  // read in place: the Mesh needs its own copy
    shadetool::reserve_bulk(mesh.corner_vertex, f.corner_count);
    mesh.corner_vertex.assign(f.corners, f.corners + f.corner_count);
  }
  if (!f.face_start) fill_face_starts(f.faces, 3, mesh.face_start);
  else if (f.face_start != mesh.face_start.data()) mesh.face_start.assign(f.face_start, f.face_start + f.faces + 1);
  return f.layout;
}

MeshViewInput mesh_view_input(py::handle V, py::handle F, const std::string& fn) {
  MeshViewInput in;
  if (std::shared_ptr<Mesh> m = as_mesh(V)) {
    if (!F.is_none()) bad(fn + ": F", "must be None when the first argument is a shadetool.Mesh");
    in.view = shadetool::MeshView(*m);
    in.layout = layout_of(*m);
    in.storage = m;
    return in;
  }
  if (F.is_none()) bad(fn + ": F", "is required when V is an array (faces: (m, 3) integers, or (indices, offsets))");
  auto storage = std::make_shared<Mesh>();
  const PositionArray p = positions_in_place_or_copied(V, fn + ": V", *storage, in.keep);
  const FaceArrays f = faces_in_place_or_copied(F, fn + ": F", p.vertices, *storage, in.keep);
  in.view = f.face_start ? shadetool::MeshView::polygons(p.data, p.vertices, f.corners, f.face_start, f.faces)
                         : shadetool::MeshView::triangles(p.data, p.vertices, f.corners, f.faces);
  in.layout = f.layout;
  in.storage = std::move(storage);
  return in;
}

std::vector<double> read_double_rows(py::handle A, std::size_t rows, std::size_t cols, const std::string& what) {
  py::array a = float_rows(A, rows, cols, what);
  std::vector<double> out;
  copy_float_rows(a, rows, cols, out);
  return out;
}

std::vector<float> read_float_rows(py::handle A, std::size_t rows, std::size_t cols, const std::string& what) {
  py::array a = float_rows(A, rows, cols, what);
  std::vector<float> out;
  copy_float_rows(a, rows, cols, out);
  return out;
}

FaceLayout layout_of(const Mesh& mesh) {
  if (mesh.num_faces() == 0) return FaceLayout{3};
  const std::size_t k = mesh.face_size(0);
  for (std::size_t f = 1; f < mesh.num_faces(); ++f)
    if (mesh.face_size(f) != k) return FaceLayout{0};
  return FaceLayout{k == 0 ? 0 : k};
}

std::shared_ptr<Mesh> as_mesh(py::handle obj) {
  if (!py::isinstance<PyMesh>(obj)) return nullptr;
  return obj.cast<PyMesh&>().mesh;
}

MeshInput mesh_input(py::handle V, py::handle F, const std::string& fn) {
  if (std::shared_ptr<Mesh> m = as_mesh(V)) {
    if (!F.is_none()) bad(fn + ": F", "must be None when the first argument is a shadetool.Mesh");
    return MeshInput{m, layout_of(*m)};
  }
  if (F.is_none()) bad(fn + ": F", "is required when V is an array (faces: (m, 3) integers, or (indices, offsets))");
  auto mesh = std::make_shared<Mesh>();
  read_positions(V, fn + ": V", *mesh);
  const FaceLayout layout = read_faces(F, fn + ": F", *mesh);
  return MeshInput{std::move(mesh), layout};
}

Mesh owned_mesh(py::handle V, py::handle F, const std::string& fn, FaceLayout& layout) {
  if (std::shared_ptr<Mesh> m = as_mesh(V)) {
    if (!F.is_none()) bad(fn + ": F", "must be None when the first argument is a shadetool.Mesh");
    layout = layout_of(*m);
    return *m;
  }
  if (F.is_none()) bad(fn + ": F", "is required when V is an array (faces: (m, 3) integers, or (indices, offsets))");
  Mesh mesh;
  read_positions(V, fn + ": V", mesh);
  layout = read_faces(F, fn + ": F", mesh);
  return mesh;
}

py::object faces_out(Mesh&& mesh, const FaceLayout& layout) {
  const std::size_t k = layout.corners_per_face;
  if (k > 0 && mesh.num_corners() == k * mesh.num_faces()) {
    bool uniform = true;
    for (std::size_t f = 0; f < mesh.num_faces() && uniform; ++f) uniform = mesh.face_size(f) == k;
    if (uniform) {
      const py::ssize_t m = py::ssize_t(mesh.num_faces());
      return to_numpy(std::move(mesh.corner_vertex), {m, py::ssize_t(k)});
    }
  }
  const py::ssize_t c = py::ssize_t(mesh.num_corners()), s = py::ssize_t(mesh.face_start.size());
  return py::make_tuple(to_numpy(std::move(mesh.corner_vertex), {c}), to_numpy(std::move(mesh.face_start), {s}));
}

}  // namespace shadetool_python
