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

void write_file_atomically(const std::string& path, std::string_view bytes) {
  if (path == "-") {
    std::fflush(stdout);
    if (!write_all(STDOUT_FILENO, bytes)) fail("stdout", 0, std::string("cannot write: ") + std::strerror(errno));
    return;
  }
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
  // reader and for a failing or killed process; fsync adds durability across a power loss at
  // ~8 ms per file here, which dominated pipelines of many small meshes (bench/pipeline).
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
  if (ok && ::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    saved = errno;
  }
  if (!ok) {
    ::unlink(tmp.c_str());
    fail(path, 0, std::string("cannot write: ") + std::strerror(saved));
  }
}

}  // namespace shadetool::io
