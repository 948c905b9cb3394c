#include "coupling/analyses/strength_reduction.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <stdexcept>

#include "coupling/analyses/sph_model.hpp"
#include "coupling/analyses/sph_stage.hpp"
#include "sph/soil/checkpoint.hpp"
#include "sph/soil/run.hpp"
#include "srm_journal.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

constexpr double min_factor = srm_min_factor, max_factor = srm_max_factor, expansion = 1.5;

double reduce_angle_deg(double angle_deg, double factor) {
  // angle_deg * pi / 180, not radians(angle_deg): this order of operations gives the pinned trials.
  return sphslope::degrees(std::atan(std::tan(angle_deg * sphslope::pi / 180.0) / factor));
}

// Slope height: highest minus lowest point of the ground line.
double slope_height(const slope::Section& section) {
  const auto& ground = section.profile_lines.front().points;
  double lo = ground.front().y, hi = ground.front().y;
  for (const auto& p : ground) {
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  return hi - lo;
}

// Slowest shear-wave speed of the section's materials [m/s].
double slowest_shear_wave(const SceneSection& section) {
  double slowest = std::numeric_limits<double>::infinity();
  for (const auto& m : section.materials) {
    const double g = m.youngs_modulus.value_or(0.0) / (2.0 * (1.0 + m.poisson_ratio.value_or(0.0)));
    slowest = std::min(slowest, std::sqrt(g / m.density()));
  }
  return slowest;
}

}  // namespace

BisectionResult bisect_factor(const std::function<SrmTrial(double)>& oracle, double lo, double hi, double tolerance,
                              int max_trials) {
  BisectionResult r;
  auto failed_at = [&](double factor) {
    SrmTrial trial = oracle(factor);
    trial.factor = factor;
    r.trials.push_back(trial);
    return trial.failed;
  };
  auto out_of_trials = [&] {
    if (static_cast<int>(r.trials.size()) < max_trials) return false;
    r.error = "no bracket after " + std::to_string(r.trials.size()) + " trials (analyses.srm.max_trials)";
    return true;
  };
  // The lower bound must be stable; when it fails it becomes the upper bound and the search moves down.
  bool hi_known_to_fail = false;
  for (;;) {
    if (out_of_trials()) return r;
    if (!failed_at(lo)) break;
    hi = lo;
    hi_known_to_fail = true;
    lo /= expansion;
    if (lo < min_factor) {
      r.error = "the slope fails even with the strength reduced by " + format_number(hi) + " (F >= " +
                format_number(hi) + ")";
      return r;
    }
  }
  // The upper bound must fail; when it is stable it becomes the lower bound and the search moves up.
  while (!hi_known_to_fail) {
    if (out_of_trials()) return r;
    if (failed_at(hi)) break;
    lo = hi;
    hi *= expansion;
    if (hi > max_factor) {
      r.error = "the slope is still stable with the strength divided by " + format_number(lo);
      r.lo = lo;
      return r;
    }
  }
  r.bracketed = true;
  while (hi - lo > tolerance * (1.0 + 1e-12)) {
    if (static_cast<int>(r.trials.size()) >= max_trials) {
      r.error = "stopped after " + std::to_string(r.trials.size()) + " trials (analyses.srm.max_trials) with bracket "
                "wider than the tolerance";
      break;
    }
    const double mid = 0.5 * (lo + hi);
    if (failed_at(mid)) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  r.lo = lo;
  r.hi = hi;
  r.factor_of_safety = 0.5 * (lo + hi);
  return r;
}

namespace {

// The per-scene values of the trials: the defaults of analyses.srm resolved from the slope's height and its first
// shear mode.
SrmPlan plan_trials(const SceneSection& scene_section, const SrmOptions& options) {
  SrmPlan plan;
  plan.height = slope_height(scene_section.section);
  const double vs = slowest_shear_wave(scene_section);
  plan.period = 4.0 * plan.height / vs;  // first shear mode of a layer of the slope height
  const double omega = 2.0 * sphslope::pi / plan.period;

  plan.damping = options.damping_per_s.value_or(omega);
  plan.max_time = options.max_time_s.value_or(std::max(2.0, 40.0 * plan.period));
  plan.failure_displacement = options.failure_displacement_m.value_or(0.05 * plan.height);
  plan.rest_speed = options.rest_speed_m_s.value_or(1.0e-3 * std::sqrt(standard_gravity * plan.height));
  // Not before the damped motion has had time to start: 5 damping time constants or 5 periods, whichever is
  // longer, but at most half the trial.
  plan.min_time =
      std::min(0.5 * plan.max_time, std::max(5.0 * plan.period, plan.damping > 0 ? 5.0 / plan.damping : 0.0));
  return plan;
}

double max_soil_displacement(const sph::ParticleSet& p) {
  double worst = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != static_cast<std::uint8_t>(sph::ParticleKind::material)) continue;
    worst = std::max(worst, std::hypot(p.x[i] - p.x0[i], p.y[i] - p.y0[i]));
  }
  return worst;
}

// The failure test of a trial, as an observer of the run: stops it once any soil particle has moved more than the
// limit from where it started. Checked after every tenth step (steps 9, 19, 29, ... of the run's own count, so a
// resumed trial checks at the same steps): the maximum over the soil particles costs as much as a tenth of a step,
// and a slope that has failed keeps moving.
class DisplacementLimit : public sph::Observer {
 public:
  explicit DisplacementLimit(double limit_m) : limit_m_(limit_m) {}

  std::string after_step(const sph::ParticleSet& particles, const sph::RunState& state, const sph::Energies&) override {
    if (state.step % 10 != 9) return {};
    exceeded_ = max_soil_displacement(particles) > limit_m_;
    return exceeded_ ? "displacement_limit" : std::string();
  }
  bool exceeded() const { return exceeded_; }

 private:
  double limit_m_;
  bool exceeded_ = false;
};

// Why a finished trial counts as failed or stable.
void judge_trial(const sph::RunSummary& summary, bool displaced, double failure_displacement, SrmTrial& trial) {
  if (displaced || trial.max_displacement_m > failure_displacement) {
    trial.failed = true;
    trial.reason = "maximum displacement above " + format_number(failure_displacement) + " m";
  } else if (summary.stopped_because == "quasi_static") {
    trial.failed = false;
    trial.reason = "came to rest";
  } else if (summary.stopped_because == "end_time") {
    trial.failed = true;
    trial.reason = "still moving at the end of the trial (max speed above the rest speed)";
  } else {
    trial.failed = true;
    trial.reason = "run stopped: " + summary.stopped_because + (summary.diagnostic.empty() ? "" : " (" + summary.diagnostic + ")");
  }
}

void log_trial(const SrmTrial& trial, double factor, std::ostream* log) {
  if (!log) return;
  char line[256];
  std::snprintf(line, sizeof line, "srm: F = %.4f: %s, max displacement %.3g m, t = %.3g s (%s), %.1f s wall\n",
                factor, trial.failed ? "FAILS" : "stable", trial.max_displacement_m, trial.simulated_time_s,
                trial.stopped_because.c_str(), trial.wall_seconds);
  *log << line << std::flush;
}

// The failure oracle of the bisection: one damped SPH run of the slope with every strength divided by F.
class TrialRunner {
 public:
  TrialRunner(const sph::soil::Model& pristine, const SrmPlan& plan, std::ostream* log, SrmJournal* journal)
      : pristine_(pristine), plan_(plan), log_(log), journal_(journal) {
    for (const auto& m : pristine.materials) {
      cohesion_.push_back(m.cohesion);
      friction_.push_back(m.friction_angle_deg);
      dilatancy_.push_back(m.dilatancy_angle_deg);
    }
  }

  SrmTrial operator()(double factor) const {
    if (journal_)
      if (std::optional<SrmTrial> done = journal_->finished(factor)) {
        if (log_) *log_ << "srm: F = " << format_number(factor) << ": from " << "srm_trials.json (finished before)\n";
        return *done;
      }
    sph::soil::Model model = reduced_model(factor);
    if (journal_) {
      if (journal_->can_continue(factor)) {
        sph::soil::read_checkpoint(journal_->checkpoint().string(), model);
        if (log_)
          *log_ << "srm: F = " << format_number(factor) << ": continuing at t = " << model.state.time << " s\n";
      }
      journal_->start(factor);
    }
    bool interrupted = false;
    DisplacementLimit displacement(plan_.failure_displacement);
    sph::RunCallbacks callbacks;
    callbacks.interrupt = [&] { return interrupted = interrupt_pending(); };
    callbacks.observers.push_back(&displacement);
    const sph::RunSummary summary = sph::soil::run(model, run_options(), callbacks);
    if (interrupted)
      throw std::runtime_error("interrupted during the trial at F = " + format_number(factor) +
                               (journal_ ? "; its state is saved: continue with --resume (same scene, same -o DIR)"
                                         : " (without an output folder nothing is saved; run it again)"));
    const bool displaced = displacement.exceeded();
    SrmTrial trial;
    trial.factor = factor;
    trial.max_displacement_m = max_soil_displacement(model.particles);
    trial.simulated_time_s = summary.simulated_time;
    trial.wall_seconds = summary.wall_seconds;
    trial.stopped_because = displaced ? "displacement_limit" : summary.stopped_because;
    judge_trial(summary, displaced, plan_.failure_displacement, trial);
    if (journal_) journal_->finish(trial);
    log_trial(trial, factor, log_);
    return trial;
  }

 private:
  sph::soil::Model reduced_model(double factor) const {
    sph::soil::Model model = pristine_;
    for (std::size_t k = 0; k < model.materials.size(); ++k) {
      model.materials[k].cohesion = cohesion_[k] / factor;
      model.materials[k].friction_angle_deg = reduce_angle_deg(friction_[k], factor);
      model.materials[k].dilatancy_angle_deg = reduce_angle_deg(dilatancy_[k], factor);
    }
    return model;
  }

  sph::RunOptions run_options() const {
    sph::RunOptions options;
    options.quasi_static_speed = plan_.rest_speed;
    options.quasi_static_min_time = plan_.min_time;
    if (journal_) options.checkpoint_path = journal_->checkpoint().string();
    options.checkpoint_on_stop = journal_ != nullptr;
    options.progress_interval_wall_s = 1e9;
    return options;
  }

  const sph::soil::Model& pristine_;
  const SrmPlan& plan_;
  std::ostream* log_;
  SrmJournal* journal_;  // null: no output folder
  std::vector<double> cohesion_, friction_, dilatancy_;
};

// The user's bracket, else [0.8, 1.25] x the LEM Bishop FS, else [0.5, 3].
SrmBracket initial_bracket(const SrmOptions& options, std::optional<double> lem_bishop_fs) {
  SrmBracket bracket;
  if (options.bracket) {
    bracket.lo = options.bracket->first;
    bracket.hi = options.bracket->second;
    bracket.source = "analyses.srm.bracket";
  } else if (lem_bishop_fs && std::isfinite(*lem_bishop_fs) && *lem_bishop_fs > 0) {
    bracket.lo = std::max(min_factor, 0.8 * *lem_bishop_fs);
    bracket.hi = std::min(max_factor, 1.25 * *lem_bishop_fs);
    bracket.source = "[0.8, 1.25] x LEM Bishop FS";
  }
  return bracket;
}

// What the trials depend on: a journal written for other values cannot be resumed.
nlohmann::json journal_fingerprint(const sph::soil::Model& pristine, const SrmPlan& plan, const SrmBracket& bracket,
                                   const SrmOptions& options) {
  nlohmann::json strengths = nlohmann::json::array();
  for (const auto& m : pristine.materials)
    strengths.push_back({m.cohesion, m.friction_angle_deg, m.dilatancy_angle_deg});
  return {{"particle_spacing_m", pristine.settings.particle_spacing},
          {"particles", pristine.particles.size()},
          {"plan", {plan.damping, plan.max_time, plan.failure_displacement, plan.rest_speed, plan.min_time}},
          {"bracket", {bracket.lo, bracket.hi}},
          {"tolerance", options.tolerance},
          {"max_trials", options.max_trials},
          {"strengths", std::move(strengths)}};
}

// What SPH leaves out of the section (loads listed in analyses.sph.ignore_loads, a material's r_u).
std::vector<std::string> left_out_load_warnings(const Scene& scene) {
  std::vector<std::string> warnings;
  for (const SectionLoad& load : loads_sph_leaves_out(scene))
    warnings.push_back(load.path + " is not carried by the SPH model (" + load.why + "): FS_SPH is for "
                       "the slope without " + load.name + ", the limit-equilibrium factors of safety are with it");
  return warnings;
}

}  // namespace

SrmResult run_strength_reduction(const Scene& scene, const SrmOptions& options, std::optional<double> lem_bishop_fs,
                                 const std::map<std::string, double>& lem_fs_by_method, std::ostream* log,
                                 const SrmFiles& files) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  if (!scene.section || !scene.analyses.sph) throw SceneError({"analyses.srm: needs a slope section and analyses.sph"});

  SphSize size;
  sph::soil::Model pristine = build_sph_model(scene, &size);
  const SrmPlan plan = plan_trials(*scene.section, options);
  pristine.settings.gravity_mode = sph::GravityMode::geostatic_k0;
  pristine.settings.damping = plan.damping;
  pristine.settings.end_time = plan.max_time;
  pristine.settings.output_interval = 0.0;
  if (!files.dir) pristine.settings.checkpoint_interval_wall_s = 0.0;  // else the scene's, for the trial in progress

  const SrmBracket bracket = initial_bracket(options, lem_bishop_fs);
  if (log)
    *log << "srm: " << size.soil_particles << " soil particles, dx = " << pristine.settings.particle_spacing
         << " m, H = " << plan.height << " m, damping " << plan.damping << " /s, trials up to " << plan.max_time
         << " s, failure at displacement > " << plan.failure_displacement << " m, bracket [" << bracket.lo << ", "
         << bracket.hi << "] (" << bracket.source << ")\n";

  std::optional<SrmJournal> journal;
  if (files.dir) {
    journal.emplace(*files.dir, journal_fingerprint(pristine, plan, bracket, options), files.resume);
    if (log && files.resume)
      *log << "srm: resuming: " << journal->finished_count() << " trial(s) finished before\n";
  }
  SrmResult result;
  const TrialRunner oracle(pristine, plan, log, journal ? &*journal : nullptr);
  result.bisection = bisect_factor(oracle, bracket.lo, bracket.hi, options.tolerance, options.max_trials);
  const BisectionResult& b = result.bisection;
  result.ok = b.bracketed && b.error.empty();

  result.tolerance = options.tolerance;
  result.initial_bracket = bracket;
  result.plan = plan;
  result.particle_spacing_m = pristine.settings.particle_spacing;
  result.soil_particles = size.soil_particles;
  result.lem_fs_by_method = lem_fs_by_method;
  result.lem_bishop = lem_bishop_fs;
  result.warnings = left_out_load_warnings(scene);
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace coupling
