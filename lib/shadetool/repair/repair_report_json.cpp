#include <shadetool/repair/repair_report_json.h>

#include <nlohmann/json.hpp>

namespace shadetool {

namespace {

nlohmann::json tally_json(const OrientationTally& t) {
  return {{"components", t.components}, {"inverted", t.inverted}, {"faces", t.faces}, {"faces_reversed", t.faces_reversed}};
}

// Each basis in the order repair trusts it (outward_orientation.h), then the normals' evidence.
nlohmann::json orientation_by_json(const OrientationBy& by) {
  nlohmann::json j = nlohmann::json::object();
  j["winding_and_normals"] = tally_json(by.winding_and_normals);
  j["normals"] = tally_json(by.normals);
  j["volume"] = tally_json(by.volume);
  j["nested_shell"] = tally_json(by.nested_shell);
  j["surface_vote"] = tally_json(by.surface_vote);
  j["majority"] = tally_json(by.majority);
  j["evidence"] = {{"faces_agreeing_with_normals", by.faces_agreeing},
                   {"faces_disagreeing_with_normals", by.faces_disagreeing},
                   {"faces_agreeing_reversed", by.faces_agreeing_reversed},
                   {"components_geometry_overruled", by.geometry_overruled}};
  return j;
}

}  // namespace

std::string repair_report_json(const RepairReport& r, double weld_eps, const std::string& weighting) {
  nlohmann::json j;
  j["faces_in"] = r.faces_in;
  j["faces_out"] = r.faces_out;
  j["components"] = r.components;
  j["closed_components"] = r.closed_components;
  j["open_components"] = r.open_components;
  j["faces_flipped"] = r.faces_flipped;
  j["faces_flipped_for_consistency"] = r.faces_flipped_for_consistency;
  j["components_inverted"] = r.components_inverted;
  j["nested_shells"] = r.nested_shells;
  j["orientation"] = {{"by_volume", r.oriented_by_volume},
                      {"by_vote", r.oriented_by_vote},
                      {"by_normals", r.oriented_by_normals},
                      {"by_majority", r.oriented_by_majority},
                      {"by_agreement", r.oriented_by_agreement},
                      {"by", orientation_by_json(r.orientation_by)},
                      {"open_component_method", "generalized winding number"}};
  j["non_manifold_edges"] = r.non_manifold_edges;
  j["duplicate_faces"] = r.duplicate_faces;
  j["non_orientable_components"] = r.non_orientable_components;
  j["inconsistent_edges"] = r.inconsistent_edges;
  j["boundary_loops"] = r.boundary_loops;
  j["degenerate_faces"] = r.degenerate_faces;
  j["degenerate_by_kind"] = {{"zero_area", r.degenerate_zero_area},
                             {"repeated_index", r.degenerate_repeated_index},
                             {"too_few_corners", r.degenerate_too_few_corners},
                             {"non_finite", r.degenerate_non_finite}};
  j["degenerate_faces_removed"] = r.degenerate_faces_removed;
  j["vertices_welded"] = r.vertices_welded;
  j["seam_vertices_joined"] = r.seam_vertices_joined;
  j["weld_eps"] = weld_eps >= 0 ? nlohmann::json(weld_eps) : nlohmann::json(nullptr);
  j["normals_recomputed"] = {{"nan", r.normals.nan},         {"inf", r.normals.inf},
                             {"zero", r.normals.zero},       {"flipped", r.normals.flipped},
                             {"missing", r.normals.missing}, {"total", r.normals.total()}};
  j["normals_recomputed_by_kind"] = {{"vertex", r.normals.vertex}, {"corner", r.normals.corner}, {"face", r.normals.face}};
  j["weighting"] = weighting;
  j["changes"] = r.changes();
  return j.dump();
}

}  // namespace shadetool
