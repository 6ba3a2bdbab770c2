#include "relslam/core/option_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam {
namespace {

struct Window {
  double near = 1;
  double far = 10;
};
void describe(OptionsOf<Window> auto& w, auto& f) {
  f.field("near", w.near, "", at_least(0.0));
  f.field("far", w.far, "", above(w.near, "near"));
}

struct Example {
  std::optional<int> count;
  std::vector<double> shares = {10, 50};
  double angle_rad = 0.5;
  bool on = false;
  Window window;
};
void describe(OptionsOf<Example> auto& o, auto& f) {
  f.field("count", o.count, "", at_least(1));
  f.field("shares", o.shares, "", length(2, "low, high"), at_least(0.0), at_most(100.0));
  f.degrees("angle_deg", o.angle_rad, "", at_most(89.0));
  f.field("on", o.on, "", holds(!o.on || o.count.has_value(), "needs count"));
  f.nested("window", o.window);
}

std::vector<std::string> problems(const Example& e) {
  std::vector<std::string> out;
  for (const OptionIssue& i : check_fields(e)) out.push_back(i.field + ": " + i.problem);
  return out;
}

TEST(OptionFields, DefaultsPass) { EXPECT_TRUE(problems(Example{}).empty()); }

TEST(OptionFields, BoundsNameTheValueAndRejectNaN) {
  Example e;
  e.count = 0;
  e.window.near = std::nan("");
  EXPECT_EQ(problems(e), (std::vector<std::string>{"count: must be >= 1, got 0", "window.near: must be >= 0, got nan",
                                                   "window.far: must be > window.near (nan), got 10"}));
}

TEST(OptionFields, ListsAreCheckedWholeThenElementByElement) {
  Example e;
  e.shares = {-1, 200, 5};
  EXPECT_EQ(problems(e), (std::vector<std::string>{"shares: needs 2 values (low, high), got 3",
                                                   "shares: must be >= 0, got -1", "shares: must be <= 100, got 200"}));
}

TEST(OptionFields, DegreesAreCheckedInDegreesAndRulesNameTheirField) {
  Example e;
  e.angle_rad = std::numbers::pi / 2;
  e.on = true;
  EXPECT_EQ(problems(e), (std::vector<std::string>{"angle_deg: must be <= 89, got 90", "on: needs count"}));
}

}  // namespace
}  // namespace relslam
