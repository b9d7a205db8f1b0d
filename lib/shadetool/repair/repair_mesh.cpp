// repair_mesh.cpp: the repair pipeline (see the header).
#include <shadetool/repair/repair_mesh.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include <shadetool/repair/authored_normals_vote.h>
#include <shadetool/repair/component_boundaries.h>
#include <shadetool/repair/consistent_winding.h>
#include <shadetool/repair/degenerate_faces.h>
#include <shadetool/repair/duplicate_faces.h>
#include <shadetool/repair/outward_orientation.h>
#include <shadetool/repair/reverse_faces.h>
#include <shadetool/repair/seam_join.h>
#include <shadetool/repair/signed_volume.h>
#include <shadetool/repair/weld_vertices.h>
#include <shadetool/core/edge_adjacency.h>

namespace shadetool {

RepairReport repair_mesh(Mesh& mesh, const RepairOptions& options) {
  RepairReport report;
  report.faces_in = mesh.num_faces();
  constexpr std::uint64_t kPasses = 7;  // the passes of RepairOptions::progress
  report_begin(options.progress, "repair", kPasses);
  if (options.weld_eps >= 0) report.vertices_welded = weld_vertices(mesh, options.weld_eps).removed;
  report_advance(options.progress, 1);

  const std::size_t F = mesh.num_faces();
  // Step 1: consistent winding. Faces without a winding of their own (fewer than 3 corners, a
  // repeated index) take no part. Duplicate faces are set aside (found from the first winding's
  // components and non-manifold edges); only when there are any are the adjacency and the winding
  // computed again without them.
  EdgeAdjacencyOptions left_out;
  left_out.skip_unwound_faces = true;
  EdgeAdjacency adj = edge_adjacency(mesh, left_out);
  // Seams: boundary vertices at exactly the same position are joined, for the decisions of steps 1
  // and 2 only (seam_join.h): `decide` is the mesh with those corners re-pointed; the output keeps
  // its vertices. A mesh without such vertices is decided on as it is.
  Mesh seams;
  const Mesh* decide = &mesh;
  if (adj.boundary_edges > 0) {
    SeamJoin join = seam_join(mesh, adj);
    if (join.joined > 0) {
      report.seam_vertices_joined = join.joined;
      seams.positions = mesh.positions;
      seams.face_start = mesh.face_start;
      seams.corner_vertex = std::move(join.corner_vertex);
      seams.vertex_normals = mesh.vertex_normals;  // evidence for outward_orientation
      seams.corner_normals = mesh.corner_normals;
      seams.corner_normal_index = mesh.corner_normal_index;
      seams.face_normals = mesh.face_normals;
      decide = &seams;
      adj = edge_adjacency(seams, left_out);
    }
  }
  report_advance(options.progress, 1);
  ConsistentWinding winding = consistent_winding(*decide, adj, left_out);
  const DuplicateFaces duplicates = duplicate_faces(*decide, adj, winding);
  report.duplicate_faces = duplicates.count;
  if (duplicates.count > 0) {
    left_out.skip.assign(F, 0);
    for (std::size_t f = 0; f < F; ++f) left_out.skip[f] = duplicates.original[f] != DuplicateFaces::kNone;
    adj = edge_adjacency(*decide, left_out);
    winding = consistent_winding(*decide, adj, left_out);
  }
  const ComponentBoundaries boundaries = component_boundaries(*decide, adj, winding);
  report.components = winding.num_components;
  report.non_manifold_edges = winding.non_manifold_edges;
  report.inconsistent_edges = winding.inconsistent_edges;
  report.boundary_loops = boundaries.boundary_loops;
  for (std::size_t k = 0; k < winding.num_components; ++k) {
    if (boundaries.component_closed[k]) ++report.closed_components; else ++report.open_components;
    report.non_orientable_components += winding.component_non_orientable[k];
  }

  // Step 2: outward orientation, then every face reversed at most once. The volume pass also
  // finds the degenerate faces (step 4), sharing its reads of the positions. It reads the output
  // mesh: joined vertices have the same positions, so the volumes are the same, and a face with
  // two coincident corners stays what it is (zero area, not a repeated index).
  report_advance(options.progress, 1);
  DegenerateFaces degenerate;
  const ComponentVolumes volumes = component_signed_volumes(mesh, winding, &degenerate);
  report.degenerate_faces = degenerate.count();
  report.degenerate_zero_area = degenerate.zero_area;
  report.degenerate_repeated_index = degenerate.repeated_index;
  report.degenerate_too_few_corners = degenerate.too_few_corners;
  report.degenerate_non_finite = degenerate.non_finite;
  report_advance(options.progress, 1);
  const OutwardOrientation outward = outward_orientation(*decide, winding, boundaries, volumes);
  report_advance(options.progress, 1);
  report.nested_shells = outward.nested_shells;
  report.oriented_by_majority = outward.majority_components;
  report.oriented_by_normals = outward.normals_components;
  report.oriented_by_agreement = outward.agreeing_components;
  OrientationBy& by = report.orientation_by;
  by.faces_agreeing = outward.faces_agreeing;
  by.faces_disagreeing = outward.faces_disagreeing;
  by.geometry_overruled = outward.geometry_overruled;
  auto tally = [&](OrientationBasis basis) -> OrientationTally& {
    switch (basis) {
      case OrientationBasis::WindingAndNormals: return by.winding_and_normals;
      case OrientationBasis::AuthoredNormals: return by.normals;
      case OrientationBasis::Volume: return by.volume;
      case OrientationBasis::NestedShell: return by.nested_shell;
      case OrientationBasis::SurfaceVote: return by.surface_vote;
      case OrientationBasis::Majority: return by.majority;
    }
    return by.majority;  // not reached: every basis is listed above
  };
  for (std::size_t k = 0; k < winding.num_components; ++k) {
    const std::size_t reversed = winding.component_reverse_count[k], total = winding.component_faces[k];
    // Faces the component's majority disagreed with: the consistency step's share.
    report.faces_flipped_for_consistency += std::min(reversed, total - reversed);
    // Inverted as a whole: the final winding reverses most of the component's input faces.
    const std::size_t changed = outward.component_invert[k] ? total - reversed : reversed;
    if (2 * changed > total) ++report.components_inverted;
    OrientationTally& t = tally(outward.component_basis[k]);
    ++t.components;
    t.inverted += 2 * changed > total;
    t.faces += total;
    t.faces_reversed += changed;
    switch (outward.component_basis[k]) {
      case OrientationBasis::Volume: case OrientationBasis::NestedShell: ++report.oriented_by_volume; break;
      case OrientationBasis::SurfaceVote: ++report.oriented_by_vote; break;
      case OrientationBasis::WindingAndNormals: case OrientationBasis::AuthoredNormals: case OrientationBasis::Majority: break;
    }
  }
  // The final reversal of each face, in place of the winding's (relative to each seed; 0 for
  // faces without a component): a pass over the faces only when some component is inverted.
  std::vector<std::uint8_t>& reverse = winding.face_reverse;
  if (std::any_of(outward.component_invert.begin(), outward.component_invert.end(), [](std::uint8_t i) { return i != 0; }))
    for (std::size_t f = 0; f < F; ++f) {
      const std::uint32_t k = winding.face_component[f];
      if (k != ConsistentWinding::kNoComponent) reverse[f] ^= outward.component_invert[k];
    }
  // A duplicate is reversed with its original: same winding stays same, opposite stays opposite.
  if (duplicates.count > 0)
    for (std::size_t f = 0; f < F; ++f)
      if (duplicates.original[f] != DuplicateFaces::kNone) reverse[f] = reverse[duplicates.original[f]];
  // Item 3 of the rule (repair_mesh.h): agreeing faces reversed, counted on the input winding.
  if (has_authored_normals(*decide))
    for (std::size_t f = 0; f < F; ++f)
      if (reverse[f] && authored_face_evidence(*decide, f) > 0) ++by.faces_agreeing_reversed;
  report.faces_flipped = reverse_faces(mesh, reverse);

  // Step 4: degenerate faces removed on request, before the normals are computed, so that a
  // sliver's arbitrary normal (angle weighting gives its middle corner pi) reaches no vertex.
  if (options.remove_degenerate && report.degenerate_faces > 0) {
    std::vector<std::uint8_t> remove(F, 0);
    for (std::size_t f = 0; f < F; ++f) remove[f] = degenerate.kind[f] != DegenerateKind::None;
    report.degenerate_faces_removed = remove_faces(mesh, remove);
  }

  report_advance(options.progress, 1);
  // Step 3: normals, on the final faces.
  report.normals = fix_normals(mesh, options.weighting);
  report_advance(options.progress, 1);
  report.faces_out = mesh.num_faces();
  return report;
}

}  // namespace shadetool
