// byte_sink.h: where a writer's bytes go, in bounded chunks.
//
// Every mesh writer (io/*_format.h, files/mesh_files.h) formats into a ByteSink instead of one
// string of the whole output, so that writing a mesh holds a fixed buffer beside the mesh rather
// than a second copy of it as text (issue 31 goal 5, bench/io/results.md "Writing streams").
//
// ByteSink    a buffer of `buffer_bytes` (default kSinkBufferBytes = 1 MiB; any size >= 1, tests
//             use 1 and 7) filled by append / +=; whenever it is full it is handed to drain(),
//             so a writer's memory is the buffer whatever the size of the output. An append at
//             least as long as the buffer skips it (drained directly after what is buffered: a
//             glTF binary chunk is not copied again). flush() drains what is buffered; a sink's
//             owner calls it once the writer returns (the destructor does not: it may throw).
//             The bytes drained, in order, are exactly the bytes appended, whatever the buffer
//             size (tests/io/byte_sink.cpp).
// StringSink  drains into a std::string (write_mesh_to_memory, tests, Python's bytes results).
// FdSink      drains into a file descriptor with write(2), retrying short writes and EINTR; an
//             error (ENOSPC, EFBIG, EPIPE, EIO...) throws shadetool::Error
//             `NAME: cannot write: REASON`, NAME being the output the user named (not the
//             temporary file behind it: io/atomic_write.h removes that).
// Not thread-safe: one sink per output being written.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

constexpr std::size_t kSinkBufferBytes = std::size_t(1) << 20;

class ByteSink {
 public:
  explicit ByteSink(std::size_t buffer_bytes = kSinkBufferBytes);
  virtual ~ByteSink() = default;
  ByteSink(const ByteSink&) = delete;
  ByteSink& operator=(const ByteSink&) = delete;

  void append(const char* bytes, std::size_t n) {
    if (n <= std::size_t(end_ - next_)) {
      if (n > 0) std::memcpy(next_, bytes, n);  // n == 0 may come with bytes == nullptr
      next_ += n;
    } else {
      append_long(bytes, n);
    }
  }
  void append(std::string_view s) { append(s.data(), s.size()); }
  void append(std::size_t count, char c);  // `count` copies of c
  ByteSink& operator+=(char c) {
    if (next_ == end_) drain_buffer();
    *next_++ = c;
    return *this;
  }
  ByteSink& operator+=(std::string_view s) {
    append(s.data(), s.size());
    return *this;
  }

  void flush() { drain_buffer(); }
  std::uint64_t bytes_appended() const { return drained_ + std::uint64_t(next_ - buffer_.get()); }

 protected:
  // Takes n > 0 bytes, in order; throws on failure (the sink is then not used again).
  virtual void drain(const char* bytes, std::size_t n) = 0;

 private:
  void drain_buffer();
  void append_long(const char* bytes, std::size_t n);

  std::unique_ptr<char[]> buffer_;  // not zero-filled: a small output touches only its first pages
  std::size_t size_;
  char* next_;
  char* end_;
  std::uint64_t drained_ = 0;
};

class StringSink final : public ByteSink {
 public:
  explicit StringSink(std::string& out, std::size_t buffer_bytes = std::size_t(64) << 10)
      : ByteSink(buffer_bytes), out_(out) {}

 private:
  void drain(const char* bytes, std::size_t n) override { out_.append(bytes, n); }
  std::string& out_;
};

class FdSink final : public ByteSink {
 public:
  FdSink(int fd, std::string name, std::size_t buffer_bytes = kSinkBufferBytes)
      : ByteSink(buffer_bytes), fd_(fd), name_(std::move(name)) {}

 private:
  void drain(const char* bytes, std::size_t n) override;
  int fd_;
  std::string name_;
};

// What a writer is, to callers that own the sink (io/atomic_write.h, files/mesh_files.h): a
// function that appends a file's contents to the sink it is given.
using ProduceBytes = std::function<void(ByteSink&)>;

// write(2) of all n bytes to fd, retrying short writes and EINTR; false (errno set) on an error.
bool write_all(int fd, const char* bytes, std::size_t n);

}  // namespace shadetool::io
#pragma GCC visibility pop
