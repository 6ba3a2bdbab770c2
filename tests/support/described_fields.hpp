#pragma once
// For the tests that every field of an options struct has a scenario key: the number of
// members of an aggregate, counted at compile time, against the number of fields its
// describe() visits (relslam/core/option_fields.hpp). Standard library only.

#include <cstddef>
#include <string_view>

namespace relslam::test {

// Converts to any member type, so T{AnyMember{}, ...} compiles for up to as many initialisers
// as T has members (and no more): aggregate initialisation, no brace elision, since each
// initialiser converts to its member directly.
struct AnyMember {
  template <class T>
  operator T() const;  // never called: unevaluated only
};

// The number of members of the aggregate T.
template <class T, class... Members>
constexpr std::size_t member_count() {
  if constexpr (requires { T{Members{}..., AnyMember{}}; })
    return member_count<T, Members..., AnyMember>();
  else
    return sizeof...(Members);
}

// Counts what a description visits; a nested struct counts once (its own test counts its fields).
struct FieldCounter {
  std::size_t fields = 0;
  void field(std::string_view, const auto&, std::string_view, const auto&...) { ++fields; }
  void degrees(std::string_view, const auto&, std::string_view, const auto&...) { ++fields; }
  template <class E, std::size_t N>
  void choice(std::string_view, const E&, std::string_view, const E (&)[N]) {
    ++fields;
  }
  void nested(std::string_view, const auto&, const auto&...) { ++fields; }
};

// The number of fields describe(T{}, f, extra...) visits.
template <class T>
std::size_t described_count(const auto&... extra) {
  const T options{};
  FieldCounter counter;
  describe(options, counter, extra...);
  return counter.fields;
}

}  // namespace relslam::test
