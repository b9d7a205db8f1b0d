// driver.h: what every mesh subcommand shares: inputs and outputs, formats, many files per call
// in parallel, notes, --stats and --json. A subcommand supplies one step, Mesh -> Mesh.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadetool/core/mesh.h>

namespace CLI { class App; }

namespace shadetool_cli {

struct IoOptions {
  std::vector<std::string> inputs;
  std::string output;        // -o FILE or -o - (stdout); one input only
  std::string output_dir;    // --output-dir DIR: outputs named after the inputs
  std::string format;        // --format obj|ply|off|stl
  std::string input_format;  // --input-format, needed for stdin
  bool ascii = false;
  bool binary = false;
  int jobs = 0;              // -j N; 0 = number of cores
  bool json = false;
  bool quiet = false;
  bool stats = false;
};

// What one file's step reports back to the driver.
struct FileResult {
  std::vector<std::string> notes;               // one line each on stderr, unless --quiet
  nlohmann::json stats = nlohmann::json::object();  // counts for --stats and --json
  std::string text;                             // printed on stdout (info's report)
  double compute_ms = 0;                        // filled by the driver
};

using MeshStep = std::function<void(shadetool::Mesh& mesh, const std::string& input, FileResult& result)>;

// Adds the shared options to a subcommand. `writes_mesh` = false for read-only commands (info).
void add_io_options(CLI::App& sub, IoOptions& io, bool writes_mesh);

// Runs `step` over every input; returns the exit code (0, or 1 if any file failed).
int run_mesh_command(const std::string& command, const IoOptions& io, const MeshStep& step, bool writes_mesh);

// Exit codes shared by every subcommand.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // bad input or processing error
constexpr int kExitUsage = 2;    // unknown flag, missing argument, conflicting options

}  // namespace shadetool_cli
