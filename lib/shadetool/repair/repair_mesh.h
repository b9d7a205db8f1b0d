// repair_mesh.h: the whole repair, in order: weld (optional), consistent winding, outward
// orientation, normals, degenerate faces.
//
// Inputs:  mesh     positions #V by 3 (finite: the CLI refuses NaN/Inf positions first), faces
//                   #F of any size, optional normals, colours, texcoords
//          options  weighting for recomputed normals (default angle); remove_degenerate;
//                   weld_eps (< 0: no welding; >= 0: weld_vertices(mesh, weld_eps) first)
// Output:  mesh repaired in place, and the RepairReport.
//   1. Consistent winding (consistent_winding.h) over the faces that have one (degenerate faces
//      with a repeated index or < 3 corners are left out and left alone), on the half-edge
//      pairing of core/edge_adjacency.h. Duplicate faces (duplicate_faces.h) are set aside
//      and later reversed together with their original.
//   2. Outward orientation (outward_orientation.h), each component by the first evidence that
//      decides, in this order (what repair trusts):
//        a. the input's winding, where it is consistent and its authored normals (OBJ vn, PLY and
//           glTF normals, STL facet normals) agree with it: kept, never overruled by geometry;
//        b. in a part whose winding is inconsistent, the majority (2:1) of its normals' evidence;
//        c. the signed volume of a closed shell, then nesting parity (only for shells the volume
//           decided);
//        d. the winding-number vote of an open surface;
//        e. the normals alone where geometry has no evidence (a thin or flat closed sheet);
//        f. the input's majority.
//      A face whose winding agreed with its normals is reversed only in case b, or in a part whose
//      normals disagree among themselves (agreeing faces not 2:1): counted in
//      RepairReport::orientation_by.faces_agreeing_reversed. Steps 1 and 2 reverse each face at most once, with
//      reverse_faces.h (first corner kept, so a face flipped by swapping two corners is restored
//      exactly), carrying corner normal and texcoord indices.
//   3. Normals (fix_normals.h), on the final faces.
//   4. Degenerate faces (degenerate_faces.h; the zero-area and non-finite tests run in step 2's
//      volume pass, signed_volume.h, which reads the same positions) are counted; removed only with
//      remove_degenerate, and then before step 3, so that no sliver's arbitrary normal reaches
//      a vertex. No other face is ever removed: faces out = faces in - degenerate_faces_removed.
// Repairing the output again changes nothing (RepairReport::changes() == 0).
#pragma once

#include <shadetool/core/progress.h>
#include <shadetool/core/mesh.h>
#include <shadetool/normals/weighting.h>
#include <shadetool/repair/repair_report.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct RepairOptions {
  Weighting weighting = Weighting::Angle;
  bool remove_degenerate = false;
  double weld_eps = -1;  // < 0: off
  // Where the stage "repair" reports, one unit per named pass (weld, adjacency and seams, winding,
  // signed volumes, outward orientation, reversal, normals; core/progress.h). Null: nobody listens.
  ProgressSink* progress = nullptr;
};

RepairReport repair_mesh(Mesh& mesh, const RepairOptions& options = {});

}  // namespace shadetool
#pragma GCC visibility pop
