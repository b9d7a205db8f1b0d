// smoothing_groups.cpp: see smoothing_groups.h.
#include <shadetool/normals/smoothing_groups.h>

#include <map>
#include <sstream>
#include <string>

#include <shadetool/core/vocabulary.h>

namespace shadetool {

FaceSmoothingGroups face_smoothing_groups(const Mesh& mesh) {
  FaceSmoothingGroups out;
  const std::size_t F = mesh.num_faces();
  if (mesh.face_group_run.size() != F) return out;
  std::map<std::string, std::uint32_t> label;
  bool any = false;
  std::uint32_t current = 0;  // before the first `s`: flat
  std::size_t run = 0;
  // `s` lines of runs [run, end): the last one sets the group.
  auto read_runs = [&](std::size_t end) {
    for (; run < end && run < mesh.group_statements.size(); ++run) {
      std::istringstream lines(mesh.group_statements[run]);
      std::string line;
      while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string keyword, value;
        if (!(words >> keyword) || keyword != "s") continue;
        any = true;
        words >> value;
        if (value.empty() || value == "off" || value == "0") { current = 0; continue; }
        auto it = label.emplace(value, std::uint32_t(label.size() + 1)).first;
        current = it->second;
      }
    }
  };
  out.groups.resize(F);
  for (std::size_t f = 0; f < F; ++f) {
    read_runs(mesh.face_group_run[f]);
    out.groups[f] = current;
    out.flat += current == 0;
  }
  if (!any) return FaceSmoothingGroups{};
  out.count = label.size();
  return out;
}

namespace {
const NamedValue<SmoothingGroups> kSmoothingGroupsChoices[] = {
    {SmoothingGroups::Honour, "honour"},
    {SmoothingGroups::Ignore, "ignore"},
};
}  // namespace

SmoothingGroups parse_smoothing_groups(std::string_view text, const std::string& what) {
  return parse_named(kSmoothingGroupsChoices, text, what);
}
const char* smoothing_groups_name(SmoothingGroups choice) { return name_of(kSmoothingGroupsChoices, choice); }
std::vector<std::string> smoothing_groups_names() { return names_of(kSmoothingGroupsChoices); }

}  // namespace shadetool
