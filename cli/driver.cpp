// driver.cpp: inputs, outputs, parallel files, notes, --stats and --json for every subcommand.
#include "driver.h"

#include <algorithm>
#include <cctype>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <memory>
#include <mutex>
#include <new>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <shadetool/core/error.h>
#include <shadetool/core/progress.h>
#include <shadetool/core/time_left.h>
#include <shadetool/core/validate.h>
#include <shadetool/io/atomic_write.h>
#include <shadetool/io/file_bytes.h>
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/gltf/gltf_tangents.h>
#include <shadetool/files/format_table.h>
#include <shadetool/io/image_io.h>
#include <shadetool/files/mesh_files.h>
#include "usage_error.h"

namespace shadetool_cli {

namespace fs = std::filesystem;
using shadetool::Format;

namespace {

// "OBJ, PLY, OFF, STL": the mesh formats of files/format_table.h, for help texts.
std::string upper_format_names() {
  std::string s;
  for (const std::string& n : shadetool::format_names()) {
    if (!s.empty()) s += ", ";
    for (char c : n) s += char(std::toupper(static_cast<unsigned char>(c)));
  }
  return s;
}

// What --format and --input-format accept: every format's name and extensions (gltf, glb, ...).
std::vector<std::string> format_names_and_extensions() {
  std::vector<std::string> names;
  for (const shadetool::FormatEntry& e : shadetool::mesh_formats()) {
    names.emplace_back(e.name);
    for (const char* ext : e.extensions)
      if (std::find(names.begin(), names.end(), ext) == names.end()) names.emplace_back(ext);
  }
  return names;
}

std::string image_format_list() {
  std::string s;
  const auto names = shadetool::image_format_names();
  for (std::size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return s;
}

}  // namespace

void add_io_options(CLI::App& sub, IoOptions& io, OutputKind kind) {
  sub.add_option("inputs", io.inputs, "Input mesh files (" + upper_format_names() + "); - reads stdin")->required();
  sub.add_option("--input-format", io.input_format, "Format of the input when it has no extension (stdin)")
      ->check(CLI::IsMember(format_names_and_extensions(), CLI::ignore_case));
  if (kind == OutputKind::Mesh) {
    sub.add_option("-o,--output", io.output, "Output file; - writes stdout (then --format is needed)");
    sub.add_option("--output-dir", io.output_dir, "Write one output per input into DIR, named after the input");
    sub.add_option("--format", io.format,
                   "Output format: " + shadetool::format_list(false) + " (glTF: glb or gltf; default: from -o's extension)")
        ->check(CLI::IsMember(format_names_and_extensions(), CLI::ignore_case));
    sub.add_flag("--in-place", io.in_place,
                 "Replace each input file by its result, atomically, in its own format (without -o, --output-dir or "
                 "--in-place: stdout when it is not a terminal)");
    auto* a = sub.add_flag("--ascii", io.ascii, "Write PLY/STL as text (glTF: JSON .gltf instead of .glb)");
    auto* b = sub.add_flag("--binary", io.binary, "Write PLY/STL as binary (the default)");
    a->excludes(b);
  } else if (kind == OutputKind::Image) {
    sub.add_option("-o,--output", io.output, "Output image; - writes stdout (then --format is needed)");
    sub.add_option("--output-dir", io.output_dir, "Write one image per input into DIR, named after the input");
    sub.add_option("--format", io.format,
                   "Image format: " + image_format_list() + " (default: from -o's extension, else " +
                       shadetool::image_format_names().front() + ")")
        ->check(CLI::IsMember(shadetool::image_format_names(), CLI::ignore_case));
  }
  sub.add_option("-j,--jobs", io.jobs, "Files processed in parallel (default: number of cores)")
      ->check(CLI::Range(0, 1024));
  sub.add_flag("--json", io.json, "Print one JSON object per file on stdout (JSON Lines)");
  sub.add_flag("-q,--quiet", io.quiet, "Print no notes, only errors");
  sub.add_flag("--stats", io.stats, "Print counts and time per stage (read, compute, write) on stderr");
}

namespace {

// A message or note as one printable line: bytes of the input quoted in it (a garbage token, a
// keyword) may hold control characters or terminal escapes; they are shown as \xNN instead.
std::string printable(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    if (u < 0x20 || u == 0x7f) out += fmt::format("\\x{:02X}", unsigned(u));
    else out += ch;
  }
  return out;
}

// JSON Lines: file contents quoted in a message need not be UTF-8; nlohmann's dump() would throw
// on them, so invalid bytes are replaced (U+FFFD) instead.
std::string dump_line(const nlohmann::json& j) { return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string read_stdin() {
  std::string data;
  char buf[1 << 16];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, stdin)) > 0) data.append(buf, n);
  return data;
}

// Where one input's output goes ("" when the command writes no file).
std::string output_path_for(const IoOptions& io, const std::string& input, OutputKind kind) {
  if (kind == OutputKind::Report) return {};
  if (!io.output.empty()) return io.output;
  if (io.in_place) return input;
  const fs::path in = input == "-" ? fs::path("stdin") : fs::path(input);
  std::string ext;
  if (kind == OutputKind::Image) {
    const shadetool::ImageFormatEntry* f =
        shadetool::find_image_format(io.format.empty() ? shadetool::image_format_names().front() : io.format);
    ext = f ? f->extensions.front() : io.format;
  } else {
    ext = !io.format.empty() ? io.format : in.extension().string();
    if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
    if (ext.empty()) ext = io.input_format;
  }
  return (fs::path(io.output_dir) / in.stem()).string() + "." + ext;
}

void refuse_overlapping_paths(const IoOptions& io, OutputKind kind);
bool input_is_gltf(const IoOptions& io, const std::string& input);

// A result no output format can hold is a usage error before any work (bake-lighting -o x.stl
// would write a file with nothing it computed). An output whose format is unknown is left to the
// writer's own message.
void refuse_unheld_result(const std::string& command, const IoOptions& io, OutputKind kind) {
  if (kind != OutputKind::Mesh || io.result_attributes.empty()) return;
  for (const std::string& input : io.inputs) {
    const std::string output = output_path_for(io, input, kind);
    Format format = Format::Auto;
    try {
      format = shadetool::output_format(output, io.format.empty() ? Format::Auto : shadetool::parse_format_name(io.format, "--format"));
    } catch (const shadetool::Error&) {
      continue;
    }
    const shadetool::FormatEntry& e = shadetool::format_entry(format);
    if (!shadetool::holds_any(e.holds, io.result_attributes))
      throw UsageError(fmt::format("{}: {} cannot hold {}'s result ({}): write {}", output == "-" ? "stdout" : output,
                                   e.name, command, io.result_name, shadetool::formats_holding(io.result_attributes)));
  }
}

void validate(const IoOptions& io, OutputKind kind) {
  if (io.inputs.empty()) throw UsageError("no input given");
  const auto stdin_inputs = std::count(io.inputs.begin(), io.inputs.end(), std::string("-"));
  if (stdin_inputs > 1) throw UsageError("stdin (-) can be read only once");
  if (stdin_inputs == 1 && io.input_format.empty()) throw UsageError("reading stdin (-) needs --input-format");
  if (kind == OutputKind::Report) return refuse_overlapping_paths(io, kind);
  if (!io.output.empty() && !io.output_dir.empty()) throw UsageError("give -o or --output-dir, not both");
  if (io.in_place && (!io.output.empty() || !io.output_dir.empty()))
    throw UsageError("--in-place replaces the inputs: give it without -o and --output-dir");
  if (io.in_place)
    for (const std::string& input : io.inputs) {
      if (input == "-") throw UsageError("--in-place cannot replace stdin (-): use -o FILE or -o -");
      if (!io.format.empty()) {
        const shadetool::FormatEntry* in = shadetool::find_format(fs::path(input).extension().string().erase(0, 1));
        const Format out = shadetool::parse_format_name(io.format, "--format");
        const bool gltf_form_differs = in && in->format == Format::Gltf &&
                                       shadetool::gltf_name_is_text(input) != shadetool::gltf_name_is_text("." + io.format);
        if (!in || in->format != out || gltf_form_differs)
          throw UsageError(shadetool::located(input, 0, "--in-place keeps the input's format: --format " + io.format +
                                                            " would change it; write the new format with -o or --output-dir"));
      }
      if (io.ascii && input_is_gltf(io, input) && !shadetool::gltf_name_is_text(input))
        throw UsageError(shadetool::located(input, 0, "--in-place keeps the input's format: --ascii would write JSON glTF into a .glb; use -o"));
    }
  if (io.output.empty() && io.output_dir.empty() && !io.in_place)
    throw UsageError(kind == OutputKind::Mesh ? "no output given: use -o FILE, --output-dir DIR or --in-place"
                                              : "no output given: use -o FILE or --output-dir DIR");
  if (!io.output.empty() && io.inputs.size() > 1)
    throw UsageError("-o takes one input; use --output-dir DIR for several");
  if (io.output == "-" && io.format.empty()) throw UsageError("writing stdout (-o -) needs --format");
  if (io.output == "-" && io.json) throw UsageError("--json and -o - both write stdout; choose one");
  if (!io.output_dir.empty() && !fs::is_directory(io.output_dir))
    throw shadetool::Error(shadetool::located(io.output_dir, 0, "output directory does not exist"));
  refuse_overlapping_paths(io, kind);
}

// A file as the system sees it: device and inode where it exists, else its normalised absolute
// path (symbolic links in the existing part resolved), so that ./a.obj, a/../a.obj and a link to
// a.obj are all one file.
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string path;

  explicit FileIdentity(const std::string& p) {
    struct stat st {};
    if (::stat(p.c_str(), &st) == 0) {
      exists = true;
      device = st.st_dev;
      inode = st.st_ino;
    }
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(fs::absolute(p, ec), ec);
    path = ec ? fs::absolute(p).lexically_normal().string() : canonical.string();
  }
  bool same_file(const FileIdentity& o) const {
    if (exists && o.exists) return device == o.device && inode == o.inode;
    return path == o.path;
  }
};

// Item by item: no output may be an input, and no two outputs one file. Usage errors (exit 2),
// raised before anything is read or written.
void refuse_overlapping_paths(const IoOptions& io, OutputKind kind) {
  struct Output {
    std::string path, origin;  // origin: the input it is written for, or the flag that names it
    bool from_input;
    FileIdentity id;
  };
  std::vector<Output> outputs;
  if (kind != OutputKind::Report)
    for (const std::string& input : io.inputs) {
      const std::string out = output_path_for(io, input, kind);
      if (out != "-") outputs.push_back({out, input, true, FileIdentity(out)});
    }
  for (const auto& [flag, path] : io.other_outputs)
    if (!path.empty() && path != "-") outputs.push_back({path, flag, false, FileIdentity(path)});
  std::vector<std::pair<std::string, FileIdentity>> inputs;
  for (const std::string& input : io.inputs)
    if (input != "-") inputs.emplace_back(input, FileIdentity(input));

  for (const Output& o : outputs)
    for (const auto& [input, id] : inputs)
      if (o.id.same_file(id)) {
        if (io.in_place && o.from_input && o.origin == input) continue;  // --in-place: replacing it is the point
        if (o.from_input && o.origin == input)
          throw UsageError(shadetool::located(input, 0, "the output " + o.path + " is the input file: refusing to overwrite the input"));
        if (o.from_input)
          throw UsageError(shadetool::located(input, 0, "the output " + o.path + " (for " + o.origin +
                                                            ") is this input file: refusing to overwrite an input"));
        throw UsageError(shadetool::located(input, 0, o.origin + " " + o.path + " is the input file: refusing to overwrite the input"));
      }
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = i + 1; j < outputs.size(); ++j) {
      const Output& a = outputs[i];
      const Output& b = outputs[j];
      if (!a.id.same_file(b.id)) continue;
      if (a.from_input && b.from_input)
        throw UsageError("inputs " + a.origin + " and " + b.origin + " would both be written to " + a.path +
                         ": give them different names, or run them separately");
      const std::string what_a = a.from_input ? "the output " + a.path : a.origin + " " + a.path;
      const std::string what_b = b.from_input ? "the output " + b.path : b.origin + " " + b.path;
      throw UsageError(what_b + " is the same file as " + what_a + ": one would overwrite the other");
    }
}

// A one-line progress display on stderr, only when stderr is a terminal and neither --quiet nor
// --json is given; pipelines and logs get nothing extra. One file: its stage ("reading...") and,
// for a stage that reports a fraction (core/progress.h), `occlusion 43% (about 7 s left)` (the
// time left by core/time_left.h's rule), drawn by a thread of its own once the file has taken
// kFirstDraw and redrawn at most every kRedraw, so a quick run prints nothing. Several files:
// `[k/n] files done`, as each ends.
class Progress {
 public:
  static constexpr std::chrono::milliseconds kFirstDraw{500}, kRedraw{100};

  Progress(const IoOptions& io, std::size_t files, std::mutex& out_mutex) : files_(files), out_mutex_(out_mutex) {
    enabled_ = !io.quiet && !io.json && isatty(STDERR_FILENO);
    if (enabled_ && files_ == 1) thread_ = std::thread([this] { draw_loop(); });
  }
  ~Progress() { stop(); }
  // Where the one file's stages report (null with several files or no display).
  shadetool::ProgressSink* sink() { return enabled_ && files_ == 1 ? &meter_ : nullptr; }
  // The driver's own stages (reading, computing, writing): a name, no fraction until a kernel
  // begins a stage of its own.
  void stage(const std::string& input, const char* what) {
    if (!sink()) return;
    {
      std::lock_guard<std::mutex> lock(state_mutex_);
      input_ = input;
    }
    meter_.begin(what, 0);
  }
  // Ends the drawing thread; call it without the output mutex held (the thread takes it to draw).
  void stop() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(state_mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  // Called with the output mutex held.
  void file_done(bool ok) {
    ++done_;
    failed_ += ok ? 0 : 1;
    if (enabled_ && files_ > 1) fmt::print(stderr, "\r\033[Kshadetool: [{}/{}] files done, {} failed", done_, files_, failed_);
  }
  // Called with the output mutex held.
  void clear() {
    if (enabled_ && (files_ > 1 || drawn_)) fmt::print(stderr, "\r\033[K");
    drawn_ = false;
  }

 private:
  // "shadetool: FILE: occlusion 43% (about 7 s left)", or "shadetool: FILE: reading...".
  std::string line(const shadetool::ProgressMeter::Snapshot& s, const std::string& input) {
    std::string text = fmt::format("shadetool: {}: {}", printable(input), s.stage ? s.stage : "starting");
    if (!s.has_fraction()) return text + "...";
    const double f = s.fraction();
    // Whole percents, rounded down: 100% only when the stage is done.
    text += fmt::format(" {}%", unsigned(f * 100));
    if (const auto left = time_left_.update(s.generation, s.elapsed, f); left && f < 1)
      text += *left < 90 ? fmt::format(" (about {:.0f} s left)", std::ceil(*left))
                         : fmt::format(" (about {:.0f} min left)", std::ceil(*left / 60));
    return text;
  }

  void draw_loop() {
    const auto start = std::chrono::steady_clock::now();
    std::string last;
    std::unique_lock<std::mutex> lock(state_mutex_);
    while (!wake_.wait_for(lock, kRedraw, [this] { return stopping_; })) {
      if (std::chrono::steady_clock::now() - start < kFirstDraw) continue;
      const std::string input = input_;
      lock.unlock();
      const std::string text = line(meter_.snapshot(), input);
      if (text != last) {
        std::lock_guard<std::mutex> out(out_mutex_);
        fmt::print(stderr, "\r\033[K{}", text);
        std::fflush(stderr);
        drawn_ = true;
        last = text;
      }
      lock.lock();
    }
  }

  std::size_t files_, done_ = 0, failed_ = 0;
  bool enabled_ = false;
  std::mutex& out_mutex_;
  bool drawn_ = false;  // a line is on the terminal (guarded by out_mutex_)
  shadetool::ProgressMeter meter_;
  shadetool::TimeLeft time_left_;  // the drawing thread's only
  std::mutex state_mutex_;         // input_, stopping_
  std::condition_variable wake_;
  std::string input_;
  bool stopping_ = false;
  std::thread thread_;
};


// Reads one input: a file, or stdin ("-") in the format --input-format names.
shadetool::Mesh read_input(const IoOptions& io, const std::string& input, shadetool::ReadInfo& read_info,
                           shadetool::ProgressSink* progress) {
  const Format in_format =
      io.input_format.empty() ? Format::Auto : shadetool::parse_format_name(io.input_format, "--input-format");
  read_info.progress = shadetool::ProgressCursor(progress);
  return input == "-" ? shadetool::read_mesh_from_memory(read_stdin(), in_format, "stdin", &read_info)
                      : shadetool::read_mesh(input, in_format, &read_info);
}

// Vertices a writer added (counts are kept or named in a note, issue 27).
std::string split_vertices_note(std::size_t added) {
  return std::to_string(added) + (added == 1 ? " vertex" : " vertices") +
         " added: the format holds one normal or colour per vertex, so a vertex with several was split";
}

// Writes what the step produced (a mesh or an image) to `output`, together with the step's other
// files (all or none); notes and counts go to `result`.
void write_output(const IoOptions& io, OutputKind kind, const shadetool::Mesh& mesh, const std::string& output,
                  FileResult& result) {
  std::string bytes;
  shadetool::io::ProduceBytes produce;  // a mesh streams into the file (io/byte_sink.h)
  shadetool::WriteInfo write_info;
  switch (kind) {
    case OutputKind::Report: break;
    case OutputKind::Mesh: {
      shadetool::WriteOptions wo;
      wo.format = io.format.empty() ? Format::Auto : shadetool::parse_format_name(io.format, "--format");
      wo.format = shadetool::output_format(output, wo.format);
      wo.binary = !io.ascii;
      wo.name = output == "-" ? "stdout" : output;
      wo.refuse_unusable_normals = true;  // no subcommand writes a zero or non-finite normal
      wo.gltf_unlit = result.unlit;
      produce = shadetool::prepare_mesh_write(mesh, wo, &write_info);  // refuses what no writer writes
      break;
    }
    case OutputKind::Image: {
      shadetool::ImageWriteInfo image_info;
      bytes = shadetool::encode_image(result.image, shadetool::image_format_for(output, io.format), output, &image_info);
      result.stats["width"] = result.image.width;
      result.stats["height"] = result.image.height;
      for (auto& n : image_info.notes) result.notes.push_back(n);
      break;
    }
  }
  std::vector<shadetool::io::FileToWrite> files;
  if (kind != OutputKind::Report) files.push_back({output, bytes, produce});
  for (const auto& [path, content] : result.other_files) files.push_back({path, content});
  shadetool::io::write_files_atomically(files);
  if (write_info.split_vertices > 0) {
    result.stats["split_vertices"] = write_info.split_vertices;
    result.notes.push_back(split_vertices_note(write_info.split_vertices));
  }
  for (auto& n : write_info.notes) result.notes.push_back(n);  // what the format could not carry
}

// glTF input: true when --input-format or the input's extension names glTF.
bool input_is_gltf(const IoOptions& io, const std::string& input) {
  if (!io.input_format.empty()) return shadetool::parse_format_name(io.input_format, "--input-format") == Format::Gltf;
  if (input == "-") return false;
  const fs::path ext = fs::path(input).extension();
  const shadetool::FormatEntry* f = ext.empty() ? nullptr : shadetool::find_format(ext.string().substr(1));
  return f && f->format == Format::Gltf;
}

// glTF output: a mesh written to a name (or --format) that says glTF.
bool output_is_gltf(const IoOptions& io, OutputKind kind, const std::string& output) {
  return kind == OutputKind::Mesh &&
         shadetool::output_format(output, io.format.empty() ? Format::Auto : shadetool::parse_format_name(io.format, "--format")) ==
             Format::Gltf;
}

// A document without a triangle primitive (only POINTS/LINES, or no mesh at all) has nothing for
// a step to do: written unchanged with a note when the output is glTF, refused otherwise.
std::unique_ptr<shadetool::GltfDocument> read_gltf_input(const IoOptions& io, const std::string& input, OutputKind kind,
                                                         const std::string& output, FileResult& result) {
  std::unique_ptr<shadetool::GltfDocument> doc;
  if (input == "-") {
    const std::string bytes = read_stdin();
    if (bytes.empty()) shadetool::fail("stdin", 0, "file is empty");
    doc = std::make_unique<shadetool::GltfDocument>(shadetool::read_gltf(bytes, "stdin"));
  } else {
    doc = std::make_unique<shadetool::GltfDocument>(shadetool::read_gltf(shadetool::io::read_file_bytes(input), input));
  }
  for (const std::string& n : doc->notes) result.notes.push_back(n);  // compressed geometry decoded
  if (doc->primitives.empty()) {
    // A report (info) describes what there is, as it does for a PLY point cloud; a step that would
    // write another format has no mesh to write.
    if (kind == OutputKind::Report) {
      result.text += fmt::format("{}: glTF, no TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN primitive\n"
                                 "  POINTS/LINES           {} primitives, {} vertices\n  faces                  0\n",
                                 input, doc->passed_through_primitives, doc->passed_through_vertices);
      result.stats["format"] = "glTF";
      result.stats["triangle_primitives"] = 0;
      result.stats["points_lines_primitives"] = doc->passed_through_primitives;
      result.stats["points_lines_vertices"] = doc->passed_through_vertices;
      result.stats["faces"] = 0;
    } else if (!output_is_gltf(io, kind, output)) {
      shadetool::fail(input, 0, "no TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN primitive: nothing to read as a mesh");
    } else {
      result.notes.push_back("no TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN primitive: nothing to compute, the document written unchanged");
    }
  }
  return doc;
}

// Runs the step on every triangle primitive; notes are merged (one line per distinct note, naming
// the primitives it concerns), numeric counts summed, other values kept from the last primitive.
void run_step_per_primitive(shadetool::GltfDocument& doc, const MeshStep& step, const std::string& input, FileResult& result) {
  std::vector<std::pair<std::string, std::vector<std::string>>> notes;
  nlohmann::json per_primitive = nlohmann::json::object();
  const bool several = doc.primitives.size() > 1;
  DocumentState document_state;  // the step's work for the whole document (FileResult::gltf_document_state)
  for (shadetool::GltfPrimitive& p : doc.primitives) {
    FileResult r;
    r.gltf = &p;
    r.gltf_document = &doc;
    r.gltf_document_state = &document_state;
    r.output_gltf = result.output_gltf;
    step(p.mesh, input + ": " + p.json_path, r);
    result.unlit = result.unlit || r.unlit;
    for (auto& n : r.notes) {
      auto it = std::find_if(notes.begin(), notes.end(), [&](const auto& e) { return e.first == n; });
      if (it == notes.end()) notes.push_back({n, {p.json_path}});
      else it->second.push_back(p.json_path);
    }
    for (auto it = r.stats.begin(); it != r.stats.end(); ++it) {
      // Integers are counts: summed (not settings: FileResult::setting). Other values are kept when every primitive agrees; a
      // non-integer that differs (a mean, a time) has no one value for the file and is left to
      // per_primitive, as is a string that differs ("mixed").
      const bool first = !result.stats.contains(it.key());
      const bool setting = std::find(r.settings.begin(), r.settings.end(), it.key()) != r.settings.end();
      auto& dst = result.stats[it.key()];
      if (first) dst = it.value();
      else if (!setting && it.value().is_number_integer() && dst.is_number_integer()) dst = dst.get<long long>() + it.value().get<long long>();
      else if (dst != it.value()) dst = it.value().is_number() ? nlohmann::json() : nlohmann::json("mixed");
    }
    result.text += r.text;  // each primitive's text names it (the step's input is "FILE: JSON.PATH")
    if (several) per_primitive[p.json_path] = r.stats;
    for (auto& [path, content] : r.other_files) {  // one file per path: several primitives' JSON reports side by side
      auto same = std::find_if(result.other_files.begin(), result.other_files.end(), [&](const auto& f) { return f.first == path; });
      if (same == result.other_files.end()) {
        result.other_files.emplace_back(path, several ? "{\"" + p.json_path + "\": " + content + "}" : content);
      } else {
        same->second.erase(same->second.find_last_of('}'));
        same->second += ", \"" + p.json_path + "\": " + content + "}";
      }
    }
  }
  for (auto it = result.stats.begin(); it != result.stats.end();) it = it.value().is_null() ? result.stats.erase(it) : std::next(it);
  if (several) result.stats["per_primitive"] = per_primitive;
  for (auto& [note, paths] : notes) {
    if (!several) result.notes.push_back(note);
    else if (paths.size() == doc.primitives.size()) result.notes.push_back("every primitive: " + note);
    else if (paths.size() == 1) result.notes.push_back(paths[0] + ": " + note);
    else result.notes.push_back(std::to_string(paths.size()) + " primitives (first " + paths[0] + "): " + note);
  }
  if (doc.passed_through_primitives > 0)
    result.notes.push_back(std::to_string(doc.passed_through_primitives) + " POINTS/LINES primitives passed through untouched");
}

// A glTF document out: glTF keeps the document; another format gets the primitives as one mesh.
void write_gltf_output(const IoOptions& io, OutputKind kind, const shadetool::GltfDocument& doc, const std::string& output,
                       FileResult& result) {
  if (kind != OutputKind::Mesh) return write_output(io, kind, shadetool::Mesh(), output, result);
  Format format = io.format.empty() ? Format::Auto : shadetool::parse_format_name(io.format, "--format");
  format = shadetool::output_format(output, format);
  if (format != Format::Gltf) {
    shadetool::Mesh world = shadetool::gltf_world_mesh(doc, result.notes);
    const std::string tangents = shadetool::gltf_world_tangents(doc, world, format == Format::Ply);
    if (!tangents.empty()) result.notes.push_back(tangents);
    result.notes.push_back("glTF materials, textures and the scene graph not written (the mesh is in world space)");
    return write_output(io, kind, world, output, result);
  }
  const std::string name = output == "-" ? "stdout" : output;
  for (const auto& p : doc.primitives) {  // what every writer refuses (io/mesh_io.h)
    shadetool::require_finite_positions(p.mesh, name + ": " + p.json_path);
    shadetool::require_finite_normals(p.mesh, name + ": " + p.json_path, "nothing written");
  }
  shadetool::GltfWriteResult wr;
  const bool text = io.ascii || shadetool::gltf_name_is_text(output) || (output == "-" && !io.format.empty() && shadetool::gltf_name_is_text("." + io.format));
  // A .gltf file gets its buffer beside it (NAME.bin); to stdout it stays a data URI.
  const std::string bin_path = text && output != "-" ? shadetool::gltf_buffer_path(output) : std::string();
  const std::string bytes =
      shadetool::write_gltf(doc, !text, name, wr, bin_path.empty() ? std::string() : fs::path(bin_path).filename().string());
  if (wr.split_vertices > 0) {
    result.stats["split_vertices"] = wr.split_vertices;
    result.notes.push_back(split_vertices_note(wr.split_vertices));
  }
  for (auto& n : wr.notes) result.notes.push_back(n);
  std::vector<shadetool::io::FileToWrite> files{{output, bytes}};
  if (!wr.buffer.empty()) {
    const FileIdentity bin(bin_path);
    std::vector<std::string> read = shadetool::gltf_external_files(doc);
    read.insert(read.end(), io.inputs.begin(), io.inputs.end());
    for (const std::string& f : read)
      if (f != "-" && FileIdentity(f).same_file(bin))
        throw shadetool::Error(shadetool::located(name, 0, "its buffer file " + bin_path + " would overwrite " + f +
                                                               ", which the input reads: nothing written (name the output differently)"));
    files.push_back({bin_path, std::move(wr.buffer)});
  }
  for (const auto& [path, content] : result.other_files) files.push_back({path, content});
  shadetool::io::write_files_atomically(files);
}

}  // namespace

namespace {

// The input's format as a --format value ("obj", "glb", ...): --input-format, else its extension.
std::string input_format_name(const IoOptions& io, const std::string& input) {
  if (!io.input_format.empty()) return io.input_format;
  std::string ext = input == "-" ? std::string() : fs::path(input).extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext.empty() || !shadetool::find_format(ext))
    throw UsageError(shadetool::located(input, 0, "no output given and the input's format is not known from its name: "
                                                  "use -o FILE, --output-dir DIR, --in-place, or -o - --format FORMAT"));
  return ext;
}

// A mesh command given none of -o, --output-dir, --in-place: to stdout when stdout is not a
// terminal (a pipe, a file), one input only, in the input's format unless --format names one.
IoOptions with_default_output(const IoOptions& io, OutputKind kind) {
  if (kind != OutputKind::Mesh || !io.output.empty() || !io.output_dir.empty() || io.in_place || io.inputs.empty())
    return io;
  if (isatty(STDOUT_FILENO))
    throw UsageError("no output given: use -o FILE, --output-dir DIR or --in-place (a mesh is written to stdout only "
                     "when it is not a terminal)");
  if (io.inputs.size() > 1)
    throw UsageError("no output given for " + std::to_string(io.inputs.size()) +
                     " inputs: stdout takes one mesh; use --output-dir DIR or --in-place");
  IoOptions out = io;
  out.output = "-";
  if (out.format.empty()) out.format = input_format_name(io, io.inputs[0]);
  return out;
}

}  // namespace

int run_command(const std::string& command, const IoOptions& given_io, const MeshStep& step, OutputKind kind) {
  shadetool::io::remove_temporaries_on_signals();  // an interrupted write leaves no PATH.tmp-XXXXXX
  const IoOptions io = with_default_output(given_io, kind);
  validate(io, kind);
  refuse_unheld_result(command, io, kind);
  const bool writes_file = kind != OutputKind::Report;

  std::mutex out_mutex;  // one line at a time on stdout and stderr
  std::atomic<std::size_t> next{0};
  std::atomic<int> failures{0};
  std::atomic<int> usage_failures{0};  // a step's UsageError: the flags do not suit that file
  std::vector<std::string> failed;
  Progress progress(io, io.inputs.size(), out_mutex);
  auto show_stage = [&](const std::string& input, const char* what) { progress.stage(input, what); };

  const std::size_t n_inputs = io.inputs.size();
  auto process = [&](const std::string& input) {
    nlohmann::json line = {{"command", command}, {"input", input}};
    const std::string output = output_path_for(io, input, kind);
    if (writes_file) line["output"] = output;
    FileResult result;
    result.progress = progress.sink();
    try {
      show_stage(input, "reading");
      auto t0 = std::chrono::steady_clock::now();
      shadetool::ReadInfo read_info;
      shadetool::Mesh mesh;
      std::unique_ptr<shadetool::GltfDocument> document;
      if (kind != OutputKind::Image && input_is_gltf(io, input)) document = read_gltf_input(io, input, kind, output, result);
      else mesh = read_input(io, input, read_info, result.progress);
      const double read_ms = ms_since(t0);
      for (auto& n : read_info.notes) result.notes.push_back(n);
      if (read_info.merged_vertices > 0) result.stats["merged_vertices"] = read_info.merged_vertices;
      if (read_info.nonfinite_color_values > 0) result.stats["nonfinite_colour_values_read"] = read_info.nonfinite_color_values;

      show_stage(input, "computing");
      t0 = std::chrono::steady_clock::now();
      result.output_gltf = writes_file && output_is_gltf(io, kind, output);
      if (document) run_step_per_primitive(*document, step, input, result);
      else step(mesh, input, result);
      if (document && result.unlit) document->unlit_materials = true;
      const double compute_ms = ms_since(t0);

      double write_ms = 0;
      if (writes_file || !result.other_files.empty()) {
        show_stage(input, "writing");
        t0 = std::chrono::steady_clock::now();
        if (document) write_gltf_output(io, kind, *document, output, result);
        else write_output(io, kind, mesh, output, result);
        write_ms = ms_since(t0);
      }
      if (document) {
        std::size_t vertices = 0, faces = 0;
        for (const auto& p : document->primitives) vertices += p.mesh.num_vertices(), faces += p.mesh.num_faces();
        result.stats["vertices"] = vertices;
        result.stats["faces"] = faces;
        result.stats["primitives"] = document->primitives.size();
      } else {
        result.stats["vertices"] = mesh.num_vertices();
        result.stats["faces"] = mesh.num_faces();
      }
      line["status"] = "ok";
      line["time_ms"] = {{"read", read_ms}, {"compute", compute_ms}, {"write", write_ms}};
      line["stats"] = result.stats;

      if (n_inputs == 1) progress.stop();
      std::lock_guard<std::mutex> lock(out_mutex);
      progress.clear();
      if (!io.quiet)
        for (auto& n : result.notes) fmt::print(stderr, "shadetool: {}: {}\n", input, printable(n));
      if (io.stats) {
        std::string counts;
        for (auto it = result.stats.begin(); it != result.stats.end(); ++it)
          counts += fmt::format(" {}={}", it.key(), it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
        fmt::print(stderr, "shadetool: {}: read {:.1f} ms, compute {:.1f} ms, write {:.1f} ms;{}\n", input, read_ms,
                   compute_ms, write_ms, counts);
      }
      if (!result.text.empty() && !io.json) fmt::print("{}", result.text);
      if (io.json) {
        if (!result.notes.empty()) line["notes"] = result.notes;
        fmt::print("{}\n", dump_line(line));
        std::fflush(stdout);
      }
      progress.file_done(true);
    } catch (const std::exception& e) {
      // shadetool::Error already names the file; anything else (std::bad_alloc for a mesh that
      // does not fit in memory, ...) gets the input's name so the line still says which file.
      const bool located = dynamic_cast<const shadetool::Error*>(&e) != nullptr || dynamic_cast<const UsageError*>(&e) != nullptr;
      const std::string message =
          located ? e.what()
                  : shadetool::located(input, 0, dynamic_cast<const std::bad_alloc*>(&e) ? "out of memory" : e.what());
      failures.fetch_add(1);
      if (dynamic_cast<const UsageError*>(&e)) usage_failures.fetch_add(1);
      if (n_inputs == 1) progress.stop();
      std::lock_guard<std::mutex> lock(out_mutex);
      failed.push_back(input);
      progress.clear();
      fmt::print(stderr, "shadetool: {}\n", printable(message));
      if (io.json) {
        line["status"] = "error";
        line["error"] = message;
        fmt::print("{}\n", dump_line(line));
        std::fflush(stdout);
      }
      progress.file_done(false);
    }
  };

  const std::size_t n = io.inputs.size();
  unsigned jobs = io.jobs > 0 ? unsigned(io.jobs) : std::max(1u, std::thread::hardware_concurrency());
  jobs = unsigned(std::min<std::size_t>(jobs, n));
  auto worker = [&] {
    for (std::size_t i = next.fetch_add(1); i < n; i = next.fetch_add(1)) process(io.inputs[i]);
  };
  if (jobs <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < jobs; ++k) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
  }
  progress.stop();
  progress.clear();
  if (n > 1 && failures > 0 && !io.json) {
    std::string list;
    for (auto& f : failed) list += (list.empty() ? "" : ", ") + f;
    fmt::print(stderr, "shadetool: {} of {} files failed: {}\n", failures.load(), n, list);
  }
  return usage_failures > 0 ? kExitUsage : failures > 0 ? kExitFailure : kExitOk;
}

}  // namespace shadetool_cli
