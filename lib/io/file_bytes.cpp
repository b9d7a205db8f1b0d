// file_bytes.cpp: whole-file read with fopen/fread (one allocation, one read).
#include "io/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "core/error.h"

namespace shadetool::io {

std::string read_file_bytes(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail(path, 0, std::string("cannot open: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) fail(path, 0, "is a directory, not a mesh file");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) fail(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::string bytes;
  if (S_ISREG(st.st_mode) && st.st_size > 0) {
    bytes.resize(static_cast<std::size_t>(st.st_size));
    const std::size_t got = std::fread(bytes.data(), 1, bytes.size(), f);
    bytes.resize(got);
  }
  // Pipes and special files report no size: read until the end.
  char buf[1 << 16];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.append(buf, n);
  const bool error = std::ferror(f) != 0;
  std::fclose(f);
  if (error) fail(path, 0, "read error");
  if (bytes.empty()) fail(path, 0, "file is empty");
  return bytes;
}

}  // namespace shadetool::io
