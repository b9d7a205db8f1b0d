// repair_report.h: what `repair_mesh` found and changed, step by step.
//
// Counts refer to the mesh as given (after welding, which comes first). A component is a set of
// faces joined through manifold edges (edges with exactly two faces); faces with a repeated
// index or fewer than 3 corners belong to none (they have no winding of their own).
// `changes()` is zero exactly when the output equals the input: repairing a repaired mesh
// reports zero (idempotence), which the tests check.
#pragma once

#include <cstddef>

#include <shadetool/repair/fix_normals.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// One orientation basis's decisions (outward_orientation.h): components it decided, of those the
// ones reversed as a whole, their faces, and of those the faces whose winding changed (steps 1 + 2).
struct OrientationTally {
  std::size_t components = 0, inverted = 0, faces = 0, faces_reversed = 0;
};

// Each basis in the order repair trusts it, with the evidence from the input's normals.
struct OrientationBy {
  OrientationTally winding_and_normals, normals, volume, nested_shell, surface_vote, majority;
  std::size_t faces_agreeing = 0;           // input winding agrees with its authored normals
  std::size_t faces_disagreeing = 0;        // ... disagrees
  std::size_t faces_agreeing_reversed = 0;  // agreeing faces whose winding changed: only in parts
                                            // whose winding was inconsistent (their majority decided)
                                            // or whose normals disagree among themselves
  std::size_t geometry_overruled = 0;       // components kept by winding and normals that volume,
                                            // nesting parity or the open-surface vote would have reversed
};

struct RepairReport {
  // Step 0: --weld EPS (off unless weld_eps >= 0).
  std::size_t vertices_welded = 0;

  // Step 1: consistent winding.
  std::size_t seam_vertices_joined = 0;        // boundary vertices at an earlier one's exact position,
                                               // joined for steps 1-2 only (seam_join.h)
  std::size_t components = 0;
  std::size_t closed_components = 0;
  std::size_t open_components = 0;
  std::size_t boundary_loops = 0;
  std::size_t non_manifold_edges = 0;          // 3 or more faces on one edge: do not propagate
                                               // (duplicate faces set aside first)
  std::size_t duplicate_faces = 0;             // same vertex set as an earlier face: follow it
  std::size_t non_orientable_components = 0;   // a Möbius strip, a Klein bottle
  std::size_t inconsistent_edges = 0;          // left in non-orientable components (the seams)
  std::size_t faces_flipped_for_consistency = 0;  // faces that disagreed with their component's majority

  // Step 2: outward orientation.
  std::size_t components_inverted = 0;         // reversed as a whole (after step 1)
  std::size_t nested_shells = 0;               // closed shells at odd nesting depth: face inward
  std::size_t oriented_by_volume = 0;          // closed: signed volume (incl. nested shells)
  std::size_t oriented_by_vote = 0;            // open: winding-number vote decisive
  std::size_t oriented_by_normals = 0;         // the input's normals decided (authored_normals_vote.h)
  std::size_t oriented_by_majority = 0;        // no evidence at all: input majority kept
  std::size_t oriented_by_agreement = 0;       // winding and normals agreed: kept as authored
  OrientationBy orientation_by;                // every decision with its evidence
  std::size_t faces_flipped = 0;               // total faces whose winding changed (steps 1 + 2)

  // Step 3: normals.
  NormalsFix normals;

  // Step 4: degenerate faces.
  std::size_t degenerate_faces = 0;            // zero area, repeated index, < 3 corners, NaN/Inf corner
  std::size_t degenerate_zero_area = 0;
  std::size_t degenerate_repeated_index = 0;
  std::size_t degenerate_too_few_corners = 0;
  std::size_t degenerate_non_finite = 0;
  std::size_t degenerate_faces_removed = 0;    // only with remove_degenerate

  std::size_t faces_in = 0, faces_out = 0;

  std::size_t changes() const {
    return vertices_welded + faces_flipped + normals.total() + degenerate_faces_removed;
  }
};

}  // namespace shadetool
#pragma GCC visibility pop
