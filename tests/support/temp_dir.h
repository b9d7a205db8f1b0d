// temp_dir.h: a fresh directory for the files one test writes, removed with everything in it when
// the test ends (permissions a test took away are restored first). Unique per process and per
// object (mkdtemp), so test executables that ctest runs side by side never share one.
//   dir / "a.ply", dir.file("a.ply")   a path inside it (as a string)
//   dir.write("a.ply", bytes)          writes bytes exactly (binary) and returns the path
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace shadetool::testing {

struct TempDir {
  std::filesystem::path path;

  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "shadetool-test-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("TempDir: mkdtemp failed for " + tmpl);
    path = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path / name).string(); }
  std::string operator/(const std::string& name) const { return file(name); }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path / name, std::ios::binary) << bytes;
    return file(name);
  }
};

}  // namespace shadetool::testing
