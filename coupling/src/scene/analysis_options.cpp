// analyses.compare and analyses.srm read into their typed settings (the scene loader calls these once).
#include "coupling/scene/analysis_options.hpp"

#include <algorithm>

namespace coupling {

namespace {

// A length criterion is given in metres ("<name>_max_m") or in particle spacings ("<name>_max_spacings"), not both.
std::optional<LengthLimit> read_length_limit(JsonReader& r, const std::string& name) {
  const auto metres = r.number(name + "_max_m", Need::optional);
  const auto spacings = r.number(name + "_max_spacings", Need::optional);
  if (metres && spacings) {
    r.diagnostics().error(r.path_of(name + "_max_spacings"),
                          "give the limit either in metres (" + name + "_max_m) or in particle spacings, not both");
    return std::nullopt;
  }
  if (metres) return LengthLimit{*metres, false};
  if (spacings) return LengthLimit{*spacings, true};
  return std::nullopt;
}

std::vector<std::string> read_methods(JsonReader& r, const std::vector<std::string>& known) {
  std::vector<std::string> methods;
  const nlohmann::json* list = r.array("methods", Need::optional, 1, limits::name_list);
  if (list == nullptr) {
    const bool has_bishop = std::find(known.begin(), known.end(), "bishop") != known.end();
    if (has_bishop) methods.push_back("bishop");
    else if (!known.empty()) methods.push_back(known.front());
    return methods;
  }
  std::string allowed;
  for (const auto& k : known) allowed += (allowed.empty() ? "" : ", ") + k;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string path = index_path(r.path_of("methods"), i);
    const auto key = read_string((*list)[i], path, r.diagnostics());
    if (!key) continue;
    if (std::find(known.begin(), known.end(), *key) == known.end())
      r.diagnostics().error(path, "method \"" + *key + "\" is not computed by analyses.lem (computed: " + allowed + ")");
    else
      methods.push_back(*key);
  }
  return methods;
}

}  // namespace

std::optional<AcceptanceCriteria> read_acceptance(const nlohmann::json& block, const std::vector<std::string>& known_methods,
                                                  Diagnostics& diagnostics) {
  JsonReader r(block, "analyses.compare.acceptance", diagnostics);
  const std::size_t errors_before = diagnostics.size();
  AcceptanceCriteria c;
  c.methods = read_methods(r, known_methods);
  c.entry_offset = read_length_limit(r, "entry_offset");
  c.exit_offset = read_length_limit(r, "exit_offset");
  c.mean_normal_distance = read_length_limit(r, "mean_normal_distance");
  c.max_normal_distance = read_length_limit(r, "max_normal_distance");
  c.min_overlap = r.number("overlap_min", Need::optional);
  c.max_fs_difference = r.number("fs_difference_max", Need::optional);
  r.finish();
  const bool any = c.entry_offset || c.exit_offset || c.mean_normal_distance || c.max_normal_distance ||
                   c.min_overlap || c.max_fs_difference;
  if (!any && diagnostics.size() == errors_before)
    diagnostics.error("analyses.compare.acceptance",
                      "no criterion given (allowed: entry_offset_max_m, exit_offset_max_m, mean_normal_distance_max_m, "
                      "max_normal_distance_max_m (each also as _max_spacings), overlap_min, fs_difference_max)");
  if (diagnostics.size() != errors_before) return std::nullopt;
  return c;
}

std::optional<ComparisonOptions> read_comparison_options(const nlohmann::json& block,
                                                         const std::vector<std::string>& lem_methods,
                                                         Diagnostics& diagnostics) {
  JsonReader r(block, "analyses.compare", diagnostics);
  const std::size_t errors_before = diagnostics.size();
  ComparisonOptions options;
  options.band.plastic_strain_threshold =
      r.number_or("plastic_strain_threshold", options.band.plastic_strain_threshold);
  options.band.bin_width = r.number_or("bin_width_m", 0.0);
  read_named(r, "configuration", band_configuration_names, options.band.initial_configuration);
  options.displacement_threshold = r.number_or("displacement_threshold_m", 0.0);
  if (const nlohmann::json* acceptance = r.raw("acceptance", Need::optional, "an object"))
    options.acceptance = read_acceptance(*acceptance, lem_methods, diagnostics);
  r.finish();
  if (diagnostics.size() != errors_before) return std::nullopt;
  return options;
}

std::optional<SrmOptions> read_srm_options(const nlohmann::json& block, Diagnostics& diagnostics) {
  JsonReader r(block, "analyses.srm", diagnostics);
  const std::size_t errors_before = diagnostics.size();
  SrmOptions o;
  o.tolerance = r.number_or("tolerance", o.tolerance);
  if (const nlohmann::json* bracket = r.raw("bracket", Need::optional)) {
    const std::string path = r.path_of("bracket");
    if (auto pair = read_pair(*bracket, path, diagnostics, "[lo, hi]")) {
      if (!(pair->first >= srm_min_factor && pair->second > pair->first && pair->second <= srm_max_factor))
        diagnostics.error(path, "must be [lo, hi] with " + format_number(srm_min_factor) + " <= lo < hi <= " +
                                    format_number(srm_max_factor) + " (got [" + format_number(pair->first) + ", " +
                                    format_number(pair->second) + "])");
      else
        o.bracket = *pair;
    }
  }
  o.failure_displacement_m = r.number("failure_displacement_m", Need::optional);
  o.max_time_s = r.number("max_time_s", Need::optional);
  o.damping_per_s = r.number("damping_per_s", Need::optional);
  o.rest_speed_m_s = r.number("rest_speed_m_s", Need::optional);
  o.max_trials = static_cast<int>(r.integer_or("max_trials", o.max_trials));
  r.finish();
  if (diagnostics.size() != errors_before) return std::nullopt;
  return o;
}

}  // namespace coupling
