#pragma once
// One description per options struct, read by every layer that needs to know its fields.
//
// Beside each options struct stands describe(options, fields), which visits every field once,
// always in the same order, with its scenario key name, its one-line help and its checks:
//
//   f.field(name, value, help, checks...)     a number, integer, boolean, text, optional
//                                              integer or list; the kind follows the C++ type
//   f.degrees(name, radians, help, checks...) stored in radians, keyed and checked in degrees
//   f.choice(name, value, help, {values...})  an enum, spelled by to_string(value)
//   f.nested(name, options, extra...)         a struct described by its own
//                                              describe(options, f, extra...); name "" puts its
//                                              keys beside this struct's
//
// check_fields() below is one visitor (the checks); the evaluation layer's key registry is
// another (names, help, JSON), so a field's default (its initialiser), key, help and checks
// are each written once. Checks may read other fields (at_least(o.local_bound)): a rule
// between fields sits on the field it names. Plain C++ only: no JSON, no I/O.

#include "relslam/core/option_issue.hpp"

#include <concepts>
#include <cstddef>
#include <numbers>
#include <optional>
#include <ranges>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace relslam {

// `Options` or `const Options`: one describe() serves the visitors that read and those that write.
template <class T, class Options>
concept OptionsOf = std::same_as<std::remove_const_t<T>, Options>;

// ---- Checks: each is called with the issues, the field's path and the value ----------------

// value >= bound, value > bound or value <= bound, finite. The bound may come from another
// field; naming it (above(f.near, "near")) says so: "must be > frustum.near (1), got 0.5".
struct Bound {
  enum class Relation { AtLeast, Above, AtMost };
  Relation relation;
  double bound;
  const char* sibling = nullptr;  // the field of the same struct the bound is, if any
  void operator()(std::vector<OptionIssue>& issues, const std::string& field, double value) const;
};
constexpr Bound at_least(double minimum, const char* sibling = nullptr) {
  return {Bound::Relation::AtLeast, minimum, sibling};
}
constexpr Bound above(double bound, const char* sibling = nullptr) { return {Bound::Relation::Above, bound, sibling}; }
constexpr Bound at_most(double maximum, const char* sibling = nullptr) {
  return {Bound::Relation::AtMost, maximum, sibling};
}

// A list of exactly `count` values, named for the message: "needs 3 values (x, y, heading), got 2".
struct Length {
  std::size_t count;
  const char* names;
  void operator()(std::vector<OptionIssue>& issues, const std::string& field,
                  const std::ranges::sized_range auto& values) const {
    if (std::ranges::size(values) != count)
      issues.push_back({field, "needs " + std::to_string(count) + " values (" + names + "), got " +
                                   std::to_string(std::ranges::size(values))});
  }
};
constexpr Length length(std::size_t count, const char* names) { return {count, names}; }

// A rule between fields, reported on this one when `ok` is false.
struct Holds {
  bool ok;
  const char* problem;
  void operator()(std::vector<OptionIssue>& issues, const std::string& field, const auto&) const {
    if (!ok) issues.push_back({field, problem});
  }
};
constexpr Holds holds(bool ok, const char* problem) { return {ok, problem}; }

// ---- The visitor that runs the checks --------------------------------------------------------

template <class T>
inline constexpr bool is_optional = false;
template <class T>
inline constexpr bool is_optional<std::optional<T>> = true;

// Collects every violated check, fields named by their path inside the described struct
// ("final_group.prev_min"). A check that cannot take the whole value (a bound on a list or on
// an optional) applies to each element, or to the value when there is one.
class OptionChecker {
 public:
  explicit OptionChecker(std::vector<OptionIssue>& issues, std::string prefix = "")
      : issues_(issues), prefix_(std::move(prefix)) {}

  template <class T, class... Checks>
  void field(std::string_view name, const T& value, std::string_view, const Checks&... checks) {
    const std::string path = prefix_ + std::string(name);
    // One problem per value (the field, or each element of a list): a NaN breaks every bound,
    // and the first check says so.
    std::size_t before = issues_.size();
    const auto fresh = [&] { return issues_.size() == before; };
    ((fresh() ? check_whole(path, value, checks) : void()), ...);
    if constexpr (is_optional<T>) {
      if (value) ((fresh() ? check_part<T>(path, *value, checks) : void()), ...);
    } else if constexpr (std::ranges::range<T> && !std::same_as<T, std::string>) {
      for (const auto& element : value) {
        before = issues_.size();
        ((fresh() ? check_part<T>(path, element, checks) : void()), ...);
      }
    } else {
      static_assert((takes<Checks, T> && ...), "every check of a single value must take that value");
    }
  }
  template <class... Checks>
  void degrees(std::string_view name, double radians, std::string_view help, const Checks&... checks) {
    field(name, radians * 180.0 / std::numbers::pi, help, checks...);
  }
  template <class E, std::size_t N>
  void choice(std::string_view, const E&, std::string_view, const E (&)[N]) {}
  template <class Options, class... Extra>
  void nested(std::string_view name, const Options& options, const Extra&... extra) {
    OptionChecker inner(issues_, name.empty() ? prefix_ : prefix_ + std::string(name) + ".");
    describe(options, inner, extra...);
  }

 private:
  template <class Check, class T>
  static constexpr bool takes = std::invocable<const Check&, std::vector<OptionIssue>&, const std::string&, const T&>;

  template <class T, class Check>
  void check_whole(const std::string& path, const T& value, const Check& check) {
    if constexpr (takes<Check, T>) check(issues_, path, value);
  }
  template <class T, class Element, class Check>
  void check_part(const std::string& path, const Element& element, const Check& check) {
    if constexpr (!takes<Check, T>) check(issues_, path, element);
  }

  std::vector<OptionIssue>& issues_;
  std::string prefix_;
};

// Every violated check of the description of `options`, in its order.
template <class Options>
std::vector<OptionIssue> check_fields(const Options& options) {
  std::vector<OptionIssue> issues;
  OptionChecker checker(issues);
  describe(options, checker);
  return issues;
}

}  // namespace relslam
