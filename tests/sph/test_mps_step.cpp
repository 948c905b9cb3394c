// The WC-MPS stepper on the engine's run loop (issue 12; docs/mps.md section 6): a water column at rest in a box
// must carry the hydrostatic pressure and stay at rest. SI units.
#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

#include "sph/mps/model.hpp"
#include "sph/mps/run.hpp"
#include "sph/mps/stepper.hpp"
#include "same_state.hpp"

namespace test_mps_step {

namespace {

constexpr double g = 9.81;  // [m/s^2]

struct ColumnResult {
  double pressure_ratio = 0;  // mean over the measured particles of p / (rho0 g d), time-averaged
  double lowest_ratio = 0, highest_ratio = 0;  // the extremes of that mean over the samples [-]
  double max_speed = 0;  // largest speed over the last `window` seconds [m/s]
  double fastest_x = 0, fastest_y = 0;  // where the largest speed was [m]
  std::size_t samples = 0;
  sph::RunSummary summary;
};

// Water (1000 kg/m^3, 1e-3 Pa s) filling [0, width] x [0, depth] in a box of walls, gravity ramped over `ramp`
// seconds, run to `end`; measured over the particles 0.25 to 0.75 depth below the surface, in the last `window`.
ColumnResult water_column(double width, double depth, double dx, double ramp, double end, double window) {
  sph::mps::Settings st;
  st.particle_spacing = dx;
  st.rest_density = 1000.0;
  st.sound_speed = 20.0;
  st.gravity_x = 0.0;
  st.gravity_y = -g;
  st.gravity_mode = sph::GravityMode::ramped;
  st.gravity_ramp_time = ramp;
  st.end_time = end;
  st.output_interval = 0.0;
  st.checkpoint_interval_wall_s = 0.0;
  sph::mps::Model model(st, {sph::mps::Material::water()});
  sph::mps::add_block(model, 0.0, 0.0, width, depth, 0);
  sph::mps::add_box(model, 0.0, width, 0.0, 1.5 * depth, 0);
  ColumnResult r;
  double ratio_sum = 0;
  auto watch = [&](const sph::mps::Step&, const sph::RunState& state) {
    if (state.time < end - window) return;
    const sph::ParticleSet& p = model.particles;
    const double* pr = p.field(model.fields.pressure).data();
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.kind[i] != 0) continue;
      const double speed = std::hypot(p.vx[i], p.vy[i]);
      if (speed > r.max_speed) {
        r.max_speed = speed;
        r.fastest_x = p.x[i];
        r.fastest_y = p.y[i];
      }
      const double d = depth - p.y[i];
      if (d < 0.25 * depth || d > 0.75 * depth) continue;
      sum += pr[i] / (st.rest_density * g * d);
      ++count;
    }
    const double ratio = sum / static_cast<double>(count);
    ratio_sum += ratio;
    r.lowest_ratio = r.samples == 0 ? ratio : std::min(r.lowest_ratio, ratio);
    r.highest_ratio = std::max(r.highest_ratio, ratio);
    ++r.samples;
  };
  sph::RunOptions options;
  options.output_dir.clear();
  r.summary = sph::mps::run(model, options, {}, watch);
  r.pressure_ratio = r.samples > 0 ? ratio_sum / static_cast<double>(r.samples) : 0.0;
  return r;
}

}  // namespace

// Measured (Release, dx = 10 mm, r_e = 4 dx, c0 = 20 m/s, alpha = 0.5, C_r = 0.2, the p_min gradient, gravity
// ramped over 0.2 s, run to 0.4 s, 4026 steps, about 7 s wall): the mean of p / (rho0 g d) over the particles 5 to
// 15 cm deep, averaged over the last 0.1 s (1011 steps), is 0.946; the column still rings acoustically (that mean
// ranges over 0.745 to 1.145 between steps); the largest speed in the last 0.1 s is 0.247 m/s = 0.18 sqrt(g H), at
// a surface particle next to the left wall (the contact line). With the plain difference gradient of eq. 24 the
// run blows up at t = 0.25 s; without clipping the negative EOS pressure at step 94.
TEST_CASE("MPS water column at rest carries the hydrostatic pressure", "[mps]") {
  const double depth = 0.2;  // [m]
  const ColumnResult r = water_column(0.2, depth, 0.01, 0.2, 0.4, 0.1);
  std::printf("mps water column: p/(rho g d) = %.4f (range %.4f to %.4f), max speed %.4g m/s = %.4g sqrt(gH), %zu "
              "samples, %llu steps, %.2f s wall, %s %s\n",
              r.pressure_ratio, r.lowest_ratio, r.highest_ratio, r.max_speed, r.max_speed / std::sqrt(g * depth),
              r.samples, static_cast<unsigned long long>(r.summary.total_steps), r.summary.wall_seconds,
              r.summary.stopped_because.c_str(), r.summary.diagnostic.c_str());
  REQUIRE(r.summary.reason == sph::StopReason::end_time);
  CHECK(r.pressure_ratio == Approx(1.0).epsilon(0.08));  // hydrostatic within 8 % (measured -5.4 %)
  CHECK(r.max_speed < 0.25 * std::sqrt(g * depth));  // measured 0.18 sqrt(g H)
}

TEST_CASE("MPS dry granular collapse runs to 0.5 s with finite values and stays in the tank", "[mps]") {
  // The seed's dry collapse (3.0-3.1): a column l0 = 0.1 m long, h0 = 0.06 m high at the left wall of a tank
  // 0.3 m long, released at t = 0 (no gate), the default material (mu0 = 1.5 Pa s^N, N = 0.25, m = 50 s,
  // phi = 22 deg, c = 0), rho0 = 1500 kg/m^3, c0 = 20 m/s, cap 200 Pa s; coarse: dx = 10 mm (60 grains).
  // Measured (Release): 13334 steps (the viscous limit of eq. 30 at the cap, 3.75e-5 s), about 6 s wall; the top
  // at 0.5 s is 0.031 m. The run loop's health guard stops the run on a non-finite value (then reason != end_time).
  sph::mps::Settings st;
  st.particle_spacing = 0.01;
  st.end_time = 0.5;
  st.output_interval = 0.0;
  st.checkpoint_interval_wall_s = 0.0;
  sph::mps::Model model(st, {sph::mps::Material::granular_material()});
  const std::size_t grains = sph::mps::add_block(model, 0.0, 0.0, 0.1, 0.06, 0);
  sph::mps::add_box(model, 0.0, 0.3, 0.0, 0.12, 0);
  sph::RunOptions options;
  const sph::RunSummary s = sph::mps::run(model, options);
  double front = 0, top = 0, bottom = 1;
  std::size_t outside = 0;  // grains outside the tank [0, 0.3] x [0, 0.12] m
  for (std::size_t i = 0; i < model.particles.size(); ++i)
    if (model.particles.kind[i] == 0) {
      const double x = model.particles.x[i], y = model.particles.y[i];
      front = std::max(front, x);
      top = std::max(top, y);
      bottom = std::min(bottom, y);
      if (x < 0 || x > 0.3 || y < 0 || y > 0.12) ++outside;
    }
  std::printf("mps dry collapse: %zu grains, %llu steps, %.2f s wall, %s %s; front %.4f m, top %.4f m, bottom %.4f m, %zu outside\n", grains,
              static_cast<unsigned long long>(s.total_steps), s.wall_seconds, s.stopped_because.c_str(),
              s.diagnostic.c_str(), front, top, bottom, outside);
  REQUIRE(s.reason == sph::StopReason::end_time);
  CHECK(s.simulated_time >= 0.5);
  // Where the deposit thins to one or two rows the grains and the wall particles under them are free-surface
  // particles at pressure 0 and only the wall collision (docs/mps.md, S7) holds them up: without it 5 of the 60
  // grains fell through the floor (lowest -0.69 m); with it none leaves the tank (measured: lowest centre 0.6 mm
  // above the floor, 0.56 dx above the wall row's centres, resting on two wall particles at 0.75 dx).
  CHECK(outside == 0);
  CHECK(top < 0.06);  // the column slumped below its initial 0.06 m (measured 0.031 m)
}

namespace {

// A lone water particle thrown at 2 m/s onto the floor of a box (dx = 10 mm): it and the wall particles under it are
// free-surface particles at pressure 0, so only the wall collision can stop it. Returns its lowest centre [m] and
// its vertical velocity at the end of 0.05 s.
std::pair<double, double> thrown_particle(double collision_distance) {
  sph::mps::Settings st;
  st.particle_spacing = 0.01;
  st.rest_density = 1000.0;
  st.gravity_y = -g;
  st.end_time = 0.05;
  st.wall_collision_distance = collision_distance;
  sph::mps::Model model(st, {sph::mps::Material::water()});
  sph::mps::add_block(model, 0.10, 0.05, 0.11, 0.06, 0);
  sph::mps::add_box(model, 0.0, 0.2, 0.0, 0.1, 0);
  const std::size_t grain = 0;
  REQUIRE(model.particles.kind[grain] == 0);
  model.particles.vy[grain] = -2.0;
  sph::mps::Step step(model);
  step.initialise();
  double lowest = 0.055;  // its start (the step's sort has reordered the particles)
  while (model.state.time < st.end_time) {
    step.advance(step.stable_time_step());
    const sph::ParticleSet& p = model.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == 0) lowest = std::min(lowest, p.y[i]);
  }
  double vy = 0;
  for (std::size_t i = 0; i < model.particles.size(); ++i)
    if (model.particles.kind[i] == 0) vy = model.particles.vy[i];
  return {lowest, vy};
}

}  // namespace

TEST_CASE("MPS wall collision stops a particle the pressure cannot hold (docs/mps.md, S7)", "[mps]") {
  // The floor's wall row has its centres at y = -dx/2 = -5 mm, 10 mm apart; at a collision distance of 0.75 dx a
  // particle rests at least sqrt(0.75^2 - 0.5^2) dx = 0.56 dx above that row (between two wall particles): y >= 0.6 mm.
  const auto [lowest_on, vy_on] = thrown_particle(0.75);
  const auto [lowest_off, vy_off] = thrown_particle(0.0);
  INFO("lowest centre with the collision " << lowest_on << " m (final vy " << vy_on << " m/s), without "
       << lowest_off << " m");
  CHECK(lowest_off < -0.05);  // without it the particle falls through the walls
  CHECK(lowest_on > 0.0005);  // measured 2.5 mm: straight above a wall particle, 0.75 dx above the row
  CHECK(std::fabs(vy_on) < 0.05);  // fully inelastic (restitution 0): it stays on the floor
}

// The hydrostatic effective pressure (settings.effective_pressure, eqs. 18-19 with the surface at the top particle's
// edge): a column 0.1 m x 0.06 m at dx = 10 mm, rho0 = 1500 kg/m^3, at rest. The bottom grain (centre 5 mm above the
// floor, 50 mm below the top row's centres) carries rho0 g (0.05 + 0.005) = 809.3 Pa; the first floor row under the
// column (centre 5 mm below the floor) rho0 g 0.065; a floor particle with no grain above it, 0.
TEST_CASE("MPS hydrostatic effective pressure is the weight of the material above (eqs. 18-19)", "[mps]") {
  sph::mps::Settings st;
  st.particle_spacing = 0.01;
  st.end_time = 0.1;
  st.effective_pressure = sph::mps::EffectivePressure::hydrostatic;
  sph::mps::Model model(st, {sph::mps::Material::granular_material()});
  sph::mps::add_block(model, 0.0, 0.0, 0.1, 0.06, 0);
  sph::mps::add_box(model, 0.0, 0.3, 0.0, 0.12, 0);
  sph::mps::Step step(model);
  step.initialise();
  const sph::ParticleSet& p = model.particles;
  const double* pp = p.field(model.fields.smoothed_pressure).data();
  auto at = [&](double x, double y) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (std::abs(p.x[i] - x) < 1e-6 && std::abs(p.y[i] - y) < 1e-6) return pp[i];
    FAIL("no particle at " << x << ", " << y);
    return 0.0;
  };
  const double rho_g = 1500.0 * g;
  CHECK(at(0.045, 0.005) == Approx(rho_g * 0.055).epsilon(1e-12));
  CHECK(at(0.045, 0.055) == Approx(rho_g * 0.005).epsilon(1e-12));  // the top row: half its own cell
  CHECK(at(0.045, -0.005) == Approx(rho_g * 0.065).epsilon(1e-12));
  CHECK(at(0.255, -0.005) == 0.0);
}

// effective_pressure smoothed_thin_layer (docs/mps.md section 7): the same column at rest at the start, where the EOS
// pressure p^m is still 0 everywhere, so the smoothed p' is 0. On a flat lattice surface with r_e = 4 dx the top
// three rows miss neighbours (n/n0 = 0.634, 0.908, 0.991) and get the weight above them, rho0 g (h + dx/2); the
// fourth row and below, away from the column's free side, have complete neighbourhoods and keep the smoothed 0; the
// grain at the free side (x = 0.095 m) misses neighbours at any depth. With "smoothed" every grain has 0.
TEST_CASE("MPS thin-layer effective pressure gives the weight above where the neighbourhood is incomplete", "[mps]") {
  auto start = [](sph::mps::EffectivePressure choice) {
    sph::mps::Settings st;
    st.particle_spacing = 0.01;
    st.end_time = 0.1;
    st.effective_pressure = choice;
    auto model = std::make_unique<sph::mps::Model>(st, std::vector{sph::mps::Material::granular_material()});
    sph::mps::add_block(*model, 0.0, 0.0, 0.1, 0.06, 0);
    sph::mps::add_box(*model, 0.0, 0.3, 0.0, 0.12, 0);
    sph::mps::Step step(*model);
    step.initialise();
    return model;
  };
  auto at = [](const sph::mps::Model& model, double x, double y) {
    const sph::ParticleSet& p = model.particles;
    const double* pp = p.field(model.fields.smoothed_pressure).data();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (std::abs(p.x[i] - x) < 1e-6 && std::abs(p.y[i] - y) < 1e-6) return pp[i];
    FAIL("no particle at " << x << ", " << y);
    return 0.0;
  };
  const auto thin = start(sph::mps::EffectivePressure::smoothed_thin_layer);
  const double rho_g = 1500.0 * g;
  CHECK(at(*thin, 0.045, 0.055) == Approx(rho_g * 0.005).epsilon(1e-12));  // the top row: half its own cell
  CHECK(at(*thin, 0.045, 0.045) == Approx(rho_g * 0.015).epsilon(1e-12));
  CHECK(at(*thin, 0.045, 0.035) == Approx(rho_g * 0.025).epsilon(1e-12));  // n/n0 = 0.991
  CHECK(at(*thin, 0.045, 0.025) == 0.0);  // complete: the smoothed p'
  CHECK(at(*thin, 0.045, 0.005) == 0.0);
  CHECK(at(*thin, 0.095, 0.025) == Approx(rho_g * 0.035).epsilon(1e-12));  // the free side
  const auto smoothed = start(sph::mps::EffectivePressure::smoothed);
  CHECK(at(*smoothed, 0.045, 0.055) == 0.0);
  CHECK(at(*smoothed, 0.095, 0.025) == 0.0);
}

namespace {

// A water block 0.1 m x 0.06 m at the left wall of a 0.3 m box (dx = 5 mm), released at t = 0.
sph::mps::Model water_dam_break() {
  sph::mps::Settings st;
  st.particle_spacing = 0.005;
  st.rest_density = 1000.0;
  st.gravity_y = -g;
  st.end_time = 10.0;
  sph::mps::Model model(st, {sph::mps::Material::water()});
  sph::mps::add_block(model, 0.0, 0.0, 0.1, 0.06, 0);
  sph::mps::add_box(model, 0.0, 0.3, 0.0, 0.12, 0);
  return model;
}

void advance(sph::mps::Step& step, int steps) {
  for (int k = 0; k < steps; ++k) step.advance(step.stable_time_step());
}

}  // namespace

TEST_CASE("MPS resumed between two listings of the neighbour candidates ends bitwise where the straight run ends",
          "[mps]") {
  // The candidates (pairs within r_e + dx/2) are listed again only when a particle has moved dx/4 since the last
  // listing; the checkpoint carries the listing positions, so the resumed run lists the same candidates in the same
  // particle order. Measured: the straight run lists them 17 times in 900 steps, 6 of them in the first 500.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "sphslope_mps_resume";
  fs::create_directories(dir);
  const std::string file = (dir / "mps.bin").string();

  sph::mps::Model straight = water_dam_break();
  sph::mps::Step straight_step(straight);
  straight_step.initialise();
  advance(straight_step, 900);

  sph::mps::Model first = water_dam_break();
  sph::mps::Step first_step(first);
  first_step.initialise();
  advance(first_step, 500);
  const std::uint64_t listings_before = first_step.candidate_listings();
  const sph::ParticleSet& fp = first.particles;
  CHECK(fp.field(first.fields.x_listed) != fp.x);  // the checkpoint falls between two listings
  sph::mps::write_checkpoint(file, first);

  sph::mps::Model resumed = water_dam_break();
  sph::mps::read_checkpoint(file, resumed);
  sph::mps::Step resumed_step(resumed);
  resumed_step.initialise();
  advance(resumed_step, 400);
  INFO("listings: straight " << straight_step.candidate_listings() << ", first part " << listings_before
                             << ", resumed part " << resumed_step.candidate_listings());
  CHECK(listings_before >= 2);  // the first part moved far enough to list the candidates again
  CHECK(resumed_step.candidate_listings() >= 2);  // the resumed part lists them again
  REQUIRE(resumed.state.step == straight.state.step);
  CHECK(resumed.state.time == straight.state.time);
  CHECK(resumed.particles.x == straight.particles.x);
  CHECK(resumed.particles.y == straight.particles.y);
  CHECK(resumed.particles.vx == straight.particles.vx);
  CHECK(resumed.particles.field(resumed.fields.pressure) == straight.particles.field(straight.fields.pressure));
  fs::remove_all(dir);
}

// docs/reliability.md: the same scene gives bitwise the same result with 1 or 2 threads. The water dam break over
// 600 steps (the candidates listed again several times) and a dry granular collapse (the Herschel-Bulkley rheology
// and the effective pressure) over 6000 steps (0.056 s), every field compared.
TEST_CASE("MPS gives bitwise the same state with 1 and 2 threads, water and grains", "[mps][threads]") {
  auto granular_collapse = [] {
    sph::mps::Settings st;
    st.particle_spacing = 0.005;
    st.end_time = 10.0;
    sph::mps::Model model(st, {sph::mps::Material::granular_material()});
    sph::mps::add_block(model, 0.0, 0.0, 0.1, 0.06, 0);
    sph::mps::add_box(model, 0.0, 0.3, 0.0, 0.12, 0);
    return model;
  };
  const int before = omp_get_max_threads();
  for (const bool water : {true, false}) {
    INFO((water ? "water dam break" : "granular collapse"));
    const int steps = water ? 600 : 6000;
    auto run_with = [&](int threads) {
      omp_set_num_threads(threads);
      sph::mps::Model model = water ? water_dam_break() : granular_collapse();
      sph::mps::Step step(model);
      step.initialise();
      advance(step, steps);
      return std::pair{std::move(model), step.candidate_listings()};
    };
    auto [one, listings_one] = run_with(1);
    auto [two, listings_two] = run_with(2);
    INFO("candidate listings: " << listings_one);
    CHECK(listings_one >= 2);  // the particles moved far enough to be listed again
    CHECK(listings_two == listings_one);
    REQUIRE(one.state.step == two.state.step);
    CHECK(one.state.time == two.state.time);
    CHECK(same_state::differing_values(one.particles, two.particles) == 0);
  }
  omp_set_num_threads(before);
}

TEST_CASE("MPS n* of every step is the sum of the weights at r*, also in the steps that list the candidates again",
          "[mps]") {
  // The number density n* is summed while the pairs at r* are listed. A step that lists the candidates again first
  // sorts the set, which reorders the fields and may move their storage: n* must land in the field as it is after
  // the sort. (Written into the storage from before the sort, the steps with a sort used the previous step's n*, and
  // the 2.5 mm dry collapse ended 0.35 mm further out; the goldens, too short to list the candidates twice, passed.)
  sph::mps::Model model = water_dam_break();
  sph::mps::Step step(model);
  step.initialise();
  std::size_t wrong = 0, steps_with_sort = 0;
  for (int k = 0; k < 900; ++k) {
    const std::uint64_t before = step.candidate_listings();
    step.advance(step.stable_time_step());
    if (step.candidate_listings() > before) ++steps_with_sort;
    const double* n = model.particles.field(model.fields.number_density).data();
    const sph::NeighbourList& pairs = step.pairs_at_predicted_positions();
    for (std::size_t i = 0; i < model.particles.size(); ++i) {
      double sum = 0;
      for (std::size_t q = 0; q < pairs.count(i); ++q) sum += pairs.values(i)[q];
      if (!(n[i] == sum)) ++wrong;
    }
  }
  INFO("steps that listed the candidates again: " << steps_with_sort);
  // measured 16 in 900 steps (a sort may come at r^m or at r*; with the storage from before the sort the check
  // failed for 1575 particle-steps of these 900 steps, and passed over the first 300)
  REQUIRE(steps_with_sort >= 8);
  CHECK(wrong == 0);
}

namespace {

struct GateRun {
  double front_end = 0;  // at the end [m]
  double gate_bottom = 0;  // the lowest gate particle's centre at the end [m]
  double gate_speed = 0;  // the gate particles' largest speed at the end [m/s]
  std::uint64_t steps = 0;
};

// The seed's dry collapse at dx = 10 mm (column 0.1 m x 0.06 m, tank 0.3 m), optionally behind a gate at x = 0.1 m
// lifted at `speed` over 0.15 m, run to `end`.
GateRun collapse_behind_gate(bool with_gate, double speed, double end) {
  sph::mps::Settings st;
  st.particle_spacing = 0.01;
  st.end_time = end;
  st.gate_lift_speed = speed;
  st.gate_lift_distance = 0.15;
  sph::mps::Model model(st, {sph::mps::Material::granular_material()});
  sph::mps::add_block(model, 0.0, 0.0, 0.1, 0.06, 0);
  sph::mps::add_box(model, 0.0, 0.3, 0.0, 0.12, 0);
  if (with_gate) sph::mps::add_gate(model, 0.1, 0.0, 0.12, 0);
  sph::mps::Step step(model);
  step.initialise();
  GateRun r;
  auto front = [&] {
    double f = 0;
    for (std::size_t i = 0; i < model.particles.size(); ++i)
      if (model.particles.kind[i] == 0) f = std::max(f, model.particles.x[i]);
    return f;
  };
  while (model.state.time < end) {
    step.advance(std::min(step.stable_time_step(), end - model.state.time + 1e-12));
  }
  r.front_end = front();
  r.gate_bottom = 1.0;
  const double* gate = model.particles.field(model.gate).data();
  for (std::size_t i = 0; i < model.particles.size(); ++i)
    if (gate[i] != 0.0) {
      r.gate_bottom = std::min(r.gate_bottom, model.particles.y[i]);
      r.gate_speed = std::max(r.gate_speed, std::hypot(model.particles.vx[i], model.particles.vy[i]));
    }
  r.steps = model.state.step;
  return r;
}

}  // namespace

TEST_CASE("MPS gate lifted at a given speed holds the column back, rises as prescribed and stops at its height",
          "[mps]") {
  // The seed's collapse gate, "lifted vertically and quickly at speed v_g" (value not given). Measured (dx = 10 mm,
  // to 0.2 s, 5333 steps each, about 3 s for the four runs): front (largest grain centre) at 0.2 s 0.1948 m released at
  // once, 0.1919 m behind a gate lifted at 5 m/s (it clears the 0.06 m column in 12 ms), 0.1764 m behind one at
  // 0.5 m/s (its bottom is 0.105 m up at the end), 0.095 m behind a gate that stays (speed 0).
  const GateRun free = collapse_behind_gate(false, 0.0, 0.2);
  const GateRun held = collapse_behind_gate(true, 0.0, 0.2);
  const GateRun slow = collapse_behind_gate(true, 0.5, 0.2);
  const GateRun fast = collapse_behind_gate(true, 5.0, 0.2);
  INFO("front at 0.2 s: released " << free.front_end << ", gate that stays " << held.front_end << ", 0.5 m/s "
                                   << slow.front_end << ", 5 m/s " << fast.front_end << "; gate bottom at the end "
                                   << held.gate_bottom << " / " << slow.gate_bottom << " / " << fast.gate_bottom
                                   << " m, speed " << held.gate_speed << " / " << slow.gate_speed << " / "
                                   << fast.gate_speed << " m/s");
  // the gate's motion: bottom row from 0.005 m up by min(v t, 0.15 m); rising at v, or at rest once it has risen
  CHECK(held.gate_bottom == Approx(0.005).epsilon(0).margin(1e-12));
  CHECK(slow.gate_bottom == Approx(0.005 + 0.5 * 0.2).epsilon(0).margin(1e-9));
  CHECK(fast.gate_bottom == Approx(0.005 + 0.15).epsilon(0).margin(1e-9));
  CHECK(held.gate_speed == 0.0);
  CHECK(slow.gate_speed == Approx(0.5).epsilon(1e-9));
  CHECK(fast.gate_speed == 0.0);
  // a gate that stays keeps every grain behind it (the column's last centre is at 0.095 m)
  CHECK(held.front_end < 0.1);
  // a slow gate holds the front back; a fast one barely changes the collapse
  CHECK(slow.front_end < 0.95 * free.front_end);
  CHECK(std::abs(fast.front_end - free.front_end) < 0.03 * free.front_end);
}

namespace {

// The highest unyielded grain (viscosity at least `unyielded` Pa s) and the highest grain of each column of the
// lattice, by x bins of width dx from the left wall [m]; -1 where there is none.
struct Columns {
  std::vector<double> top, top_unyielded, bottom_viscosity;
};
Columns columns_by_viscosity(const sph::mps::Model& model, double dx, double unyielded) {
  Columns c;
  const double* mu = model.particles.field(model.fields.viscosity).data();
  std::vector<double> bottom;
  for (std::size_t i = 0; i < model.particles.size(); ++i) {
    if (model.particles.kind[i] != 0) continue;
    const auto b = static_cast<std::size_t>(std::max(0.0, model.particles.x[i] / dx));
    if (b >= c.top.size()) {
      c.top.resize(b + 1, -1.0);
      c.top_unyielded.resize(b + 1, -1.0);
      c.bottom_viscosity.resize(b + 1, 0.0);
      bottom.resize(b + 1, 1e9);
    }
    const double y = model.particles.y[i];
    c.top[b] = std::max(c.top[b], y);
    if (mu[i] >= unyielded) c.top_unyielded[b] = std::max(c.top_unyielded[b], y);
    if (y < bottom[b]) {
      bottom[b] = y;
      c.bottom_viscosity[b] = mu[i];
    }
  }
  return c;
}

}  // namespace

TEST_CASE("MPS dry collapse: an unyielded zone in the bottom corner under a yielded top layer, as the paper's Fig. 14",
          "[mps]") {
  // The seed (section 7-5, Fig. 14): after the release "a trapezoidal unyielded zone forms in the bottom-left corner,
  // bounded by the bed, the wall, a concave yield line and a flat top", the material above it flowing. So the
  // paper's viscoplastic model does not keep the column's top corner at the wall, which the experiments keep for
  // a < 0.7 (docs/mps.md section 7: the height at the wall 19 % low at 2.5 mm). The library's defaults (the case's
  // forms) at dx = 10 mm, 0.05 s after the release; unyielded = at least half the viscosity cap (200 Pa s).
  // Measured (10 mm, 0.05 s, columns of 10 mm from the wall): the unyielded zone's top at 0.035 m in the three
  // columns nearest the wall (the flat top), then 0.025, 0.015, 0.005 m (the yield line), none beyond x = 0.07 m;
  // two grains above it at the wall are yielded (the top 0.053 m).
  sph::mps::Settings st;
  st.particle_spacing = 0.01;
  sph::mps::Model model(st, {sph::mps::Material::granular_material()});
  sph::mps::add_block(model, 0.0, 0.0, 0.1, 0.06, 0);
  sph::mps::add_box(model, 0.0, 0.3, 0.0, 0.12, 0);
  sph::mps::Step step(model);
  step.initialise();
  const double end = 0.05;
  while (model.state.time < end) step.advance(std::min(step.stable_time_step(), end - model.state.time + 1e-12));
  const double cap = st.viscosity_cap;
  const Columns c = columns_by_viscosity(model, st.particle_spacing, 0.5 * cap);
  for (std::size_t b = 0; b < c.top.size(); ++b)
    std::printf("mps unyielded zone at 0.05 s: column %zu: top %.3f m, unyielded to %.3f m, bottom grain %.1f Pa s\n", b,
                c.top[b], c.top_unyielded[b], c.bottom_viscosity[b]);
  REQUIRE(c.top.size() > 7);  // the loop below checks the bins from the eighth on
  // at the wall: unyielded from the bed, a yielded layer on top
  CHECK(c.bottom_viscosity[0] >= 0.5 * cap);
  CHECK(c.top_unyielded[0] > 0.02);
  CHECK(c.top_unyielded[0] < c.top[0] - 0.5 * st.particle_spacing);
  // the flat top and the yield line falling away from the wall to the bed
  CHECK(c.top_unyielded[1] == Approx(c.top_unyielded[0]).margin(0.25 * st.particle_spacing));
  CHECK(c.top_unyielded[4] < c.top_unyielded[0] - st.particle_spacing);
  for (std::size_t b = 7; b < c.top.size(); ++b) CHECK(c.top_unyielded[b] < 0);
  // the frames carry log10 of the viscosity (issue 12: "viscosity (log)"), the cap at log10(200) = 2.30
  const std::vector<sph::DerivedField> derived = step.derived_outputs();
  REQUIRE(derived.size() == 1);
  CHECK(derived[0].name == "log10_viscosity");
  REQUIRE(derived[0].values.size() == model.particles.size());
  const double* mu = model.particles.field(model.fields.viscosity).data();
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < model.particles.size(); ++i)
    if (!(derived[0].values[i] == std::log10(mu[i]))) ++wrong;
  CHECK(wrong == 0);
  CHECK(*std::max_element(derived[0].values.begin(), derived[0].values.end()) == Approx(std::log10(cap)));
}

}  // namespace test_mps_step
