// number_text.h: numbers to text for the text writers (OBJ, PLY ascii, OFF, STL ascii).
//
// Every value is printed in its shortest representation that reads back to the same value
// (std::to_chars without a precision, i.e. Ryu-style shortest round trip), so text output
// round-trips exactly. Values of a Float-precision mesh are narrowed to float first and printed
// as the shortest float: 0.1f prints "0.1", not "0.100000001490116".
#pragma once

#include <charconv>
#include <cstdint>
#include <string>

#include "core/mesh.h"

namespace shadetool::io {

inline void append_shortest(std::string& out, double v, ValuePrecision precision) {
  char buf[40];
  const auto r = precision == ValuePrecision::Float ? std::to_chars(buf, buf + sizeof buf, static_cast<float>(v))
                                                    : std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

inline void append_shortest_float(std::string& out, float v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

inline void append_uint(std::string& out, std::uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// A colour channel stored as float in [0,1] to the uchar a PLY/OFF file holds: round(c * 255),
// clamped; NaN becomes 0.
inline std::uint8_t color_to_uchar(float c) {
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(c * 255.0f + 0.5f);
}

}  // namespace shadetool::io
