// fuzz_mesh_reader.h: what every mesh-reader fuzz target checks, for one format.
//
// A reader given arbitrary bytes must either return a mesh that satisfies the Mesh invariants
// (core/mesh.h) or throw shadetool::Error. Anything else is a bug the fuzzer reports:
//   - any other exception (std::bad_alloc from a count the file lied about, std::length_error, ...),
//   - a crash, a sanitizer report (ASan/UBSan are on in the fuzz build),
//   - an allocation above -malloc_limit_mb (run.sh sets it: a 2^40-vertex header must not allocate),
//   - a mesh that breaks an invariant (index out of range, attribute array of the wrong size),
//   - a mesh our own writers cannot write, or whose written file our reader cannot read back with
//     the same vertex and face counts (OBJ, PLY binary and ascii, OFF; STL is checked for faces).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/files/mesh_files.h>

namespace shadetool_fuzz {

// Under libFuzzer a broken invariant aborts (the fuzzer saves the input); the corpus replay test
// (tests/bad_inputs/fuzz_corpus_replay.cpp) defines SHADETOOL_FUZZ_REPLAY to get an exception.
[[noreturn]] inline void bug(const char* what, std::size_t a = 0, std::size_t b = 0) {
  char message[256];
  std::snprintf(message, sizeof message, "fuzz: invariant broken: %s (%zu, %zu)", what, a, b);
#ifdef SHADETOOL_FUZZ_REPLAY
  throw std::logic_error(message);
#else
  std::fprintf(stderr, "%s\n", message);
  std::abort();
#endif
}

inline void check_invariants(const shadetool::Mesh& m) {
  using std::size_t;
  if (m.positions.size() % 3 != 0) bug("positions not a multiple of 3", m.positions.size());
  const size_t nv = m.num_vertices();
  if (m.face_start.empty() || m.face_start[0] != 0) bug("face_start must start with 0");
  if (m.face_start.back() != m.corner_vertex.size()) bug("face_start.back() != #corners", m.face_start.back(), m.corner_vertex.size());
  const size_t nf = m.num_faces();
  for (size_t f = 0; f < nf; ++f)
    if (m.face_start[f + 1] < m.face_start[f] + 3) bug("face with fewer than 3 corners", f, m.face_size(f));
  for (size_t c = 0; c < m.corner_vertex.size(); ++c)
    if (m.corner_vertex[c] >= nv) bug("corner_vertex out of range", c, m.corner_vertex[c]);
  if (!m.vertex_normals.empty() && m.vertex_normals.size() != 3 * nv) bug("vertex_normals size", m.vertex_normals.size(), nv);
  if (!m.face_normals.empty() && m.face_normals.size() != 3 * nf) bug("face_normals size", m.face_normals.size(), nf);
  if (m.corner_normals.size() % 3 != 0) bug("corner_normals not a multiple of 3");
  if (!m.corner_normal_index.empty()) {
    if (m.corner_normal_index.size() != m.corner_vertex.size()) bug("corner_normal_index size");
    for (auto i : m.corner_normal_index)
      if (i >= m.corner_normals.size() / 3) bug("corner_normal_index out of range", i);
  }
  if (m.texcoord_dims < 1 || m.texcoord_dims > 3) bug("texcoord_dims", size_t(m.texcoord_dims));
  if (!m.corner_texcoord_index.empty()) {
    if (m.corner_texcoord_index.size() != m.corner_vertex.size()) bug("corner_texcoord_index size");
    for (auto i : m.corner_texcoord_index)
      if (i != shadetool::kNoTexcoord && i >= m.texcoords.size() / size_t(m.texcoord_dims)) bug("corner_texcoord_index out of range", i);
  }
  if (m.color_channels != 3 && m.color_channels != 4) bug("color_channels", size_t(m.color_channels));
  const size_t ch = size_t(m.color_channels);
  if (!m.vertex_colors.empty() && m.vertex_colors.size() != ch * nv) bug("vertex_colors size", m.vertex_colors.size(), nv);
  if (!m.face_colors.empty() && m.face_colors.size() != ch * nf) bug("face_colors size", m.face_colors.size(), nf);
}

// Our writers must write what our readers accept, and the counts must survive.
inline void check_round_trip(const shadetool::Mesh& m) {
  using shadetool::Format;
  struct Case { Format format; bool binary; };
  const Case cases[] = {{Format::Obj, false}, {Format::Ply, true}, {Format::Ply, false}, {Format::Off, false},
                        {Format::Stl, true}};
  std::size_t triangles = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) triangles += m.face_size(f) - 2;
  for (const Case& c : cases) {
    shadetool::WriteOptions wo;
    wo.format = c.format;
    wo.binary = c.binary;
    shadetool::WriteInfo wi;
    std::string bytes;
    try {
      bytes = shadetool::write_mesh_to_memory(m, wo, &wi);
    } catch (const shadetool::Error&) {
      continue;  // a writer may refuse (e.g. more than 2^32 triangles for STL), with a message
    }
    shadetool::Mesh back;
    try {
      back = shadetool::read_mesh_from_memory(bytes, c.format, "roundtrip");
    } catch (const shadetool::Error& e) {
      std::fprintf(stderr, "fuzz: our own %s output does not read back: %s\n",
                   shadetool::format_extension(c.format), e.what());
      bug("our own output does not read back");
    }
    check_invariants(back);
    if (c.format == Format::Stl) {
      if (back.num_faces() != triangles) bug("STL round trip: triangle count", back.num_faces(), triangles);
      continue;
    }
    if (back.num_faces() != m.num_faces()) bug("round trip: face count", back.num_faces(), m.num_faces());
    if (back.num_vertices() != m.num_vertices() + wi.split_vertices)
      bug("round trip: vertex count", back.num_vertices(), m.num_vertices() + wi.split_vertices);
  }
}

inline int fuzz_one(const std::uint8_t* data, std::size_t size, shadetool::Format format, const char* name) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  shadetool::Mesh mesh;
  try {
    mesh = shadetool::read_mesh_from_memory(bytes, format, name);
  } catch (const shadetool::Error&) {
    return 0;  // refused with a message: the expected outcome for most inputs
  }
  // Any other exception escapes: libFuzzer reports it as a crash.
  check_invariants(mesh);
  check_round_trip(mesh);
  return 0;
}

}  // namespace shadetool_fuzz
