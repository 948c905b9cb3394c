#include "sph/coupled/model.hpp"

#include <cstring>
#include <stdexcept>

#include "sph/engine/atomic_file.hpp"
#include "sph/engine/checkpoint.hpp"
#include "sph/engine/vtk_output.hpp"
#include "sph/fluid/run.hpp"
#include "sph/soil/checkpoint.hpp"

namespace sph::coupled {

namespace {

constexpr char kMagic[16] = {'S', 'P', 'H', 'S', 'L', 'O', 'P', 'E', '-', 'C', 'O', 'U', 'P', 'L', 'E', 'D'};

void put_part(std::string& out, const std::string& part) {
  const std::uint64_t n = part.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out += part;
}

std::string get_part(const std::string& in, std::size_t& pos, const std::string& path) {
  std::uint64_t n = 0;
  if (pos + sizeof n > in.size()) throw std::runtime_error("coupled checkpoint " + path + " is truncated");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  if (n > in.size() - pos) throw std::runtime_error("coupled checkpoint " + path + " is truncated");
  std::string part = in.substr(pos, static_cast<std::size_t>(n));
  pos += static_cast<std::size_t>(n);
  return part;
}

std::vector<int> phases(const ParticleSet& p, bool soil) {
  std::vector<int> out(p.size(), -1);
  const auto material = static_cast<std::uint8_t>(ParticleKind::material);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] == material)
      out[i] = static_cast<int>(soil ? Phase::soil : Phase::water);
    else if (soil)
      out[i] = static_cast<int>(Phase::wall);
  }
  return out;
}

}  // namespace

void write_checkpoint(const std::string& path, const Model& model) {
  std::string out(kMagic, sizeof kMagic);
  put_part(out, soil::checkpoint_bytes(model.soil));
  put_part(out, fluid::checkpoint_bytes(model.water));
  write_file_atomically(path, out);
}

void read_checkpoint(const std::string& path, Model& model) {
  const std::string bytes = read_checkpoint_file(path);
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw std::runtime_error(path + " is not the checkpoint of a coupled run (soil and water)");
  std::size_t pos = sizeof kMagic;
  const std::string soil_part = get_part(bytes, pos, path), water_part = get_part(bytes, pos, path);
  const SoilBoundary twins(model.water, model.soil);  // the water's set as the run left it: with the twins
  soil::restore_checkpoint(soil_part, path + " (soil)", model.soil);
  fluid::restore_checkpoint(water_part, path + " (water)", model.water);
}

void write_frame(const std::string& path, const Model& model, const CoupledStep& step, double time) {
  std::vector<FramePart> parts(2);
  parts[0] = {&model.soil.particles, step.soil_outputs(), phases(model.soil.particles, true)};
  parts[1] = {&model.water.particles, {}, phases(model.water.particles, false)};
  write_vtu(path, parts, time);
}

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks, const StepWatcher& watcher) {
  CoupledStep step(model.soil, model.water);
  RunTarget target = run_target(model.water.particles, model.water.state, step, model.water.settings);
  target.checkpoint_interval_wall_s = model.soil.settings.checkpoint_interval_wall_s;
  target.energy_floor += moving_energy_floor(model.soil.particles, model.soil.settings);
  target.write_checkpoint = [&model](const std::string& path) { write_checkpoint(path, model); };
  target.write_frame = [&model, &step](const std::string& path, double time) { write_frame(path, model, step, time); };
  RunCallbacks cb = callbacks;
  WatchObserver<CoupledStep> watch(step, watcher);
  if (watcher) cb.observers.insert(cb.observers.begin(), &watch);
  return run_loop(target, options, cb);
}

}  // namespace sph::coupled
