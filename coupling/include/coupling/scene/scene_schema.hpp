#pragma once
// The scene format's JSON Schema, docs/scene.schema.json: the one published source of every key of a scene file,
// its type, unit (the custom keyword "x-unit"), bounds, default and enum names. It is compiled into the program.
//
// A scene is read in two passes. validate_against_schema() checks the document against the schema with valijson
// (a validator made for JSON Schema, so the program accepts what an editor that completes scenes from the schema
// accepts); when it does not conform, a walk of the document with the schema reports each fault in the program's own
// words, at its JSON path, from the schema node that it breaks (valijson keeps nothing per fault and the walk keeps
// only the faults shown, so a hostile file with millions of faults costs one pass and little memory):
//
//   section.materials[0].unit_weight_kN_m3: must be > 0 (got -18)
//   analyses.lem.slice: unknown key (did you mean "slices"?; allowed here: methods, slices, refine, search, ...)
//
// Each path reported is marked invalid in the Diagnostics; the typed readers (JsonReader) then skip those values
// without a second message and check what a schema cannot say (lines that must not cross, a material named by a
// line, a spacing that fits the bodies).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

// The schema as written (key order kept: it is the order of the "allowed here" lists).
const nlohmann::ordered_json& scene_schema();

// One node of the schema (an object's property, an array's items), with "$ref" resolved. A null node stands for
// a place the schema does not describe (free-form "notes", or a path through an unknown key).
class SchemaNode {
 public:
  SchemaNode() = default;
  explicit SchemaNode(const nlohmann::ordered_json* node);

  explicit operator bool() const { return node_ != nullptr; }
  const nlohmann::ordered_json* json() const { return node_; }

  // The node of property `key` of an object node; null when the object has no such property.
  SchemaNode property(std::string_view key) const;
  // The node of the elements of an array node (of element `index` where "items" is a list, one node per place).
  SchemaNode items(std::size_t index = 0) const;
  // An object node's property names in the schema's order, "notes", "$schema" and the keys it names only to refuse
  // them ("x-refused": the message) left out.
  std::vector<std::string> property_names() const;
  bool requires_key(std::string_view key) const;

  // "number", "string", "boolean", "object", "array" (empty when the node names no single type).
  std::string type() const;
  bool is_whole_number() const;  // "multipleOf": 1
  Bounds bounds() const;  // minimum, maximum, exclusiveMinimum, exclusiveMaximum
  std::vector<std::string> enum_names() const;
  const nlohmann::ordered_json* default_value() const;
  std::string unit() const;  // "x-unit", empty when dimensionless
  // What a value here must be, for messages: "a number > 0", "a whole number in [5, 1000]", "an object",
  // "true or false", "\"bishop\", \"spencer\" or ...".
  std::string expected() const;

 private:
  const nlohmann::ordered_json* node_ = nullptr;
};

// The node at a JSON path as the readers spell it ("", "section", "section.materials[0].name"); null when the
// schema does not describe that path.
SchemaNode schema_node_at(std::string_view path);

// Checks `document` against the scene schema; reports every fault through `diagnostics` and marks its path invalid.
void validate_against_schema(const nlohmann::json& document, Diagnostics& diagnostics);

}  // namespace coupling
