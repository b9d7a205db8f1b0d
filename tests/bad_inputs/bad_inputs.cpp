// The hostile-input corpus, end to end: every file of tests/bad_inputs/files/ through every
// subcommand this build has, plus the cases made at run time (a directory, an unreadable file, a
// missing output directory, an output directory that is a file's place, output = input).
//
// The contract (issue 9, foundation issue 3): one line on stderr, `shadetool: FILE[:LINE]: what`,
// naming the file and the problem; exit code 1; no output file (and no temporary left beside it);
// the input unchanged; an output file that existed before left exactly as it was.
// What each corpus file must produce is in expected.tsv, written with the files by make_corpus.py.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <shadetool/files/mesh_files.h>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace fs = std::filesystem;
using shadetool_test::ProcessOptions;
using shadetool_test::ProcessResult;
using shadetool_test::read_file;
using shadetool_test::run_process;

namespace {

const std::string kBin = SHADETOOL_BIN;
const fs::path kCorpus = fs::path(SHADETOOL_SOURCE_DIR) / "tests" / "bad_inputs";

struct Expected {
  std::string file, cls, fragment, why;
};

std::vector<Expected> manifest() {
  std::ifstream in(kCorpus / "expected.tsv");
  std::vector<Expected> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cols;
    std::stringstream s(line);
    std::string col;
    while (std::getline(s, col, '\t')) cols.push_back(col);
    REQUIRE(cols.size() == 4);
    rows.push_back({cols[0], cols[1], cols[2], cols[3]});
  }
  return rows;
}

using shadetool::testing::TempDir;

void write_file(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

struct Subcommand {
  std::string name;
  std::vector<std::string> args;  // what it needs besides the input and output
  bool writes = true;
};

// The subcommands of this build, from `shadetool --help`, with the least they need to run.
// A subcommand in --help that this table does not know fails the test: add it here.
std::vector<Subcommand> subcommands(const fs::path& scene) {
  const std::map<std::string, Subcommand> known = {
      {"info", {"info", {}, false}},
      {"normals", {"normals", {}, true}},
      {"repair", {"repair", {}, true}},
      {"transform", {"transform", {"--translate", "1,2,3"}, true}},
      {"bake-lighting", {"bake-lighting", {"--scene", scene.string()}, true}},
      {"render", {"render", {"--scene", scene.string(), "--size", "16,12"}, true}},
      {"occlusion", {"occlusion", {"--samples", "4"}, true}},
  };
  const ProcessResult help = run_process({kBin, "--help"});
  REQUIRE(help.code == 0);
  std::vector<Subcommand> found;
  std::istringstream lines(help.out);
  std::string line;
  bool in_list = false;
  while (std::getline(lines, line)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      in_list = true;
      continue;
    }
    if (!in_list || line.size() < 3 || line[0] != ' ' || line[2] == ' ') continue;
    const std::string name = line.substr(2, line.find(' ', 2) - 2);
    INFO("subcommand '" << name << "' from --help");
    REQUIRE(known.count(name) == 1);
    found.push_back(known.at(name));
  }
  REQUIRE(!found.empty());
  static bool warned = false;  // once per run, not once per test case
  for (const auto& [name, sub] : known)
    if (!warned && std::none_of(found.begin(), found.end(), [&](const Subcommand& s) { return s.name == name; }))
      WARN("no `" << name << "` subcommand in this build: not covered by the bad-input tests");
  warned = true;
  return found;
}

fs::path write_scene(const fs::path& dir) {
  const fs::path p = dir / "scene.json";
  write_file(p, R"({"lights": [{"type": "directional", "direction": [0, 0, -1]}]})");
  return p;
}

// The input's extension, except where the subcommand's result has no place in that format (STL
// holds no colours or quality: bake-lighting and occlusion to STL are usage errors, not bad input).
std::string output_extension(const std::string& input, const std::string& subcommand = "") {
  const std::string ext = fs::path(input).extension().string();
  if (ext == ".stl" && (subcommand == "bake-lighting" || subcommand == "occlusion")) return ".ply";
  return (ext == ".obj" || ext == ".ply" || ext == ".off" || ext == ".stl") ? ext : ".ply";
}

bool any_of_fragments(const std::string& text, const std::string& alternatives) {
  std::stringstream s(alternatives);
  std::string f;
  while (std::getline(s, f, '|'))
    if (text.find(f) != std::string::npos) return true;
  return false;
}

// The stderr of a failed run: exactly one line, `shadetool: NAMED...`, short enough to read.
void check_one_line(const std::string& err, const std::string& named) {
  INFO("stderr: " << err.substr(0, 600));
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK(!err.empty());
  CHECK(err.back() == '\n');
  CHECK(err.rfind("shadetool: " + named, 0) == 0);
  CHECK(err.size() < 400);  // a 300 kB line in the file is not echoed
}

const std::string kSentinel = "an output file that existed before the failed run\n";

// Runs `sub` on `input` (inside `dir`) with no output file and, when `with_existing_output`, again
// with an output file present. Checks the failure contract; returns the stderr of the first run.
std::string check_failure(const Subcommand& sub, const fs::path& dir, const fs::path& input, const std::string& named,
                          const ProcessOptions& options = {}, bool with_existing_output = true) {
  const bool input_exists = fs::is_regular_file(input);
  const std::string before = input_exists ? read_file(input.string()) : "";
  const fs::path output = dir / ("out" + output_extension(input.filename().string(), sub.name));
  std::vector<std::string> argv = {kBin, sub.name, input.string()};
  if (sub.writes) argv.insert(argv.end(), {"-o", output.string()});
  argv.insert(argv.end(), sub.args.begin(), sub.args.end());

  const std::set<std::string> files_before = listing(dir);
  const ProcessResult r = run_process(argv, options);
  INFO(sub.name << " on " << input.filename().string());
  CHECK(r.code == 1);
  check_one_line(r.err, named);
  CHECK(!fs::exists(output));
  CHECK(listing(dir) == files_before);  // no output, no temporary file left behind
  if (input_exists) CHECK(read_file(input.string()) == before);

  if (sub.writes && with_existing_output) {
    write_file(output, kSentinel);
    const ProcessResult again = run_process(argv, options);
    CHECK(again.code == 1);
    CHECK(read_file(output.string()) == kSentinel);
    fs::remove(output);
    CHECK(listing(dir) == files_before);
    if (input_exists) CHECK(read_file(input.string()) == before);
  }
  return r.err;
}

}  // namespace

TEST_CASE("bad inputs: the corpus has at least 40 files across the formats, each in the manifest", "[bad_inputs]") {
  const auto rows = manifest();
  std::set<std::string> listed, formats;
  for (const auto& r : rows) {
    listed.insert(r.file);
    formats.insert(fs::path(r.file).extension().string());
    CHECK((r.cls == "read" || r.cls == "nonfinite" || r.cls == "nonfinite_normals"));
    CHECK(!r.fragment.empty());
  }
  CHECK(listed.size() == rows.size());  // no file listed twice
  CHECK(listing(kCorpus / "files") == listed);
  CHECK(rows.size() >= 40);
  for (const char* ext : {".obj", ".ply", ".off", ".stl"}) CHECK(formats.count(ext) == 1);
}

TEST_CASE("bad inputs: every corpus file through every subcommand fails cleanly", "[bad_inputs]") {
  TempDir scene_dir;
  const auto subs = subcommands(write_scene(scene_dir.path));
  // The existing-output check runs once per file, with the writing subcommands taking turns over
  // the files (each still sees every class of file): half the runs, which matters under ASan.
  std::size_t file_index = 0, writers = 0;
  for (const auto& sub : subs) writers += sub.writes;
  for (const auto& row : manifest()) {
    const std::size_t turn = writers > 0 ? file_index++ % writers : 0;
    TempDir dir;
    const fs::path input = dir.path / row.file;
    fs::copy_file(kCorpus / "files" / row.file, input);
    INFO(row.file << " (" << row.why << ")");
    for (const auto& sub : subs) {
      if (row.cls != "read" && sub.name == "info") {
        // Read, then reported: info is where NaN/Inf are shown.
        const ProcessResult r = run_process({kBin, "info", input.string()});
        CHECK(r.code == 0);
        CHECK(r.out.find(row.fragment) != std::string::npos);
        continue;
      }
      const bool replaces_normals =
          sub.name == "repair" || sub.name == "transform" || sub.name == "bake-lighting" || sub.name == "occlusion";
      if (row.cls == "nonfinite_normals" && replaces_normals) {
        // repair recomputes NaN/Inf normals; transform, bake-lighting and occlusion replace them by
        // the computed ones with a counted note (issue 27 item 14): the output holds none.
        // (colours need a format that holds them: an STL input's baked output is a PLY, issue 27 item 11)
        const bool colours = sub.name == "bake-lighting" || sub.name == "occlusion";
        const std::string ext = output_extension(row.file);
        const fs::path output = dir.path / ("repaired" + (colours && ext == ".stl" ? std::string(".ply") : ext));
        std::vector<std::string> argv = {kBin, sub.name, input.string(), "-o", output.string()};
        argv.insert(argv.end(), sub.args.begin(), sub.args.end());
        const ProcessResult r = run_process(argv);
        INFO(sub.name << ": " << r.err);
        CHECK(r.code == 0);
        if (sub.name != "repair") CHECK(r.err.find("1 input normal had no direction") != std::string::npos);
        REQUIRE(fs::exists(output));
        const shadetool::Mesh out = shadetool::read_mesh(output.string());
        for (const auto* a : {&out.positions, &out.vertex_normals, &out.corner_normals, &out.face_normals})
          for (double x : *a) CHECK(std::isfinite(x));
        fs::remove(output);
        continue;
      }
      ProcessOptions limited;
      limited.memory_limit_mb = 1024;  // the files are < 1 MiB: a lying count must not be trusted
      std::size_t writer_index = 0;
      for (const auto& other : subs) {
        if (&other == &sub) break;
        writer_index += other.writes;
      }
      const std::string err =
          check_failure(sub, dir.path, input, input.string(), limited, sub.writes && writer_index == turn);
      const std::string fragment = row.cls == "nonfinite"           ? "NaN or Inf"
                                   : row.cls == "nonfinite_normals" ? "NaN or Inf|invalid (NaN"
                                                                    : row.fragment;
      INFO(sub.name << ": stderr " << err.substr(0, 300));
      CHECK(any_of_fragments(err, fragment));
    }
  }
}

TEST_CASE("bad inputs: --json reports each failure as one JSON line, even with binary garbage in the message",
          "[bad_inputs]") {
  for (const auto& row : manifest()) {
    if (row.cls != "read") continue;
    const ProcessResult r = run_process({kBin, "info", "--json", (kCorpus / "files" / row.file).string()});
    INFO(row.file << ": stdout " << r.out.substr(0, 300) << " stderr " << r.err.substr(0, 300));
    CHECK(r.code == 1);
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 1);
    nlohmann::json j;
    REQUIRE_NOTHROW(j = nlohmann::json::parse(r.out));
    CHECK(j["status"] == "error");
    CHECK(j["input"] == (kCorpus / "files" / row.file).string());
    CHECK(any_of_fragments(j["error"].get<std::string>(), row.fragment));
  }
}

TEST_CASE("bad inputs: a directory where a mesh file should be", "[bad_inputs]") {
  TempDir scene_dir;
  for (const auto& sub : subcommands(write_scene(scene_dir.path))) {
    TempDir dir;
    const fs::path input = dir.path / "folder.obj";
    fs::create_directory(input);
    const std::string err = check_failure(sub, dir.path, input, input.string());
    CHECK(err.find("is a directory") != std::string::npos);
    CHECK(fs::is_directory(input));
    CHECK(fs::is_empty(input));
  }
}

TEST_CASE("bad inputs: a missing input file", "[bad_inputs]") {
  TempDir scene_dir;
  for (const auto& sub : subcommands(write_scene(scene_dir.path))) {
    TempDir dir;
    const fs::path input = dir.path / "missing.obj";
    const std::string err = check_failure(sub, dir.path, input, input.string());
    CHECK(err.find("No such file") != std::string::npos);
  }
}

TEST_CASE("bad inputs: an unreadable file (permissions)", "[bad_inputs]") {
  // Root reads a mode-000 file anyway, so as root the command runs as `nobody` (65534), for whom
  // the permission bits hold. If that cannot be arranged, the test says so and checks nothing.
  ProcessOptions as;
  if (::geteuid() == 0) {
    as.uid = 65534;
    as.gid = 65534;
    const ProcessResult probe = run_process({kBin, "--version"}, as);
    if (probe.code != 0) {
      WARN("running as root and cannot run " << kBin << " as nobody (exit " << probe.code
                                             << "): the unreadable-file case is not checked");
      return;
    }
  }
  TempDir scene_dir;
  fs::permissions(scene_dir.path, fs::perms::all);
  const fs::path scene = write_scene(scene_dir.path);
  for (const auto& sub : subcommands(scene)) {
    TempDir dir;
    fs::permissions(dir.path, fs::perms::all);  // nobody may create the output: only reading fails
    const fs::path input = dir.path / "secret.obj";
    fs::copy_file(fs::path(SHADETOOL_SOURCE_DIR) / "data" / "cube.obj", input);
    fs::permissions(input, fs::perms::none);
    const std::string err = check_failure(sub, dir.path, input, input.string(), as);
    CHECK(err.find("Permission denied") != std::string::npos);
    fs::permissions(input, fs::perms::owner_read | fs::perms::owner_write);
    CHECK(read_file(input.string()) == read_file((fs::path(SHADETOOL_SOURCE_DIR) / "data" / "cube.obj").string()));
  }
}

TEST_CASE("bad inputs: output into a directory that does not exist", "[bad_inputs]") {
  TempDir scene_dir;
  for (const auto& sub : subcommands(write_scene(scene_dir.path))) {
    if (!sub.writes) continue;
    TempDir dir;
    const fs::path input = dir.path / "cube.obj";
    fs::copy_file(fs::path(SHADETOOL_SOURCE_DIR) / "data" / "cube.obj", input);
    const std::string before = read_file(input.string());
    INFO(sub.name);
    {
      const fs::path output = dir.path / "no-such-dir" / "out.obj";
      std::vector<std::string> argv = {kBin, sub.name, input.string(), "-o", output.string()};
      argv.insert(argv.end(), sub.args.begin(), sub.args.end());
      const ProcessResult r = run_process(argv);
      CHECK(r.code == 1);
      check_one_line(r.err, output.string());
      CHECK(!fs::exists(dir.path / "no-such-dir"));
    }
    {
      const fs::path outdir = dir.path / "no-such-dir";
      std::vector<std::string> argv = {kBin, sub.name, input.string(), "--output-dir", outdir.string()};
      argv.insert(argv.end(), sub.args.begin(), sub.args.end());
      const ProcessResult r = run_process(argv);
      CHECK(r.code == 1);
      check_one_line(r.err, outdir.string());
      CHECK(r.err.find("does not exist") != std::string::npos);
      CHECK(!fs::exists(outdir));
    }
    CHECK(read_file(input.string()) == before);
    CHECK(listing(dir.path) == std::set<std::string>{"cube.obj"});
  }
}

TEST_CASE("bad inputs: output path is an existing directory", "[bad_inputs]") {
  TempDir scene_dir;
  for (const auto& sub : subcommands(write_scene(scene_dir.path))) {
    if (!sub.writes) continue;
    TempDir dir;
    const fs::path input = dir.path / "cube.obj";
    fs::copy_file(fs::path(SHADETOOL_SOURCE_DIR) / "data" / "cube.obj", input);
    const std::string taken = sub.name == "render" ? "taken.png" : "taken.obj";  // an image, or a mesh
    const fs::path output = dir.path / taken;
    fs::create_directory(output);
    std::vector<std::string> argv = {kBin, sub.name, input.string(), "-o", output.string()};
    argv.insert(argv.end(), sub.args.begin(), sub.args.end());
    const ProcessResult r = run_process(argv);
    INFO(sub.name);
    CHECK(r.code == 1);
    check_one_line(r.err, output.string());
    CHECK(r.err.find("is a directory") != std::string::npos);
    CHECK(fs::is_directory(output));
    CHECK(fs::is_empty(output));
    CHECK(listing(dir.path) == std::set<std::string>{"cube.obj", taken});
  }
}

TEST_CASE("bad inputs: output path equal to the input path is refused, the input kept", "[bad_inputs]") {
  TempDir scene_dir;
  for (const auto& sub : subcommands(write_scene(scene_dir.path))) {
    if (!sub.writes) continue;
    TempDir dir;
    const fs::path input = dir.path / "cube.obj";
    fs::copy_file(fs::path(SHADETOOL_SOURCE_DIR) / "data" / "cube.obj", input);
    fs::create_symlink(input, dir.path / "link.obj");
    const std::string before = read_file(input.string());
    // The same path; the same file by another spelling; through a link; --output-dir of its folder.
    const std::vector<std::vector<std::string>> outputs = {{"-o", input.string()},
                                                           {"-o", (dir.path / "." / "cube.obj").string()},
                                                           {"-o", (dir.path / "link.obj").string()},
                                                           {"--output-dir", dir.path.string()}};
    for (const auto& out : outputs) {
      if (sub.name == "render" && out[0] == "--output-dir") continue;  // writes cube.png: not the input
      std::vector<std::string> argv = {kBin, sub.name, input.string()};
      argv.insert(argv.end(), out.begin(), out.end());
      argv.insert(argv.end(), sub.args.begin(), sub.args.end());
      const ProcessResult r = run_process(argv);
      INFO(sub.name << " " << out[0] << " " << out[1]);
      CHECK(r.code == 2);  // a usage error, found before any work (issue 21, item 1)
      check_one_line(r.err, input.string());
      CHECK(r.err.find("is the input file") != std::string::npos);
      CHECK(read_file(input.string()) == before);
      CHECK(fs::is_symlink(dir.path / "link.obj"));
      CHECK(listing(dir.path) == std::set<std::string>{"cube.obj", "link.obj"});
    }
  }
}
