// The strength-reduction journal (srm_journal.hpp).
#include "srm_journal.hpp"

#include <fstream>

#include "sph/engine/atomic_file.hpp"
#include "coupling/scene/json_text.hpp"

namespace coupling {

namespace {

constexpr const char* kFormat = "sphslope-srm-journal/1";

nlohmann::json trial_json(const SrmTrial& t) {
  return {{"factor", t.factor},
          {"failed", t.failed},
          {"max_displacement_m", t.max_displacement_m},
          {"simulated_time_s", t.simulated_time_s},
          {"wall_seconds", t.wall_seconds},
          {"stopped_because", t.stopped_because},
          {"reason", t.reason}};
}

SrmTrial trial_from(const nlohmann::json& j) {
  SrmTrial t;
  t.factor = j.at("factor").get<double>();
  t.failed = j.at("failed").get<bool>();
  t.max_displacement_m = j.at("max_displacement_m").get<double>();
  t.simulated_time_s = j.at("simulated_time_s").get<double>();
  t.wall_seconds = j.at("wall_seconds").get<double>();
  t.stopped_because = j.at("stopped_because").get<std::string>();
  t.reason = j.at("reason").get<std::string>();
  return t;
}

// The fingerprint as it reads back from the file (doubles round-trip through their shortest decimal form).
nlohmann::json normalised(const nlohmann::json& j) { return nlohmann::json::parse(j.dump()); }

}  // namespace

SrmJournal::SrmJournal(const std::filesystem::path& dir, nlohmann::json fingerprint, bool resume)
    : file_(dir / "srm_trials.json"), checkpoint_(dir / "srm_trial_checkpoint.bin"),
      fingerprint_(normalised(fingerprint)) {
  std::filesystem::create_directories(dir);
  if (!resume || !std::filesystem::exists(file_)) {
    std::filesystem::remove(checkpoint_);
    write();
    return;
  }
  nlohmann::json journal;
  try {
    std::ifstream in(file_);
    journal = nlohmann::json::parse(in);
    if (journal.value("format", "") != kFormat) throw std::runtime_error("not a " + std::string(kFormat) + " file");
    for (const nlohmann::json& t : journal.at("trials")) trials_.push_back(trial_from(t));
  } catch (const std::exception& error) {
    throw SceneError({"--resume: " + file_.string() + " cannot be read (" + error.what() +
                      "); start the strength reduction again without --resume"});
  }
  if (journal["fingerprint"] != fingerprint_)
    throw SceneError({"--resume: " + file_.string() +
                      " was written for other strength-reduction settings (spacing, particles, trial plan, bracket, "
                      "tolerance or strengths differ); start again without --resume"});
  if (journal["in_progress_factor"].is_number()) in_progress_ = journal["in_progress_factor"].get<double>();
}

std::optional<SrmTrial> SrmJournal::finished(double factor) const {
  for (const SrmTrial& t : trials_)
    if (t.factor == factor) return t;
  return std::nullopt;
}

bool SrmJournal::can_continue(double factor) const {
  return in_progress_ && *in_progress_ == factor && std::filesystem::exists(checkpoint_);
}

void SrmJournal::start(double factor) {
  if (!(in_progress_ && *in_progress_ == factor)) std::filesystem::remove(checkpoint_);
  in_progress_ = factor;
  write();
}

void SrmJournal::finish(const SrmTrial& trial) {
  // The checkpoint goes first: a journal that lists the trial never sits beside that trial's checkpoint (killed in
  // between, the trial is run again from the start, to the same result).
  std::filesystem::remove(checkpoint_);
  trials_.push_back(trial);
  in_progress_.reset();
  write();
}

void SrmJournal::write() const {
  nlohmann::json trials = nlohmann::json::array();
  for (const SrmTrial& t : trials_) trials.push_back(trial_json(t));
  const nlohmann::json journal = {{"format", kFormat},
                                  {"fingerprint", fingerprint_},
                                  {"trials", std::move(trials)},
                                  {"in_progress_factor", in_progress_ ? nlohmann::json(*in_progress_) : nullptr}};
  sph::write_file_atomically(file_, json_text(journal, 1));
}

}  // namespace coupling
