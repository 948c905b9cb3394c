// The table of analysis stages, in pipeline order (coupling/analyses/stage.hpp).
#include "coupling/analyses/stage.hpp"

namespace coupling {

namespace {

bool lem_requested(const Scene&, const StageContext& context) { return context.lem.has_value(); }
// A coupled scene runs its sph and isph blocks in the coupled stage, not in their own.
bool sph_requested(const Scene& scene, const StageContext&) {
  return scene.analyses.sph.has_value() && !scene.analyses.coupled;
}
bool compare_requested(const Scene& scene, const StageContext&) { return scene.analyses.compare.has_value(); }
bool srm_requested(const Scene& scene, const StageContext&) { return scene.analyses.srm.has_value(); }
bool isph_requested(const Scene& scene, const StageContext&) {
  return scene.analyses.isph.has_value() && !scene.analyses.coupled;
}
bool coupled_requested(const Scene& scene, const StageContext&) { return scene.analyses.coupled.has_value(); }
bool mps_requested(const Scene& scene, const StageContext&) { return scene.analyses.mps.has_value(); }

constexpr Stage stages[] = {
    {"lem", lem_requested, run_lem_stage},
    {"sph", sph_requested, run_sph_analysis_stage},
    {"compare", compare_requested, run_compare_stage},
    {"srm", srm_requested, run_srm_stage},
    {"isph", isph_requested, run_isph_stage},
    {"mps", mps_requested, run_mps_stage},
    {"coupled", coupled_requested, run_coupled_stage},
};

}  // namespace

std::span<const Stage> pipeline_stages() { return stages; }

}  // namespace coupling
