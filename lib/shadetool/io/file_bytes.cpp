// file_bytes.cpp: mmap for large regular files; read(2) into an uninitialised buffer otherwise
// (in growing chunks when the size is unknown: pipes, /dev/stdin).
#include <shadetool/io/file_bytes.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <shared_mutex>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include <shadetool/core/engine/usable_threads.h>
#include <shadetool/core/error.h>

namespace shadetool::io {

namespace {

constexpr std::size_t kMapAtLeast = std::size_t(1) << 20;
// Mapping a file's cached pages into the process costs about as much as copying them with read(2)
// (bench/io/results.md); with more than one thread and at least this many bytes it is done in
// blocks of kPopulateBlock by the threads at once (MADV_POPULATE_READ, Linux 5.14), else by
// MAP_POPULATE in the mmap call.
constexpr std::size_t kPopulateInParallelAtLeast = std::size_t(8) << 20;
constexpr std::size_t kPopulateBlock = std::size_t(2) << 20;

// Maps [0, size) of fd read-only, its pages present; MAP_FAILED when mmap refuses.
void* map_populated(int fd, std::size_t size) {
#if defined(__linux__)
  constexpr int kPopulateRead = 22;  // MADV_POPULATE_READ; glibc 2.36's headers may lack it
  if (size >= kPopulateInParallelAtLeast && usable_threads() > 1) {
    void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (p == MAP_FAILED) return p;
    char* const base = static_cast<char*>(p);
    std::atomic<bool> refused{false};  // an older kernel: the first page faults in every page as it is read
    tbb::parallel_for(std::size_t(0), (size + kPopulateBlock - 1) / kPopulateBlock, [&](std::size_t b) {
      const std::size_t at = b * kPopulateBlock;
      if (::madvise(base + at, std::min(kPopulateBlock, size - at), kPopulateRead) != 0) refused.store(true, std::memory_order_relaxed);
    });
    if (!refused) return p;
    ::munmap(p, size);
  }
#endif
  return ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
}

// The live mappings read_file_bytes made (begin, size): release_mapped_pages drops pages only
// inside one of them.
std::shared_mutex g_mappings_mutex;  // shared: threads drop pages of one mapping at once
std::vector<std::pair<const char*, std::size_t>> g_mappings;

void register_mapping(const char* p, std::size_t n) {
  const std::lock_guard<std::shared_mutex> lock(g_mappings_mutex);
  g_mappings.emplace_back(p, n);
}

void unregister_mapping(const char* p) {
  const std::lock_guard<std::shared_mutex> lock(g_mappings_mutex);
  for (std::size_t i = 0; i < g_mappings.size(); ++i)
    if (g_mappings[i].first == p) {
      g_mappings[i] = g_mappings.back();
      g_mappings.pop_back();
      return;
    }
}

// Reads up to `n` bytes; returns how many (fewer only at the end of the file); -1 on error.
ssize_t read_fully(int fd, char* p, std::size_t n) {
  std::size_t got = 0;
  while (got < n) {
    const ssize_t r = ::read(fd, p + got, n - got);
    if (r < 0) {
      if (errno == EINTR) continue;
      return -1;
    }
    if (r == 0) break;
    got += std::size_t(r);
  }
  return ssize_t(got);
}

}  // namespace

FileBytes::FileBytes(FileBytes&& o) noexcept
    : owned_(std::move(o.owned_)), data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)),
      mapped_(std::exchange(o.mapped_, false)) {}

FileBytes& FileBytes::operator=(FileBytes&& o) noexcept {
  if (this != &o) {
    this->~FileBytes();
    new (this) FileBytes(std::move(o));
  }
  return *this;
}

// Unmapping a populated mapping drops its page-table entries one page at a time under the
// process's memory-map lock, held for writing: 6 ms for a 177 MB file, all on one thread
// (bench/io/results.md). madvise(MADV_DONTNEED) does the same work holding the lock for reading,
// so the threads drop blocks of the mapping at once first and the munmap finds nothing left to
// drop. The bytes are the file's (a private read-only mapping never written): nothing is lost.
FileBytes::~FileBytes() {
  if (!mapped_ || !data_) return;
  unregister_mapping(data_);
#if defined(__linux__)
  if (size_ >= kPopulateInParallelAtLeast && usable_threads() > 1) {
    try {
      char* const base = data_;
      const std::size_t size = size_;
      tbb::parallel_for(std::size_t(0), (size + kPopulateBlock - 1) / kPopulateBlock, [&](std::size_t b) {
        const std::size_t at = b * kPopulateBlock;
        ::madvise(base + at, std::min(kPopulateBlock, size - at), MADV_DONTNEED);  // on failure munmap drops them
      });
    } catch (...) {  // a task scheduler that cannot run the loop: munmap does it all
    }
  }
#endif
  ::munmap(data_, size_);
}

FileBytes read_file_bytes(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail(path, 0, std::string("cannot open: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) fail(path, 0, "is a directory, not a mesh file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, 0, std::string("cannot open: ") + std::strerror(errno));
  if (::fstat(fd, &st) != 0) st.st_mode = 0;

  FileBytes f;
  if (S_ISREG(st.st_mode) && std::size_t(st.st_size) >= kMapAtLeast) {
    void* p = map_populated(fd, std::size_t(st.st_size));
    if (p != MAP_FAILED) {
      ::close(fd);
      f.data_ = static_cast<char*>(p);
      f.size_ = std::size_t(st.st_size);
      f.mapped_ = true;
      register_mapping(f.data_, f.size_);
      return f;
    }
    // mmap refused (some file systems): read it instead
  }
  // Regular files: one read of the known size (+1 to see growth). Others: chunks, doubling.
  std::size_t capacity = S_ISREG(st.st_mode) ? std::size_t(st.st_size) + 1 : std::size_t(1) << 16;
  f.owned_.reset(new char[capacity]);
  for (;;) {
    const ssize_t r = read_fully(fd, f.owned_.get() + f.size_, capacity - f.size_);
    if (r < 0) {
      const int e = errno;
      ::close(fd);
      fail(path, 0, std::string("read error: ") + std::strerror(e));
    }
    f.size_ += std::size_t(r);
    if (f.size_ < capacity) break;  // end of file
    std::unique_ptr<char[]> bigger(new char[2 * capacity]);
    std::memcpy(bigger.get(), f.owned_.get(), f.size_);
    f.owned_ = std::move(bigger);
    capacity *= 2;
  }
  ::close(fd);
  f.data_ = f.owned_.get();
  if (f.size_ == 0) fail(path, 0, "file is empty");
  return f;
}

void release_mapped_pages(const char* begin, const char* end) noexcept {
#if defined(__linux__)
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (page_size <= 0 || !begin || end <= begin) return;
  const std::uintptr_t page = std::uintptr_t(page_size);
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) & ~(page - 1);  // whole pages inside
  const std::uintptr_t e = reinterpret_cast<std::uintptr_t>(end) & ~(page - 1);
  if (e <= b) return;
  // The lock is held across the madvise: the mapping cannot be unmapped (and its addresses
  // reused by another allocation) while its pages are dropped.
  const std::shared_lock<std::shared_mutex> lock(g_mappings_mutex);
  for (const auto& [p, n] : g_mappings) {
    const std::uintptr_t mb = reinterpret_cast<std::uintptr_t>(p);
    if (b >= mb && e <= mb + n) {
      ::madvise(reinterpret_cast<void*>(b), e - b, MADV_DONTNEED);
      return;
    }
  }
#else
  (void)begin;
  (void)end;
#endif
}

}  // namespace shadetool::io
