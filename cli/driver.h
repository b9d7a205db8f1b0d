// driver.h: what every subcommand shares: inputs and outputs, formats, many files per call in
// parallel, notes, --stats and --json, exit codes. A subcommand supplies one step per input file
// (MeshStep: it gets the mesh read from the file) and says what the step produces (OutputKind):
//
//   OutputKind::Mesh    the step changes the mesh in place; the driver writes it with a mesh format
//                       (files/format_table.h): -o FILE, -o - (stdout, needs --format), --output-dir
//                       DIR (named after the input, extension from --format or the input's),
//                       --format, --ascii/--binary, --in-place (each input replaced atomically by
//                       its result, in its own format). Without any of -o, --output-dir and
//                       --in-place: when stdout is not a terminal, one input's mesh goes there in
//                       the input's format (as `-o - --format INPUT'S` would); at a terminal it is
//                       a usage error naming the three.
//   OutputKind::Image   the step fills FileResult::image; the driver writes it with an image format
//                       (io/image_io.h: --format, else -o's extension; --output-dir names files
//                       INPUT_STEM.EXT with EXT the format's, by default the table's first).
//   OutputKind::Report  nothing is written to a file: FileResult::text goes to stdout (--json: the
//                       JSON line's "stats" instead). info is one.
// glTF input (Mesh and Report kinds): the whole document is kept; the step runs per triangle
// primitive (each in its own object space) and a glTF output keeps everything else (see
// gltf/gltf_document.h); another output format gets the primitives as one mesh (with a note).
// For every kind the driver handles -j (files in parallel), --json (one JSON line per file),
// --stats, notes (stderr, one line each, unless --quiet), the per-file error line and the exit
// code (0 all ok, 1 any file failed, 2 usage: also a step's UsageError, flags that do not suit a
// file), and writes every file atomically (no output for a
// failed file, an existing file untouched). Before any work it refuses (exit 2) an output that is
// an input (same device and inode where the file exists, same normalised path where it does
// not), two outputs that are one file (inputs a/x.obj and b/x.obj under --output-dir, -o equal to
// --report), naming them.
//
// A new subcommand: add_io_options(sub, io, OutputKind::Image) when it adds its flags, then
// `return run_command("render", io, step, OutputKind::Image);` from its run function (see
// command_registry.h for the registration and where the options live).
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadetool/core/mesh.h>
#include <shadetool/core/progress.h>
#include <shadetool/files/format_table.h>
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/io/image_io.h>

namespace CLI { class App; }

namespace shadetool_cli {

enum class OutputKind { Mesh, Image, Report };

struct IoOptions {
  std::vector<std::string> inputs;
  std::string output;        // -o FILE or -o - (stdout); one input only
  std::string output_dir;    // --output-dir DIR: outputs named after the inputs
  bool in_place = false;     // --in-place (Mesh only): each input replaced atomically, in its own format
  std::string format;        // --format: a mesh format (OutputKind::Mesh) or an image format (Image)
  std::string input_format;  // --input-format, needed for stdin
  bool ascii = false;
  bool binary = false;
  int jobs = 0;              // -j N; 0 = number of cores
  bool json = false;
  bool quiet = false;
  bool stats = false;
  // Files a command writes besides its main output, as (flag, path): repair's --report. The
  // driver refuses (exit 2, before any work) any two outputs that are one file, and any output
  // that is an input.
  std::vector<std::pair<std::string, std::string>> other_outputs;
  // What the command's result is written as (bake-lighting: vertex colours) and its name for the
  // message: a mesh output whose format holds none of them (files/format_table.h's `holds`) is a
  // usage error, before any work. Empty: any format.
  std::vector<shadetool::HeldAttribute> result_attributes;
  std::string result_name;
};

// A step's work for a whole glTF document (occlusion against the whole scene, one shadow BVH):
// made at the document's first primitive, read at the others, dropped after the last. Typed: the
// step names T, and a slot made with another type is a programming error (std::logic_error), not
// a cast.
class DocumentState {
 public:
  // The document's T: default-constructed and filled in place by fill(T&) at the first call (it
  // does not move: a BVH may point into it), the same object after. `made` (optional) says
  // whether this call made it.
  template <class T, class Fill>
  T& get_or_make(Fill&& fill, bool* made = nullptr) {
    if (made) *made = !value_.has_value();
    if (!value_.has_value()) {
      auto fresh = std::make_shared<T>();
      fill(*fresh);
      value_ = std::move(fresh);
    }
    auto* held = std::any_cast<std::shared_ptr<T>>(&value_);
    if (!held) throw std::logic_error("DocumentState: the document's state was made with another type");
    return **held;
  }

 private:
  std::any value_;  // std::shared_ptr<T>
};

// What one file's step reports back to the driver.
struct FileResult {
  std::vector<std::string> notes;               // one line each on stderr, unless --quiet
  nlohmann::json stats = nlohmann::json::object();  // counts for --stats and --json
  // Keys of `stats` that are settings (a sample count, a number of lights), not counts: over a glTF
  // file's primitives they are kept when every primitive agrees, never summed. setting() sets both.
  std::vector<std::string> settings;
  void setting(const std::string& key, const nlohmann::json& value) {
    stats[key] = value;
    settings.push_back(key);
  }
  std::string text;                             // printed on stdout (info's report)
  shadetool::Image image;                       // OutputKind::Image: the picture to write
  // Files that belong with the main output, as (path, bytes): committed together with it (every
  // temporary written first, then all renamed; if one fails none replaces anything).
  std::vector<std::pair<std::string, std::string>> other_files;
  double compute_ms = 0;                        // filled by the driver
  // glTF input (OutputKind Mesh and Report): the step runs once per triangle primitive, its mesh
  // in the primitive's object space; these point at the primitive and its document so that a step
  // can reach what a Mesh does not hold (tangents, morph targets, lights, cameras). Null otherwise.
  shadetool::GltfPrimitive* gltf = nullptr;
  const shadetool::GltfDocument* gltf_document = nullptr;
  // A slot that lives across the document's primitives (DocumentState); null for other input.
  DocumentState* gltf_document_state = nullptr;
  // Set by the driver before the step: the output is glTF (COLOR_0 is linear, materials exist).
  bool output_gltf = false;
  // Set by a step that bakes colours: a glTF output's materials get KHR_materials_unlit.
  bool unlit = false;
  // Set by the driver: where a step's long kernels report their fraction done (the options'
  // `progress` of occlusion, render, bake-lighting, repair; core/progress.h). Null when nothing
  // shows progress (stderr not a terminal, --quiet, --json, several files).
  shadetool::ProgressSink* progress = nullptr;
};

using MeshStep = std::function<void(shadetool::Mesh& mesh, const std::string& input, FileResult& result)>;

// Adds the shared options to a subcommand: inputs, --input-format, -j, --json, -q, --stats, and
// for Mesh and Image outputs -o, --output-dir, --format (and --ascii/--binary for meshes).
void add_io_options(CLI::App& sub, IoOptions& io, OutputKind kind);
// Runs `step` over every input and writes what it produced; returns the exit code (0, or 1 if any
// file failed). Usage errors throw UsageError (exit 2, from main).
int run_command(const std::string& command, const IoOptions& io, const MeshStep& step, OutputKind kind);

// Exit codes shared by every subcommand.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // bad input or processing error
constexpr int kExitUsage = 2;    // unknown flag, missing argument, conflicting options

}  // namespace shadetool_cli
