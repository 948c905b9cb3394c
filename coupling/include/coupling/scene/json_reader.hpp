#pragma once
// Reading validated input out of JSON with errors that name the JSON path, what is wrong and what is allowed:
//
//   section.materials[0].unit_weight_kN_m3: must be > 0 (got -18)
//   analyses.lem.slice: unknown key (did you mean "slices"?; allowed here: methods, slices, refine, search)
//
// A JsonReader wraps one JSON object. Every key the program understands is read through it (typed, with bounds);
// finish() then reports every key that was never asked for as unknown. Errors are collected, not thrown, so one
// pass reports every fault in a file. Readers return std::nullopt for a missing or invalid value, so checks that
// depend on it are skipped instead of cascading.
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/input_limits.hpp"
#include "sphslope/names.hpp"

namespace coupling {

// Validation errors, each "<json path>: <what is wrong> (<what is allowed>)". Only the first max_reported_faults
// are kept; a last line counts the others, so a hostile file cannot make the program print millions of lines.
class Diagnostics {
 public:
  void error(std::string_view path, std::string_view message);
  bool empty() const { return count_ == 0; }
  // Every fault reported, including those not kept.
  std::size_t size() const { return count_; }
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  std::vector<std::string> messages_;
  std::size_t count_ = 0;
};

// "section.materials" + "name" -> "section.materials.name"; "" + "section" -> "section".
std::string join_path(std::string_view parent, std::string_view key);
// "section.profile_lines" + 2 -> "section.profile_lines[2]".
std::string index_path(std::string_view parent, std::size_t index);

// "a number", "a string", "an object", ... for messages.
std::string json_type_name(const nlohmann::json& value);
// Short text of a number for messages: 12 -> "12", 0.1 -> "0.1", 1.0/3 -> "0.333333".
std::string format_number(double value);

// Allowed interval of a number; either end may be open, closed or absent.
struct Bounds {
  std::optional<double> min;
  bool min_inclusive = true;
  std::optional<double> max;
  bool max_inclusive = true;

  static Bounds any() { return {}; }
  static Bounds positive() { return {0.0, false, std::nullopt, true}; }       // > 0
  static Bounds non_negative() { return {0.0, true, std::nullopt, true}; }    // >= 0
  static Bounds at_least(double a) { return {a, true, std::nullopt, true}; }  // >= a
  static Bounds closed(double a, double b) { return {a, true, b, true}; }     // [a, b]
  static Bounds half_open(double a, double b) { return {a, true, b, false}; } // [a, b)
  static Bounds open(double a, double b) { return {a, false, b, false}; }     // (a, b)

  bool contains(double value) const;
  std::string describe() const;  // "> 0", "in [0, 90)", "any number"
};

enum class Need { required, optional };

class JsonReader {
 public:
  // `value` must outlive the reader. If it is not an object, one error is reported and every read returns nothing.
  JsonReader(const nlohmann::json& value, std::string path, Diagnostics& diagnostics);

  const std::string& path() const { return path_; }
  std::string path_of(std::string_view key) const { return join_path(path_, key); }
  Diagnostics& diagnostics() const { return *diagnostics_; }
  bool is_object() const { return object_ != nullptr; }

  // Whether the key is present; marks it as known.
  bool has(std::string_view key);
  // Marks a key as known without reading it (free-form content such as "notes").
  void allow(std::string_view key);

  // The raw value of a key of any type (kept for a later stage); reports a missing required key.
  const nlohmann::json* raw(std::string_view key, Need need, std::string_view expected = "a value");

  std::optional<double> number(std::string_view key, Need need, const Bounds& bounds = Bounds::any());
  double number_or(std::string_view key, double fallback, const Bounds& bounds = Bounds::any());
  std::optional<long> integer(std::string_view key, Need need, const Bounds& bounds = Bounds::any());
  std::optional<bool> boolean(std::string_view key, Need need);
  // `non_empty`: an empty string is an error.
  std::optional<std::string> string(std::string_view key, Need need, bool non_empty = true);
  // A nested object; the returned reader reports its own unknown keys in its finish().
  std::optional<JsonReader> object(std::string_view key, Need need, std::string_view expected = "an object");
  // An array; `min_size` elements at least. Returns the JSON array (elements are read with the free functions below).
  // `limit`: the most elements allowed (input_limits.hpp); a larger array is reported and not returned, so nothing
  // is done per element.
  const nlohmann::json* array(std::string_view key, Need need, std::size_t min_size, const SizeLimit& limit,
                              std::string_view expected = "an array");

  // Reports every key of the object that was never asked for, with a suggestion when one is close.
  // Keys under "notes" are free-form and never checked.
  void finish();

 private:
  const nlohmann::json* find(std::string_view key, Need need, std::string_view expected);

  const nlohmann::json* object_ = nullptr;
  std::string path_;
  Diagnostics* diagnostics_;
  std::vector<std::string> known_;  // in the order asked for, for the "allowed here" list
  std::set<std::string, std::less<>> known_set_;
};

// Free readers for values that are not object members (array elements and the like). Each reports at `path`.
std::optional<double> read_number(const nlohmann::json& value, const std::string& path, Diagnostics& diagnostics,
                                  const Bounds& bounds = Bounds::any());
std::optional<long> read_integer(const nlohmann::json& value, const std::string& path, Diagnostics& diagnostics,
                                 const Bounds& bounds = Bounds::any());
std::optional<std::string> read_string(const nlohmann::json& value, const std::string& path,
                                       Diagnostics& diagnostics, bool non_empty = true);

// Whether the array `value` has at most `limit.max` elements; reports at `path` when not:
//   section.surcharges: too many surcharges (got 5000; at most 1000 allowed: each strip load is ...)
bool within_size_limit(const nlohmann::json& value, const std::string& path, const SizeLimit& limit,
                       Diagnostics& diagnostics);

// An [x, y] pair of numbers (a point, or a [min, max] range).
std::optional<std::pair<double, double>> read_pair(const nlohmann::json& value, const std::string& path,
                                                   Diagnostics& diagnostics, std::string_view what = "[x, y]");

// Closest string within edit distance 2 (case-insensitive), for "did you mean" hints; empty if none.
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

// An optional string key naming one of a setting's choices (its name table): `target` is set to the named one;
// another name is an error "expected "a" or "b", got "c"".
template <class Choice, std::size_t N>
void read_named(JsonReader& r, const char* key, const sphslope::NameTable<Choice, N>& names, Choice& target) {
  const auto name = r.string(key, Need::optional);
  if (!name) return;
  if (const auto value = sphslope::value_named(names, *name)) {
    target = *value;
    return;
  }
  r.diagnostics().error(r.path_of(key), "expected " + sphslope::names_listed(names, true) + ", got \"" + *name + "\"");
}

}  // namespace coupling
