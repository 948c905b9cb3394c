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
#include "sph/soil/run.hpp"

namespace coupling {

namespace {

constexpr double min_factor = srm_min_factor, max_factor = srm_max_factor, expansion = 1.5;

double reduce_angle_deg(double angle_deg, double factor) {
  return std::atan(std::tan(angle_deg * M_PI / 180.0) / factor) * 180.0 / M_PI;
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

SrmResult run_strength_reduction(const Scene& scene, const SrmOptions& options, std::optional<double> lem_bishop_fs,
                                 const nlohmann::json& lem_fs_by_method, std::ostream* log) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  if (!scene.section || !scene.analyses.sph) throw SceneError({"analyses.srm: needs a slope section and analyses.sph"});
  const slope::Section& section = scene.section->section;

  SphSize size;
  sph::Model pristine = build_sph_model(scene, &size);
  const double height = slope_height(section);
  const double vs = slowest_shear_wave(*scene.section);
  const double period = 4.0 * height / vs;  // first shear mode of a layer of the slope height
  const double omega = 2.0 * M_PI / period;

  const double damping = options.damping_per_s.value_or(omega);
  const double max_time = options.max_time_s.value_or(std::max(2.0, 40.0 * period));
  const double failure_displacement = options.failure_displacement_m.value_or(0.05 * height);
  const double rest_speed = options.rest_speed_m_s.value_or(1.0e-3 * std::sqrt(standard_gravity * height));
  // Not before the damped motion has had time to start: 5 damping time constants or 5 periods, whichever is
  // longer, but at most half the trial.
  const double min_time = std::min(0.5 * max_time, std::max(5.0 * period, damping > 0 ? 5.0 / damping : 0.0));

  pristine.settings.gravity_mode = sph::GravityMode::geostatic_k0;
  pristine.settings.damping = damping;
  pristine.settings.end_time = max_time;
  pristine.settings.output_interval = 0.0;
  pristine.settings.checkpoint_interval_wall_s = 0.0;

  std::vector<double> cohesion, friction, dilatancy;
  for (const auto& m : pristine.materials) {
    cohesion.push_back(m.cohesion);
    friction.push_back(m.friction_angle_deg);
    dilatancy.push_back(m.dilatancy_angle_deg);
  }

  auto oracle = [&](double factor) {
    sph::Model model = pristine;
    for (std::size_t k = 0; k < model.materials.size(); ++k) {
      model.materials[k].cohesion = cohesion[k] / factor;
      model.materials[k].friction_angle_deg = reduce_angle_deg(friction[k], factor);
      model.materials[k].dilatancy_angle_deg = reduce_angle_deg(dilatancy[k], factor);
    }
    const auto& p = model.particles;
    auto max_displacement = [&] {
      double worst = 0.0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.kind[i] != static_cast<std::uint8_t>(sph::ParticleKind::soil)) continue;
        worst = std::max(worst, std::hypot(p.x[i] - p.x0[i], p.y[i] - p.y0[i]));
      }
      return worst;
    };
    sph::RunOptions run_options;
    run_options.quasi_static_speed = rest_speed;
    run_options.quasi_static_min_time = min_time;
    run_options.checkpoint_on_stop = false;
    run_options.progress_interval_wall_s = 1e9;
    sph::RunCallbacks callbacks;
    bool displaced = false;
    std::uint64_t polls = 0;
    bool interrupted = false;
    callbacks.interrupt = [&] {
      if (interrupt_pending()) return interrupted = true;
      if (++polls % 10 != 0) return false;
      displaced = max_displacement() > failure_displacement;
      return displaced;
    };
    const sph::RunSummary summary = sph::run(model, run_options, callbacks);
    if (interrupted)
      throw std::runtime_error("interrupted during the trial at F = " + format_number(factor) +
                               " (strength reduction cannot be resumed; run it again)");
    SrmTrial trial;
    trial.factor = factor;
    trial.max_displacement_m = max_displacement();
    trial.simulated_time_s = summary.simulated_time;
    trial.wall_seconds = summary.wall_seconds;
    trial.stopped_because = displaced ? "displacement_limit" : summary.stopped_because;
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
    if (log) {
      char line[256];
      std::snprintf(line, sizeof line, "srm: F = %.4f: %s, max displacement %.3g m, t = %.3g s (%s), %.1f s wall\n",
                    factor, trial.failed ? "FAILS" : "stable", trial.max_displacement_m, trial.simulated_time_s,
                    trial.stopped_because.c_str(), trial.wall_seconds);
      *log << line << std::flush;
    }
    return trial;
  };

  double lo = 0.5, hi = 3.0;
  std::string bracket_source = "default [0.5, 3]";
  if (options.bracket) {
    lo = options.bracket->first;
    hi = options.bracket->second;
    bracket_source = "analyses.srm.bracket";
  } else if (lem_bishop_fs && std::isfinite(*lem_bishop_fs) && *lem_bishop_fs > 0) {
    lo = std::max(min_factor, 0.8 * *lem_bishop_fs);
    hi = std::min(max_factor, 1.25 * *lem_bishop_fs);
    bracket_source = "[0.8, 1.25] x LEM Bishop FS";
  }
  if (log)
    *log << "srm: " << size.soil_particles << " soil particles, dx = " << pristine.settings.particle_spacing
         << " m, H = " << height << " m, damping " << damping << " /s, trials up to " << max_time
         << " s, failure at displacement > " << failure_displacement << " m, bracket [" << lo << ", " << hi << "] ("
         << bracket_source << ")\n";

  SrmResult result;
  result.bisection = bisect_factor(oracle, lo, hi, options.tolerance, options.max_trials);
  const BisectionResult& b = result.bisection;
  result.ok = b.bracketed && b.error.empty();

  nlohmann::json& report = result.report;
  report["method"] = "SPH strength reduction: c/F, atan(tan(phi)/F), atan(tan(psi)/F) for every material; "
                     "geostatic K0 initial stress, linear velocity damping; bisection on F";
  report["failure_criterion"] = "a trial fails if the largest soil-particle displacement exceeds "
                                "failure_displacement_m, or if the soil is still moving faster than rest_speed_m_s "
                                "at max_time_s, or if the run stops abnormally; it is stable if it comes to rest";
  report["bracketed"] = b.bracketed;
  if (b.bracketed) {
    report["factor_of_safety"] = b.factor_of_safety;
    report["bracket"] = {b.lo, b.hi};
  } else {
    report["factor_of_safety"] = nullptr;
  }
  if (!b.error.empty()) report["error"] = "srm: " + b.error;
  report["tolerance"] = options.tolerance;
  report["initial_bracket"] = {lo, hi};
  report["initial_bracket_source"] = bracket_source;
  report["slope_height_m"] = height;
  report["failure_displacement_m"] = failure_displacement;
  report["damping_per_s"] = damping;
  report["first_mode_period_s"] = period;
  report["max_time_s"] = max_time;
  report["rest_speed_m_s"] = rest_speed;
  report["rest_check_after_s"] = min_time;
  report["particle_spacing_m"] = pristine.settings.particle_spacing;
  report["soil_particles"] = size.soil_particles;
  report["lem_factor_of_safety"] = lem_fs_by_method;
  nlohmann::json warnings = nlohmann::json::array();
  for (const SectionLoad& load : loads_sph_leaves_out(scene))  // only those listed in analyses.sph.ignore_loads
    warnings.push_back(load.path + " is not carried by the SPH model (analyses.sph.ignore_loads): FS_SPH is for "
                       "the slope without " + load.name + ", the limit-equilibrium factors of safety are with it");
  report["warnings"] = warnings;
  if (lem_bishop_fs) {
    report["lem_bishop"] = *lem_bishop_fs;
    if (b.bracketed) report["ratio_to_lem_bishop"] = b.factor_of_safety / *lem_bishop_fs;
  }
  nlohmann::json trials = nlohmann::json::array();
  for (const SrmTrial& t : b.trials)
    trials.push_back({{"factor", t.factor},
                      {"failed", t.failed},
                      {"max_displacement_m", t.max_displacement_m},
                      {"stopped_because", t.stopped_because},
                      {"reason", t.reason},
                      {"simulated_time_s", t.simulated_time_s},
                      {"wall_seconds", t.wall_seconds}});
  report["trials"] = trials;
  report["seconds"] = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace coupling
