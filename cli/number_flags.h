// number_flags.h: numeric flag values checked as the user typed them (issue 21, item 13).
//
// finite_number(lo, hi): a CLI11 validator for a flag that takes one finite number in [lo, hi]
// (hi = +inf: no upper bound). "nan", "inf" and "1e999" are usage errors saying they are not
// finite; a word is "not a number"; an out-of-range value says the range. Numbers in messages are
// in shortest form (std::to_chars): "-1", "180", never 309 digits.
#pragma once

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>

namespace shadetool_cli {

inline std::string shortest(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

inline CLI::Validator finite_number(double lo, double hi) {
  const std::string range = std::isinf(hi) ? ">= " + shortest(lo) : "from " + shortest(lo) + " to " + shortest(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& value) -> std::string {
        const char* b = value.data();
        const char* e = b + value.size();
        if (b != e && *b == '+') ++b;
        double x = 0;
        const auto r = std::from_chars(b, e, x, std::chars_format::general);
        if (r.ptr != e || b == e || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range))
          return "'" + value + "' is not a number";
        if (r.ec == std::errc::result_out_of_range || !std::isfinite(x))
          return "'" + value + "' is not a finite number";
        if (x < lo || x > hi) return shortest(x) + " is out of range (" + range + ")";
        return {};
      },
      "NUMBER " + range);
}

}  // namespace shadetool_cli
