#include "coupling/scene/json_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include "coupling/scene/scene_schema.hpp"

namespace coupling {

void Diagnostics::error(std::string_view path, std::string_view message) {
  ++count_;
  if (count_ > max_reported_faults) {
    std::string summary = "... and " + std::to_string(count_ - max_reported_faults) + " more fault" +
                          (count_ - max_reported_faults == 1 ? "" : "s") + " (only the first " +
                          std::to_string(max_reported_faults) + " are shown)";
    if (count_ == max_reported_faults + 1) {
      messages_.push_back(std::move(summary));
    } else {
      messages_.back() = std::move(summary);
    }
    return;
  }
  std::string line(path.empty() ? std::string_view("(top level)") : path);
  line += ": ";
  line += message;
  messages_.push_back(std::move(line));
}

std::string join_path(std::string_view parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  std::string out(parent);
  out += '.';
  out += key;
  return out;
}

std::string index_path(std::string_view parent, std::size_t index) {
  return std::string(parent) + "[" + std::to_string(index) + "]";
}

std::string json_type_name(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

std::string format_number(double value) {
  if (!std::isfinite(value)) return value > 0 ? "inf" : (value < 0 ? "-inf" : "nan");
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

bool Bounds::contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (min && (min_inclusive ? value < *min : value <= *min)) return false;
  if (max && (max_inclusive ? value > *max : value >= *max)) return false;
  return true;
}

std::string Bounds::describe() const {
  if (min && max) {
    return std::string("in ") + (min_inclusive ? "[" : "(") + format_number(*min) + ", " + format_number(*max) +
           (max_inclusive ? "]" : ")");
  }
  if (min) return std::string(min_inclusive ? ">= " : "> ") + format_number(*min);
  if (max) return std::string(max_inclusive ? "<= " : "< ") + format_number(*max);
  return "any number";
}

std::string shown_value(const nlohmann::json& value) {
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

std::string found_value(const nlohmann::json& value) {
  if (value.is_string() || value.is_number() || value.is_boolean() || value.is_null()) {
    return json_type_name(value) + " " + shown_value(value);
  }
  return json_type_name(value);
}

namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string needle = lower(word);
  std::string best;
  std::size_t best_distance = 3;
  for (const std::string& candidate : candidates) {
    const std::size_t d = edit_distance(needle, lower(candidate));
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

std::optional<double> read_number(const nlohmann::json& value, const std::string& path, Diagnostics& diagnostics,
                                  const Bounds& bounds) {
  if (diagnostics.skip_invalid(path)) return std::nullopt;
  if (!value.is_number()) {
    const bool any = !bounds.min && !bounds.max;
    diagnostics.error(path, std::string("expected a number") + (any ? "" : " (" + bounds.describe() + ")") + ", got " +
                                found_value(value));
    return std::nullopt;
  }
  const double number = value.get<double>();
  if (!std::isfinite(number)) {
    diagnostics.error(path, "must be a finite number (got " + shown_value(value) + ")");
    return std::nullopt;
  }
  if (!bounds.contains(number)) {
    diagnostics.error(path, "must be " + bounds.describe() + " (got " + shown_value(value) + ")");
    return std::nullopt;
  }
  return number;
}

std::optional<long> read_integer(const nlohmann::json& value, const std::string& path, Diagnostics& diagnostics,
                                 const Bounds& bounds) {
  if (diagnostics.skip_invalid(path)) return std::nullopt;
  const bool whole = value.is_number_integer() || value.is_number_unsigned() ||
                     (value.is_number_float() && std::isfinite(value.get<double>()) &&
                      std::floor(value.get<double>()) == value.get<double>());
  if (!whole) {
    const bool any = !bounds.min && !bounds.max;
    diagnostics.error(path, std::string("expected a whole number") + (any ? "" : " (" + bounds.describe() + ")") +
                                ", got " + found_value(value));
    return std::nullopt;
  }
  const double number = value.get<double>();
  if (!bounds.contains(number) || std::fabs(number) > 1e15) {
    diagnostics.error(path, "must be " + bounds.describe() + " (got " + shown_value(value) + ")");
    return std::nullopt;
  }
  return static_cast<long>(number);
}

std::optional<std::string> read_string(const nlohmann::json& value, const std::string& path,
                                       Diagnostics& diagnostics, bool non_empty) {
  if (diagnostics.skip_invalid(path)) return std::nullopt;
  if (!value.is_string()) {
    diagnostics.error(path, "expected a string, got " + found_value(value));
    return std::nullopt;
  }
  std::string text = value.get<std::string>();
  if (non_empty && text.empty()) {
    diagnostics.error(path, "must not be empty");
    return std::nullopt;
  }
  return text;
}

std::optional<std::pair<double, double>> read_pair(const nlohmann::json& value, const std::string& path,
                                                   Diagnostics& diagnostics, std::string_view what) {
  if (diagnostics.skip_invalid(path)) return std::nullopt;
  if (!value.is_array() || value.size() != 2) {
    diagnostics.error(path, "expected " + std::string(what) + " (an array of two numbers), got " +
                                (value.is_array() ? "an array of " + std::to_string(value.size()) + " elements"
                                                  : found_value(value)));
    return std::nullopt;
  }
  const auto a = read_number(value[0], index_path(path, 0), diagnostics);
  const auto b = read_number(value[1], index_path(path, 1), diagnostics);
  if (!a || !b) return std::nullopt;
  return std::pair{*a, *b};
}

bool within_size_limit(const nlohmann::json& value, const std::string& path, const SizeLimit& limit,
                       Diagnostics& diagnostics) {
  if (value.size() <= limit.max) return true;
  if (diagnostics.skip_invalid(path)) return false;
  diagnostics.error(path, "too many " + std::string(limit.what) + " (got " + std::to_string(value.size()) +
                              "; at most " + std::to_string(limit.max) + " allowed: " + std::string(limit.reason) +
                              ")");
  return false;
}

JsonReader::JsonReader(const nlohmann::json& value, std::string path, Diagnostics& diagnostics)
    : JsonReader(value, path, diagnostics, schema_node_at(path).json()) {}

JsonReader::JsonReader(const nlohmann::json& value, std::string path, Diagnostics& diagnostics,
                       const nlohmann::ordered_json* schema)
    : schema_(schema), path_(std::move(path)), diagnostics_(&diagnostics) {
  if (value.is_object()) {
    object_ = &value;
  } else {
    report(path_, "expected an object, got " + found_value(value));
  }
}

void JsonReader::report(std::string_view path, std::string_view message) const {
  if (!diagnostics_->skip_invalid(path)) diagnostics_->error(path, message);
}

void JsonReader::schema_disagrees(std::string_view path, std::string_view detail) const {
  diagnostics_->error(path, "the program and its scene schema (docs/scene.schema.json) disagree: " +
                                std::string(detail) + " (a fault of sphslope, not of the scene)");
}

void JsonReader::check_default(std::string_view key, double fallback) const {
  const SchemaNode node = SchemaNode(schema_).property(key);
  const nlohmann::ordered_json* given = node ? node.default_value() : nullptr;
  if (given == nullptr) return;
  if (!given->is_number() || given->get<double>() != fallback)
    schema_disagrees(path_of(key), "the schema's default is " + given->dump() + ", the program's " +
                                       format_number(fallback));
}

void check_names_against_schema(const JsonReader& parent, std::string_view key, const std::vector<std::string>& names,
                                std::string_view current, bool items) {
  SchemaNode node = SchemaNode(parent.schema()).property(key);
  if (node && items) node = node.items();
  if (!node) return;
  if (node.enum_names() != names) {
    std::string program;
    for (const std::string& name : names) program += (program.empty() ? "" : ", ") + name;
    parent.schema_disagrees(parent.path_of(key), "the program's names are " + program);
  }
  const nlohmann::ordered_json* given = node.default_value();
  if (given != nullptr && !(given->is_string() && given->get<std::string>() == current))
    parent.schema_disagrees(parent.path_of(key),
                            "the schema's default is " + given->dump() + ", the program's \"" + std::string(current) + "\"");
}

void unknown_name(JsonReader& r, const std::string& path, const std::string& name, const std::string& allowed) {
  r.diagnostics().error(path, "unknown name \"" + name + "\" (allowed: " + allowed + ")");
}

bool JsonReader::has(std::string_view key) {
  allow(key);
  return object_ != nullptr && object_->contains(key);
}

void JsonReader::allow(std::string_view key) {
  if (known_set_.insert(std::string(key)).second) known_.emplace_back(key);
}

const nlohmann::json* JsonReader::find(std::string_view key, Need need, std::string_view expected) {
  allow(key);
  if (object_ == nullptr) return nullptr;
  const auto it = object_->find(key);
  if (it == object_->end()) {
    if (need == Need::required) report(path_of(key), "missing (required: " + std::string(expected) + ")");
    return nullptr;
  }
  return &*it;
}

const nlohmann::json* JsonReader::raw(std::string_view key, Need need, std::string_view expected) {
  const nlohmann::json* value = find(key, need, expected);
  return value == nullptr || diagnostics_->skip_invalid(path_of(key)) ? nullptr : value;
}

std::optional<double> JsonReader::number(std::string_view key, Need need, const Bounds& bounds) {
  const bool any = !bounds.min && !bounds.max;
  const SchemaNode node = SchemaNode(schema_).property(key);
  const nlohmann::json* value =
      find(key, need, node ? node.expected() : any ? std::string("a number") : "a number " + bounds.describe());
  if (value == nullptr) return std::nullopt;
  return read_number(*value, path_of(key), *diagnostics_, bounds);
}

double JsonReader::number_or(std::string_view key, double fallback, const Bounds& bounds) {
  if (object_ != nullptr && !object_->contains(key)) check_default(key, fallback);
  return number(key, Need::optional, bounds).value_or(fallback);
}

std::optional<long> JsonReader::integer(std::string_view key, Need need, const Bounds& bounds) {
  const bool any = !bounds.min && !bounds.max;
  const SchemaNode node = SchemaNode(schema_).property(key);
  const nlohmann::json* value =
      find(key, need, node ? node.expected() : any ? std::string("a whole number") : "a whole number " + bounds.describe());
  if (value == nullptr) return std::nullopt;
  return read_integer(*value, path_of(key), *diagnostics_, bounds);
}

long JsonReader::integer_or(std::string_view key, long fallback) {
  if (object_ != nullptr && !object_->contains(key)) check_default(key, static_cast<double>(fallback));
  return integer(key, Need::optional).value_or(fallback);
}

std::optional<bool> JsonReader::boolean(std::string_view key, Need need) {
  const nlohmann::json* value = find(key, need, "true or false");
  if (value == nullptr) return std::nullopt;
  if (diagnostics_->skip_invalid(path_of(key))) return std::nullopt;
  if (!value->is_boolean()) {
    report(path_of(key), "expected true or false, got " + found_value(*value));
    return std::nullopt;
  }
  return value->get<bool>();
}

std::optional<std::string> JsonReader::string(std::string_view key, Need need, bool non_empty) {
  const nlohmann::json* value = find(key, need, "a string");
  if (value == nullptr) return std::nullopt;
  return read_string(*value, path_of(key), *diagnostics_, non_empty);
}

std::optional<JsonReader> JsonReader::object(std::string_view key, Need need, std::string_view expected) {
  const nlohmann::json* value = find(key, need, expected);
  if (value == nullptr || diagnostics_->skip_invalid(path_of(key))) return std::nullopt;
  if (!value->is_object()) {
    report(path_of(key), "expected " + std::string(expected) + ", got " + found_value(*value));
    return std::nullopt;
  }
  return JsonReader(*value, path_of(key), *diagnostics_, SchemaNode(schema_).property(key).json());
}

const nlohmann::json* JsonReader::array(std::string_view key, Need need, std::size_t min_size,
                                        const SizeLimit& limit, std::string_view expected) {
  const nlohmann::json* value = find(key, need, expected);
  if (value == nullptr || diagnostics_->skip_invalid(path_of(key))) return nullptr;
  if (!value->is_array()) {
    report(path_of(key), "expected " + std::string(expected) + ", got " + found_value(*value));
    return nullptr;
  }
  if (value->size() < min_size) {
    report(path_of(key), "needs at least " + std::to_string(min_size) + " element" +
                                          (min_size == 1 ? "" : "s") + " (got " + std::to_string(value->size()) +
                                          ")");
    return nullptr;
  }
  if (!within_size_limit(*value, path_of(key), limit, *diagnostics_)) return nullptr;
  return value;
}

void JsonReader::finish() {
  if (object_ == nullptr) return;
  std::string allowed;
  for (const std::string& key : known_) {
    if (key == "notes") continue;
    if (!allowed.empty()) allowed += ", ";
    allowed += key;
  }
  // A key the schema knows may still be unknown here: the schema lists the union of the keys of, e.g., every
  // reinforcement type, and the reader asks only for those of the element's own type.
  for (const auto& [key, value] : object_->items()) {
    if (key == "notes" || known_set_.count(key) != 0 || diagnostics_->is_invalid(path_of(key))) continue;
    std::string message = "unknown key (";
    const std::string suggestion = closest_match(key, known_);
    if (!suggestion.empty()) message += "did you mean \"" + suggestion + "\"? ";
    message += allowed.empty() ? "no keys are allowed here" : "allowed here: " + allowed;
    message += ")";
    diagnostics_->error(path_of(key), message);
  }
}

}  // namespace coupling
