// smoothing_groups.h: the smoothing group of every face, from OBJ `s N` / `s off` statements as
// read (Mesh::group_statements, face_group_run), the way 3ds Max and Blender's OBJ importer treat
// them when they compute normals: faces in different groups never share a normal, `s off` and
// `s 0` faces (and faces before the first `s`, in a file that has one) are flat. (Blender's legacy
// importer reads `s 0` as a group named "0", its new importer as flat: tests/blender_normals.sh.)
//
// Input:   mesh    group_statements and face_group_run as the OBJ reader keeps them
// Output:  groups  #F: 0 for a flat face, else a label >= 1 (one per distinct N, in order of first
//                  appearance); empty when the mesh has no `s` statement (nothing to honour)
//          count   distinct labels >= 1; flat: faces with label 0
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// Whether normals computed for a mesh follow its file's smoothing groups (`--smoothing-groups`).
enum class SmoothingGroups { Honour, Ignore };
// Its vocabulary (core/vocabulary.h, smoothing_groups.cpp): "honour", "ignore".
SmoothingGroups parse_smoothing_groups(std::string_view text, const std::string& what);
const char* smoothing_groups_name(SmoothingGroups choice);
std::vector<std::string> smoothing_groups_names();

struct FaceSmoothingGroups {
  std::vector<std::uint32_t> groups;
  std::size_t count = 0, flat = 0;
  // True when honouring them changes anything: more than one group, or a flat face.
  bool matter() const { return !groups.empty() && (count > 1 || flat > 0); }
};

FaceSmoothingGroups face_smoothing_groups(const Mesh& mesh);

}  // namespace shadetool
#pragma GCC visibility pop
