#pragma once
// analyses.lem.probabilistic: the probabilistic analysis (slope/probabilistic.hpp) as the scene asks for it, in SI,
// with the scene's names of its variables for the report. Keys, units and defaults: docs/scene-format.md.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "slope/methods.hpp"
#include "slope/probabilistic.hpp"
#include "sphslope/names.hpp"

namespace coupling {

// The surface each sample is analysed on: the method's critical circle from the deterministic search, a given
// surface (analyses.lem.surfaces), or each sample's own critical circle (a search per sample).
enum class ProbabilisticMode { critical_surface, given_surface, overall };
inline constexpr sphslope::NameTable<ProbabilisticMode, 3> probabilistic_mode_names{{
    {"critical_surface", ProbabilisticMode::critical_surface},
    {"given_surface", ProbabilisticMode::given_surface},
    {"overall", ProbabilisticMode::overall},
}};

inline constexpr sphslope::NameTable<slope::Distribution, 4> distribution_names{{
    {"normal", slope::Distribution::normal},
    {"lognormal", slope::Distribution::lognormal},
    {"uniform", slope::Distribution::uniform},
    {"triangular", slope::Distribution::triangular},
}};

inline constexpr sphslope::NameTable<slope::Sampling, 2> sampling_names{{
    {"monte_carlo", slope::Sampling::monte_carlo},
    {"latin_hypercube", slope::Sampling::latin_hypercube},
}};

// The parameters a variable may set, by their scene names (the units in the name).
enum class RandomParameter {
  cohesion, friction_angle, tan_friction_angle, unit_weight, saturated_unit_weight, cohesion_increase,
  pore_pressure_ratio, horizontal_seismic_coefficient, water_level, surcharge
};
inline constexpr sphslope::NameTable<RandomParameter, 10> random_parameter_names{{
    {"cohesion_kPa", RandomParameter::cohesion},
    {"friction_angle_deg", RandomParameter::friction_angle},
    {"tan_friction_angle", RandomParameter::tan_friction_angle},
    {"unit_weight_kN_m3", RandomParameter::unit_weight},
    {"saturated_unit_weight_kN_m3", RandomParameter::saturated_unit_weight},
    {"cohesion_increase_kPa_per_m", RandomParameter::cohesion_increase},
    {"pore_pressure_ratio", RandomParameter::pore_pressure_ratio},
    {"horizontal_seismic_coefficient", RandomParameter::horizontal_seismic_coefficient},
    {"water_level_m", RandomParameter::water_level},
    {"surcharge_kPa", RandomParameter::surcharge},
}};

// One variable as the scene names it, beside its SI form in ProbabilisticAnalysis::plan.variables.
struct ProbabilisticVariableInput {
  RandomParameter parameter = RandomParameter::cohesion;
  std::string material;                  // its material's name; empty for a parameter of the section
  std::optional<std::size_t> surcharge;  // surcharge_kPa: the index into section.surcharges
  double scene_unit = 1.0;               // one unit of the scene's (kPa, deg, ...) in SI (Pa, rad, ...)
  // The physical range the samples are kept in (in SI; the user's min and max may narrow it, not widen it).
  std::optional<double> lowest, highest;
};

// The c'-phi' correlation of one material, by the scene's name.
struct ProbabilisticCorrelationInput {
  std::string material;
};

struct ProbabilisticAnalysis {
  slope::Method method = slope::Method::bishop;  // default Bishop when analysed, else the first method analysed
  ProbabilisticMode mode = ProbabilisticMode::critical_surface;
  std::optional<std::size_t> surface;            // given_surface: index into LemAnalysis::surfaces
  slope::SamplingPlan plan;                      // SI
  std::vector<ProbabilisticVariableInput> variables;       // beside plan.variables
  std::vector<ProbabilisticCorrelationInput> correlations;  // beside plan.correlations
};

// analyses.lem.sensitivity: one variable at a time over its range, the others at the scene's values.
struct SensitivityAnalysis {
  slope::Method method = slope::Method::bishop;
  ProbabilisticMode mode = ProbabilisticMode::critical_surface;
  std::optional<std::size_t> surface;  // given_surface: index into LemAnalysis::surfaces
  int points = 11;                     // values of each variable, evenly from min to max
  // SI; each uniform on [min, max] (the range swept), its mean the scene's value
  std::vector<slope::RandomVariable> variables;
  std::vector<ProbabilisticVariableInput> inputs;  // beside `variables`
};

// "soil cohesion_kPa", "horizontal_seismic_coefficient", "surcharges[1] surcharge_kPa": a variable's name in reports.
std::string variable_label(const ProbabilisticVariableInput& variable);

}  // namespace coupling
