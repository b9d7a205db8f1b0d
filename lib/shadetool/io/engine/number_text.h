// number_text.h: numbers to text for the text writers (OBJ, PLY ascii, OFF, STL ascii).
//
// Every value is printed in its shortest representation that reads back to the same value
// (std::to_chars without a precision, i.e. Ryu-style shortest round trip). Which type's shortest
// form depends on the value alone, never on Mesh::precision (that is only the hint binary writers
// use for the value type):
//   - a double that is exactly a float (double(float(x)) == x) prints the shortest text that reads
//     back to that float: 0.1f (read from a binary PLY or STL) prints "0.1", not
//     "0.10000000149011612". Read back as double that text is the double nearest to 0.1, which
//     narrows to the same float: float data round-trips as floats, bitwise.
//   - any other double prints the shortest text that reads back to that double: 0.1 typed in an
//     OBJ prints "0.1", 123456.789 prints "123456.789", 1/3 prints "0.3333333333333333" (at most
//     17 significant digits). Such values round-trip exactly.
// NaN and infinities print as "nan", "inf", "-inf" (the readers accept them).
#pragma once

#include <charconv>
#include <cmath>
#include <limits>
#include <cstdint>
#include <string>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

// True when x is exactly representable as a float: double(float(x)) == x. Values beyond float's
// range are tested first (narrowing them is not a value-preserving conversion); infinities are
// floats; NaN is not (it prints "nan" either way).
inline bool is_exact_float(double x) {
  if (!(std::fabs(x) <= static_cast<double>(std::numeric_limits<float>::max()))) return std::isinf(x);
  return static_cast<double>(static_cast<float>(x)) == x;
}

// Out: std::string or io::ByteSink (byte_sink.h).
template <class Out>
inline void append_shortest(Out& out, double v) {
  char buf[40];
  const auto r = is_exact_float(v) ? std::to_chars(buf, buf + sizeof buf, static_cast<float>(v))
                                   : std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, std::size_t(r.ptr - buf));
}

template <class Out>
inline void append_shortest_float(Out& out, float v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, std::size_t(r.ptr - buf));
}

template <class Out>
inline void append_uint(Out& out, std::uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, std::size_t(r.ptr - buf));
}

template <class Out>
inline void append_int(Out& out, std::int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, std::size_t(r.ptr - buf));
}

// A colour channel stored as float in [0,1] to the uchar a PLY/OFF file holds: round(c * 255),
// clamped; NaN becomes 0.
inline std::uint8_t color_to_uchar(float c) {
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(c * 255.0f + 0.5f);
}

}  // namespace shadetool::io
#pragma GCC visibility pop
