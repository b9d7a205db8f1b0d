// Every writer's output read by a second, independent reader (issue 21, item 10): `assimp info`
// (package assimp-utils) must load what shadetool writes, in every format and form, with the
// attributes that trip readers up (colours: OBJ `v x y z r g b`, OFF `r g b a`; polygons;
// normals). Skipped with a message when assimp is not installed.
#include <unistd.h>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

bool have_assimp() { return ::access("/usr/bin/assimp", X_OK) == 0; }

// "Faces:              12" -> 12; -1 if absent.
long count_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  if (at == std::string::npos) return -1;
  return std::strtol(text.c_str() + at + label.size(), nullptr, 10);
}

}  // namespace

TEST_CASE("assimp reads every writer's output, every format and form", "[assimp][write]") {
  if (!have_assimp()) {
    WARN("assimp not installed (apt-get install assimp-utils): second-reader round trip skipped");
    return;
  }
  ScratchDir dir;
  Mesh rich = rich_mesh();  // polygons, corner normals, texcoords, vertex and face colours
  Mesh rgba = rich;
  rgba.color_channels = 4;
  rgba.vertex_colors.clear();
  for (std::size_t v = 0; v < rgba.num_vertices(); ++v) rgba.vertex_colors.insert(rgba.vertex_colors.end(), {0.5f, 0.25f, 1.0f, 0.5f});
  rgba.face_colors.clear();
  Mesh vertex_only = rich;  // vertex colours alone (COFF, OBJ v x y z r g b)
  vertex_only.face_colors.clear();
  const std::pair<const char*, const Mesh*> meshes[] = {{"rich", &rich}, {"rgba", &rgba}, {"vertex_colours", &vertex_only}};
  for (const auto& [label, mesh] : meshes)
    for (Format f : {Format::Obj, Format::Ply, Format::Off, Format::Stl})
      for (bool binary : {true, false}) {
        if (!binary && (f == Format::Obj || f == Format::Off)) continue;
        const std::string path = dir / (std::string(label) + (binary ? "_bin." : "_txt.") + format_extension(f));
        WriteOptions o;
        o.format = f;
        o.binary = binary;
        write_mesh(*mesh, path, o);
        const Run r = shadetool_test::run_process({"/usr/bin/assimp", "info", path});
        INFO(path << "\n" << r.out << r.err);
        CHECK(r.code == 0);
        CHECK(r.out.find("ERROR") == std::string::npos);
        // assimp triangulates: 1 + 2 + 3 triangles from the triangle, quad and pentagon
        CHECK(count_after(r.out, "Faces:") >= long(mesh->num_faces()));
        CHECK(count_after(r.out, "Vertices:") >= long(mesh->num_vertices()));
      }
}
