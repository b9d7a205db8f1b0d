// mesh_files.h's reading progress (ReadInfo::progress, core/progress.h): the stage "reading"
// counts the file's bytes, ends at exactly the file's size, and moves more than once on a file of
// many lines or elements (OBJ: every 65536 lines; PLY: every element); listening changes nothing.
// Formats whose reader does not report (FormatEntry::reports_progress false) begin the stage with
// no total: a display shows its name, not a fraction that never moves.
#include <catch2/catch.hpp>

#include <shadetool/files/mesh_files.h>
#include "support/analytic_meshes.h"
#include "support/recording_progress.h"

using namespace shadetool;

TEST_CASE("reading reports the file's bytes, ending at exactly its size, and listening changes nothing",
          "[mesh_io][progress]") {
  const Mesh mesh = testing::torus(200, 200).mesh;  // 40000 vertices, 80000 faces: 120000 OBJ lines
  struct Case {
    Format format;
    bool binary;
    const char* name;
  };
  for (const Case c : {Case{Format::Obj, false, "t.obj"}, Case{Format::Ply, true, "t.ply"}, Case{Format::Ply, false, "t.ply"}}) {
    WriteOptions wo;
    wo.format = c.format;
    wo.binary = c.binary;
    const std::string bytes = write_mesh_to_memory(mesh, wo);
    INFO(c.name << (c.binary ? " binary" : " text") << ", " << bytes.size() << " bytes");
    testing::RecordingProgress rec;
    ReadInfo listened;
    listened.progress = ProgressCursor(&rec);
    const Mesh a = read_mesh_from_memory(bytes, c.format, c.name);
    const Mesh b = read_mesh_from_memory(bytes, c.format, c.name, &listened);
    CHECK(a.positions == b.positions);
    CHECK(a.corner_vertex == b.corner_vertex);
    REQUIRE(rec.stages().size() == 1);
    CHECK(rec.stages()[0].name == "reading");
    CHECK(rec.stages()[0].total == bytes.size());
    CHECK(rec.stages()[0].advances >= 2);
    CHECK(rec.overshoots() == 0);
    CHECK(rec.every_stage_monotone_and_complete());
  }
}

TEST_CASE("a reader that does not report (OFF, STL) shows reading by its name alone: no fraction stuck at 0",
          "[mesh_io][progress]") {
  const Mesh mesh = testing::torus(40, 20).mesh;
  for (const Format format : {Format::Off, Format::Stl}) {
    WriteOptions wo;
    wo.format = format;
    const std::string bytes = write_mesh_to_memory(mesh, wo);
    testing::RecordingProgress rec;
    ReadInfo listened;
    listened.progress = ProgressCursor(&rec);
    read_mesh_from_memory(bytes, format, format == Format::Off ? "t.off" : "t.stl", &listened);
    REQUIRE(rec.stages().size() == 1);
    CHECK(rec.stages()[0].name == "reading");
    CHECK(rec.stages()[0].total == 0);
    CHECK(rec.stages()[0].advances == 0);
  }
}
