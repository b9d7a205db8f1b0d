// atomic_write.cpp: mkstemp in the target directory, write, (fsync if asked), rename.
#include <shadetool/io/atomic_write.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include <shadetool/core/error.h>

namespace shadetool::io {

namespace {

bool write_all(int fd, std::string_view bytes) {
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

// Read once (umask can only be read by setting it): calling umask(0); umask(m) from several writer
// threads at once (-j N) could interleave and leave the process's umask at 0, so that later files
// got mode 0666 whatever the user's umask. A function-local static is initialised exactly once.
mode_t current_umask() {
  static const mode_t m = [] {
    const mode_t old = ::umask(0);
    ::umask(old);
    return old;
  }();
  return m;
}

}  // namespace

namespace {

// Writes `bytes` to a new temporary file next to `path` (same directory: rename(2) is atomic there)
// with the mode the final file should get; returns its name. On any error nothing is left behind.
std::string write_temporary(const std::string& path, std::string_view bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) fail(path, 0, "cannot write: is a directory");

  std::string tmpl = path + ".tmp-XXXXXX";
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail(path, 0, std::string("cannot write: ") + std::strerror(errno));
  const std::string tmp(name.data());

  // Keep the mode of a file being replaced; a new file gets 0666 & ~umask like fopen would.
  const mode_t mode = ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~current_umask());
  // fsync only when SHADETOOL_FSYNC=1: rename already makes the replacement atomic for every
  // reader and for a failing or killed process; fsync adds durability across a power loss at a
  // cost per file that dominated pipelines of many small meshes (bench/pipeline/results.md).
  static const bool want_fsync = [] {
    const char* e = std::getenv("SHADETOOL_FSYNC");
    return e != nullptr && std::string_view(e) == "1";
  }();
  bool ok = ::fchmod(fd, mode) == 0 && write_all(fd, bytes) && (!want_fsync || ::fsync(fd) == 0);
  int saved = errno;
  if (::close(fd) != 0 && ok) {
    ok = false;
    saved = errno;
  }
  if (!ok) {
    ::unlink(tmp.c_str());
    fail(path, 0, std::string("cannot write: ") + std::strerror(saved));
  }
  return tmp;
}

void write_stdout(std::string_view bytes) {
  std::fflush(stdout);
  if (!write_all(STDOUT_FILENO, bytes)) fail("stdout", 0, std::string("cannot write: ") + std::strerror(errno));
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
  if (path == "-") return write_stdout(bytes);
  const std::string tmp = write_temporary(path, bytes);
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    ::unlink(tmp.c_str());
    fail(path, 0, std::string("cannot write: ") + std::strerror(saved));
  }
}

void write_files_atomically(const std::vector<FileToWrite>& files) {
  std::vector<std::string> temporaries;  // one per file that is not stdout, in order
  auto remove_temporaries = [&](std::size_t from) {
    for (std::size_t i = from; i < temporaries.size(); ++i) ::unlink(temporaries[i].c_str());
  };
  try {
    for (const FileToWrite& f : files)
      if (f.path != "-") temporaries.push_back(write_temporary(f.path, f.bytes));
  } catch (...) {
    remove_temporaries(0);
    throw;
  }
  std::size_t t = 0;
  for (const FileToWrite& f : files) {
    if (f.path == "-") continue;
    if (::rename(temporaries[t].c_str(), f.path.c_str()) != 0) {
      const int saved = errno;
      remove_temporaries(t);
      fail(f.path, 0, std::string("cannot write: ") + std::strerror(saved));
    }
    ++t;
  }
  for (const FileToWrite& f : files)
    if (f.path == "-") write_stdout(f.bytes);
}

}  // namespace shadetool::io
