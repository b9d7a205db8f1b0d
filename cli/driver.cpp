// driver.cpp: inputs, outputs, parallel files, notes, --stats and --json for every subcommand.
#include "driver.h"

#include <algorithm>
#include <cctype>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <mutex>
#include <new>
#include <thread>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <shadetool/core/error.h>
#include <shadetool/io/format_table.h>
#include <shadetool/io/image_io.h>
#include <shadetool/io/mesh_io.h>
#include "usage_error.h"

namespace shadetool_cli {

namespace fs = std::filesystem;
using shadetool::Format;

namespace {

// "OBJ, PLY, OFF, STL": the mesh formats of io/format_table.h, for help texts.
std::string upper_format_names() {
  std::string s;
  for (const std::string& n : shadetool::format_names()) {
    if (!s.empty()) s += ", ";
    for (char c : n) s += char(std::toupper(static_cast<unsigned char>(c)));
  }
  return s;
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
      ->check(CLI::IsMember(shadetool::format_names(), CLI::ignore_case));
  if (kind == OutputKind::Mesh) {
    sub.add_option("-o,--output", io.output, "Output file; - writes stdout (then --format is needed)");
    sub.add_option("--output-dir", io.output_dir, "Write one output per input into DIR, named after the input");
    sub.add_option("--format", io.format,
                   "Output format: " + shadetool::format_list(false) + " (default: from -o's extension)")
        ->check(CLI::IsMember(shadetool::format_names(), CLI::ignore_case));
    auto* a = sub.add_flag("--ascii", io.ascii, "Write PLY/STL as text");
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

void add_io_options(CLI::App& sub, IoOptions& io, bool writes_mesh) {
  add_io_options(sub, io, writes_mesh ? OutputKind::Mesh : OutputKind::Report);
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

void validate(const IoOptions& io, OutputKind kind) {
  if (io.inputs.empty()) throw UsageError("no input given");
  const auto stdin_inputs = std::count(io.inputs.begin(), io.inputs.end(), std::string("-"));
  if (stdin_inputs > 1) throw UsageError("stdin (-) can be read only once");
  if (stdin_inputs == 1 && io.input_format.empty()) throw UsageError("reading stdin (-) needs --input-format");
  if (kind == OutputKind::Report) return;
  if (!io.output.empty() && !io.output_dir.empty()) throw UsageError("give -o or --output-dir, not both");
  if (io.output.empty() && io.output_dir.empty()) throw UsageError("no output given: use -o FILE or --output-dir DIR");
  if (!io.output.empty() && io.inputs.size() > 1)
    throw UsageError("-o takes one input; use --output-dir DIR for several");
  if (io.output == "-" && io.format.empty()) throw UsageError("writing stdout (-o -) needs --format");
  if (io.output == "-" && io.json) throw UsageError("--json and -o - both write stdout; choose one");
  if (!io.output_dir.empty() && !fs::is_directory(io.output_dir))
    throw shadetool::Error(shadetool::located(io.output_dir, 0, "output directory does not exist"));
}

// A one-line progress display on stderr, only when stderr is a terminal and the work is long
// (several files, or one file over 32 MiB); pipelines and logs get nothing extra.
class Progress {
 public:
  Progress(const IoOptions& io, std::size_t files) : files_(files) {
    if (io.quiet || io.json || !isatty(STDERR_FILENO)) return;
    std::error_code ec;
    const bool big = files == 1 && io.inputs[0] != "-" && fs::file_size(io.inputs[0], ec) > (32u << 20) && !ec;
    enabled_ = files > 1 || big;
  }
  // Called with the output mutex held.
  void stage(const std::string& input, const char* what) {
    if (enabled_ && files_ == 1) fmt::print(stderr, "\r\033[Kshadetool: {}: {}...", input, what);
  }
  void file_done(bool ok) {
    ++done_;
    failed_ += ok ? 0 : 1;
    if (enabled_ && files_ > 1) fmt::print(stderr, "\r\033[Kshadetool: [{}/{}] files done, {} failed", done_, files_, failed_);
  }
  void clear() {
    if (enabled_) fmt::print(stderr, "\r\033[K");
  }
  bool enabled() const { return enabled_; }

 private:
  std::size_t files_, done_ = 0, failed_ = 0;
  bool enabled_ = false;
};


// Reads one input: a file, or stdin ("-") in the format --input-format names.
shadetool::Mesh read_input(const IoOptions& io, const std::string& input, shadetool::ReadInfo& read_info) {
  const Format in_format =
      io.input_format.empty() ? Format::Auto : shadetool::parse_format_name(io.input_format, "--input-format");
  return input == "-" ? shadetool::read_mesh_from_memory(read_stdin(), in_format, "stdin", &read_info)
                      : shadetool::read_mesh(input, in_format, &read_info);
}

// Writes what the step produced (a mesh or an image) to `output`; its notes and counts go to `result`.
void write_output(const IoOptions& io, OutputKind kind, const shadetool::Mesh& mesh, const std::string& output,
                  FileResult& result) {
  switch (kind) {
    case OutputKind::Report: return;
    case OutputKind::Mesh: {
      shadetool::WriteOptions wo;
      wo.format = io.format.empty() ? Format::Auto : shadetool::parse_format_name(io.format, "--format");
      wo.binary = !io.ascii;
      shadetool::WriteInfo write_info;
      shadetool::write_mesh(mesh, output, wo, &write_info);
      if (write_info.split_vertices > 0) result.stats["split_vertices"] = write_info.split_vertices;
      for (auto& n : write_info.notes) result.notes.push_back(n);  // what the format could not carry
      return;
    }
    case OutputKind::Image: {
      shadetool::ImageWriteInfo write_info;
      shadetool::write_image(result.image, output, io.format, &write_info);
      result.stats["width"] = result.image.width;
      result.stats["height"] = result.image.height;
      for (auto& n : write_info.notes) result.notes.push_back(n);
      return;
    }
  }
}

}  // namespace

int run_command(const std::string& command, const IoOptions& io, const MeshStep& step, OutputKind kind) {
  validate(io, kind);
  const bool writes_file = kind != OutputKind::Report;

  std::mutex out_mutex;  // one line at a time on stdout and stderr
  std::atomic<std::size_t> next{0};
  std::atomic<int> failures{0};
  std::vector<std::string> failed;
  Progress progress(io, io.inputs.size());
  auto show_stage = [&](const std::string& input, const char* what) {
    if (!progress.enabled()) return;
    std::lock_guard<std::mutex> lock(out_mutex);
    progress.stage(input, what);
  };

  auto process = [&](const std::string& input) {
    nlohmann::json line = {{"command", command}, {"input", input}};
    const std::string output = output_path_for(io, input, kind);
    if (writes_file) line["output"] = output;
    FileResult result;
    try {
      // Writing over the input would lose it if anything failed later; the same file under another
      // name (./a.obj, a link, --output-dir of the input's own folder) counts too.
      std::error_code same_ec;
      if (writes_file && input != "-" && output != "-" && fs::equivalent(input, output, same_ec))
        throw shadetool::Error(shadetool::located(
            input, 0, "the output " + output + " is the input file: refusing to overwrite the input"));
      show_stage(input, "reading");
      auto t0 = std::chrono::steady_clock::now();
      shadetool::ReadInfo read_info;
      shadetool::Mesh mesh = read_input(io, input, read_info);
      const double read_ms = ms_since(t0);
      for (auto& n : read_info.notes) result.notes.push_back(n);
      if (read_info.merged_vertices > 0) result.stats["merged_vertices"] = read_info.merged_vertices;

      show_stage(input, "computing");
      t0 = std::chrono::steady_clock::now();
      step(mesh, input, result);
      const double compute_ms = ms_since(t0);

      double write_ms = 0;
      if (writes_file) {
        show_stage(input, "writing");
        t0 = std::chrono::steady_clock::now();
        write_output(io, kind, mesh, output, result);
        write_ms = ms_since(t0);
      }
      result.stats["vertices"] = mesh.num_vertices();
      result.stats["faces"] = mesh.num_faces();
      line["status"] = "ok";
      line["time_ms"] = {{"read", read_ms}, {"compute", compute_ms}, {"write", write_ms}};
      line["stats"] = result.stats;

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
      const bool located = dynamic_cast<const shadetool::Error*>(&e) != nullptr;
      const std::string message =
          located ? e.what()
                  : shadetool::located(input, 0, dynamic_cast<const std::bad_alloc*>(&e) ? "out of memory" : e.what());
      failures.fetch_add(1);
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
  progress.clear();
  if (n > 1 && failures > 0 && !io.json) {
    std::string list;
    for (auto& f : failed) list += (list.empty() ? "" : ", ") + f;
    fmt::print(stderr, "shadetool: {} of {} files failed: {}\n", failures.load(), n, list);
  }
  return failures > 0 ? kExitFailure : kExitOk;
}

int run_mesh_command(const std::string& command, const IoOptions& io, const MeshStep& step, bool writes_mesh) {
  return run_command(command, io, step, writes_mesh ? OutputKind::Mesh : OutputKind::Report);
}

}  // namespace shadetool_cli
