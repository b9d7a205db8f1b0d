// update_mesh_normals.cpp: see update_mesh_normals.h.
#include <shadetool/normals/update_mesh_normals.h>

#include <shadetool/core/math_constants.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/flat_patches.h>
#include <shadetool/normals/invalid_normals.h>
#include <shadetool/normals/two_sided_faces.h>
#include <shadetool/normals/vertex_fallback.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {
namespace {

std::size_t rows(const std::vector<double>& a) { return a.size() / 3; }

// Invalid corner normals: referenced pool entries that are NaN/Inf/zero, plus corners whose index
// points outside the pool (a broken file; such a corner has no normal at all).
std::size_t invalid_corner_normals(const Mesh& mesh) {
  std::vector<double> used;
  std::vector<char> seen(rows(mesh.corner_normals), 0);
  std::size_t out_of_range = 0;
  for (std::uint32_t i : mesh.corner_normal_index) {
    if (i >= seen.size()) { ++out_of_range; continue; }
    if (seen[i]) continue;
    seen[i] = 1;
    for (int k = 0; k < 3; ++k) used.push_back(mesh.corner_normals[3 * std::size_t(i) + k]);
  }
  return count_invalid_normals(used) + out_of_range;
}

std::size_t count_degenerate(const std::vector<double>& face_normals) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < rows(face_normals); ++f)
    if (face_normals[3 * f] == 0.0 && face_normals[3 * f + 1] == 0.0 && face_normals[3 * f + 2] == 0.0) ++n;
  return n;
}

// Corner normals computed on front_faces(mesh, two) become the whole mesh's: a front face's corners
// keep theirs; a back face's corner gets the reverse of its front's corner at the same vertex (one
// reversed pool entry per front entry, appended): each side shades as itself.
void split_back_corners(const Mesh& mesh, const TwoSidedFaces& two, CornerNormals& cn) {
  const std::size_t F = mesh.num_faces();
  std::vector<std::uint32_t> front_start(F, 0);  // first corner of each front face in the front mesh
  std::uint32_t next = 0;
  for (std::size_t f = 0; f < F; ++f)
    if (two.front_of[f] == TwoSidedFaces::kNotBack) {
      front_start[f] = next;
      next += std::uint32_t(mesh.face_size(f));
    }
  std::vector<std::uint32_t> index(mesh.num_corners());
  std::vector<std::uint32_t> reversed(rows(cn.normals), TwoSidedFaces::kNotBack);
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t t = two.front_of[f];
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      if (t == TwoSidedFaces::kNotBack) {
        index[c] = cn.corner_index[front_start[f] + (c - mesh.face_start[f])];
        continue;
      }
      std::uint32_t k = 0;  // the front's corner at this vertex (it has the same vertices)
      while (mesh.corner_vertex[mesh.face_start[t] + k] != mesh.corner_vertex[c]) ++k;
      const std::uint32_t i = cn.corner_index[front_start[t] + k];
      if (reversed[i] == TwoSidedFaces::kNotBack) {
        reversed[i] = std::uint32_t(rows(cn.normals));
        for (int j = 0; j < 3; ++j) cn.normals.push_back(-cn.normals[3 * std::size_t(i) + j]);
      }
      index[c] = reversed[i];
    }
  }
  cn.corner_index = std::move(index);
}

// The mesh's normals become the corner normals `cn` (its vertex normals dropped); the report counts them.
void store_corner_normals(Mesh& mesh, CornerNormals&& cn, NormalsReport& report) {
  mesh.corner_normals = std::move(cn.normals);
  mesh.corner_normal_index = std::move(cn.corner_index);
  mesh.vertex_normals.clear();
  report.computed = rows(mesh.corner_normals);
  report.fallback = cn.fallback_corners;
  report.degenerate_faces = cn.degenerate_faces;
}

// The mesh's normals become the vertex normals `normals` (its corner normals dropped).
void store_vertex_normals(Mesh& mesh, std::vector<double>&& normals, std::size_t fallback, std::size_t degenerate,
                          NormalsReport& report) {
  mesh.vertex_normals = std::move(normals);
  mesh.corner_normals.clear();
  mesh.corner_normal_index.clear();
  report.computed = rows(mesh.vertex_normals);
  report.fallback = fallback;
  report.degenerate_faces = degenerate;
}

NormalsReport compute_mesh_normals(Mesh& mesh, const NormalsRequest& request) {
  NormalsReport report;
  if (request.recompute) {
    report.discarded = rows(mesh.vertex_normals) + rows(mesh.corner_normals) + rows(mesh.face_normals);
    mesh.vertex_normals.clear();
    mesh.corner_normals.clear();
    mesh.corner_normal_index.clear();
    mesh.face_normals.clear();
  } else if (request.kind == NormalKind::Face) {
    if (mesh.has_face_normals()) {
      report.kept = true;
      report.kept_what = "face normals";
      report.existing = rows(mesh.face_normals);
      report.invalid_existing = count_invalid_normals(mesh.face_normals);
      return report;
    }
  } else if (mesh.has_corner_normals()) {
    report.kept = true;
    report.kept_what = "corner normals";
    report.existing = rows(mesh.corner_normals);
    report.invalid_existing = invalid_corner_normals(mesh);
    return report;
  } else if (mesh.has_vertex_normals()) {
    report.kept = true;
    report.kept_what = "vertex normals";
    report.existing = rows(mesh.vertex_normals);
    report.invalid_existing = count_invalid_normals(mesh.vertex_normals);
    return report;
  }

  if (request.kind != NormalKind::Face && request.ranked) {
    RankedWeightingOptions options = request.ranked_options;
    options.crease_angle = request.kind == NormalKind::Corner ? request.crease_angle : -1.0;
    CornerNormals cn = ranked_normals(mesh, options);
    if (request.kind == NormalKind::Corner)
      store_corner_normals(mesh, std::move(cn), report);
    else  // one normal per vertex: cn's pool is per vertex
      store_vertex_normals(mesh, std::move(cn.normals), cn.fallback_corners, cn.degenerate_faces, report);
    return report;
  }
  if (request.kind != NormalKind::Face && request.smoothing_groups == SmoothingGroups::Honour) {
    const FaceSmoothingGroups groups = face_smoothing_groups(mesh);
    if (groups.matter()) {
      const double crease = request.kind == NormalKind::Corner ? request.crease_angle : kPi;
      store_corner_normals(mesh, corner_normals(mesh, crease, groups.groups, request.weighting, request.precision), report);
      report.honoured_groups = true;
      report.smoothing_groups = groups.count;
      report.flat_faces = groups.flat;
      return report;
    }
  }
  switch (request.kind) {
    case NormalKind::Vertex: {
      // A two-sided surface: the vertex normal from the front side only (the earlier face).
      const TwoSidedFaces two = two_sided_faces(mesh);
      report.two_sided_faces = two.backs;
      VertexNormals vn = two.backs > 0 ? vertex_normals(front_faces(mesh, two), request.weighting, request.precision)
                                       : vertex_normals(mesh, request.weighting, request.precision);
      store_vertex_normals(mesh, std::move(vn.normals), vn.fallback_vertices, vn.degenerate_faces, report);
      break;
    }
    case NormalKind::Corner: {
      const TwoSidedFaces two = two_sided_faces(mesh);
      report.two_sided_faces = two.backs;
      CornerNormals cn = two.backs > 0 ? corner_normals(front_faces(mesh, two), request.crease_angle, request.weighting, request.precision)
                                       : corner_normals(mesh, request.crease_angle, request.weighting, request.precision);
      if (two.backs > 0) split_back_corners(mesh, two, cn);
      store_corner_normals(mesh, std::move(cn), report);
      break;
    }
    case NormalKind::Face: {
      report.dropped = rows(mesh.vertex_normals) + rows(mesh.corner_normals);
      mesh.vertex_normals.clear();
      mesh.corner_normals.clear();
      mesh.corner_normal_index.clear();
      mesh.face_normals = face_normals(mesh, request.precision);
      report.computed = rows(mesh.face_normals);
      report.degenerate_faces = count_degenerate(mesh.face_normals);
      // A degenerate face has no direction; the file gets kFallbackNormal instead of (0,0,0) so that
      // no written normal is invalid (a zero-area face is invisible, any unit normal is harmless).
      for (std::size_t f = 0; f < rows(mesh.face_normals) && report.degenerate_faces > 0; ++f) {
        double* n = &mesh.face_normals[3 * f];
        if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
          for (int k = 0; k < 3; ++k) n[k] = kFallbackNormal[k];
      }
      report.fallback = report.degenerate_faces;
      break;
    }
  }
  return report;
}

}  // namespace

NormalsReport update_mesh_normals(Mesh& mesh, const NormalsRequest& request) {
  NormalsReport report = compute_mesh_normals(mesh, request);
  if (request.flat_patches && !report.kept && request.kind != NormalKind::Face) {
    if (mesh.has_corner_normals())
      report.flat_patches = snap_flat_patches(mesh, mesh.corner_normals, &mesh.corner_normal_index);
    else if (mesh.has_vertex_normals())
      report.flat_patches = snap_flat_patches(mesh, mesh.vertex_normals, nullptr);
  }
  return report;
}

}  // namespace shadetool
