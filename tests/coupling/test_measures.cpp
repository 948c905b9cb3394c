// The measuring code of the particle-flow analyses on data with a known answer (a front that moves exactly at
// Ritter's speed, Martin & Moyce's own table, a solitary-like pulse passing two gauges at a known speed, a still tank
// with an exact hydrostatic pressure, heaps of particles with a known top, front and stray particles): what the
// reports say of a run is only as good as these.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "coupling/analyses/isph_front.hpp"
#include "coupling/analyses/isph_measures.hpp"
#include "coupling/analyses/isph_waves.hpp"
#include "coupling/analyses/tank_monitors.hpp"
#include "coupling/analyses/monitor_table.hpp"
#include "sph/fluid/cases.hpp"
#include "sph/fluid/reference_fronts.hpp"
#include "sph/soil/benchmarks.hpp"

namespace test_measures {

namespace {

constexpr double g = 9.81;  // [m/s^2]

// One column `name` of a monitor table, a value per time.
coupling::MonitorTable table_of(const std::vector<double>& times, const std::vector<std::string>& columns,
                                const std::vector<std::vector<double>>& rows) {
  coupling::MonitorTable t;
  t.columns = columns;
  t.times = times;
  t.rows = rows;
  return t;
}

}  // namespace

// Ritter (1892): on a dry bed the front of a dam break moves at 2 sqrt(g h0) and the depth at the dam site is
// 4 h0 / 9. A front that moves exactly so must give the speed ratio 1, Pearson's r 1 and no error.
TEST_CASE("Ritter comparison: a front at exactly Ritter's speed gives speed ratio 1 and r = 1", "[measures][isph]") {
  coupling::RitterSetting s;
  s.dam_x = 2.0;
  s.depth = 0.5;
  s.g = g;
  s.reservoir_length = 2.0;
  s.far_wall_x = 10.0;
  s.dam_gauge = "dam_m";
  s.gauge_offset = 0.5;  // the gauge reads the elevation relative to the still water, 0.5 m above the bed
  const double c = std::sqrt(g * s.depth), t_min = 2.0 / std::sqrt(g / s.depth), t_max = 3.0 * 2.0 / c;
  for (const double speed_factor : {1.0, 0.9}) {
    INFO("front at " << speed_factor << " of Ritter's speed");
    std::vector<double> times;
    std::vector<std::vector<double>> rows;
    int dam_rows = 0;  // rows of the dam gauge inside [t_min, t_max)
    for (int k = 0; k <= 400; ++k) {
      const double t = 0.01 * k;
      // the front stops at the far wall: those rows (within h0 of it) are left out
      const double front = std::min(s.dam_x + speed_factor * 2.0 * c * t, s.far_wall_x);
      const double dam_level = 4.0 * s.depth / 9.0 - 0.5;  // Ritter's depth at the dam, as the gauge reads it
      times.push_back(t);
      rows.push_back({front, dam_level});
      dam_rows += t >= t_min && t < t_max;
    }
    const auto r = coupling::ritter_comparison(table_of(times, {"front_x_m", "dam_m"}, rows), s);
    REQUIRE(r);
    CHECK(r->front_speed_ratio == Approx(speed_factor).epsilon(1e-12));
    CHECK(r->front.r == Approx(1.0).epsilon(1e-12));  // a straight line in time either way
    REQUIRE(r->dam_depth_ratio);
    CHECK(*r->dam_depth_ratio == Approx(1.0).epsilon(1e-12));
    CHECK(r->dam_depth_points == dam_rows);
    if (speed_factor == 1.0) {
      CHECK(r->front.mean_error == Approx(0.0).margin(1e-12));
      CHECK(r->front.rms_error == Approx(0.0).margin(1e-12));
      CHECK(r->front.nse == Approx(1.0).epsilon(1e-12));
    } else {
      CHECK(r->front.mean_error < 0.0);  // behind Ritter's front
    }
  }
}

TEST_CASE("agreement statistics of a series against itself, and against a known offset", "[measures]") {
  const std::vector<double> o{1.0, 2.0, 4.0, 3.0, 5.0};
  const coupling::AgreementStatistics same = coupling::agreement(o, o);
  CHECK(same.points == 5);
  CHECK(same.r == Approx(1.0).epsilon(1e-12));
  CHECK(same.rms_error == 0.0);
  CHECK(same.nse == Approx(1.0).epsilon(1e-12));
  std::vector<double> s = o;
  for (double& v : s) v += 0.5;  // a constant offset: r stays 1, every error is 0.5
  const coupling::AgreementStatistics off = coupling::agreement(o, s);
  CHECK(off.r == Approx(1.0).epsilon(1e-12));
  CHECK(off.mean_error == Approx(0.5).epsilon(1e-12));
  CHECK(off.mean_absolute_error == Approx(0.5).epsilon(1e-12));
  CHECK(off.rms_error == Approx(0.5).epsilon(1e-12));
  // NSE = 1 - n 0.25 / sum (o - 3)^2 = 1 - 1.25 / 10
  CHECK(off.nse == Approx(1.0 - 1.25 / 10.0).epsilon(1e-12));
}

// The table is data: pinned here against its source, J.C. Martin and W.J. Moyce (1952), Phil. Trans. R. Soc. A
// 244:312-324, Tables 2 and 6, as the arrays mmTvec and mmZvec of TormodLandet/Ocellaris scripts/plot_dam_break.py
// (commit 44fd559f), read again for this test.
TEST_CASE("Martin & Moyce (1952) n^2 = 2 table: the values of the source", "[measures][isph]") {
  const std::array<double, 15> T{0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65,
                                 2.83, 2.98, 3.11, 3.33};
  const std::array<double, 15> Z{1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22,
                                 3.44, 3.67, 3.89, 4.11};
  const auto table = sph::fluid::martin_moyce_1952_n2_2();
  REQUIRE(table.size() == T.size());
  for (std::size_t k = 0; k < T.size(); ++k) {
    INFO(k);
    CHECK(table[k].T == T[k]);
    CHECK(table[k].Z == Z[k]);
  }
}

// A run whose front is the table itself gives no error; a run 0.1 ahead in T is found at the shift -0.1.
TEST_CASE("Martin & Moyce front errors: the table itself gives 0, an early run its shift", "[measures][isph]") {
  const coupling::MartinMoyceColumn column{0.05715, g, 0.0};
  const double scale = column.time_scale();  // T per second
  const auto table = sph::fluid::martin_moyce_1952_n2_2();
  for (const double ahead : {0.0, 0.1}) {
    INFO("run ahead by dT = " << ahead);
    std::vector<double> times{0.0};
    std::vector<std::vector<double>> rows{{column.x_wall + column.a}};
    for (const sph::fluid::FrontPoint& p : table) {
      times.push_back((p.T - ahead) / scale);
      rows.push_back({column.x_wall + p.Z * column.a});
    }
    times.push_back(times.back() + 0.3 / scale);  // the run goes on past the table's last point
    rows.push_back({rows.back()[0] + 0.5 * column.a});
    const auto e = coupling::martin_moyce_front_errors(table_of(times, {"front_x_m"}, rows), column);
    REQUIRE(e);
    CHECK(e->points == 14);  // the table's points with 0.84 <= T <= 3.33
    CHECK(e->rms_shifted == Approx(0.0).margin(1e-9));
    CHECK(e->shift == Approx(-ahead).margin(1e-9));
    if (ahead == 0.0) CHECK(e->rms == Approx(0.0).margin(1e-12));
    if (ahead > 0.0) CHECK(e->rms > 0.01);
  }
}

// Two gauges 2 m apart in water 0.5 m deep see a pulse travel at 2 m/s: a crest below the leading-crest threshold
// (0.005 d) first, then the leading crest H1 at x/2 s, then a higher one 0.6 s later. Every sample carries the
// discretised still surface's offset (+4 mm), which the reader takes off.
TEST_CASE("wave gauges: a pulse at a known speed gives its crests, their times and its celerity", "[measures][isph]") {
  coupling::Tank tank{0.0, 10.0, 0.0, 1.0};
  coupling::TankMonitors setup;
  setup.gauges = {{"g2", 2.0}, {"g4", 4.0}};
  setup.still_water = 0.5;
  const double speed = 2.0, H1 = 0.02, H2 = 0.05, small = 0.002, offset = 0.004;
  auto eta = [&](double x, double t) {
    const double s = x / speed;  // the arrival of the leading crest [s]
    auto bump = [&](double height, double at, double width) {
      return height / std::pow(std::cosh((t - at) / width), 2);
    };
    return bump(small, s - 0.4, 0.03) + bump(H1, s, 0.05) + bump(H2, s + 0.6, 0.05) - bump(0.3 * H2, s + 0.9, 0.05);
  };
  std::vector<double> times;
  std::vector<std::vector<double>> rows;
  for (int k = 0; k <= 800; ++k) {
    const double t = 0.005 * k;
    times.push_back(t);
    rows.push_back({eta(2.0, t) + offset, eta(4.0, t) + offset});
  }
  const coupling::GaugeWaves w = coupling::gauge_waves(table_of(times, {"g2_m", "g4_m"}, rows), setup, tank, g);
  CHECK(w.depth == 0.5);
  CHECK(w.long_wave_celerity == Approx(std::sqrt(g * 0.5)).epsilon(1e-12));
  REQUIRE(w.gauges.size() == 2);
  for (const coupling::GaugeWave& gauge : w.gauges) {
    INFO(gauge.name);
    const double arrival = gauge.x / speed;
    CHECK(gauge.initial == Approx(offset + eta(gauge.x, 0.0)).epsilon(1e-12));
    REQUIRE(gauge.crest);
    CHECK(*gauge.crest == Approx(H1).epsilon(0.01));  // the small bump's tail adds under 1 %
    CHECK(*gauge.crest_at == Approx(arrival).margin(1e-9));
    CHECK(gauge.highest == Approx(H2).epsilon(0.01));
    CHECK(gauge.highest_at == Approx(arrival + 0.6).margin(1e-9));
    CHECK(gauge.lowest == Approx(-0.3 * H2).epsilon(0.02));
  }
  REQUIRE(w.celerity.size() == 1);
  CHECK(w.celerity[0].from == "g2");
  CHECK(w.celerity[0].to == "g4");
  CHECK(w.celerity[0].speed == Approx(speed).epsilon(1e-9));
  CHECK(w.celerity[0].ratio == Approx(speed / std::sqrt(g * 0.5)).epsilon(1e-9));
}

// A still tank whose pressure is exactly hydrostatic with P = 0 at the top row's centres (dx/2 below the surface):
// the fitted floor pressure is rho0 g (H - dx/2) and the gradient rho0 g, whatever the free-surface particles carry
// (they are left out of the fit); the largest speed is the one particle given a speed.
TEST_CASE("still tank check: an exact hydrostatic state gives its floor pressure, gradient and speed",
          "[measures][isph]") {
  coupling::IsphAnalysis a;
  a.settings.particle_spacing = 0.02;
  a.settings.gravity_y = -g;
  const double width = 0.6, depth = 0.3, dx = a.settings.particle_spacing;
  a.tank = {0.0, width, 0.0, 1.5 * depth};
  a.water = {{0.0, 0.0, width, depth}};
  sph::fluid::Model model = sph::fluid::make_still_tank(a.settings, width, depth);
  sph::fluid::Arrays f = model.arrays();
  sph::ParticleSet& p = model.particles;
  const double rho_g = a.settings.rest_density * g;
  std::size_t fluid = 0, surface = 0, moving = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != 0) continue;
    ++fluid;
    const bool top_row = p.y[i] > depth - dx;
    f.free_surface[i] = top_row ? 1.0 : 0.0;
    f.pressure[i] = top_row ? 1.0e6 : rho_g * (depth - 0.5 * dx - p.y[i]);  // the top row's value is ignored
    surface += top_row;
    p.vx[i] = p.vy[i] = 0.0;
    if (moving == 0 && !top_row) {
      p.vx[i] = 0.03;
      p.vy[i] = -0.04;
      ++moving;
    }
  }
  REQUIRE(fluid == 30 * 15);
  REQUIRE(surface == 30);
  const auto c = coupling::still_tank_check(model, a);
  REQUIRE(c);
  CHECK(c->depth == Approx(depth).epsilon(1e-12));
  CHECK(c->rho_g_depth == Approx(rho_g * depth).epsilon(1e-12));
  CHECK(c->expected_ratio == Approx(1.0 - 0.5 * dx / depth).epsilon(1e-12));
  CHECK(c->floor_pressure == Approx(rho_g * (depth - 0.5 * dx)).epsilon(1e-9));
  CHECK(c->floor_pressure / c->rho_g_depth == Approx(c->expected_ratio).epsilon(1e-9));
  CHECK(c->gradient_ratio == Approx(1.0).epsilon(1e-9));
  CHECK(c->max_speed_end == Approx(0.05).epsilon(1e-12));
  CHECK(c->celerity == Approx(std::sqrt(g * depth)).epsilon(1e-12));
}

namespace {

// A heap of moving particles (kind 0) on the lattice of spacing dx: columns i = 0..n-1 at x = (i + 1/2) dx, column
// i holding rows j = 0..n-1-i (a staircase falling from the left wall), plus wall particles (kind 1) along the floor
// and a tall left wall that the measures must ignore.
void add_staircase_heap(sph::ParticleSet& p, int n, double dx) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n - i; ++j) p.add((i + 0.5) * dx, (j + 0.5) * dx, 1.0, 1000.0, 0, sph::ParticleKind::material);
  for (int i = -3; i < 3 * n; ++i) p.add((i + 0.5) * dx, -0.5 * dx, 1.0, 1000.0, 0, sph::ParticleKind::wall);
  for (int j = 0; j < 4 * n; ++j) p.add(-0.5 * dx, (j + 0.5) * dx, 1.0, 1000.0, 0, sph::ParticleKind::wall);
}

}  // namespace

// The wave-gauge reader (surface_at), the front (front_of, contact_front) and the wall height of the monitors on a
// staircase heap 10 columns wide whose top is known everywhere, with one stray particle thrown 5 dx ahead.
TEST_CASE("tank monitors: the surface, the front and the wall height of a heap with a stray particle",
          "[measures][mps][isph]") {
  const double dx = 0.01;
  const int n = 10;
  sph::ParticleSet p;
  add_staircase_heap(p, n, dx);
  // column i's top: n - i rows, the top of the highest particle (n - i) dx; the gauge at x reads the highest centre
  // closer than dx to x (at 4.6 dx: columns 4 and 5, not 3)
  CHECK(coupling::surface_at(p, 0.5 * dx, dx, 0.0) == Approx(n * dx).epsilon(1e-12));
  CHECK(coupling::surface_at(p, 4.6 * dx, dx, 0.0) == Approx((n - 4) * dx).epsilon(1e-12));  // columns 4 and 5
  CHECK(coupling::surface_at(p, 4.9 * dx, dx, 0.0) == Approx((n - 4) * dx).epsilon(1e-12));
  CHECK(coupling::surface_at(p, 20.0 * dx, dx, 0.0) == 0.0);  // past the heap: the floor
  CHECK(coupling::front_of(p, dx) == Approx(n * dx).epsilon(1e-12));
  CHECK(coupling::contact_front(p, dx) == Approx(n * dx).epsilon(1e-12));
  // a stray particle 5 dx past the heap's last column: the largest x sees it, the front of the body does not
  p.add((n + 4.5) * dx, 0.5 * dx, 1.0, 1000.0, 0, sph::ParticleKind::material);
  CHECK(coupling::front_of(p, dx) == Approx((n + 5) * dx).epsilon(1e-12));
  CHECK(coupling::contact_front(p, dx) == Approx(n * dx).epsilon(1e-12));
  // the monitors' row: gauges relative to the still water, the front, the wall height at the left wall
  coupling::TankMonitors setup;
  setup.gauges = {{"g", 2.6 * dx}};
  setup.still_water = 0.05;
  setup.front = true;
  setup.wall_height = true;
  const coupling::Tank tank{0.0, 1.0, 0.0, 0.5};
  coupling::TankMonitorObserver monitors(setup, tank, dx);
  monitors.sample(p, 0.25);
  const coupling::MonitorTable& t = monitors.table();
  REQUIRE(t.columns == std::vector<std::string>{"g_m", "front_x_m", "wall_height_m"});
  REQUIRE(t.rows.size() == 1);
  CHECK(t.times[0] == 0.25);
  CHECK(t.rows[0][0] == Approx((n - 2) * dx - 0.05).epsilon(1e-12));  // columns 2 and 3: column 2, n - 2 high
  CHECK(t.rows[0][1] == Approx((n + 5) * dx).epsilon(1e-12));
  CHECK(t.rows[0][2] == Approx(n * dx).epsilon(1e-12));
  // and back through monitors.csv
  const coupling::MonitorTable back = coupling::parse_monitors_csv(coupling::monitors_csv(t));
  CHECK(back.columns == t.columns);
  CHECK(back.times == t.times);
  CHECK(back.rows == t.rows);
}

TEST_CASE("farthest_in_contact: the farthest position still within the gap of the next", "[measures]") {
  CHECK(coupling::farthest_in_contact({0.0, 0.1, 0.2, 0.3}, 0.15) == 0.3);
  CHECK(coupling::farthest_in_contact({0.3, 0.0, 0.9, 0.1, 0.2}, 0.15) == 0.3);  // unsorted, 0.9 stray
  CHECK(coupling::farthest_in_contact({0.0, 0.1, 0.2, 0.6, 0.7}, 0.15) == 0.7);  // a pair ahead is a body
  CHECK(coupling::farthest_in_contact({0.0, 1.0, 2.0}, 0.15) == 0.0);  // no contact at all: the smallest
}

// sph::soil::measure_deposit (the soil's column collapse): the extent of the deposit from the back wall and the floor, on
// a staircase heap 20 columns wide, with an isolated particle and a pair of particles thrown ahead and above (fewer
// than 2 neighbours within 1.5 dx: left out) and wall particles (never soil).
TEST_CASE("deposit measure: run-out and height of a heap, stray particles left out", "[measures][sph]") {
  const double dx = 0.005;
  const int n = 20;
  sph::soil::Model model;
  model.settings.particle_spacing = dx;
  add_staircase_heap(model.particles, n, dx);
  const sph::soil::DepositShape heap = sph::soil::measure_deposit(model);
  CHECK(heap.runout == Approx(n * dx).epsilon(1e-12));
  CHECK(heap.height == Approx(n * dx).epsilon(1e-12));
  model.particles.add((n + 10.5) * dx, 0.5 * dx, 1.0, 1000.0, 0, sph::ParticleKind::material);  // alone
  model.particles.add((n + 20.5) * dx, 0.5 * dx, 1.0, 1000.0, 0, sph::ParticleKind::material);  // a pair
  model.particles.add((n + 21.5) * dx, 0.5 * dx, 1.0, 1000.0, 0, sph::ParticleKind::material);
  model.particles.add(5.5 * dx, (n + 8.5) * dx, 1.0, 1000.0, 0, sph::ParticleKind::material);  // thrown up
  const sph::soil::DepositShape with_strays = sph::soil::measure_deposit(model);
  CHECK(with_strays.runout == Approx(n * dx).epsilon(1e-12));
  CHECK(with_strays.height == Approx(n * dx).epsilon(1e-12));
  // three in a row ahead: the middle one has two neighbours, so that group counts (its centre is the extent)
  model.particles.add((n + 22.5) * dx, 0.5 * dx, 1.0, 1000.0, 0, sph::ParticleKind::material);
  CHECK(sph::soil::measure_deposit(model).runout == Approx((n + 22) * dx).epsilon(1e-12));
  // measured from another back wall and floor
  const sph::soil::DepositShape shifted = sph::soil::measure_deposit(model, -dx, 2 * dx);
  CHECK(shifted.height == Approx((n + 1) * dx).epsilon(1e-12));
}

}  // namespace test_measures
