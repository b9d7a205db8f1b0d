// Tests of io/file_bytes: a file's bytes are what was written, whichever way they are brought in
// (read(2) for small files, mmap with MAP_POPULATE on one thread, mmap with its pages mapped in
// 2 MiB blocks by two threads for files of 8 MiB or more).
#include <random>

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
