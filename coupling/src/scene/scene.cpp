// Scene files: reading, JSON syntax, the top level and the analyses block. The section is in scene_section.cpp.
#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/scene.hpp"
#include "coupling/scene/scene_schema.hpp"
#include "scene_internal.hpp"

namespace coupling {

SceneError::SceneError(std::vector<std::string> messages)
    : std::runtime_error(messages.empty() ? std::string("invalid scene") : messages.front()),
      messages_(std::move(messages)) {}

namespace {

// Duplicate keys are legal JSON but nlohmann keeps only the last one, which would silently drop what the user
// wrote first. The parser callback tracks the JSON path and reports them.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(Diagnostics& diagnostics) : diagnostics_(&diagnostics) {}

  bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start: stack_.push_back(Frame{true, {}, {}, 0}); break;
      case Event::array_start: stack_.push_back(Frame{false, {}, {}, 0}); break;
      case Event::key: {
        Frame& top = stack_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second) {
          diagnostics_->error(path(),
                              "duplicate key (each key may appear once in an object; the JSON parser "
                              "would keep only the last one)");
        }
        break;
      }
      case Event::value: advance(); break;
      case Event::object_end:
      case Event::array_end:
        stack_.pop_back();
        advance();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool is_object;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };

  void advance() {
    if (!stack_.empty() && !stack_.back().is_object) ++stack_.back().index;
  }

  std::string path() const {
    std::string out;
    for (const Frame& frame : stack_) out = frame.is_object ? join_path(out, frame.key) : index_path(out, frame.index);
    return out;
  }

  Diagnostics* diagnostics_;
  std::vector<Frame> stack_;
};

// "JSON syntax error at line 3, column 14: ..." from nlohmann's parse_error (byte offset is 1-based, of the last
// character read).
std::string syntax_error_message(std::string_view text, const nlohmann::json::parse_error& error) {
  const std::size_t end = std::min<std::size_t>(error.byte == 0 ? 0 : error.byte - 1, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  std::string detail = error.what();
  // Drop nlohmann's "[json.exception.parse_error.101] parse error at line L, column C: " prefix.
  if (const auto colon = detail.find(": "); colon != std::string::npos && detail.rfind("[json.exception", 0) == 0) {
    detail = detail.substr(colon + 2);
  }
  return "JSON syntax error at line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + detail;
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) out += (out.empty() ? "" : ", ") + word;
  return out;
}

// analyses.lem.fs_map {"method", "colour_scale_max"}: which method the safety map of the search shows (one of
// those analysed; default Bishop when analysed, else the first) and the top of its colour scale.
// Bishop when it is analysed, else the first method analysed (none when there is none).
std::optional<slope::Method> default_method(const LemAnalysis& result) {
  if (result.methods.empty()) return std::nullopt;
  const bool has_bishop =
      std::find(result.methods.begin(), result.methods.end(), slope::Method::bishop) != result.methods.end();
  return has_bishop ? slope::Method::bishop : result.methods[0];
}

// block.method, which must be one of the methods analysed: into `target` when it is; an error naming the allowed
// ones when it is not.
void read_analysed_method(JsonReader& block, const LemAnalysis& result, std::optional<slope::Method>& target,
                          Diagnostics& diagnostics) {
  const auto key = block.string("method", Need::optional);
  if (!key) return;
  const auto method = slope::method_from_key(*key);
  if (method && std::find(result.methods.begin(), result.methods.end(), *method) != result.methods.end()) {
    target = *method;
    return;
  }
  std::vector<std::string> analysed;
  for (slope::Method m : result.methods) analysed.emplace_back(slope::method_key(m));
  diagnostics.error(block.path_of("method"),
                    "\"" + *key + "\" is not one of the methods analysed (allowed: " + join(analysed) + ")");
}

void read_fs_map(JsonReader& lem, LemAnalysis& result, Diagnostics& diagnostics) {
  result.search.fs_map_method = default_method(result);
  auto map = lem.object("fs_map", Need::optional, "an object: {\"method\": \"bishop\", \"colour_scale_max\": 2.0}");
  if (!map) return;
  read_analysed_method(*map, result, result.search.fs_map_method, diagnostics);
  if (const auto top = map->number("colour_scale_max", Need::optional))
    result.fs_map_scale_max = *top;
  map->finish();
}

// analyses.lem.critical_seismic_coefficient {"method"}: seek k_c with this method's search (one of those analysed;
// default Bishop when analysed, else the first).
// With "acceleration_record", Newmark's displacement at k_c under it.
void read_critical_coefficient(JsonReader& lem, LemAnalysis& result, const std::filesystem::path& scene_file,
                               Diagnostics& diagnostics) {
  auto block = lem.object("critical_seismic_coefficient", Need::optional,
                          "an object (may be empty: {}), e.g. {\"method\": \"spencer\"}");
  if (!block) return;
  result.critical_coefficient_method = default_method(result);
  read_analysed_method(*block, result, result.critical_coefficient_method, diagnostics);
  if (auto record = block->object("acceleration_record", Need::optional,
                                  "an object: {\"file\": \"records/pulse.csv\", \"scale\": 1}"))
    result.acceleration_record = read_acceleration_record(*record, scene_file);
  block->finish();
}

// analyses.lem.<key> of the analyses that take one method (probabilistic, sensitivity, rapid_drawdown): the method
// (one of those analysed; default Bishop when analysed, else the first), the rest by `read` (lem_probabilistic.cpp,
// lem_drawdown.cpp) into `target`.
template <class Analysis, class Reader>
void read_method_block(JsonReader& lem, LemAnalysis& result, const slope::Section* section, Diagnostics& diagnostics,
                       const char* key, const char* expected, std::optional<Analysis>& target, Reader read) {
  auto block = lem.object(key, Need::optional, expected);
  if (!block) return;
  std::optional<slope::Method> method = default_method(result);
  read_analysed_method(*block, result, method, diagnostics);
  if (!method) {
    block->finish();
    return;
  }
  target = read(*block, result, section, *method);
}

void read_method_blocks(JsonReader& lem, LemAnalysis& result, const slope::Section* section,
                        Diagnostics& diagnostics) {
  read_method_block(lem, result, section, diagnostics, "probabilistic",
                    "an object: {\"variables\": [{\"parameter\": \"cohesion_kPa\", \"material\": \"clay\", "
                    "\"std_dev\": 3.6}]}",
                    result.probabilistic, read_probabilistic);
  read_method_block(lem, result, section, diagnostics, "sensitivity",
                    "an object: {\"variables\": [{\"parameter\": \"cohesion_kPa\", \"material\": \"clay\", "
                    "\"min\": 10, \"max\": 26}]}",
                    result.sensitivity, read_sensitivity);
  read_method_block(lem, result, section, diagnostics, "rapid_drawdown",
                    "an object: {\"water_after\": {\"piezometric_line_m\": [[x, y], ...]}, \"materials\": [...]}",
                    result.rapid_drawdown, read_drawdown);
}

void read_lem(JsonReader& analyses, Scene& scene, bool has_section, Diagnostics& diagnostics) {
  auto lem = analyses.object("lem", Need::optional, "an object (may be empty: {})");
  if (!lem) return;
  LemAnalysis result = default_lem_analysis();

  std::vector<std::string> method_keys;
  for (slope::Method method : slope::all_methods()) method_keys.emplace_back(slope::method_key(method));
  if (const nlohmann::json* methods =
          lem->array("methods", Need::optional, 1, limits::name_list, "an array of method names")) {
    result.methods.clear();
    result.methods_given = true;
    for (std::size_t i = 0; i < methods->size(); ++i) {
      const std::string path = index_path(lem->path_of("methods"), i);
      const auto key = read_string((*methods)[i], path, diagnostics);
      if (!key) continue;
      const auto method = slope::method_from_key(*key);
      if (!method) {
        const std::string suggestion = closest_match(*key, method_keys);
        diagnostics.error(path, "unknown method \"" + *key + "\" (" +
                                    (suggestion.empty() ? "" : "did you mean \"" + suggestion + "\"? ") +
                                    "allowed: " + join(method_keys) + ")");
        continue;
      }
      if (std::find(result.methods.begin(), result.methods.end(), *method) != result.methods.end()) {
        diagnostics.error(path, "method \"" + *key + "\" is listed twice (list each method once)");
        continue;
      }
      result.methods.push_back(*method);
    }
  }
  result.search.slicing.slices = static_cast<int>(lem->integer_or("slices", result.search.slicing.slices));
  if (const auto refine = lem->boolean("refine", Need::optional)) result.search.refine = *refine;
  if (auto search = lem->object("search", Need::optional)) {
    result.has_search_limits =
        read_search_limits(*search, scene.section ? &scene.section->section : nullptr, result.search.limits);
    if (const auto depth = read_minimum_depth(*search)) {
      result.search.minimum_depth = *depth;
      result.has_search_limits = true;
    }
    search->finish();
  }
  if (auto noncircular = lem->object("noncircular_search", Need::optional, "an object (may be empty: {})")) {
    result.noncircular = slope::NonCircularOptions{};
    result.noncircular->segments = static_cast<int>(noncircular->integer_or("segments", result.noncircular->segments));
    noncircular->finish();
  }
  read_fs_map(*lem, result, diagnostics);
  read_critical_coefficient(*lem, result, scene.file, diagnostics);
  read_given_surfaces(*lem, scene.section ? &scene.section->section : nullptr, result.search.slicing,
                      result.surfaces);
  read_method_blocks(*lem, result, scene.section ? &scene.section->section : nullptr, diagnostics);
  lem->finish();

  if (!scene.section) {
    // Only a fault of its own when the scene has no section at all (an invalid section is reported already).
    if (!has_section) diagnostics.error(lem->path(), "limit equilibrium needs a \"section\" (this scene has none)");
    return;
  }
  scene.analyses.lem = std::move(result);
}

void read_analyses(JsonReader& top, Scene& scene, bool has_section, SphBlocks& blocks, Diagnostics& diagnostics) {
  auto analyses = top.object("analyses", Need::required, "an object naming the analyses to run: lem, sph, compare");
  if (!analyses) return;
  read_lem(*analyses, scene, has_section, diagnostics);
  if (const nlohmann::json* sph = analyses->raw("sph", Need::optional)) {
    if (!sph->is_object()) {
      diagnostics.error(analyses->path_of("sph"), "expected an object, got " + json_type_name(*sph));
    } else {
      blocks.sph = sph;
      if (scene.section) check_materials_for_sph(top.path_of("section"), *scene.section, diagnostics);
    }
  }
  if (const nlohmann::json* compare = analyses->raw("compare", Need::optional)) {
    if (!compare->is_object()) {
      diagnostics.error(analyses->path_of("compare"), "expected an object, got " + json_type_name(*compare));
    } else {
      blocks.compare = compare;
      if (!analyses->has("lem") || !analyses->has("sph")) {
        diagnostics.error(analyses->path_of("compare"),
                          "comparing surfaces needs both analyses.lem and analyses.sph in the scene");
      }
    }
  }
  if (const nlohmann::json* srm = analyses->raw("srm", Need::optional)) {
    if (!srm->is_object()) {
      diagnostics.error(analyses->path_of("srm"), "expected an object, got " + json_type_name(*srm));
    } else {
      blocks.srm = srm;
    }
  }
  if (auto isph = analyses->object("isph", Need::optional, "an object (docs/scene-format.md, analyses.isph)")) {
    IsphOutputs outputs = read_isph_outputs(*isph);  // before the rest: the reader's finish() sees its keys read
    scene.analyses.isph = read_isph_analysis(*isph);
    check_isph_outputs(outputs, *scene.analyses.isph, isph->path(), diagnostics);
    scene.analyses.isph->outputs = std::move(outputs);
  }
  if (const nlohmann::json* coupled = analyses->raw("coupled", Need::optional)) {
    if (!coupled->is_object())
      diagnostics.error(analyses->path_of("coupled"), "expected an object, got " + json_type_name(*coupled));
    else
      blocks.coupled = coupled;
  }
  if (auto mps = analyses->object("mps", Need::optional, "an object (docs/scene-format.md, analyses.mps)")) {
    scene.analyses.mps = read_mps_analysis(*mps);
    if (analyses->has("isph"))
      diagnostics.error(analyses->path_of("mps"), "a scene runs one flow in a tank, analyses.isph or analyses.mps, "
                                                  "not both (both write monitors.csv)");
  }
  if (!analyses->has("lem") && !analyses->has("sph") && !analyses->has("compare") && !analyses->has("srm") &&
      !analyses->has("isph") && !analyses->has("mps")) {
    diagnostics.error(analyses->path(), "no analysis requested (add at least one of: \"lem\": {}, \"sph\": {...}, "
                                        "\"isph\": {...}, \"mps\": {...})");
  }
  analyses->finish();
}

}  // namespace

void read_srm_scene(const SphBlocks& blocks, Scene& scene, Diagnostics& diagnostics) {
  if (!blocks.srm) return;
  scene.analyses.srm = read_srm_options(*blocks.srm, diagnostics);
  if (!scene.section)
    diagnostics.error("analyses.srm", "strength reduction needs a slope \"section\" (this is a particle scene)");
  if (!blocks.sph)
    diagnostics.error("analyses.srm",
                      "strength reduction needs analyses.sph in the scene for the particle settings "
                      "(particle_spacing_m, ...)");
}

LemAnalysis lem_analysis_of_empty_block() {
  LemAnalysis lem = default_lem_analysis();
  lem.search.fs_map_method = default_method(lem);
  return lem;
}

LemAnalysis default_lem_analysis() {
  LemAnalysis lem;
  lem.methods = slope::all_methods();
  lem.search.slicing.slices = 50;
  lem.search.refine = true;
  return lem;
}

Scene scene_from_json(const nlohmann::json& document, const std::filesystem::path& file) {
  Diagnostics diagnostics;
  Scene scene;
  scene.file = file;

  // First the schema's checks (types, bounds, required keys, names, unknown keys), then the program's own.
  validate_against_schema(document, diagnostics);
  if (diagnostics.size() > max_reported_faults) throw SceneError(diagnostics.messages());  // no room for more
  JsonReader top(document, "", diagnostics);
  if (!top.is_object()) throw SceneError(diagnostics.messages());

  if (const auto format = top.string("format", Need::required)) {
    if (*format != scene_format) {
      diagnostics.error("format",
                        "unsupported format \"" + *format + "\" (allowed: \"" + std::string(scene_format) + "\")");
    }
  }
  scene.name = top.string("name", Need::optional).value_or(file.stem().string());
  scene.source = top.string("source", Need::optional, false).value_or("");
  top.string("$schema", Need::optional);  // where an editor finds the format's schema; not used here
  top.allow("notes");

  const bool has_section = top.has("section");
  const bool has_bodies = top.has("bodies");
  // a flow in a tank: analyses.isph or analyses.mps carries its own tank and material
  const auto analyses_block = document.find("analyses");
  const bool tank_scene = analyses_block != document.end() && analyses_block->is_object() &&
                          (analyses_block->contains("isph") || analyses_block->contains("mps"));
  if (!has_section && !has_bodies && !tank_scene && top.is_object()) {
    diagnostics.error("section",
                      "missing (required: a \"section\" for a slope, \"bodies\" (and \"walls\") for a "
                      "particle scene, or analyses.isph or analyses.mps for a flow in a tank)");
  }
  if (has_section) {
    if (auto section = top.object("section", Need::required)) {
      scene.section = read_section(*section, diagnostics);
      section->finish();
    }
  }
  // Particle scenes: read with analyses.sph below (read_sph_scene), the only analysis that uses them.
  SphBlocks blocks;
  if (const nlohmann::json* bodies = top.raw("bodies", Need::optional)) {
    if (!bodies->is_array()) {
      diagnostics.error("bodies", "expected an array of bodies, got " + json_type_name(*bodies));
    } else {
      blocks.bodies = bodies;
      scene.body_count = bodies->size();
    }
  }
  blocks.walls = top.raw("walls", Need::optional);

  read_analyses(top, scene, has_section, blocks, diagnostics);
  top.finish();
  read_sph_scene(blocks, scene, diagnostics);
  if (blocks.compare)
    scene.analyses.compare = read_comparison_options(*blocks.compare, lem_method_keys(scene), diagnostics);
  read_srm_scene(blocks, scene, diagnostics);
  if (blocks.coupled) read_coupled_scene(*blocks.coupled, blocks.sph, blocks.walls, scene, diagnostics);

  if (!diagnostics.empty()) throw SceneError(diagnostics.messages());
  return scene;
}

Scene parse_scene(std::string_view text, const std::filesystem::path& file) {
  // Before parsing: a deeply nested document would overflow the stack when it is copied or printed.
  if (auto fault = nesting_depth_fault(text)) throw SceneError({std::move(*fault)});
  Diagnostics diagnostics;
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text.begin(), text.end(), DuplicateKeyCheck(diagnostics), true, false);
  } catch (const nlohmann::json::parse_error& error) {
    throw SceneError({syntax_error_message(text, error)});
  } catch (const nlohmann::json::exception& error) {
    // e.g. out_of_range.406 "number overflow parsing '1e400'" (no position is available for these).
    std::string detail = error.what();
    if (const auto bracket = detail.find("] ");
        detail.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) {
      detail = detail.substr(bracket + 2);
    }
    throw SceneError({"invalid JSON: " + detail});
  }
  if (!diagnostics.empty()) {
    // Report duplicates together with whatever else is wrong.
    std::vector<std::string> messages = diagnostics.messages();
    try {
      scene_from_json(document, file);
    } catch (const SceneError& error) {
      messages.insert(messages.end(), error.messages().begin(), error.messages().end());
    }
    throw SceneError(messages);
  }
  return scene_from_json(document, file);
}

namespace {

std::string file_too_large(const std::filesystem::path& file, const std::string& size) {
  return "scene file \"" + file.string() + "\" is too large (" + size + "; at most " +
         std::to_string(max_scene_file_bytes) + " bytes allowed: " + std::string(max_scene_file_reason) + ")";
}

// The whole text of `in`, or nullopt once it exceeds max_scene_file_bytes: a pipe or device of unknown (or endless)
// size is never read further than the limit.
std::optional<std::string> read_at_most_limit(std::istream& in) {
  std::string text;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_scene_file_bytes) return std::nullopt;
  }
  return text;
}

// The text of a scene file, refused when it is larger than max_scene_file_bytes.
std::string read_scene_text(const std::filesystem::path& file) {
  // Regular files are refused by their size, before anything is read.
  std::error_code size_error;
  const std::uintmax_t bytes = std::filesystem::file_size(file, size_error);
  if (!size_error && bytes > max_scene_file_bytes) {
    throw SceneError({file_too_large(file, std::to_string(bytes) + " bytes")});
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError({"cannot read scene file \"" + file.string() + "\" (does it exist and is it readable?)"});
  const std::optional<std::string> text = read_at_most_limit(in);
  if (!text) throw SceneError({file_too_large(file, "more than " + std::to_string(max_scene_file_bytes) + " bytes")});
  if (in.bad()) throw SceneError({"cannot read scene file \"" + file.string() + "\""});
  return *text;
}

}  // namespace

Scene load_scene(const std::filesystem::path& file) { return parse_scene(read_scene_text(file), file); }

Scene scene_with_spacing(const Scene& scene, double spacing) {
  Scene out = scene;
  Diagnostics diagnostics;
  if (out.analyses.mps)
    apply_mps_spacing(*out.analyses.mps, spacing, diagnostics);
  else if (out.analyses.isph)
    apply_isph_spacing(*out.analyses.isph, spacing, diagnostics);
  else if (out.analyses.sph)
    apply_sph_spacing(out, *out.analyses.sph, spacing, diagnostics);
  if (!diagnostics.empty()) throw SceneError(diagnostics.messages());
  return out;
}

std::vector<std::string> lem_method_keys(const Scene& scene) {
  std::vector<std::string> keys;
  if (scene.analyses.lem)
    for (slope::Method method : scene.analyses.lem->methods) keys.emplace_back(slope::method_key(method));
  return keys;
}

namespace {

// "lem (7 methods, 2 given slip surfaces, k_c and Newmark's displacement under pulse.csv (...))" for summarize.
std::string lem_summary(const LemAnalysis& lem) {
  const std::size_t n = lem.methods.size();
  const std::size_t given = lem.surfaces.size();
  std::string record;
  if (const auto& r = lem.acceleration_record)
    record = ", k_c and Newmark's displacement under " + r->file + " (" +
             std::to_string(r->record.acceleration.size()) + " samples every " + format_number(r->record.time_step) +
             " s)";
  else if (lem.critical_coefficient_method)
    record = ", k_c";
  if (const auto& p = lem.probabilistic)
    record += ", a probabilistic analysis (" + std::to_string(p->plan.samples) + " samples of " +
              std::to_string(p->variables.size()) + " variable" + (p->variables.size() == 1 ? "" : "s") + ")";
  return "lem (" + std::to_string(n) + " method" + (n == 1 ? "" : "s") +
         (given > 0 ? ", " + std::to_string(given) + " given slip surface" + (given == 1 ? "" : "s") : std::string()) +
         record + ")";
}

}  // namespace

std::string summarize(const Scene& scene) {
  std::ostringstream out;
  out << '"' << scene.name << "\": ";
  if (scene.section) {
    const slope::Section& s = scene.section->section;
    out << "section x " << format_number(s.x_min()) << " to " << format_number(s.x_max()) << " m, "
        << s.profile_lines.size() << " profile line" << (s.profile_lines.size() == 1 ? "" : "s") << ", "
        << s.materials.size() << " material" << (s.materials.size() == 1 ? "" : "s");
    if (s.water) out << ", water table";
    for (const slope::Material& m : s.materials)
      if (m.pore_pressure_ratio > 0.0) out << ", r_u " << format_number(m.pore_pressure_ratio) << " in " << m.name;
    for (const slope::Material& m : s.materials)
      if (m.cohesion_rate > 0.0)
        out << ", cohesion + " << format_number(m.cohesion_rate / 1e3) << " kPa/m with depth in " << m.name;
    for (const slope::Material& m : s.materials)
      if (m.saturated_unit_weight && s.water)
        out << ", " << format_number(*m.saturated_unit_weight / 1e3) << " kN/m3 below water in " << m.name;
    for (const slope::Material& m : s.materials)
      if (m.envelope) out << ", " << slope::describe_envelope(*m.envelope) << " in " << m.name;
    if (!s.surcharges.empty())
      out << ", " << s.surcharges.size() << " surcharge" << (s.surcharges.size() == 1 ? "" : "s");
    if (!s.line_loads.empty())
      out << ", " << s.line_loads.size() << " line load" << (s.line_loads.size() == 1 ? "" : "s");
    if (s.seismic_coefficient > 0) out << ", seismic kh = " << format_number(s.seismic_coefficient);
    if (s.vertical_seismic_coefficient != 0)
      out << ", kv = " << format_number(std::fabs(s.vertical_seismic_coefficient))
          << (s.vertical_seismic_coefficient > 0 ? " upward" : " downward");
    if (!s.reinforcement.empty()) {
      std::size_t passive = 0;
      for (const slope::Reinforcement& e : s.reinforcement) passive += e.application == slope::SupportApplication::passive;
      out << ", " << s.reinforcement.size() << " reinforcement element" << (s.reinforcement.size() == 1 ? "" : "s")
          << " (" << s.reinforcement.size() - passive << " active, " << passive << " passive)";
    }
  }
  if (scene.analyses.isph) {
    const IsphAnalysis& f = *scene.analyses.isph;
    out << "fluid tank x " << format_number(f.tank.x_min) << " to " << format_number(f.tank.x_max) << " m, "
        << f.water.size() << " water block" << (f.water.size() == 1 ? "" : "s");
    if (!f.solids.empty()) out << ", " << f.solids.size() << " solid" << (f.solids.size() == 1 ? "" : "s");
    if (!f.bodies.empty()) out << ", " << f.bodies.size() << " rigid bod" << (f.bodies.size() == 1 ? "y" : "ies");
    if (f.bed_slope != 0) out << ", bed slope " << format_number(100.0 * f.bed_slope) << " %";
    if (scene.section || scene.body_count) out << "; ";
  }
  if (scene.analyses.mps) {
    const MpsAnalysis& m = *scene.analyses.mps;
    out << "MPS tank x " << format_number(m.tank.x_min) << " to " << format_number(m.tank.x_max) << " m, "
        << m.blocks.size() << " block" << (m.blocks.size() == 1 ? "" : "s") << " of " << m.materials.size()
        << " material" << (m.materials.size() == 1 ? "" : "s");
    if (m.gate_x)
      out << ", a gate at x = " << format_number(*m.gate_x) << " m lifted at "
          << format_number(m.settings.gate_lift_speed) << " m/s";
    if (scene.section || scene.body_count) out << "; ";
  }
  if (scene.body_count) {
    if (scene.section) out << "; ";
    out << *scene.body_count << " particle bod" << (*scene.body_count == 1 ? "y" : "ies");
  }
  std::vector<std::string> analyses;
  if (scene.analyses.lem) analyses.push_back(lem_summary(*scene.analyses.lem));
  if (scene.analyses.sph) analyses.emplace_back("sph");
  if (scene.analyses.compare) analyses.emplace_back("compare");
  if (scene.analyses.srm) analyses.emplace_back("srm");
  if (scene.analyses.isph) analyses.emplace_back("isph");
  if (scene.analyses.mps) analyses.emplace_back("mps");
  if (scene.analyses.coupled) analyses.emplace_back("coupled (sph and isph in one run)");
  out << "; analyses: " << join(analyses);
  return out.str();
}

}  // namespace coupling
