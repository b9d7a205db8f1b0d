// core/progress.h and core/time_left.h: the meter's counts under many threads, and the rule for
// the time left against a clock the test drives (the values are worked out by hand below, not by
// the code: at a steady rate the time left is exactly total time minus elapsed).
#include <catch2/catch.hpp>

#include <cmath>

#include <tbb/parallel_for.h>

#include <shadetool/core/progress.h>
#include <shadetool/core/time_left.h>

using namespace shadetool;

namespace {

double fake_now = 0;
double fake_clock() { return fake_now; }

}  // namespace

TEST_CASE("ProgressMeter: advances from many threads add up exactly; begin starts a new stage", "[core][progress]") {
  fake_now = 100;
  ProgressMeter meter(fake_clock);
  CHECK(meter.snapshot().stage == nullptr);
  meter.begin("occlusion", 1000000);
  tbb::parallel_for(0, 1000000, [&](int) { meter.advance(1); });
  fake_now = 107.5;
  ProgressMeter::Snapshot s = meter.snapshot();
  CHECK(std::string(s.stage) == "occlusion");
  CHECK(s.done == 1000000);
  CHECK(s.fraction() == 1.0);
  CHECK(s.elapsed == 7.5);
  CHECK(s.generation == 1);

  meter.begin("writing", 0);  // a name without a total: no fraction
  s = meter.snapshot();
  CHECK(s.done == 0);
  CHECK_FALSE(s.has_fraction());
  CHECK(s.fraction() == 0);
  CHECK(s.elapsed == 0);
  CHECK(s.generation == 2);

  meter.begin("render", 4);  // more units than the total (a caller's mistake) still shows 100%, not more
  meter.advance(5);
  CHECK(meter.snapshot().fraction() == 1.0);
}

TEST_CASE("ProgressCursor turns positions into advances, never backwards", "[core][progress]") {
  ProgressMeter meter(fake_clock);
  meter.begin("reading", 100);
  ProgressCursor cursor(&meter);
  cursor.at(30);
  cursor.at(20);  // an earlier position advances nothing
  cursor.at(75);
  CHECK(meter.snapshot().done == 75);
  ProgressCursor none;  // nobody listens: a no-op
  none.at(50);
  CHECK(none.sink() == nullptr);
}

TEST_CASE("time left at a steady rate is exact: a 20 s stage seen at 5 s has 15 s left", "[core][progress][time_left]") {
  // A stage that does 5% of its work per second (20 s in all), polled every 0.1 s.
  TimeLeft rule;
  for (int tick = 1; tick < 200; ++tick) {
    const double t = 0.1 * tick, f = t / 20;
    const std::optional<double> left = rule.update(1, t, f);
    if (t < kTimeLeftMinSeconds - 1e-12) {
      CHECK_FALSE(left.has_value());  // too early to say
      continue;
    }
    REQUIRE(left.has_value());
    CHECK(*left == Approx(20 - t).margin(1e-9));
  }
  CHECK(*rule.update(1, 20, 1.0) == 0);
}

TEST_CASE("time left: no estimate before 1% of the work, whatever the time", "[core][progress][time_left]") {
  TimeLeft rule;
  CHECK_FALSE(rule.update(1, 30, 0.005).has_value());  // 30 s for 0.5%: the rate is not known yet
  CHECK_FALSE(rule.update(1, 0.5, 0.5).has_value());   // half done in 0.5 s: under the 1 s minimum
  CHECK_FALSE(rule.update(1, 5, 0.0).has_value());
  CHECK_FALSE(rule.update(1, NAN, 0.5).has_value());
  CHECK(rule.update(1, 30, 0.01).value() == Approx(30 * 0.99 / 0.01));
}

TEST_CASE("time left is smoothed: a sudden change of rate moves the estimate a quarter of the way", "[core][progress][time_left]") {
  TimeLeft rule;
  // 10 s for half the work: 10 s left.
  REQUIRE(rule.update(1, 10, 0.5).value() == Approx(10));
  // 1 s later the work jumped to 90%: raw = 11 * 0.1 / 0.9 = 1.2222 s. The previous estimate less
  // the second passed is 9 s; a quarter of the way from 9 to 1.2222 is 9 - 0.25 * 7.7778 = 7.0556 s.
  const double raw = 11 * 0.1 / 0.9;
  CHECK(rule.update(1, 11, 0.9).value() == Approx(9 + 0.25 * (raw - 9)));
  // A new stage forgets the old one: its first estimate is its own raw value.
  CHECK(rule.update(2, 2, 0.25).value() == Approx(6));
}

TEST_CASE("time left is never negative", "[core][progress][time_left]") {
  TimeLeft rule;
  REQUIRE(rule.update(1, 1, 0.5).value() == Approx(1));
  // 100 s later at 99%: the previous estimate less the time passed would be -99 s: carried as 0.
  const double raw = 101 * 0.01 / 0.99;
  CHECK(rule.update(1, 101, 0.99).value() == Approx(0.25 * raw));
}
