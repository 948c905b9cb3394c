// The loads the soil model carries besides its weight (sph/soil/loads.hpp; docs/sph.md, "Loads"), against closed
// forms:
//  - a saturated elastic column in a free-slip box (oedometric), the water table inside it or ponded above it:
//    effective sigma'_yy = -(rho g d - gamma_w d_w), d the depth below the top, d_w the depth below the water table
//    (0 above it) within the soil; total sigma_yy = sigma'_yy - u with u = gamma_w (line - y). Tolerance 5 % of the
//    total vertical stress on row averages, rows over 3 dx from the top and the floor (as the dry column test);
//  - the K0 initial stress of a saturated column is in balance with the pore-pressure force: it moves no more than a
//    dry column with its K0 state (measured 0.24 mm against 0.32 mm), and 1.5 times as much without that force
//    (0.51 mm: the buoyancy unbalanced, an uplift of about 0.26 mm statically, twice that dynamically);
//  - the fully submerged body equals the dry body of buoyant density (rho - rho_w): same effective stress at rest
//    within 3 % of the column's buoyant weight (measured 229 Pa of 9810 Pa, 2.3 %);
//  - a strip surcharge q over the top of the column: sigma_yy = -(rho g d + q), 5 % per row (measured within 2 %);
//  - a trapezoidal strip (5 to 15 kPa) or a line load (2 kN/m at the middle) on the top: the row averages of
//    sigma_yy = -(rho g d + resultant / width), 5 % per row (free-slip walls carry no shear);
//  - k_v = 0.3: sigma_yy = -(1 - k_v) rho g d, 5 % per row;
//  - k_h: a block on a frictionless floor accelerates at k_h g, 5 % (measured -0.04904 m/s for -0.04905 m/s).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "elastic_box.hpp"
#include "sph/engine/fill.hpp"
#include "sph/soil/run.hpp"
#include "sph/soil/soil_step.hpp"

namespace test_loads {

namespace {

constexpr double rho = test_column::density, g = 9.81, gamma_w = 9810.0, H = test_column::height;

using test_column::elastic_box;

sph::soil::PiezometricLine level_line(double y) {
  sph::soil::PiezometricLine line;
  line.x = {-1.0, 2.0};
  line.y = {y, y};
  line.unit_weight = gamma_w;
  return line;
}

// Row averages of the effective and total sigma_yy against the closed form: water table at `table` (none: below
// the column), a surcharge q (Pa) on the top, the soil's weight times `weight_factor` (1 - k_v).
void check_saturated_profile(const sph::soil::Model& m, double table, double q = 0.0, double weight_factor = 1.0) {
  const auto& p = m.particles;
  const auto soil = m.soil();
  const double dx = m.settings.particle_spacing;
  std::map<long, double> effective, total;
  std::map<long, int> count;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != 0) continue;
    const long row = std::lround((p.y0[i] - 0.5 * dx) / dx);
    effective[row] += soil.syy[i];
    total[row] += soil.syy[i] - (m.loads.water ? m.loads.water->pressure(p.x[i], p.y[i]) : 0.0);
    count[row] += 1;
  }
  int checked = 0;
  for (const auto& [row, n] : count) {
    const double y = (static_cast<double>(row) + 0.5) * dx;
    const double depth = H - y;
    if (depth < 3 * dx || y < 3 * dx) continue;
    const double submerged = std::max(table - y, 0.0) - std::max(table - H, 0.0);
    const double exact_effective = -(weight_factor * rho * g * depth + q - gamma_w * submerged);
    const double exact_total = exact_effective - gamma_w * std::max(table - y, 0.0);
    const double got_effective = effective[row] / n, got_total = total[row] / n;
    INFO("table " << table << " m, surcharge " << q << " m, depth " << depth << " m: sigma'_yy " << got_effective << " vs " << exact_effective
                  << ", sigma_yy " << got_total << " vs " << exact_total);
    CHECK(std::fabs(got_effective - exact_effective) < 0.05 * std::fabs(exact_total));
    CHECK(std::fabs(got_total - exact_total) < 0.05 * std::fabs(exact_total));
    ++checked;
  }
  CHECK(checked > 30);
}

double largest_displacement(const sph::soil::Model& m) {
  double umax = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (m.particles.kind[i] == 0)
      umax = std::max(umax, std::hypot(m.particles.x[i] - m.particles.x0[i], m.particles.y[i] - m.particles.y0[i]));
  return umax;
}

}  // namespace

TEST_CASE("loads: a saturated elastic column settles to the effective and total stresses of the closed form",
          "[sph][validation][loads]") {
  for (const double table : {0.6, 1.3}) {  // inside the column; ponded 0.3 m above its top
    auto m = elastic_box(sph::GravityMode::sudden, 150.0);
    m.loads.water = level_line(table);
    const auto sum = sph::soil::run(m, {});
    REQUIRE(sum.stopped_because == "end_time");
    check_saturated_profile(m, table);
  }
}

TEST_CASE("loads: a saturated column with its K0 initial stress is at rest", "[sph][validation][loads]") {
  // The geostatic initial stress (effective, with the rise of the pore pressure below the table) and the body force
  // of the pore-pressure gradient balance: the column does not move, and its stress stays that of the closed form.
  auto m = elastic_box(sph::GravityMode::geostatic_k0, 0.0);
  m.loads.water = level_line(0.6);
  const auto sum = sph::soil::run(m, {});
  REQUIRE(sum.stopped_because == "end_time");
  check_saturated_profile(m, 0.6);
  CHECK(largest_displacement(m) < 1e-3);
  // Without the water the same initial stress is out of balance by the buoyancy: the column moves up.
  auto dry = elastic_box(sph::GravityMode::geostatic_k0, 0.0);
  dry.loads.water = level_line(0.6);
  {
    sph::soil::SoilStep step(dry);
    step.initialise();  // the initial stress of the saturated column
  }
  dry.loads.water.reset();
  REQUIRE(sph::soil::run(dry, {}).stopped_because == "end_time");
  // The reference: a dry column with its K0 state moves by the lattice's own settling.
  auto reference = elastic_box(sph::GravityMode::geostatic_k0, 0.0);
  REQUIRE(sph::soil::run(reference, {}).stopped_because == "end_time");
  INFO("largest displacement: saturated " << largest_displacement(m) << " m, its stress without the water force "
       << largest_displacement(dry) << " m, dry column " << largest_displacement(reference) << " m");
  CHECK(largest_displacement(m) < 1.1 * largest_displacement(reference));
  CHECK(largest_displacement(dry) > 1.5 * largest_displacement(reference));
}

TEST_CASE("loads: the submerged column equals the dry column of buoyant density", "[sph][validation][loads]") {
  auto wet = elastic_box(sph::GravityMode::sudden, 150.0);
  wet.loads.water = level_line(1.5);
  auto buoyant = elastic_box(sph::GravityMode::sudden, 150.0, rho - gamma_w / g);
  REQUIRE(sph::soil::run(wet, {}).stopped_because == "end_time");
  REQUIRE(sph::soil::run(buoyant, {}).stopped_because == "end_time");
  const auto a = wet.soil(), b = buoyant.soil();
  std::map<std::uint32_t, std::size_t> index_of;
  for (std::size_t i = 0; i < buoyant.particles.size(); ++i) index_of[buoyant.particles.id[i]] = i;
  double worst = 0, scale = (rho - gamma_w / g) * g * H;
  for (std::size_t i = 0; i < wet.particles.size(); ++i) {
    if (wet.particles.kind[i] != 0) continue;
    const std::size_t j = index_of.at(wet.particles.id[i]);
    worst = std::max(worst, std::fabs(a.syy[i] - b.syy[j]));
  }
  INFO("largest difference of sigma'_yy " << worst << " Pa, buoyant weight of the column " << scale << " Pa");
  CHECK(worst < 0.03 * scale);
}

TEST_CASE("loads: a strip surcharge over the whole top of a column adds q to its vertical stress",
          "[sph][validation][loads]") {
  const double q = 10e3;  // Pa: half the weight of the column
  auto m = elastic_box(sph::GravityMode::sudden, 150.0);
  const std::size_t loaded = sph::soil::add_strip_load(m.particles, m.loads, -1.0, 2.0, q, m.settings.particle_spacing);
  CHECK(loaded == 60);  // the three topmost particles of each of the 20 columns
  REQUIRE(sph::soil::run(m, {}).stopped_because == "end_time");
  check_saturated_profile(m, -1.0, q);
}

TEST_CASE("loads: a trapezoidal strip or a line load adds its resultant over the width to the mean vertical stress",
          "[sph][validation][loads]") {
  // Free-slip walls carry no shear: at rest, the mean sigma_yy of a row is minus the weight above it and the loads'
  // vertical resultant, over the column's width, however a load spreads below it.
  const double width = test_column::width;
  auto strip = elastic_box(sph::GravityMode::sudden, 150.0);  // 5 kPa at the left wall, 15 kPa at the right
  CHECK(sph::soil::add_strip_load(strip.particles, strip.loads, 0.0, width, 5e3, strip.settings.particle_spacing, 15e3) == 60);
  REQUIRE(sph::soil::run(strip, {}).stopped_because == "end_time");
  check_saturated_profile(strip, -1.0, 10e3);
  auto line = elastic_box(sph::GravityMode::sudden, 150.0);
  CHECK(sph::soil::add_line_load(line.particles, line.loads, 0.5 * width, 0.0, -2e3, line.settings.particle_spacing) == 9);
  REQUIRE(sph::soil::run(line, {}).stopped_because == "end_time");
  check_saturated_profile(line, -1.0, 2e3 / width);
}

TEST_CASE("loads: k_v lightens the column: sigma_yy = -(1 - k_v) rho g d", "[sph][validation][loads]") {
  auto m = elastic_box(sph::GravityMode::sudden, 150.0);
  m.loads.vertical_seismic_coefficient = 0.3;
  REQUIRE(sph::soil::run(m, {}).stopped_because == "end_time");
  check_saturated_profile(m, -1.0, 0.0, 0.7);
}

TEST_CASE("loads: k_h accelerates a block on a frictionless floor at k_h g", "[sph][validation][loads]") {
  // An elastic block resting on a free-slip floor, no side walls, K0 initial stress (at rest): the pseudo-static
  // force is the only horizontal force, so the mean horizontal velocity after t is k_h g t.
  auto m = elastic_box(sph::GravityMode::geostatic_k0, 0.0, rho, false);
  m.loads.seismic_coefficient = -0.1;
  m.settings.end_time = 0.05;
  REQUIRE(sph::soil::run(m, {}).stopped_because == "end_time");
  double momentum = 0, mass = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (m.particles.kind[i] == 0) {
      momentum += m.particles.mass[i] * m.particles.vx[i];
      mass += m.particles.mass[i];
    }
  const double expected = -0.1 * g * 0.05;
  INFO("mean vx " << momentum / mass << " m/s, k_h g t = " << expected << " m/s");
  CHECK(std::fabs(momentum / mass - expected) < 0.05 * std::fabs(expected));
}

}  // namespace test_loads
