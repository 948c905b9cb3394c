#pragma once
// What a probabilistic analysis (analyses.lem.probabilistic) writes: report.json's lem.probabilistic block, the
// samples file, the terminal line, and the figures of the factors of safety.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/run_results.hpp"
#include "coupling/compare/comparison.hpp"

namespace coupling {

inline constexpr const char* probabilistic_samples_file = "probabilistic_samples.csv";

// lem.probabilistic: the settings, the variables (scene units) with the mean and standard deviation of their samples,
// the deterministic and the sampled statistics of the factor of safety, their convergence with the samples; with the
// SPH strength reduction of the same scene (`srm`, at the scene's values: the means), its FS_SPH beside them.
nlohmann::json probabilistic_report(const ProbabilisticAnalysis& analysis, const ProbabilisticOutcome& outcome,
                                    const std::vector<GivenSurface>& surfaces, const SrmResult* srm = nullptr);
// lem.probabilistic.sph_strength_reduction: FS_SPH and its bracket, and the share of the LE samples below it.
nlohmann::json sph_beside_probabilistic(const SrmResult& srm, const ProbabilisticOutcome& outcome);

// probabilistic_samples.csv: one line per sample, its values in the scene's units and its factor of safety (empty
// when the method failed); overall mode adds the sample's critical circle.
std::string probabilistic_samples_csv(const ProbabilisticAnalysis& analysis, const ProbabilisticOutcome& outcome);

// "probabilistic (bishop, critical surface, 10000 Monte Carlo samples): mean FS 1.336, sd 0.150, P(FS < 1) 1.2 %,
// beta 2.24 (lognormal 2.40)" for the terminal.
std::string probabilistic_line(const ProbabilisticAnalysis& analysis, const ProbabilisticOutcome& outcome);

// figures/probabilistic_histogram.svg (the share of the samples in each band of FS) and probabilistic_cdf.svg (the
// share below each FS), with FS = 1, the deterministic FS and the mean marked.
std::string probabilistic_histogram_svg(const ProbabilisticOutcome& outcome, const std::string& title);
std::string probabilistic_cdf_svg(const ProbabilisticOutcome& outcome, const std::string& title);

// lem.sensitivity: the settings and, per variable, its values (the scene's units) and the factor of safety at each.
nlohmann::json sensitivity_report(const SensitivityAnalysis& analysis, const SensitivityOutcome& outcome,
                                  const std::vector<GivenSurface>& surfaces);
// The sensitivity analysis for the terminal: one line per variable with its range and the factors over it.
std::string sensitivity_table(const SensitivityAnalysis& analysis, const SensitivityOutcome& outcome);
// figures/sensitivity.svg: the spider plot, FS against each variable's place in its range (%), the scene's values
// marked.
std::string sensitivity_svg(const SensitivityAnalysis& analysis, const SensitivityOutcome& outcome,
                            const std::string& title);

// Overall mode: the critical circles of the first `count` samples that have one, for the section figure.
std::vector<Polyline> sample_surface_lines(const slope::Section& section, const ProbabilisticOutcome& outcome,
                                           const slope::SliceOptions& slicing, std::size_t count = 100);

}  // namespace coupling
