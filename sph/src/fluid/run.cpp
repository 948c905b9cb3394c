#include "sph/fluid/run.hpp"

#include <cmath>
#include <limits>

#include "sph/engine/checkpoint.hpp"

namespace sph::fluid {

namespace {

CheckpointFingerprint fingerprint(const Model& model) {
  CheckpointFingerprint f;
  f.materials = 1;
  f.particle_spacing = model.settings.particle_spacing;
  f.h_over_dx = model.settings.h_over_dx;
  return f;
}

// Floor for the kinetic-energy runaway test: 1 % of (fluid weight x fluid height range).
double fluid_energy_floor(const Model& model) {
  const ParticleSet& p = model.particles;
  const Settings& st = model.settings;
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == 0) {
      ymin = std::min(ymin, p.y[i]);
      ymax = std::max(ymax, p.y[i]);
    }
  const double g = std::hypot(st.gravity_x, st.gravity_y);
  return 0.01 * model.fluid_mass() * g * std::max(ymax - ymin, st.particle_spacing);
}

// Passes the stepper's diagnostics to a watcher after every step (never stops the run).
class WatchObserver : public Observer {
 public:
  WatchObserver(const Step& step, const StepWatcher& watcher) : step_(step), watcher_(watcher) {}
  std::string after_step(const ParticleSet&, const RunState& state, const Energies&) override {
    watcher_(step_, state);
    return {};
  }

 private:
  const Step& step_;
  const StepWatcher& watcher_;
};

}  // namespace

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks, const StepWatcher& watcher) {
  Step stepper(model);
  const Settings& st = model.settings;
  RunTarget target(model.particles, model.state, stepper);
  target.end_time = st.end_time;
  target.output_interval = st.output_interval;
  target.checkpoint_interval_wall_s = st.checkpoint_interval_wall_s;
  target.blow_up_energy_factor = st.blow_up_energy_factor;
  target.energy_floor = fluid_energy_floor(model);
  target.write_checkpoint = [&model](const std::string& path) { write_checkpoint(path, model); };
  RunCallbacks cb = callbacks;
  WatchObserver watch(stepper, watcher);
  if (watcher) cb.observers.insert(cb.observers.begin(), &watch);
  return run_loop(target, options, cb);
}

void write_checkpoint(const std::string& path, const Model& model) {
  sph::write_checkpoint(path, model.particles, model.state, fingerprint(model));
}

void read_checkpoint(const std::string& path, Model& model) {
  sph::read_checkpoint(path, model.particles, model.state, fingerprint(model));
}

}  // namespace sph::fluid
