#include "sph/soil/run.hpp"

#include <cmath>
#include <limits>

#include "sph/soil/checkpoint.hpp"
#include "sph/soil/soil_step.hpp"

namespace sph {

namespace {

// Floor for the kinetic-energy runaway test: 1 % of (soil weight x soil height range).
double soil_energy_floor(const Model& model) {
  const ParticleSet& p = model.particles;
  const Settings& st = model.settings;
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin, weight = 0;
  const double g = std::hypot(st.gravity_x, st.gravity_y);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == 0) {
      ymin = std::min(ymin, p.y[i]);
      ymax = std::max(ymax, p.y[i]);
      weight += p.mass[i] * g;
    }
  return 0.01 * weight * std::max(ymax - ymin, st.particle_spacing);
}

}  // namespace

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks) {
  SoilStep stepper(model);
  const Settings& st = model.settings;
  RunTarget target(model.particles, model.state, stepper);
  target.end_time = st.end_time;
  target.output_interval = st.output_interval;
  target.checkpoint_interval_wall_s = st.checkpoint_interval_wall_s;
  target.blow_up_energy_factor = st.blow_up_energy_factor;
  target.energy_floor = soil_energy_floor(model);
  target.write_checkpoint = [&model](const std::string& path) { write_checkpoint(path, model); };
  return run_loop(target, options, callbacks);
}

}  // namespace sph
