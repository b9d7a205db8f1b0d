// outward_orientation.cpp: agreeing normals, volume, containment parity, vote, normals, majority (see the header).
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
  // Closed shells with a volume sign take part in the nesting test as containers (evaluated
  // outward-facing, by `volume_invert`); only those oriented by Volume are reversed by parity.
  std::vector<std::uint32_t> shells;
  std::vector<std::uint8_t> volume_invert(K, 0);
  std::vector<std::uint32_t> faces;
  const bool normals = has_authored_normals(mesh);
  auto component_faces = [&](std::size_t k) -> const std::vector<std::uint32_t>& {
    const ComponentFaces& g = group();
    faces.assign(g.faces.begin() + g.start[k], g.faces.begin() + g.start[k + 1]);
    return faces;
  };
  auto decide = [&](std::size_t k, OrientationBasis basis, bool invert) {
    out.component_invert[k] = invert;
    out.component_basis[k] = basis;
  };
  for (std::size_t k = 0; k < K; ++k) {
    if (winding.component_non_orientable[k]) continue;
    const bool closed = boundaries.component_closed[k];
    AuthoredNormalsVote authored;
    if (normals) {
      authored = authored_normals_vote(mesh, winding, component_faces(k));
      out.faces_agreeing += authored.agreeing;
      out.faces_disagreeing += authored.disagreeing;
    }
    const bool input_consistent = winding.component_reverse_count[k] == 0;
    // A closed shell with a volume sign is a container for the nesting test, however it is decided.
    const bool has_sign = closed && volume_has_sign(volumes.volume[k], volumes.magnitude[k]);
    if (has_sign) {
      volume_invert[k] = volumes.volume[k] < 0;
      shells.push_back(std::uint32_t(k));
    }
    // 1. The input's winding and its normals agree: kept, whatever the geometry would say.
    // 2. The part's winding is inconsistent: the majority of its agreeing evidence decides.
    const bool agrees = normals && winding_agrees(authored, input_consistent);
    if (normals && !agrees && !input_consistent && authored.decided) {
      decide(k, OrientationBasis::AuthoredNormals, authored.invert);
      continue;
    }
    // 3. Geometry (asked for kept components too, to report what it would have done).
    bool geometry_decided = false, geometry_invert = false, thin_volume = false;
    if (closed) {
      const bool thin = has_sign && normals && thin_closed_component(mesh, component_faces(k), volumes.volume[k]);
      if (has_sign && !thin) { geometry_decided = true; geometry_invert = volume_invert[k]; }
      thin_volume = thin;
    } else if (winding.component_faces[k] >= 2) {  // one face wraps nothing: no geometric evidence
      const OpenSurfaceVote vote = open_surface_vote(mesh, winding, component_faces(k));
      if (vote.decided) { geometry_decided = true; geometry_invert = vote.invert; }
    }
    if (agrees) {
      decide(k, OrientationBasis::WindingAndNormals, false);
      if (geometry_decided && geometry_invert) ++out.geometry_overruled;
    } else if (geometry_decided) {
      decide(k, closed ? OrientationBasis::Volume : OrientationBasis::SurfaceVote, geometry_invert);
    } else if (normals && authored.decided) {  // 4. the normals alone, where geometry has nothing
      decide(k, OrientationBasis::AuthoredNormals, authored.invert);
    } else if (thin_volume) {  // a thin shell whose normals are undecided: its volume's sign, for want of better
      decide(k, OrientationBasis::Volume, volume_invert[k]);
    }
  }

  const std::vector<std::uint32_t> depth =
      shells.size() < 2 ? std::vector<std::uint32_t>(K, 0) : shell_nesting_depth(mesh, winding, group(), shells, volume_invert);
  for (std::uint32_t k : shells) {
    if (depth[k] % 2 == 0) continue;
    // Containment parity is a guess for inputs without evidence: it never turns a shell whose
    // winding its normals confirm (Grey_Nurse_Shark.stl's teeth, buried in the body).
    switch (out.component_basis[k]) {
      case OrientationBasis::Volume:
        out.component_invert[k] ^= 1;
        out.component_basis[k] = OrientationBasis::NestedShell;
        break;
      case OrientationBasis::WindingAndNormals:
        if (!volume_invert[k]) ++out.geometry_overruled;  // parity alone would have reversed it
        break;
      case OrientationBasis::AuthoredNormals: case OrientationBasis::NestedShell: case OrientationBasis::SurfaceVote:
      case OrientationBasis::Majority:
        break;
    }
  }

  for (std::size_t k = 0; k < K; ++k) {
    switch (out.component_basis[k]) {
      case OrientationBasis::Majority:
        ++out.majority_components;
        out.component_invert[k] = 2 * std::size_t(winding.component_reverse_count[k]) > winding.component_faces[k];
        break;
      case OrientationBasis::WindingAndNormals: ++out.agreeing_components; break;
      case OrientationBasis::AuthoredNormals: ++out.normals_components; break;
      case OrientationBasis::NestedShell: ++out.nested_shells; break;
      case OrientationBasis::Volume: case OrientationBasis::SurfaceVote: break;
    }
  }
  return out;
}

}  // namespace shadetool
