#pragma once
// What one run found, stage by stage, as typed results. The stages (coupling/analyses) fill it; coupling/output alone
// turns it into report.json, report.html, monitors.csv, profiles and figures; the command line prints its tables
// from it. Nothing here is JSON.
#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coupling/analyses/coupled_stage.hpp"
#include "coupling/analyses/isph_stage.hpp"
#include "coupling/analyses/mps_stage.hpp"
#include "coupling/analyses/sph_stage.hpp"
#include "coupling/analyses/strength_reduction.hpp"
#include "coupling/compare/comparison.hpp"
#include "coupling/compare/failure_surface.hpp"
#include "coupling/scene/scene.hpp"
#include "slope/drawdown.hpp"
#include "slope/newmark.hpp"
#include "slope/probabilistic.hpp"
#include "slope/search.hpp"

namespace coupling {

// A slip surface given in the scene (analyses.lem.surfaces), analysed with every method asked for.
struct GivenSurfaceResult {
  std::string name;
  std::vector<slope::CriticalSurface> methods;  // in the order asked for, each with the mass and its forces
};

// The limit-equilibrium stage's result: the settings it ran with (the scene's, or the defaults for "sphslope lem"),
// the critical circle of every method, the given surfaces and, when asked for, the non-circular search.
// Newmark's displacement at k_c under analyses.lem.critical_seismic_coefficient.acceleration_record, the record as
// given and reversed (which way is downslope in a recording is a matter of its orientation).
struct NewmarkOutcome {
  slope::NewmarkResult as_given, reversed;
  std::vector<double> as_given_history, reversed_history;  // m, the displacement at each sample (figures)
  double peak_acceleration = 0.0;  // g, the largest |a| times the scale
};

// Part `index` (from 0) of `parts` of a probabilistic analysis's samples: samples [index N / parts, (index + 1) N /
// parts), rounded down.
struct SamplePart {
  long index = 0;
  long parts = 1;
};

// analyses.lem.probabilistic's result (lem_probabilistic_stage.cpp): the surface, every sample's values and factor of
// safety, and their statistics.
struct ProbabilisticOutcome {
  slope::ProbabilisticSurface surface;
  std::optional<double> deterministic;  // FS at the scene's values (on the surface; overall: the search's least)
  std::vector<double> values;           // SI, sample by sample: values[s * V + v] in the order of the variables
  std::vector<slope::SampleOutcome> samples;
  long first_sample = 0;                // the index of samples[0] (a part of the samples: see `part`)
  std::optional<SamplePart> part;       // this run's part of the samples, when split
  std::vector<std::string> merged_from; // the parts' sample files, when merged
  slope::ProbabilisticStatistics statistics;
  // The Taylor series method (Duncan 2000) beside the samples: FS with each variable at its mean +- one standard
  // deviation (kept in its range), the others at the scene's values; sigma_F^2 = sum (dF_i / 2)^2 with the
  // correlations' cross terms, about the deterministic FS.
  std::vector<std::optional<double>> taylor_change;  // per variable: FS(+sd) - FS(-sd); empty where either failed
  std::optional<double> taylor_std_dev;
  double seconds = 0.0;
  std::string error;  // why it did not run (no critical surface for its method); the rest is then empty
};

// analyses.lem.sensitivity's result: for each variable its values from min to max and the factor of safety at each
// (empty where the method failed), the others at the scene's values.
struct SensitivityOutcome {
  slope::ProbabilisticSurface surface;
  std::optional<double> deterministic;  // FS at the scene's values
  std::vector<std::vector<double>> values;                  // SI, per variable
  std::vector<std::vector<std::optional<double>>> factors;  // per variable, per value
  double seconds = 0.0;
  std::string error;  // why it did not run (no critical surface for its method)
};

// analyses.lem.rapid_drawdown's result on one given surface (its name: LemAnalysis::surfaces).
struct DrawdownSurfaceResult {
  std::string name;
  slope::DrawdownResult result;
};

struct LemStageResult {
  LemAnalysis analysis;
  slope::SearchResult search;
  std::vector<GivenSurfaceResult> surfaces;
  std::optional<slope::NonCircularResult> noncircular;
  std::optional<slope::CriticalCoefficient> critical_coefficient;  // analyses.lem.critical_seismic_coefficient
  std::optional<NewmarkOutcome> newmark;  // with its acceleration_record, when k_c was found
  std::optional<ProbabilisticOutcome> probabilistic;  // analyses.lem.probabilistic
  std::optional<SensitivityOutcome> sensitivity;      // analyses.lem.sensitivity
  std::vector<DrawdownSurfaceResult> rapid_drawdown;  // analyses.lem.rapid_drawdown, one per given surface
};

// One stage of a run: its typed result, or the error that stopped it before it had one.
template <class Result>
struct StageRecord {
  std::optional<Result> result;
  std::string error;  // "<stage>: why", when there is no result
};

struct RunResults {
  std::vector<std::string> analyses;  // the stages asked for, in pipeline order
  std::optional<StageRecord<LemStageResult>> lem;
  std::optional<StageRecord<SphStageResult>> sph;
  std::optional<StageRecord<ComparisonResult>> comparison;
  std::optional<StageRecord<SrmResult>> srm;
  std::optional<StageRecord<IsphStageResult>> isph;
  std::optional<StageRecord<MpsStageResult>> mps;
  std::optional<StageRecord<CoupledStageResult>> coupled;
  // Wall-clock seconds: each stage by its key, "lem_noncircular", and "load" and "total" for the whole run.
  std::map<std::string, double> seconds;
  std::optional<ParticleSnapshot> sph_final_state;  // the soil particles at the end (none after a blow-up)
  std::optional<SphFailure> sph_failure;            // the SPH failure surface, once the comparison read it
  std::vector<std::string> failures;                // why the run failed, one line each (the report's "errors")

  const LemStageResult* lem_result() const { return lem && lem->result ? &*lem->result : nullptr; }
  const SrmResult* srm_result() const { return srm && srm->result ? &*srm->result : nullptr; }
  const ComparisonResult* comparison_result() const {
    return comparison && comparison->result ? &*comparison->result : nullptr;
  }
};

// Slices each surface of analysis.surfaces and solves it with every method of the analysis.
std::vector<GivenSurfaceResult> analyse_given_surfaces(const slope::Section& section, const LemAnalysis& analysis);

// analyses.lem.probabilistic on the search's and the given surfaces' result `lem` (lem_probabilistic_stage.cpp);
// progress on `log` (may be null) every 2 s.
SensitivityOutcome run_sensitivity(const slope::Section& section, const LemStageResult& lem,
                                   const SensitivityAnalysis& analysis);
// With `part`, only that part of the samples; with `merge` (sample files or the run folders holding them), none: the
// samples' results read from them. Throws std::invalid_argument, saying what is wrong, when the parts are not those of
// this analysis or do not hold every sample once.
ProbabilisticOutcome run_probabilistic(const slope::Section& section, const LemStageResult& lem,
                                       const ProbabilisticAnalysis& analysis, std::ostream* log,
                                       const std::optional<SamplePart>& part = {},
                                       const std::vector<std::filesystem::path>& merge = {});

}  // namespace coupling
