#pragma once
// The journal of a strength-reduction run (DIR/srm_trials.json) and the checkpoint of its trial in progress
// (DIR/srm_trial_checkpoint.bin): what `sphslope run --resume` needs to continue an interrupted strength reduction
// with the same result. The bisection is deterministic, so a resumed run asks for the same factors in the same
// order: finished trials are answered from the journal, the interrupted one continues from its checkpoint.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/strength_reduction.hpp"

namespace coupling {

class SrmJournal {
 public:
  // `fingerprint`: everything the trials depend on (spacing, particles, plan, bracket, tolerance, strengths). With
  // `resume`, an existing journal is read and must carry the same fingerprint (SceneError otherwise); without it,
  // the run starts afresh and any earlier journal and trial checkpoint are removed.
  SrmJournal(const std::filesystem::path& dir, nlohmann::json fingerprint, bool resume);

  // The finished trial at this factor, when the journal holds one.
  std::optional<SrmTrial> finished(double factor) const;
  // True when the interrupted trial was at this factor and left a checkpoint to continue from.
  bool can_continue(double factor) const;
  const std::filesystem::path& checkpoint() const { return checkpoint_; }
  std::size_t finished_count() const { return trials_.size(); }

  void start(double factor);           // marks the trial in progress (written at once)
  void finish(const SrmTrial& trial);  // records it, forgets its checkpoint

 private:
  void write() const;

  std::filesystem::path file_, checkpoint_;
  nlohmann::json fingerprint_;
  std::vector<SrmTrial> trials_;
  std::optional<double> in_progress_;
};

}  // namespace coupling
