// The scene schema compiled in (docs/scene.schema.json), its nodes, and the validation pass: valijson decides whether
// a document conforms; where it does not, a walk of the document with the schema writes each fault, in the format of
// every other scene fault, from the schema node at its path and the value found there.
#include "coupling/scene/scene_schema.hpp"

#include <algorithm>
#include <cmath>
#include <string>

// g++ 12 reports a false -Wrestrict inside valijson's JSON-pointer code (std::string::replace inlined from
// valijson/internal/json_pointer.hpp); the warning is silenced for this file only (it compiles alone in unity builds).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

namespace coupling {

// The text of docs/scene.schema.json (scene_schema_text.cpp, written by CMake at configure time).
std::string_view scene_schema_text();

const nlohmann::ordered_json& scene_schema() {
  static const nlohmann::ordered_json schema = nlohmann::ordered_json::parse(scene_schema_text());
  return schema;
}

namespace {

// "#/definitions/point_m" -> its node; null for a reference outside this document.
const nlohmann::ordered_json* resolve(const nlohmann::ordered_json& node) {
  const nlohmann::ordered_json* at = &node;
  for (int hops = 0; hops < 16 && at->is_object(); ++hops) {
    const auto ref = at->find("$ref");
    if (ref == at->end() || !ref->is_string()) return at;
    const std::string target = ref->get<std::string>();
    if (target.rfind("#", 0) != 0) return nullptr;
    const nlohmann::ordered_json::json_pointer pointer(target.substr(1));
    if (!scene_schema().contains(pointer)) return nullptr;
    at = &scene_schema().at(pointer);
  }
  return at;
}

const nlohmann::ordered_json* member(const nlohmann::ordered_json* node, const char* key) {
  if (node == nullptr || !node->is_object()) return nullptr;
  const auto it = node->find(key);
  return it == node->end() ? nullptr : &*it;
}

std::optional<double> number_member(const nlohmann::ordered_json* node, const char* key) {
  const auto* value = member(node, key);
  if (value == nullptr || !value->is_number()) return std::nullopt;
  return value->get<double>();
}

std::string in_quotes(std::string_view text) {
  std::string out;
  out += '"';
  out.append(text);
  out += '"';
  return out;
}

// "\"a\", \"b\" or \"c\"" (quoted) or "a, b, c".
std::string listed(const std::vector<std::string>& names, bool quote) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += quote ? (i + 1 == names.size() ? " or " : ", ") : ", ";
    out += quote ? in_quotes(names[i]) : names[i];
  }
  return out;
}

}  // namespace

SchemaNode::SchemaNode(const nlohmann::ordered_json* node) : node_(node ? resolve(*node) : nullptr) {}

SchemaNode SchemaNode::property(std::string_view key) const {
  const auto* properties = member(node_, "properties");
  if (properties == nullptr || !properties->is_object()) return {};
  const auto it = properties->find(key);
  return it == properties->end() ? SchemaNode{} : SchemaNode(&*it);
}

SchemaNode SchemaNode::items(std::size_t index) const {
  const auto* items = member(node_, "items");
  if (items != nullptr && items->is_array()) return index < items->size() ? SchemaNode(&(*items)[index]) : SchemaNode{};
  return items != nullptr && items->is_object() ? SchemaNode(items) : SchemaNode{};
}

std::vector<std::string> SchemaNode::property_names() const {
  std::vector<std::string> names;
  const auto* properties = member(node_, "properties");
  if (properties == nullptr || !properties->is_object()) return names;
  for (const auto& [key, value] : properties->items())
    if (key != "notes" && key != "$schema" && member(&value, "x-refused") == nullptr) names.push_back(key);
  return names;
}

bool SchemaNode::requires_key(std::string_view key) const {
  const auto* required = member(node_, "required");
  if (required == nullptr || !required->is_array()) return false;
  return std::any_of(required->begin(), required->end(),
                     [&](const nlohmann::ordered_json& name) { return name.is_string() && name == key; });
}

std::string SchemaNode::type() const {
  const auto* type = member(node_, "type");
  return type != nullptr && type->is_string() ? type->get<std::string>() : std::string();
}

bool SchemaNode::is_whole_number() const { return number_member(node_, "multipleOf") == 1.0; }

Bounds SchemaNode::bounds() const {
  Bounds b;
  if (const auto v = number_member(node_, "minimum")) b.min = *v;
  if (const auto v = number_member(node_, "exclusiveMinimum"); v && (!b.min || *v >= *b.min)) {
    b.min = *v;
    b.min_inclusive = false;
  }
  if (const auto v = number_member(node_, "maximum")) b.max = *v;
  if (const auto v = number_member(node_, "exclusiveMaximum"); v && (!b.max || *v <= *b.max)) {
    b.max = *v;
    b.max_inclusive = false;
  }
  return b;
}

std::vector<std::string> SchemaNode::enum_names() const {
  std::vector<std::string> names;
  const auto* values = member(node_, "enum");
  if (values == nullptr || !values->is_array()) return names;
  for (const auto& value : *values)
    if (value.is_string()) names.push_back(value.get<std::string>());
  return names;
}

const nlohmann::ordered_json* SchemaNode::default_value() const { return member(node_, "default"); }

std::string SchemaNode::unit() const {
  const auto* unit = member(node_, "x-unit");
  return unit != nullptr && unit->is_string() ? unit->get<std::string>() : std::string();
}

std::string SchemaNode::expected() const {
  const std::string t = type();
  const Bounds b = bounds();
  const bool bounded = b.min || b.max;
  if (t == "number")
    return std::string(is_whole_number() ? "a whole number" : "a number") +
           (bounded ? " " + b.describe() : std::string());
  if (t == "string") {
    const auto names = enum_names();
    return names.empty() ? "a string" : listed(names, true);
  }
  if (t == "boolean") return "true or false";
  if (t == "object") return "an object";
  if (t == "array") return "an array";
  return "a value";
}

SchemaNode schema_node_at(std::string_view path) {
  SchemaNode node(&scene_schema());
  std::size_t i = 0;
  while (node && i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos) return {};
      std::size_t index = 0;
      for (std::size_t k = i + 1; k < close; ++k) index = index * 10 + static_cast<std::size_t>(path[k] - '0');
      node = node.items(index);
      i = close + 1;
    } else {
      if (path[i] == '.') ++i;
      const std::size_t end = path.find_first_of(".[", i);
      node = node.property(path.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i));
      i = end == std::string_view::npos ? path.size() : end;
    }
  }
  return node;
}

namespace {

// The faults of `value` against the constraints of `node` itself (its children are checked at their own paths).
class FaultWriter {
 public:
  FaultWriter(const std::string& path, Diagnostics& diagnostics) : path_(path), diagnostics_(diagnostics) {}

  // The faults of the value itself; whether its elements or members are to be checked too (not when it has the
  // wrong type, is refused, or is an array beyond its size limit: nothing is done per element then).
  bool check(const SchemaNode& node, const nlohmann::json& value) {
    if (!node) return false;
    if (const auto* refused = member(node.json(), "x-refused"); refused != nullptr && refused->is_string()) {
      fault(path_, refused->get<std::string>());  // a key the schema names only to refuse it, with the reason
      return false;
    }
    if (!type_matches(node, value)) return false;
    if (const auto* constant = member(node.json(), "const"); constant != nullptr && constant->dump() != value.dump()) {
      fault(path_, "must be " + constant->dump() + " (got " + shown_value(value) + ")");
      return false;
    }
    if (value.is_number() && !check_numeric_enum(node, value)) return false;
    if (value.is_number()) check_number(node, value);
    if (value.is_string()) check_string(node, value);
    if (value.is_array()) return check_array(node, value);
    if (value.is_object()) check_object(node, value);
    return true;
  }

 private:
  void fault(const std::string& path, const std::string& message) {
    if (diagnostics_.is_invalid(path)) return;
    diagnostics_.error(path, message);
    diagnostics_.mark_invalid(path);
  }

  // A pair such as [x, y] or [min, max]: its "title" names it.
  static std::string shape(const SchemaNode& node) {
    const auto* title = member(node.json(), "title");
    return title != nullptr && title->is_string() ? title->get<std::string>() : std::string();
  }

  bool type_matches(const SchemaNode& node, const nlohmann::json& value) {
    const std::string t = node.type();
    const bool ok = t.empty() || (t == "number" && value.is_number()) || (t == "string" && value.is_string()) ||
                    (t == "boolean" && value.is_boolean()) || (t == "object" && value.is_object()) ||
                    (t == "array" && value.is_array()) || (t == "null" && value.is_null());
    if (ok) return true;
    std::string expected = node.expected();
    if (t == "number") {
      const Bounds b = node.bounds();
      expected = std::string(node.is_whole_number() ? "a whole number" : "a number") +
                 (b.min || b.max ? " (" + b.describe() + ")" : std::string());
    } else if (t == "array" && !shape(node).empty()) {
      expected = shape(node) + " (an array of two numbers)";
    } else if (t == "string") {
      expected = "a string";
    }
    fault(path_, "expected " + expected + ", got " + found_value(value));
    return false;
  }

  // A number that must be one of a list ("enum"), with the list's reason ("x-enum-reason") when it has one.
  bool check_numeric_enum(const SchemaNode& node, const nlohmann::json& value) {
    const auto* values = member(node.json(), "enum");
    if (values == nullptr || !values->is_array()) return true;
    std::vector<std::string> allowed;
    for (const auto& v : *values) {
      if (v.is_number() && v.get<double>() == value.get<double>()) return true;
      allowed.push_back(v.dump());
    }
    const auto* reason = member(node.json(), "x-enum-reason");
    fault(path_, "must be " + listed(allowed, false) + " (got " + shown_value(value) + ")" +
                     (reason != nullptr && reason->is_string() ? ": " + reason->get<std::string>() : std::string()));
    return false;
  }

  void check_number(const SchemaNode& node, const nlohmann::json& value) {
    const double number = value.get<double>();
    const Bounds b = node.bounds();
    if (node.is_whole_number() && std::floor(number) != number) {
      fault(path_, "expected a whole number" + (b.min || b.max ? " (" + b.describe() + ")" : std::string()) + ", got " +
                       found_value(value));
      return;
    }
    if (!b.contains(number)) fault(path_, "must be " + b.describe() + " (got " + shown_value(value) + ")");
  }

  void check_string(const SchemaNode& node, const nlohmann::json& value) {
    const std::string text = value.get<std::string>();
    const auto min_length = number_member(node.json(), "minLength");
    if (min_length && static_cast<double>(text.size()) < *min_length) {
      fault(path_, "must not be empty");
      return;
    }
    const auto names = node.enum_names();
    if (names.empty() || std::find(names.begin(), names.end(), text) != names.end()) return;
    const std::string suggestion = closest_match(text, names);
    const std::string hint = suggestion.empty() ? std::string() : "did you mean " + in_quotes(suggestion) + "? ";
    const auto* noun = member(node.json(), "x-enum-noun");
    if (noun != nullptr && noun->is_string())
      fault(path_, "unknown " + noun->get<std::string>() + " " + in_quotes(text) + " (" + hint +
                       "allowed: " + listed(names, false) + ")");
    else
      fault(path_, "expected " + listed(names, true) + ", got " + in_quotes(text) +
                       (hint.empty() ? std::string() : " (" + hint.substr(0, hint.size() - 1) + ")"));
  }

  // False when the array is beyond its size limit.
  bool check_array(const SchemaNode& node, const nlohmann::json& value) {
    const auto min_items = number_member(node.json(), "minItems");
    const auto max_items = number_member(node.json(), "maxItems");
    const double size = static_cast<double>(value.size());
    if (!shape(node).empty() && min_items && max_items && *min_items == *max_items) {
      if (size != *min_items)
        fault(path_, "expected " + shape(node) + " (an array of two numbers), got an array of " +
                         std::to_string(value.size()) + " elements");
      return size == *min_items;
    }
    if (min_items && size < *min_items) {
      const auto n = static_cast<long>(*min_items);
      fault(path_, "needs at least " + std::to_string(n) + " element" + (n == 1 ? "" : "s") + " (got " +
                       std::to_string(value.size()) + ")");
      return true;
    }
    if (max_items && size > *max_items) {
      const auto* what = member(node.json(), "x-items");
      const auto* reason = member(node.json(), "x-limit-reason");
      fault(path_, "too many " + (what && what->is_string() ? what->get<std::string>() : std::string("elements")) +
                       " (got " + std::to_string(value.size()) + "; at most " +
                       std::to_string(static_cast<long>(*max_items)) + " allowed" +
                       (reason && reason->is_string() ? ": " + reason->get<std::string>() : std::string()) + ")");
      return false;
    }
    const auto* unique = member(node.json(), "uniqueItems");
    if (unique == nullptr || !unique->is_boolean() || !unique->get<bool>()) return true;
    for (std::size_t j = 1; j < value.size(); ++j)
      for (std::size_t i = 0; i < j; ++i)
        if (value[i] == value[j]) {
          const auto* noun = member(node.items().json(), "x-enum-noun");
          const std::string what = noun && noun->is_string() ? noun->get<std::string>() : std::string("value");
          fault(index_path(path_, j),
                what + " " + shown_value(value[j]) + " is listed twice (list each " + what + " once)");
          break;
        }
    return true;
  }

  void check_object(const SchemaNode& node, const nlohmann::json& value) {
    const auto* required = member(node.json(), "required");
    if (required != nullptr && required->is_array())
      for (const auto& key : *required)
        if (key.is_string() && !value.contains(key.get<std::string>()))
          fault(join_path(path_, key.get<std::string>()),
                "missing (required: " + node.property(key.get<std::string>()).expected() + ")");
    const auto* additional = member(node.json(), "additionalProperties");
    if (additional == nullptr || !additional->is_boolean() || additional->get<bool>()) return;
    const std::vector<std::string> allowed = node.property_names();
    for (const auto& [key, child] : value.items()) {
      if (key == "notes" || node.property(key)) continue;
      const std::string suggestion = closest_match(key, allowed);
      fault(join_path(path_, key),
            "unknown key (" + (suggestion.empty() ? std::string() : "did you mean " + in_quotes(suggestion) + "? ") +
                (allowed.empty() ? "no keys are allowed here" : "allowed here: " + listed(allowed, false)) + ")");
    }
  }

  const std::string& path_;
  Diagnostics& diagnostics_;
};

// The schema compiled for valijson once, on first use.
struct CompiledSchema {
  valijson::Schema schema;
  CompiledSchema() {
    const nlohmann::json document = nlohmann::json::parse(scene_schema_text());
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    valijson::adapters::NlohmannJsonAdapter adapter(document);
    parser.populateSchema(adapter, schema);
  }
};

const valijson::Schema& compiled_schema() {
  static const CompiledSchema compiled;
  return compiled.schema;
}

// Walks the document with the schema, node by node, and writes the faults of each value. Its cost is one visit per
// value and it keeps no more than the faults shown (Diagnostics counts the others), whatever the document holds.
void walk(const SchemaNode& node, const nlohmann::json& value, const std::string& path, Diagnostics& diagnostics) {
  FaultWriter writer(path, diagnostics);
  if (!writer.check(node, value)) return;
  if (value.is_object()) {
    for (const auto& [key, child] : value.items())
      if (const SchemaNode child_node = node.property(key)) walk(child_node, child, join_path(path, key), diagnostics);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      if (const SchemaNode child_node = node.items(i)) walk(child_node, value[i], index_path(path, i), diagnostics);
  }
}

// valijson's own words for a rule the walk does not word, at the deepest places it names (few: the scene schema
// uses no such rule today). Its context ("<root>", "[section]", "[0]") is written as a JSON path.
void report_in_valijson_words(const nlohmann::json& document, Diagnostics& diagnostics) {
  valijson::Validator validator(valijson::Validator::kStrongTypes);
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter adapter(document);
  validator.validate(compiled_schema(), adapter, &results);
  std::vector<std::string> reported;
  valijson::ValidationResults::Error error;
  while (results.popError(error) && diagnostics.size() <= max_reported_faults) {
    std::string path;
    const nlohmann::json* at = &document;
    for (std::size_t i = 1; i < error.context.size() && at != nullptr; ++i) {
      const std::string key = error.context[i].substr(1, error.context[i].size() - 2);
      if (at->is_array() && !key.empty() &&
          std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        path = index_path(path, std::stoul(key));
        at = std::stoul(key) < at->size() ? &(*at)[std::stoul(key)] : nullptr;
      } else {
        path = join_path(path, key);
        at = at->is_object() && at->contains(key) ? &(*at)[key] : nullptr;
      }
    }
    // valijson names each parent of a failing value too: only the first (deepest) place of a chain is kept.
    const bool parent_of_reported = std::any_of(reported.begin(), reported.end(), [&](const std::string& r) {
      return r.size() > path.size() && r.compare(0, path.size(), path) == 0;
    });
    if (parent_of_reported || diagnostics.is_invalid(path)) continue;
    diagnostics.error(path, "does not match the scene schema: " + error.description);
    diagnostics.mark_invalid(path);
    reported.push_back(path);
  }
}

}  // namespace

void validate_against_schema(const nlohmann::json& document, Diagnostics& diagnostics) {
  // valijson decides (it holds nothing per fault: it stops at the first); the walk then words every fault.
  valijson::Validator validator(valijson::Validator::kStrongTypes);
  valijson::adapters::NlohmannJsonAdapter adapter(document);
  if (validator.validate(compiled_schema(), adapter, nullptr)) return;
  const std::size_t before = diagnostics.size();
  walk(SchemaNode(&scene_schema()), document, "", diagnostics);
  if (diagnostics.size() == before) report_in_valijson_words(document, diagnostics);
}

}  // namespace coupling
