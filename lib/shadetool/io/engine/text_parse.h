// text_parse.h: the token-level parsing shared by the text readers (OBJ, PLY ascii, OFF, STL ascii).
//
// Numbers are parsed with fast_float (exact IEEE round-to-nearest, like strtod, without locale or
// stream overhead). A token must end at whitespace or the end of the line: "1.5x" is malformed.
// NaN and Inf ("nan", "inf", "infinity", any case, and Microsoft's 1.#INF, -1.#IND, 1.#QNAN) are
// accepted: `shadetool info` reports them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include <fast_float/fast_float.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

constexpr bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
constexpr bool is_space_or_newline(char c) { return is_space(c) || c == '\n'; }

inline const char* skip_spaces(const char* p, const char* end) {
  while (p < end && is_space(*p)) ++p;
  return p;
}

// Microsoft's C runtime (printf before Visual Studio 2015) wrote Inf and NaN as 1.#INF, -1.#INF,
// 1.#IND, -1.#IND, 1.#QNAN, 1.#SNAN, zeros following at a fixed precision (1.#INF00, -1.#IND000):
// exporters built with it put these in OBJ files (tinyobjloader's models/test-nan.obj). They read
// as "inf" and "nan" read. q: the token after an optional '+'. Returns the end of the token, or
// nullptr when it is not one of these (a malformed number then).
inline const char* parse_msvc_nonfinite(const char* q, const char* end, double& value) {
  const bool negative = q < end && *q == '-';
  const char* t = q + (negative ? 1 : 0);
  if (end - t < 3 || t[0] != '1' || t[1] != '.' || t[2] != '#') return nullptr;
  t += 3;
  const std::string_view rest(t, std::size_t(end - t));
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const struct {
    std::string_view word;
    double v;
  } words[] = {{"INF", inf}, {"IND", nan}, {"QNAN", nan}, {"SNAN", nan}};
  for (const auto& w : words) {
    if (rest.substr(0, w.word.size()) != w.word) continue;
    const char* e = t + w.word.size();
    while (e < end && *e == '0') ++e;
    if (e < end && !is_space_or_newline(*e)) return nullptr;
    value = negative ? -w.v : w.v;
    return e;
  }
  return nullptr;
}

// Parses a double starting at p (after optional spaces); on success advances p past the token.
// Returns false for a malformed token (p is left at its start).
inline bool parse_double(const char*& p, const char* end, double& value) {
  const char* q = skip_spaces(p, end);
  const char* start = q;
  if (q < end && *q == '+') ++q;  // fast_float refuses a leading '+', strtod accepts it
  auto r = fast_float::from_chars(q, end, value);
  if (r.ec != std::errc() || (r.ptr < end && !is_space_or_newline(*r.ptr))) {
    if (r.ec == std::errc() && r.ptr < end && *r.ptr == '#')  // 1.#INF, -1.#IND: Microsoft's spellings
      if (const char* e = parse_msvc_nonfinite(q, end, value)) {
        p = e;
        return true;
      }
    p = start;
    return false;
  }
  p = r.ptr;
  return true;
}

// Parses a (possibly signed) decimal integer; false if malformed or out of int64 range.
inline bool parse_int64(const char*& p, const char* end, std::int64_t& value) {
  const char* q = skip_spaces(p, end);
  const char* start = q;
  bool negative = false;
  if (q < end && (*q == '-' || *q == '+')) negative = *q++ == '-';
  if (q >= end || *q < '0' || *q > '9') {
    p = start;
    return false;
  }
  std::uint64_t v = 0;
  while (q < end && *q >= '0' && *q <= '9') {
    if (v > (std::uint64_t(1) << 62)) {  // far beyond any index or count we accept
      p = start;
      return false;
    }
    v = v * 10 + std::uint64_t(*q++ - '0');
  }
  value = negative ? -static_cast<std::int64_t>(v) : static_cast<std::int64_t>(v);
  p = q;
  return true;
}

// True when the decimal token [b, e) has more significant digits than float can carry (9, float's
// max_digits10): text with more digits was written from double data, so Mesh::precision = Double
// (the hint binary writers use for the value type; values are never rounded either way).
// Leading and trailing zeros of the mantissa do not count ("0.500000000000" has one digit).
inline bool has_more_digits_than_float(const char* b, const char* e) {
  if (e - b <= 10) return false;  // at most 9 digits plus a sign or a point: fast path
  int counted = 0, significant = 0;
  bool nonzero_seen = false;
  for (const char* q = b; q < e; ++q) {
    const char c = *q;
    if (c == 'e' || c == 'E') break;
    if (c < '0' || c > '9') continue;
    if (c == '0' && !nonzero_seen) continue;
    nonzero_seen = true;
    ++counted;
    if (c != '0') significant = counted;
  }
  return significant > 9;
}

// parse_double and has_more_digits_than_float(token) in one scan, for the hot loop of the OBJ
// reader: the token starts at p (no leading spaces); on success p is past it, `value` is what
// parse_double gives and `more_digits` what has_more_digits_than_float gives for the token
// (including the short-token shortcut). The digits are gathered once (fast_float's
// parse_number_string); a mantissa of at most 2^53 with a decimal exponent in [-22, 22] is
// converted by Clinger's fast path (both operands exact, one correctly rounded IEEE operation, the
// same path and result as fast_float's under the default round-to-nearest mode, which shadetool
// never changes); anything else (more digits, larger exponents, inf, nan) goes through
// fast_float::from_chars and the textual digit count.
inline bool parse_double_counting_digits(const char*& p, const char* end, double& value, bool& more_digits) {
  const char* const start = p;
  const char* q = p;
  if (q < end && *q == '+') ++q;  // as parse_double
  const fast_float::parsed_number_string pns = fast_float::parse_number_string(q, end, fast_float::parse_options{});
  using Binary = fast_float::binary_format<double>;
  if (pns.valid && !pns.too_many_digits && pns.exponent >= Binary::min_exponent_fast_path() &&
      pns.exponent <= Binary::max_exponent_fast_path() && pns.mantissa <= Binary::max_mantissa_fast_path()) {
    if (pns.lastmatch < end && !is_space_or_newline(*pns.lastmatch)) {
      if (*pns.lastmatch != '#') return false;
      // 1.#INF, -1.#IND: parse_double reads them (parse_msvc_nonfinite)
      if (!parse_double(p, end, value)) return false;
      more_digits = false;
      return true;
    }
    double v = double(pns.mantissa);
    if (pns.exponent < 0) v = v / Binary::exact_power_of_ten(-pns.exponent);
    else v = v * Binary::exact_power_of_ten(pns.exponent);
    value = pns.negative ? -v : v;
    p = pns.lastmatch;
    // Significant digits: the mantissa's, less its trailing zeros (leading ones are not in it).
    more_digits = false;
    if (p - start > 10 && pns.mantissa >= 1000000000u) {
      std::uint64_t m = pns.mantissa;
      while (m % 10 == 0) m /= 10;
      more_digits = m >= 1000000000u;
    }
    return true;
  }
  if (!parse_double(p, end, value)) return false;
  more_digits = has_more_digits_than_float(start, p);
  return true;
}

// True when x is finite but float cannot hold it at all: beyond float's range (narrowed it would be
// Inf) or so small that it would narrow to 0. Such text keeps the mesh's precision hint at Double,
// so binary writers do not turn 1e300 into Inf (short text like "1e300" has few digits).
inline bool outside_float_range(double x) {
  const double a = x < 0 ? -x : x;
  return a <= std::numeric_limits<double>::max() &&
         (a > std::numeric_limits<float>::max() ||
          (a != 0 && a <= double(std::numeric_limits<float>::denorm_min()) / 2));
}

// Text quoted in a message, at most `max` bytes: a longer text is cut at the last space before
// the limit (mid-word only when one word is longer than the limit) and ends in an ellipsis.
inline std::string quoted_excerpt(std::string_view s, std::size_t max) {
  if (s.size() <= max) return std::string(s);
  std::size_t cut = max;
  const std::size_t space = s.substr(0, max + 1).find_last_of(" \t");
  if (space != std::string_view::npos && space > max / 2) cut = space;
  while (cut > 0 && (s[cut - 1] == ' ' || s[cut - 1] == '\t')) --cut;
  // Never cut inside a UTF-8 sequence: back up over continuation bytes.
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
  return std::string(s.substr(0, cut)) + "\u2026";
}

// The token starting at p (for messages), at most 40 characters (then an ellipsis).
inline std::string token_at(const char* p, const char* end) {
  p = skip_spaces(p, end);
  const char* q = p;
  while (q < end && !is_space_or_newline(*q) && q - p <= 40) ++q;
  return quoted_excerpt(std::string_view(p, std::size_t(q - p)), 40);
}

}  // namespace shadetool::io
#pragma GCC visibility pop
