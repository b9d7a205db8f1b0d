// atomic_write.cpp: mkstemp in the target directory, write, (fsync if asked), rename.
#include <shadetool/io/atomic_write.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <memory>
#include <vector>

#include <shadetool/core/error.h>

namespace shadetool::io {

namespace {

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

// The temporaries being written, for the signal handler: a fixed table (no allocation, no lock in
// the handler). A slot is claimed (state 0 -> 1), given the template `PATH.tmp-XXXXXX` and listed
// (1 -> 2); mkstemp then fills the X's in place (so the file never exists unlisted), and the slot
// is released (-> 0) once the temporary is renamed or removed. The handler unlinks listed slots
// only: a name whose X's are half-filled, or already renamed, names no file (or a temporary of
// ours, which the handler removes anyway), never a user's file.
constexpr std::size_t kSlots = 256;
struct TemporarySlot {
  std::atomic<int> in_use{0};
  char name[PATH_MAX];
};
TemporarySlot g_slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' flags");

// A claimed slot, released on destruction; index -1: none (table full or name too long).
class Registration {
 public:
  explicit Registration(const std::string& tmpl) {
    if (tmpl.size() + 1 > sizeof(g_slots[0].name)) return;
    for (std::size_t i = 0; i < kSlots; ++i) {
      int expected = 0;
      if (g_slots[i].in_use.load(std::memory_order_relaxed) == 0 &&
          g_slots[i].in_use.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) {
        std::memcpy(g_slots[i].name, tmpl.c_str(), tmpl.size() + 1);
        g_slots[i].in_use.store(2, std::memory_order_release);  // listed: the name is whole
        index_ = static_cast<int>(i);
        return;
      }
    }
  }
  ~Registration() { release(); }
  Registration(const Registration&) = delete;
  Registration& operator=(const Registration&) = delete;
  // The buffer mkstemp fills: the slot's own, or `fallback` when no slot was free.
  char* buffer(std::vector<char>& fallback) { return index_ >= 0 ? g_slots[index_].name : fallback.data(); }
  void release() {
    if (index_ < 0) return;
    g_slots[index_].in_use.store(0, std::memory_order_release);
    index_ = -1;
  }

 private:
  int index_ = -1;
};

extern "C" void remove_temporaries_and_reraise(int sig) {
  const int saved = errno;
  for (TemporarySlot& s : g_slots)
    if (s.in_use.load(std::memory_order_acquire) == 2) ::unlink(s.name);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  errno = saved;
  ::raise(sig);  // blocked while the handler runs: delivered, with the default action, on return
}

}  // namespace

void remove_temporaries_on_signals() {
  static std::atomic<bool> installed{false};
  if (installed.exchange(true)) return;
  for (const int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || (old.sa_flags & SA_SIGINFO) || old.sa_handler != SIG_DFL) continue;
    struct sigaction sa {};
    sa.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    ::sigaction(sig, &sa, nullptr);
  }
}

namespace {

// Writes `contents` (its bytes, or what its producer appends, through a 1 MiB FdSink) to a new
// temporary file next to `path` (same directory: rename(2) is atomic there) with the mode the
// final file should get; returns its name. On any error nothing is left behind.
// `reg` lists the temporary for the signal handler until the caller has renamed or removed it.
std::string write_temporary(const std::string& path, const FileToWrite& contents, Registration& reg) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) fail(path, 0, "cannot write: is a directory");

  const std::string tmpl = path + ".tmp-XXXXXX";
  std::vector<char> fallback(tmpl.begin(), tmpl.end());
  fallback.push_back('\0');
  char* name = reg.buffer(fallback);
  const int fd = ::mkstemp(name);
  if (fd < 0) fail(path, 0, std::string("cannot write: ") + std::strerror(errno));
  const std::string tmp(name);

  // Keep the mode of a file being replaced; a new file gets 0666 & ~umask like fopen would.
  const mode_t mode = ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~current_umask());
  // fsync only when SHADETOOL_FSYNC=1: rename already makes the replacement atomic for every
  // reader and for a failing or killed process; fsync adds durability across a power loss at a
  // cost per file that dominated pipelines of many small meshes (bench/pipeline/results.md).
  static const bool want_fsync = [] {
    const char* e = std::getenv("SHADETOOL_FSYNC");
    return e != nullptr && std::string_view(e) == "1";
  }();
  bool ok = ::fchmod(fd, mode) == 0;
  if (ok) {
    try {
      FdSink sink(fd, path);
      if (contents.produce) contents.produce(sink);
      else sink.append(contents.bytes);
      sink.flush();
    } catch (...) {  // a write error (FdSink's Error names `path`) or the producer's own
      ::close(fd);
      ::unlink(tmp.c_str());
      throw;
    }
    ok = !want_fsync || ::fsync(fd) == 0;
  }
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

void write_stdout(const FileToWrite& contents) {
  std::fflush(stdout);
  FdSink sink(STDOUT_FILENO, "stdout");
  if (contents.produce) contents.produce(sink);
  else sink.append(contents.bytes);
  sink.flush();
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
  write_files_atomically({FileToWrite{path, bytes}});
}

void write_file_atomically(const std::string& path, const ProduceBytes& produce) {
  write_files_atomically({FileToWrite{path, {}, produce}});
}

void write_files_atomically(const std::vector<FileToWrite>& files) {
  std::vector<std::string> temporaries;  // one per file that is not stdout, in order
  std::vector<std::unique_ptr<Registration>> registrations;  // released when this function returns
  auto remove_temporaries = [&](std::size_t from) {
    for (std::size_t i = from; i < temporaries.size(); ++i) ::unlink(temporaries[i].c_str());
  };
  try {
    for (const FileToWrite& f : files)
      if (f.path != "-") {
        registrations.push_back(std::make_unique<Registration>(f.path + ".tmp-XXXXXX"));
        temporaries.push_back(write_temporary(f.path, f, *registrations.back()));
      }
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
    if (f.path == "-") write_stdout(f);
}

}  // namespace shadetool::io
