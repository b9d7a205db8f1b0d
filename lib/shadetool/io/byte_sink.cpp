// byte_sink.cpp: the buffer of ByteSink, and FdSink's write(2) loop.
#include <shadetool/io/byte_sink.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <unistd.h>

#include <shadetool/core/error.h>

namespace shadetool::io {

ByteSink::ByteSink(std::size_t buffer_bytes)
    : buffer_(new char[buffer_bytes > 0 ? buffer_bytes : 1]), size_(buffer_bytes > 0 ? buffer_bytes : 1) {
  next_ = buffer_.get();
  end_ = buffer_.get() + size_;
}

void ByteSink::drain_buffer() {
  const std::size_t n = std::size_t(next_ - buffer_.get());
  if (n == 0) return;
  next_ = buffer_.get();  // first: a drain that throws leaves no bytes to drain twice
  drained_ += n;
  drain(buffer_.get(), n);
}

// Called when `n` does not fit in what is left of the buffer: fill it up and drain it, then either
// buffer the rest or, when the rest is at least a whole buffer, drain it directly (no copy).
void ByteSink::append_long(const char* bytes, std::size_t n) {
  const std::size_t room = std::size_t(end_ - next_);
  std::memcpy(next_, bytes, room);
  next_ += room;
  bytes += room;
  n -= room;
  drain_buffer();
  if (n >= size_) {
    drained_ += n;
    drain(bytes, n);
    return;
  }
  std::memcpy(next_, bytes, n);
  next_ += n;
}

void ByteSink::append(std::size_t count, char c) {
  while (count > 0) {
    if (next_ == end_) drain_buffer();
    const std::size_t k = std::min(count, std::size_t(end_ - next_));
    std::memset(next_, c, k);
    next_ += k;
    count -= k;
  }
}

bool write_all(int fd, const char* bytes, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, bytes, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes += w;
    n -= std::size_t(w);
  }
  return true;
}

void FdSink::drain(const char* bytes, std::size_t n) {
  if (!write_all(fd_, bytes, n)) fail(name_, 0, std::string("cannot write: ") + std::strerror(errno));
}

}  // namespace shadetool::io
