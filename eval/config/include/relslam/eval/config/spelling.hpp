#pragma once
// "Did you mean": the nearest of a list of names to a mistyped one, for every message that
// refuses a name (scenario keys, commands, options, algorithms).

#include <string>
#include <string_view>
#include <vector>

namespace relslam::eval {

// Levenshtein distance: insertions, deletions and substitutions.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest `word`, if it is within `max_distance` edits; "" otherwise.
std::string nearest_name(std::string_view word, const std::vector<std::string>& candidates,
                         std::size_t max_distance = 3);

// "; did you mean \"name\"?" for the nearest candidate, or "" when none is near.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace relslam::eval
