#include "coupling/scene/json_text.hpp"

#include <cmath>

namespace coupling {

namespace {

constexpr std::size_t paths_in_message = 10;

// Visits every non-finite number of `value` with its path; `Json` is const or not (to read or to replace).
template <class Json, class Visit>
void visit_non_finite(Json& value, const std::string& path, const Visit& visit) {
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it)
      visit_non_finite(it.value(), path.empty() ? it.key() : path + "." + it.key(), visit);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      visit_non_finite(value[i], path + "[" + std::to_string(i) + "]", visit);
  } else if (value.is_number_float() && !std::isfinite(value.template get<double>())) {
    visit(value, path.empty() ? std::string("(the top level)") : path);
  }
}

std::string message(const std::vector<std::string>& paths) {
  std::string text = "a number that is not finite (NaN or infinity) at ";
  for (std::size_t i = 0; i < paths.size() && i < paths_in_message; ++i) text += (i > 0 ? ", " : "") + paths[i];
  if (paths.size() > paths_in_message)
    text += " and " + std::to_string(paths.size() - paths_in_message) + " more";
  return text + " (JSON has no such number; a defect of the program: please report it with the scene)";
}

}  // namespace

std::vector<std::string> non_finite_paths(const nlohmann::json& value) {
  std::vector<std::string> found;
  visit_non_finite(value, "", [&](const nlohmann::json&, const std::string& path) { found.push_back(path); });
  return found;
}

std::vector<std::string> null_non_finite_numbers(nlohmann::json& value) {
  std::vector<std::string> found;
  visit_non_finite(value, "", [&](nlohmann::json& number, const std::string& path) {
    number = nullptr;
    found.push_back(path);
  });
  return found;
}

NonFiniteNumber::NonFiniteNumber(std::vector<std::string> paths)
    : std::runtime_error(message(paths)), paths_(std::move(paths)) {}

std::string json_text(const nlohmann::json& value, int indent) {
  std::vector<std::string> bad = non_finite_paths(value);
  if (!bad.empty()) throw NonFiniteNumber(std::move(bad));
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace coupling
