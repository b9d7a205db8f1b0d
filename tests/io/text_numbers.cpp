// Tests of io/engine/number_text.h and io/engine/text_parse.h: shortest output, strict tokens, the digit rule.
#include <shadetool/io/engine/number_text.h>
#include <shadetool/io/engine/text_parse.h>
#include <cstring>
#include <random>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::io;

namespace {
std::string shortest(double v) {
  std::string s;
  append_shortest(s, v);
  return s;
}
double parse(const std::string& s) {
  double v = 0;
  const char* p = s.data();
  REQUIRE(parse_double(p, s.data() + s.size(), v));
  return v;
}
}  // namespace

TEST_CASE("exact floats: double(float(x)) == x, range checked first", "[text]") {
  CHECK(is_exact_float(double(0.1f)));
  CHECK(!is_exact_float(0.1));           // 0.1 needs 53 bits of mantissa
  CHECK(is_exact_float(16777216.0));     // 2^24
  CHECK(!is_exact_float(16777217.0));    // 2^24 + 1 needs 25 bits
  CHECK(!is_exact_float(1e-300));        // below float's smallest subnormal (~1.4e-45)
  CHECK(!is_exact_float(1e300));         // beyond FLT_MAX (~3.4e38)
  CHECK(is_exact_float(double(std::numeric_limits<float>::max())));
  CHECK(is_exact_float(double(std::numeric_limits<float>::denorm_min())));
  CHECK(is_exact_float(INFINITY));
  CHECK(!is_exact_float(NAN));
}

TEST_CASE("shortest text: the value decides, float form for exact floats, else double form", "[text]") {
  // a float read from binary PLY/STL prints as the float: 0.1f = 0.100000001490116119384765625
  CHECK(shortest(double(0.1f)) == "0.1");
  CHECK(shortest(double(1.0f / 3.0f)) == "0.33333334");
  // a double typed as text prints back as typed
  CHECK(shortest(0.1) == "0.1");
  CHECK(shortest(123456.789) == "123456.789");
  // the float nearest 123456.789 is 123456.7890625 (spacing 2^-7 = 0.0078125 at 2^16..2^17)
  CHECK(double(123456.789f) == 123456.7890625);
  CHECK(shortest(123456.7890625) == "123456.79");
  CHECK(shortest(1.0 / 3.0) == "0.3333333333333333");
  CHECK(shortest(16777217.0) == "16777217");
  CHECK(shortest(1e-300) == "1e-300");
  CHECK(shortest(1e300) == "1e+300");
  CHECK(shortest(-0.0) == "-0");
  CHECK(shortest(INFINITY) == "inf");
  CHECK(shortest(-INFINITY) == "-inf");
  CHECK(shortest(NAN) == "nan");
}

TEST_CASE("shortest text reads back: doubles exactly, floats as the same float", "[text]") {
  for (double x : {0.1, 123456.789, 1.0 / 3.0, 2.0 / 3.0 * 1e-10, 16777217.0, 1e300, -5e-324, 0.30000000000000004}) {
    INFO(x);
    CHECK(parse(shortest(x)) == x);
  }
  for (float f : {0.1f, 1.0f / 3.0f, 123456.789f, 3.4e38f, 1e-40f /* subnormal */, -7.0e-45f}) {
    INFO(f);
    const double back = parse(shortest(double(f)));
    CHECK(float(back) == f);
    // and the text is stable: the value read back prints the same text
    CHECK(shortest(back) == shortest(double(f)));
  }
}

TEST_CASE("number tokens: strict ends, leading +, NaN and Inf", "[text]") {
  auto parse = [](const std::string& s, double& v) {
    const char* p = s.data();
    return parse_double(p, s.data() + s.size(), v);
  };
  double v = 0;
  CHECK(parse(" +1.5 ", v));
  CHECK(v == 1.5);
  CHECK(parse("-2e3", v));
  CHECK(v == -2000);
  CHECK(parse("nan", v));
  CHECK(std::isnan(v));
  CHECK(parse("-Infinity", v));
  CHECK(v == -INFINITY);
  CHECK(!parse("1.5x", v));
  CHECK(!parse("1,5", v));
  CHECK(!parse("", v));
  CHECK(!parse("e5", v));
}

TEST_CASE("digit rule: more than 9 significant digits means double data", "[text]") {
  auto more = [](const std::string& s) { return has_more_digits_than_float(s.data(), s.data() + s.size()); };
  CHECK(!more("0.123456789"));
  CHECK(more("0.1234567891"));
  CHECK(!more("-0.000000000123456789"));  // leading zeros do not count
  CHECK(!more("1.00000000000000000000"));  // nor trailing ones
  CHECK(more("1.0000000001"));
  CHECK(!more("1.23456789e-300"));
  CHECK(more("0.10000000000000001"));
}

TEST_CASE("parse_double_counting_digits gives parse_double's value and end and has_more_digits_than_float's answer",
          "[text]") {
  // Truth: fast_float::from_chars (through parse_double) and the textual digit count, on tokens of
  // every shape the one-scan path and its fallback see: 1 to 25 digits, leading and trailing zeros,
  // exponents inside and outside Clinger's range, signs, inf/nan, malformed tails.
  std::mt19937_64 rng(31);
  std::vector<std::string> tokens{"0", "-0", "+1", "+-1", "1e", "1.5x", "1.5.2", ".5", "5.", "-.5e-3", "inf", "-Infinity",
                                  "nan", "1234567891", "0.00790996756", "-9.39081747e-06", "123456.789", "0.500000000000",
                                  "1e308", "1e-320", "4.9e-324", "1e400", "12345678901234567890123", "0.1234567890123e22",
                                  "9007199254740993", "1.0000000000000000000001", "e5", "-", ""};
  const char digits[] = "0123456789";
  for (int i = 0; i < 20000; ++i) {
    std::string t;
    if (rng() % 3 == 0) t += rng() % 2 ? '-' : '+';
    const int lead_zeros = int(rng() % 4), n = 1 + int(rng() % 24);
    t.append(std::size_t(lead_zeros), '0');
    for (int k = 0; k < n; ++k) t += digits[rng() % 10];
    if (rng() % 2) t.insert(t.size() - std::size_t(rng() % std::size_t(n)), ".");
    if (rng() % 4 == 0) t.append(std::size_t(rng() % 5), '0');
    if (rng() % 3 == 0) t += "e" + std::to_string(int(rng() % 80) - 40);
    tokens.push_back(t);
  }
  for (const std::string& t : tokens) {
    for (const std::string& tail : {std::string(), std::string(" 2"), std::string("\n"), std::string("x")}) {
      const std::string text = t + tail;
      INFO("'" << text << "'");
      const char *p1 = text.data(), *p2 = text.data();
      double v1 = 0, v2 = 0;
      bool more = false;
      const bool ok1 = parse_double(p1, text.data() + text.size(), v1);
      const bool ok2 = parse_double_counting_digits(p2, text.data() + text.size(), v2, more);
      REQUIRE(ok1 == ok2);
      if (!ok1) continue;
      CHECK(p1 == p2);
      CHECK(std::memcmp(&v1, &v2, sizeof v1) == 0);
      CHECK(more == has_more_digits_than_float(text.data(), p1));
    }
  }
}

TEST_CASE("number tokens: Microsoft's 1.#INF, -1.#IND, 1.#QNAN read as inf and nan read; near misses stay malformed",
          "[text][xcorpus3]") {
  // Truth: the C99 spelling of the same value, read by fast_float.
  auto value = [](const std::string& s, double& v) {
    const char* p = s.data();
    const bool ok = parse_double(p, s.data() + s.size(), v);
    return ok && p == s.data() + s.size();
  };
  double v = 0, c99 = 0;
  for (const char* s : {"1.#INF", "+1.#INF", "1.#INF00", "-1.#INF"}) {
    CAPTURE(s);
    REQUIRE(value(s, v));
    REQUIRE(value(s[0] == '-' ? "-inf" : "inf", c99));
    CHECK(v == c99);
  }
  for (const char* s : {"1.#IND", "-1.#IND", "-1.#IND000", "1.#QNAN", "-1.#QNAN0", "1.#SNAN"}) {
    CAPTURE(s);
    REQUIRE(value(s, v));
    CHECK(std::isnan(v));
  }
  for (const char* s : {"2.#INF", "1.#INFX", "1.#", "1.#INF0x", "1#INF", "1.#inf", "1.5#INF"}) {
    CAPTURE(s);
    CHECK(!value(s, v));
  }
  // The OBJ hot loop's parser agrees token for token.
  for (const char* s : {"1.#INF", "-1.#IND", "1.#QNAN0", "2.#INF", "1.#INFX"}) {
    CAPTURE(s);
    const std::string t = s;
    const char* p = t.data();
    double a = 0, b = 0;
    bool more = true;
    const bool ok = parse_double_counting_digits(p, t.data() + t.size(), a, more);
    CHECK(ok == value(t, b));
    if (ok) {
      CHECK((std::isnan(a) ? std::isnan(b) : a == b));
      CHECK(!more);
    }
  }
  // tinyobjloader's test-nan.obj: its vertices read as the same text with C99 spellings reads.
  const std::string msvc = "v 1.#IND -1.#IND 1.#IND\nv 1.#INF -1.#INF 1.#INF\nv 0 0 0\nf 1 2 3\n";
  const std::string c99text = "v nan -nan nan\nv inf -inf inf\nv 0 0 0\nf 1 2 3\n";
  const Mesh a = iotest::read_text(msvc, Format::Obj), b = iotest::read_text(c99text, Format::Obj);
  REQUIRE(a.positions.size() == b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    CAPTURE(i);
    CHECK((std::isnan(b.positions[i]) ? std::isnan(a.positions[i]) : a.positions[i] == b.positions[i]));
  }
  CHECK(a.corner_vertex == b.corner_vertex);
}
