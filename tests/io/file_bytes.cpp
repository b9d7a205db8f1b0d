// Tests of io/file_bytes: a file's bytes are what was written, whichever way they are brought in
// (read(2) for small files, mmap with MAP_POPULATE on one thread, mmap with its pages mapped in
// 2 MiB blocks by two threads for files of 8 MiB or more).
#include <algorithm>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include <shadetool/io/file_bytes.h>
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

TEST_CASE("file bytes: every byte of small, mapped and parallel-mapped files is the byte written", "[io][file_bytes]") {
  ScratchDir dir;
  std::mt19937 rng(31);
  // Sizes below the mapping threshold (1 MiB), above it, above the parallel one (8 MiB) and not a
  // multiple of the page or of the 2 MiB block.
  for (std::size_t size : {std::size_t(1000), (std::size_t(3) << 20) + 5, (std::size_t(9) << 20) + 4097}) {
    std::string bytes(size, '\0');
    for (char& c : bytes) c = char(rng() & 0xff);
    const std::string path = dir / ("f" + std::to_string(size));
    write_file(path, bytes);
    for (int threads : {1, 2}) {
      INFO("size " << size << ", threads " << threads);
      tbb::task_arena arena(threads);
      arena.execute([&] {
        const io::FileBytes f = io::read_file_bytes(path);
        REQUIRE(f.size() == size);
        CHECK(f.view() == bytes);
      });
    }
  }
}

TEST_CASE("file bytes: pages released behind a reader still read as the bytes written; other memory is left alone",
          "[io][file_bytes]") {
  // release_mapped_pages drops pages of a mapping read_file_bytes made (MADV_DONTNEED on a private
  // read-only file mapping: the next read faults them in again from the page cache). On any other
  // memory it must do nothing: MADV_DONTNEED on a heap buffer would turn its pages into zeros.
  ScratchDir dir;
  std::mt19937 rng(3131);
  const std::size_t size = (std::size_t(9) << 20) + 4097;  // mapped (>= 1 MiB), not a whole number of pages
  std::string bytes(size, '\0');
  for (char& c : bytes) c = char(1 + rng() % 255);  // no zero byte: a page turned into zeros shows
  const std::string path = dir / "released";
  write_file(path, bytes);
  for (int threads : {1, 2}) {
    INFO("threads " << threads);
    tbb::task_arena arena(threads);
    arena.execute([&] {
      const io::FileBytes f = io::read_file_bytes(path);
      REQUIRE(f.size() == size);
      const char* p = f.view().data();
      io::release_mapped_pages(p + 12345, p + (std::size_t(5) << 20) + 77);  // ends inside pages
      CHECK(f.view() == bytes);
      io::release_mapped_pages(p, p + size);  // the whole mapping
      CHECK(f.view() == bytes);
      io::release_mapped_pages(p + size - 10, p + size + 4096 * 4);  // past the mapping's end: refused
      CHECK(f.view() == bytes);
    });
  }
  // A heap copy of the bytes (as a reader's CRLF-converted text is): untouched.
  std::string copy = bytes;
  io::release_mapped_pages(copy.data(), copy.data() + copy.size());
  CHECK(copy == bytes);
  // Once the FileBytes is gone its addresses are no longer a mapping of ours.
  const char* gone = nullptr;
  { gone = io::read_file_bytes(path).view().data(); }
  std::vector<char> after(size, 'x');  // may reuse the addresses
  if (after.data() >= gone && after.data() + size <= gone + size) {
    io::release_mapped_pages(after.data(), after.data() + size);
    CHECK(std::count(after.begin(), after.end(), 'x') == std::ptrdiff_t(size));
  }
}
