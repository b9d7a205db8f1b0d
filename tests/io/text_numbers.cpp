// Tests of io/number_text.h and io/text_parse.h: shortest output, strict tokens, the digit rule.
#include "io/number_text.h"
#include "io/text_parse.h"
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::io;

namespace {
std::string shortest(double v, ValuePrecision p) {
  std::string s;
  append_shortest(s, v, p);
  return s;
}
}  // namespace

TEST_CASE("shortest text: float data prints as float, double as double", "[text]") {
  CHECK(shortest(double(0.1f), ValuePrecision::Float) == "0.1");
  CHECK(shortest(0.1, ValuePrecision::Double) == "0.1");
  CHECK(shortest(double(0.1f), ValuePrecision::Double) == "0.10000000149011612");
  CHECK(shortest(1e-300, ValuePrecision::Double) == "1e-300");
  CHECK(shortest(-0.0, ValuePrecision::Float) == "-0");
  CHECK(shortest(16777217.0, ValuePrecision::Double) == "16777217");
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
