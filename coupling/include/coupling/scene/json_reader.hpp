#pragma once
// Reading validated input out of JSON with errors that name the JSON path, what is wrong and what is allowed:
//
//   section.materials[0].unit_weight_kN_m3: must be > 0 (got -18)
//   analyses.lem.slice: unknown key (did you mean "slices"?; allowed here: methods, slices, refine, search)
//
// A JsonReader wraps one JSON object. Every key the program understands is read through it (typed, with the bounds
// that only the program knows: a range that depends on other values); finish() then reports every key that was never
// asked for. Types, static bounds, required keys, enum names and unknown keys are the scene schema's
// (scene_schema.hpp): its pass reports those faults first and marks their paths invalid, and the readers skip such a
// value without a second message. Errors are collected, not thrown, so one pass reports every fault in a file. Readers
// return std::nullopt for a missing or invalid value, so checks that depend on it are skipped instead of cascading.
// Where the program and the schema spell the same thing (a default, an enum's names) the reader checks that they
// agree and reports a fault of the program when they do not, so every scene read in the tests checks them.
#include <algorithm>
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
  // Every fault reported, including those not kept, and every time a reader met a value already reported: a reader
  // of a block tells whether anything in it failed by comparing size() before and after.
  std::size_t size() const { return count_ + skipped_; }
  const std::vector<std::string>& messages() const { return messages_; }

  // The paths whose fault is reported already (the schema pass marks them): the typed readers skip their values
  // without a second message.
  // Only the paths of the faults shown are kept: a scene with more faults is refused on the schema's alone
  // (scene_from_json), so that no reader meets an invalid value that is not marked.
  void mark_invalid(std::string_view path) {
    if (count_ <= max_reported_faults) invalid_.emplace(path);
  }
  bool is_invalid(std::string_view path) const { return invalid_.find(path) != invalid_.end(); }
  // For a reader about to read the value at `path`: whether to skip it (it is invalid), counted in size().
  bool skip_invalid(std::string_view path) {
    if (!is_invalid(path)) return false;
    ++skipped_;
    return true;
  }

 private:
  std::vector<std::string> messages_;
  std::size_t count_ = 0;
  std::size_t skipped_ = 0;
  std::set<std::string, std::less<>> invalid_;
};

// "section.materials" + "name" -> "section.materials.name"; "" + "section" -> "section".
std::string join_path(std::string_view parent, std::string_view key);
// "section.profile_lines" + 2 -> "section.profile_lines[2]".
std::string index_path(std::string_view parent, std::size_t index);

// "a number", "a string", "an object", ... for messages.
std::string json_type_name(const nlohmann::json& value);
// Short text of a number for messages: 12 -> "12", 0.1 -> "0.1", 1.0/3 -> "0.333333".
std::string format_number(double value);
// The value as written (numbers keep their JSON spelling), shortened to 40 characters, for messages.
std::string shown_value(const nlohmann::json& value);
// What was found, for "expected ..., got ..." messages: "a number -1", "a string \"x\"", "an object".
std::string found_value(const nlohmann::json& value);

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

  // The raw value of a key of any type (kept for a later stage); reports a missing required key. Null when the key is
  // absent or its value is invalid (reported already).
  const nlohmann::json* raw(std::string_view key, Need need, std::string_view expected = "a value");

  std::optional<double> number(std::string_view key, Need need, const Bounds& bounds = Bounds::any());
  double number_or(std::string_view key, double fallback, const Bounds& bounds = Bounds::any());
  std::optional<long> integer(std::string_view key, Need need, const Bounds& bounds = Bounds::any());
  long integer_or(std::string_view key, long fallback);
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

  // The schema node of this object (null where the schema does not describe it).
  const nlohmann::ordered_json* schema() const { return schema_; }
  // Reports that the program and the scene schema disagree at `path` (a fault of the program, not of the scene).
  void schema_disagrees(std::string_view path, std::string_view detail) const;

 private:
  JsonReader(const nlohmann::json& value, std::string path, Diagnostics& diagnostics,
             const nlohmann::ordered_json* schema);
  const nlohmann::json* find(std::string_view key, Need need, std::string_view expected);
  void report(std::string_view path, std::string_view message) const;
  // When `key` is absent and the program falls back to `fallback`: the schema's default must be the same.
  void check_default(std::string_view key, double fallback) const;

  const nlohmann::json* object_ = nullptr;
  const nlohmann::ordered_json* schema_ = nullptr;
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

// The program's names of a choice at `parent.key` against the schema's enum and default there (a fault of the program
// when they differ): the schema lists `names` in their order, and its default is `current`'s name (none: `current`
// empty). `items`: the names are those of the elements of the array at `parent.key`.
void check_names_against_schema(const JsonReader& parent, std::string_view key, const std::vector<std::string>& names,
                                std::string_view current, bool items = false);

// A name that is not in its table: the schema, which every scene meets first, refuses it with the allowed names, so
// this is reached only by a reader not run after the schema: an error all the same, "unknown name "c" (allowed: a, b)".
void unknown_name(JsonReader& r, const std::string& path, const std::string& name, const std::string& allowed);

template <class Choice, std::size_t N>
std::vector<std::string> names_of(const sphslope::NameTable<Choice, N>& names) {
  std::vector<std::string> listed;
  for (const auto& entry : names) listed.emplace_back(entry.name);
  return listed;
}

// An optional string key naming one of a setting's choices (its name table, which the schema's enum there must
// equal): `target` is set to the named one.
template <class Choice, std::size_t N>
void read_named(JsonReader& r, const char* key, const sphslope::NameTable<Choice, N>& names, Choice& target) {
  check_names_against_schema(r, key, names_of(names), sphslope::name_of(names, target));
  const auto name = r.string(key, Need::optional);
  if (!name) return;
  if (const auto value = sphslope::value_named(names, *name)) {
    target = *value;
    return;
  }
  unknown_name(r, r.path_of(key), *name, sphslope::names_listed(names));
}

// A required string key naming one of a setting's choices (its name table, which has no default): the named one,
// or nullopt after an error (missing, not a string, not a name of the table).
template <class Choice, std::size_t N>
std::optional<Choice> read_named_required(JsonReader& r, const char* key, const sphslope::NameTable<Choice, N>& names) {
  check_names_against_schema(r, key, names_of(names), "");
  const auto name = r.string(key, Need::required);
  if (!name) return std::nullopt;
  const auto value = sphslope::value_named(names, *name);
  if (!value) unknown_name(r, r.path_of(key), *name, sphslope::names_listed(names));
  return value;
}

// An optional array of names from a setting's name table (`expected` describes it in messages): the choices in the
// order given, a name listed twice once (the schema refuses the repeat where a list may not have one, uniqueItems);
// an empty list when the key is absent; nullopt after an error.
template <class Choice, std::size_t N>
std::optional<std::vector<Choice>> read_named_list(JsonReader& r, const char* key,
                                                   const sphslope::NameTable<Choice, N>& names,
                                                   std::string_view expected) {
  check_names_against_schema(r, key, names_of(names), "", /*items=*/true);
  std::vector<Choice> chosen;
  const nlohmann::json* list = r.array(key, Need::optional, 0, limits::name_list, expected);
  if (list == nullptr) return r.has(key) ? std::nullopt : std::optional<std::vector<Choice>>(chosen);
  bool ok = true;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string path = index_path(r.path_of(key), i);
    const auto name = read_string((*list)[i], path, r.diagnostics());
    const auto value = name ? sphslope::value_named(names, *name) : std::nullopt;
    if (name && !value) unknown_name(r, path, *name, sphslope::names_listed(names));
    if (!value) ok = false;
    else if (std::find(chosen.begin(), chosen.end(), *value) == chosen.end()) chosen.push_back(*value);
  }
  return ok ? std::optional<std::vector<Choice>>(chosen) : std::nullopt;
}

}  // namespace coupling
