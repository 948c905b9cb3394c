#pragma once
// The one writer of JSON text for the files the program writes (report.json, study.json, summary.json, the
// strength-reduction journal), beside the reader of scene files (json_reader.hpp) at the bottom layer of coupling/. JSON has no NaN or infinity, and nlohmann's dump would print such a number as null
// without a word: here it is refused, with the path of every key that holds one. A value that may be missing is
// written as an explicit null by the code that knows why (next to an "error", or documented in
// docs/scene-format.md), never left for the dump to turn into one.
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace coupling {

// The paths (e.g. "lem.methods.bishop.factor_of_safety", "slices[3].weight_kN_m") of the non-finite numbers of a
// JSON value, in document order.
std::vector<std::string> non_finite_paths(const nlohmann::json& value);

// Sets every non-finite number of `value` to null; returns their paths (as non_finite_paths gave them).
std::vector<std::string> null_non_finite_numbers(nlohmann::json& value);

// Thrown by json_text: what() names the paths (the first ten, then a count).
class NonFiniteNumber : public std::runtime_error {
 public:
  explicit NonFiniteNumber(std::vector<std::string> paths);
  const std::vector<std::string>& paths() const { return paths_; }

 private:
  std::vector<std::string> paths_;
};

// The JSON text of `value` (indented by `indent` spaces; -1: one line), ending in a newline. Throws
// NonFiniteNumber when a number in it is NaN or infinite.
std::string json_text(const nlohmann::json& value, int indent = 2);

}  // namespace coupling
