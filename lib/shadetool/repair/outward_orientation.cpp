// outward_orientation.cpp: volume, containment parity, vote, majority (see the header).
#include <shadetool/repair/outward_orientation.h>

#include <shadetool/repair/authored_normals_vote.h>
#include <shadetool/repair/open_surface_vote.h>
#include <shadetool/repair/shell_nesting.h>
#include <shadetool/repair/signed_volume.h>

namespace shadetool {

OutwardOrientation outward_orientation(const Mesh& mesh, const ConsistentWinding& winding,
                                       const ComponentBoundaries& boundaries) {
  return outward_orientation(mesh, winding, boundaries, component_signed_volumes(mesh, winding));
}

OutwardOrientation outward_orientation(const Mesh& mesh, const ConsistentWinding& winding,
                                       const ComponentBoundaries& boundaries, const ComponentVolumes& volumes) {
  const std::size_t K = winding.num_components;
  OutwardOrientation out;
  out.component_invert.assign(K, 0);
  out.component_basis.assign(K, OrientationBasis::Majority);

  // Face lists are needed only for votes and nesting: built on first use.
  ComponentFaces groups;
  bool grouped = false;
  auto group = [&]() -> const ComponentFaces& {
    if (!grouped) { groups = faces_by_component(winding); grouped = true; }
    return groups;
  };
  std::vector<std::uint32_t> shells;
  std::vector<std::uint32_t> faces;
  const bool normals = has_authored_normals(mesh);
  auto component_faces = [&](std::size_t k) -> const std::vector<std::uint32_t>& {
    const ComponentFaces& g = group();
    faces.assign(g.faces.begin() + g.start[k], g.faces.begin() + g.start[k + 1]);
    return faces;
  };
  // The input's normals decide where the geometry does not (see the header); `faces` holds k's.
  auto by_normals = [&](std::size_t k) {
    const AuthoredNormalsVote vote = authored_normals_vote(mesh, winding, faces);
    if (!vote.decided) return false;
    out.component_invert[k] = vote.invert;
    out.component_basis[k] = OrientationBasis::AuthoredNormals;
    ++out.normals_components;
    return true;
  };
  for (std::size_t k = 0; k < K; ++k) {
    if (winding.component_non_orientable[k]) continue;
    if (boundaries.component_closed[k]) {
      const bool has_sign = volume_has_sign(volumes.volume[k], volumes.magnitude[k]);
      if (normals && (!has_sign || thin_closed_component(mesh, component_faces(k), volumes.volume[k]))) {
        component_faces(k);
        if (by_normals(k)) continue;
      }
      if (!has_sign) continue;
      out.component_invert[k] = volumes.volume[k] < 0;
      out.component_basis[k] = OrientationBasis::Volume;
      shells.push_back(std::uint32_t(k));
    } else {
      if (winding.component_faces[k] < 2) {  // one face wraps nothing: no geometric evidence
        if (normals) {
          component_faces(k);
          by_normals(k);
        }
        continue;
      }
      const OpenSurfaceVote vote = open_surface_vote(mesh, winding, component_faces(k));
      if (!vote.decided) {
        if (normals) by_normals(k);
        continue;
      }
      out.component_invert[k] = vote.invert;
      out.component_basis[k] = OrientationBasis::SurfaceVote;
    }
  }

  const std::vector<std::uint32_t> depth =
      shells.size() < 2 ? std::vector<std::uint32_t>(K, 0) : shell_nesting_depth(mesh, winding, group(), shells, out.component_invert);
  for (std::uint32_t k : shells)
    if (depth[k] % 2 == 1) {
      out.component_invert[k] ^= 1;
      out.component_basis[k] = OrientationBasis::NestedShell;
      ++out.nested_shells;
    }

  for (std::size_t k = 0; k < K; ++k) {
    if (out.component_basis[k] != OrientationBasis::Majority) continue;
    ++out.majority_components;
    out.component_invert[k] = 2 * std::size_t(winding.component_reverse_count[k]) > winding.component_faces[k];
  }
  return out;
}

}  // namespace shadetool
