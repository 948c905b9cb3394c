#include "sph/mps/run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/engine/checkpoint.hpp"

namespace sph::mps {

namespace {

CheckpointFingerprint fingerprint(const Model& model) {
  CheckpointFingerprint f;
  f.materials = static_cast<std::uint32_t>(model.materials.size());
  f.particle_spacing = model.settings.particle_spacing;
  f.h_over_dx = model.settings.re_over_dx;  // the MPS's radius in spacings takes the place of h/dx
  return f;
}

// Floor for the kinetic-energy runaway test: 1 % of (moving weight x height range of the moving particles) [J/m].
double energy_floor(const Model& model) {
  const ParticleSet& p = model.particles;
  const Settings& st = model.settings;
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::soil)) {
      ymin = std::min(ymin, p.y[i]);
      ymax = std::max(ymax, p.y[i]);
    }
  const double g = std::hypot(st.gravity_x, st.gravity_y);
  return 0.01 * model.moving_mass() * g * std::max(ymax - ymin, st.particle_spacing);
}

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
  target.energy_floor = energy_floor(model);
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

}  // namespace sph::mps
