// Profiles of a two-phase flow in a tank and the dam-break figures (coupling/analyses/mps_profiles.hpp).
#include "coupling/analyses/mps_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>

#include "coupling/analyses/tank_monitors.hpp"

namespace coupling {

namespace {

constexpr std::uint8_t kMoving = 0;  // kind 0: the moving material

std::size_t bin_count(const Tank& tank, double dx) {
  return static_cast<std::size_t>(std::max(1.0, std::ceil((tank.x_max - tank.x_min) / (2.0 * dx) - 1e-9)));
}

// The top of the highest particle still in contact with the one below it (farthest_in_contact on y), the floor
// when there is none.
double top_of(std::vector<double>& ys, double dx, double floor) {
  if (ys.empty()) return floor;
  return farthest_in_contact(std::move(ys), 1.5 * dx) + 0.5 * dx;
}

// The mean of a profile's values over the bins whose centres lie within `half` of x.
double mean_near(const Profile& p, const std::vector<double>& values, double x, double half) {
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < p.x.size(); ++k)
    if (std::abs(p.x[k] - x) <= half) {
      sum += values[k];
      ++count;
    }
  return count > 0 ? sum / count : 0.0;
}

}  // namespace

Profile measure_profile(const sph::ParticleSet& p, const Tank& tank, double dx,
                        const std::vector<std::uint8_t>& granular, double time) {
  const std::size_t bins = bin_count(tank, dx);
  std::vector<std::vector<double>> all(bins), grains(bins);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kMoving) continue;
    const double b = std::floor((p.x[i] - tank.x_min) / (2.0 * dx));
    if (b < 0 || b >= static_cast<double>(bins)) continue;  // outside the tank: not part of the profile
    const auto k = static_cast<std::size_t>(b);
    all[k].push_back(p.y[i]);
    if (p.material[i] < granular.size() && granular[p.material[i]]) grains[k].push_back(p.y[i]);
  }
  Profile out;
  out.time = time;
  for (std::size_t k = 0; k < bins; ++k) {
    out.x.push_back(tank.x_min + (2.0 * static_cast<double>(k) + 1.0) * dx);
    out.surface.push_back(top_of(all[k], dx, tank.y_min));
    out.bed.push_back(top_of(grains[k], dx, tank.y_min));
  }
  return out;
}

ProfileObserver::ProfileObserver(std::vector<double> times, const Tank& tank, double dx,
                                 std::vector<std::uint8_t> granular)
    : times_(std::move(times)), tank_(tank), dx_(dx), granular_(std::move(granular)) {
  std::sort(times_.begin(), times_.end());
}

std::string ProfileObserver::after_step(const sph::ParticleSet& p, const sph::RunState& state,
                                        const sph::Energies&) {
  while (next_ < times_.size() && state.time + 1e-12 >= times_[next_]) {
    profiles_.push_back(measure_profile(p, tank_, dx_, granular_, state.time));
    ++next_;
  }
  return {};
}

void ProfileObserver::restore(const std::string& csv, double time) {
  std::istringstream in(csv);
  std::string line;
  if (std::getline(in, line) && line == "time_s,x_m,surface_m,bed_m") {
    while (std::getline(in, line)) {
      double v[4];
      char comma = 0;
      std::istringstream row(line);
      if (!(row >> v[0] >> comma >> v[1] >> comma >> v[2] >> comma >> v[3])) break;
      if (v[0] > time + 1e-12) break;
      if (profiles_.empty() || profiles_.back().time != v[0]) profiles_.push_back({v[0], {}, {}, {}});
      profiles_.back().x.push_back(v[1]);
      profiles_.back().surface.push_back(v[2]);
      profiles_.back().bed.push_back(v[3]);
    }
  }
  while (next_ < times_.size() && times_[next_] <= time + 1e-12) ++next_;
}

DamBreakFigures dam_break_figures(const Profile& start, const Profile& now, double dam_x, double dx, double g) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  DamBreakFigures f;
  f.time = now.time;
  std::size_t upstream = 0;  // the bin just upstream of the dam
  for (std::size_t k = 0; k < start.x.size(); ++k)
    if (start.x[k] < dam_x) upstream = k;
  f.depth = start.surface[upstream] - start.bed[upstream];
  const double c0 = std::sqrt(g * std::max(f.depth, 0.0));
  f.ritter_front_x = dam_x + 2.0 * c0 * f.time;
  f.front_x = dam_x;
  for (std::size_t k = 0; k < now.x.size(); ++k)
    if (now.x[k] > dam_x && now.surface[k] >= start.surface[k] + 0.5 * dx) f.front_x = std::max(f.front_x, now.x[k]);
  double level = 0, bed = 0;
  int count = 0;
  for (std::size_t k = 0; k < now.x.size(); ++k)
    if (now.x[k] >= now.x.front() + 2.0 * dx && now.x[k] <= dam_x - 1.2 * c0 * f.time) {
      level += now.surface[k];
      bed += now.bed[k];
      ++count;
    }
  f.level_ahead = f.depth_ahead = f.negative_wave_x = f.ritter_negative_wave_x = nan;
  if (count > 0) {
    f.level_ahead = level / count;
    f.depth_ahead = f.level_ahead - bed / count;
    const double drop = 0.25 * f.depth_ahead, c = std::sqrt(g * std::max(f.depth_ahead, 0.0));
    f.ritter_negative_wave_x = dam_x + (2.0 * c - 3.0 * std::sqrt(g * (f.depth_ahead - drop))) * f.time;
    for (std::size_t k = 0; k < now.x.size(); ++k)
      if (now.x[k] < dam_x && mean_near(now, now.surface, now.x[k], 4.5 * dx) <= f.level_ahead - drop) {
        f.negative_wave_x = now.x[k];
        break;
      }
  }
  f.bed_at_dam = mean_near(now, now.bed, dam_x, 2.0 * dx);
  f.bed_at_dam_start = mean_near(start, start.bed, dam_x, 2.0 * dx);
  return f;
}

}  // namespace coupling
