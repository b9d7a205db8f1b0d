// file_bytes.h: a whole file in memory in one call (readers parse from memory).
//
// Inputs:  path  file to read
// Outputs: FileBytes, the file's bytes. Regular files of 1 MiB or more are mapped (mmap,
//          MAP_POPULATE: no copy, and no fresh pages to fault in, which is most of the cost of
//          reading a binary mesh; files of 8 MiB or more, read with more than one thread, have
//          their pages mapped in 2 MiB blocks by the threads at once); smaller files and pipes are read into a buffer that is not
//          zero-filled first. A mapped file that another process truncates while it is being
//          parsed raises SIGBUS, as with any mmap-based reader (ripgrep, git); it does not
//          happen to files that are only read or replaced by rename, as shadetool writes them.
//          A mapping is released page table by page table: with more than one thread the
//          threads drop its pages in 2 MiB blocks at once (madvise MADV_DONTNEED) before the
//          munmap, and a reader may drop the pages of what it has parsed as it goes
//          (release_mapped_pages).
// Errors (shadetool::Error, `PATH: what`): missing file, a directory, unreadable, empty file.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

class FileBytes {
 public:
  FileBytes() = default;
  FileBytes(FileBytes&& o) noexcept;
  FileBytes& operator=(FileBytes&& o) noexcept;
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;
  ~FileBytes();

  std::string_view view() const { return {data_, size_}; }
  std::size_t size() const { return size_; }

 private:
  friend FileBytes read_file_bytes(const std::string& path);

// A reader done with [begin, end) of a file's bytes (a chunk parsed on a worker thread) lets the
// process drop the whole pages inside it now, in parallel with the other chunks, instead of all of
// them in the one-threaded munmap when the FileBytes goes away (bench/io/results.md). Only pages of
// a live mapping read_file_bytes made are dropped (madvise MADV_DONTNEED on a private read-only
// file mapping: the bytes stay readable, a later read faults them in again from the page cache);
// bytes anywhere else (a buffer, a converted copy, a string) are left alone. Never changes what
// the bytes read as.
void release_mapped_pages(const char* begin, const char* end) noexcept;
  std::unique_ptr<char[]> owned_;
  char* data_ = nullptr;
  std::size_t size_ = 0;
  bool mapped_ = false;
};

FileBytes read_file_bytes(const std::string& path);

// A reader done with [begin, end) of a file's bytes (a chunk parsed on a worker thread) lets the
// process drop the whole pages inside it now, in parallel with the other chunks, instead of all of
// them in the one-threaded munmap when the FileBytes goes away (bench/io/results.md). Only pages of
// a live mapping read_file_bytes made are dropped (madvise MADV_DONTNEED on a private read-only
// file mapping: the bytes stay readable, a later read faults them in again from the page cache);
// bytes anywhere else (a buffer, a converted copy, a string) are left alone. Never changes what
// the bytes read as.
void release_mapped_pages(const char* begin, const char* end) noexcept;

}  // namespace shadetool::io
#pragma GCC visibility pop
