// bench-lem: limit-equilibrium throughput on one core.
//   trial circles per second (slicing + factor of safety together, 50 slices) for Bishop, Spencer and
//   Morgenstern-Price on the homogeneous Griffiths & Lane (1999) slope, and the wall time of the default critical
//   search with refinement, also with a Hoek-Brown envelope and with reinforcement; trial polylines per second for
//   Spencer, and the wall time of the non-circular search.
//   A benchmark program, not a test: it prints figures (docs/performance.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "slope/evaluator.hpp"
#include "slope/search.hpp"
#include "sphslope/units.hpp"

namespace {

using Clock = std::chrono::steady_clock;

slope::Section griffiths_lane() {
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back({"soil", 20e3, 10e3, sphslope::radians(20.0)});
  s.profile_lines.push_back({0, {{0, 20}, {20, 20}, {40, 10}, {60, 10}}});
  return s;
}

// Hammah et al. (2005) Example 1 (cases/hammah_2005_hoek_brown.json): a 10 m, 45 degree rock slope with a
// generalized Hoek-Brown envelope (sigma_ci 30 MPa, GSI 5, m_i 2, D 0, 25 kN/m^3); with hoek_brown = false the
// same slope in a Mohr-Coulomb soil of about its strength (c' = 17 kPa, phi' = 24 deg), for the envelope's cost.
slope::Section hammah(bool hoek_brown) {
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back({"rock mass", 25e3, 17e3, sphslope::radians(24.0)});
  if (hoek_brown) {
    slope::StrengthEnvelope e;
    e.hoek_brown = slope::hoek_brown_from_gsi(30e6, 5.0, 2.0, 0.0);
    s.materials[0].envelope = e;
  }
  s.profile_lines.push_back({0, {{0, 15}, {20, 15}, {30, 5}, {50, 5}}});
  return s;
}

// Duncan & Wright (2005) Fig. 7.28 (cases/duncan_wright_2005_geogrids.json): a 24 ft cohesionless fill at
// 1.25H:1V on rock, bare or with its five geogrids (11.675 kN/m along the grid), active or passive.
slope::Section geogrid_fill(int grids) {  // 0: none, 1: active, 2: passive
  constexpr double ft = 0.3048;
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back({"fill", 20.421e3, 0.0, sphslope::radians(37.0)});
  s.profile_lines.push_back({0, {{-20 * ft, 0}, {0, 0}, {30 * ft, 24 * ft}, {75 * ft, 24 * ft}}});
  for (double y : {4.0, 8.0, 12.0, 16.0, 20.0}) {
    if (grids == 0) break;
    slope::Reinforcement g = slope::reinforcement_defaults(slope::SupportType::geosynthetic);
    g.head = {1.25 * y * ft, y * ft};
    g.tail = {(1.25 * y + 20.0) * ft, y * ft};
    slope::set_tensile_capacity(g, 11.675e3);
    g.direction = slope::SupportDirection::along;
    g.application = grids == 2 ? slope::SupportApplication::passive : slope::SupportApplication::active;
    s.reinforcement.push_back(g);
  }
  return s;
}

// Trial circles scattered around the critical one, all admissible for every method measured.
std::vector<slope::Circle> trial_circles(const slope::Section& section, int count) {
  slope::CircleEvaluator evaluator(section);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> xc(28.0, 42.0), yc(24.0, 40.0), depth(0.5, 8.0);
  std::vector<slope::Circle> circles;
  while (static_cast<int>(circles.size()) < count) {
    const double x = xc(rng), y = yc(rng);
    // radius so that the circle reaches `depth` below the slope face line near its centre
    const slope::Circle c{x, y, y - 10.0 + depth(rng) * 0.5};
    if (evaluator.factor_of_safety(c, slope::Method::bishop) && evaluator.factor_of_safety(c, slope::Method::spencer) &&
        evaluator.factor_of_safety(c, slope::Method::morgenstern_price))
      circles.push_back(c);
  }
  return circles;
}

void throughput(const char* name, slope::Method method, const slope::Section& section,
                const std::vector<slope::Circle>& circles) {
  slope::CircleEvaluator evaluator(section, slope::SliceOptions{50});
  long evaluated = 0, slices = 0;
  double checksum = 0.0;
  const auto start = Clock::now();
  double seconds = 0.0;
  do {
    for (const slope::Circle& c : circles) {
      if (auto fs = evaluator.factor_of_safety(c, method)) checksum += *fs;
      slices += evaluator.last_slice_count();
      ++evaluated;
    }
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } while (seconds < 1.5);
  std::printf("%-28s %10.0f trial circles/s  (%.1f slices per circle, %ld circles, mean FS %.4f)\n", name,
              evaluated / seconds, static_cast<double>(slices) / evaluated, evaluated, checksum / evaluated);
}

void search_time(const char* name, const std::vector<slope::Method>& methods, const slope::Section& section) {
  std::vector<double> times;
  slope::SearchResult last;
  for (int run = 0; run < 7; ++run) {
    const auto start = Clock::now();
    last = slope::search_critical(section, methods, slope::SearchOptions{});
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  std::printf("%-28s median %.4f s (min %.4f s) over 7 runs, %ld FS evaluations;", name, times[times.size() / 2],
              times.front(), last.trial_surfaces);
  for (const slope::CriticalSurface& c : last.methods)
    std::printf(" %s %.4f", std::string(slope::method_key(c.method)).c_str(),
                c.result.factor_of_safety.value_or(std::nan("")));
  std::printf("\n");
}

// Polylines of 33 vertices inscribed in the trial circles, their depth below the entry-exit chord scaled by a
// random 0.8-1.0 (still concave; kept only when admissible and solved by Spencer): slicing + factor of safety per
// second.
void polyline_throughput(const slope::Section& section, const std::vector<slope::Circle>& circles) {
  std::mt19937 rng(54321);
  std::uniform_real_distribution<double> scale(0.8, 1.0);
  std::vector<slope::SlipPolyline> surfaces;
  for (const slope::Circle& c : circles) {
    auto p = slope::circle_as_polyline(section, c, 32);
    if (!p) continue;
    const slope::Point a = p->points.front(), b = p->points.back();
    const double f = scale(rng);
    for (std::size_t i = 1; i + 1 < p->points.size(); ++i) {
      const double on_chord = a.y + (b.y - a.y) * (p->points[i].x - a.x) / (b.x - a.x);
      p->points[i].y = on_chord - f * (on_chord - p->points[i].y);
    }
    p->moment_point.reset();
    const auto mass = slope::slice_polyline(section, *p, slope::SliceOptions{50});
    if (mass && slope::factor_of_safety(*mass, slope::Method::spencer).factor_of_safety) surfaces.push_back(*p);
  }
  long evaluated = 0, slices = 0;
  double checksum = 0.0, seconds = 0.0;
  const auto start = Clock::now();
  do {
    for (const slope::SlipPolyline& p : surfaces) {
      const auto mass = slope::slice_polyline(section, p, slope::SliceOptions{50});
      if (!mass) continue;
      if (auto fs = slope::factor_of_safety(*mass, slope::Method::spencer).factor_of_safety) checksum += *fs;
      slices += static_cast<long>(mass->slices.size());
      ++evaluated;
    }
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } while (seconds < 1.5);
  std::printf("%-28s %10.0f trial polylines/s (%.1f slices per polyline, %zu polylines, mean FS %.4f; public "
              "slice_polyline + factor_of_safety, allocating)\n",
              "Spencer, 32-segment polyline", evaluated / seconds, static_cast<double>(slices) / evaluated,
              surfaces.size(), checksum / evaluated);
}

void noncircular_time(const char* name, const std::vector<slope::Method>& methods, const slope::Section& section) {
  const slope::SearchResult circular = slope::search_critical(section, methods, slope::SearchOptions{});
  std::vector<double> times;
  slope::NonCircularResult last;
  for (int run = 0; run < 5; ++run) {
    const auto start = Clock::now();
    last = slope::search_noncircular(section, circular, slope::SearchOptions{});
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  std::printf("%-28s median %.4f s (min %.4f s) over 5 runs after the circular search, %ld trial polylines;", name,
              times[times.size() / 2], times.front(), last.trial_surfaces);
  for (const slope::NonCircularSurface& c : last.methods)
    std::printf(" %s %.4f", std::string(slope::method_key(c.method)).c_str(),
                c.result.factor_of_safety.value_or(std::nan("")));
  std::printf("\n");
}

}  // namespace

int main() {
  const slope::Section section = griffiths_lane();
  std::printf("bench-lem: Griffiths & Lane (1999) homogeneous slope (H = 10 m, 2:1, c' = 10 kPa, phi' = 20 deg), "
              "one core\n");
  const std::vector<slope::Circle> circles = trial_circles(section, 2000);
  throughput("Bishop simplified", slope::Method::bishop, section, circles);
  throughput("Spencer", slope::Method::spencer, section, circles);
  throughput("Morgenstern-Price half-sine", slope::Method::morgenstern_price, section, circles);
  throughput("Ordinary", slope::Method::ordinary, section, circles);
  throughput("Janbu simplified", slope::Method::janbu, section, circles);
  search_time("default search, Bishop", {slope::Method::bishop}, section);
  search_time("default search, all methods", slope::all_methods(), section);
  std::printf("Hammah et al. (2005) 45 degree rock slope: Mohr-Coulomb (c' 17 kPa, phi' 24 deg), then the "
              "generalized Hoek-Brown envelope\n");
  for (bool hoek_brown : {false, true}) {
    const slope::Section rock = hammah(hoek_brown);
    search_time(hoek_brown ? "Hoek-Brown, Bishop" : "Mohr-Coulomb, Bishop", {slope::Method::bishop}, rock);
    search_time(hoek_brown ? "Hoek-Brown, all methods" : "Mohr-Coulomb, all methods", slope::all_methods(), rock);
  }
  std::printf("Duncan & Wright (2005) Fig. 7.28 fill: bare, then with five geogrids active, then passive\n");
  for (int grids : {0, 1, 2}) {
    const slope::Section fill = geogrid_fill(grids);
    const char* names[][2] = {{"bare, Bishop", "bare, all methods"},
                              {"active grids, Bishop", "active grids, all methods"},
                              {"passive grids, Bishop", "passive grids, all methods"}};
    search_time(names[grids][0], {slope::Method::bishop}, fill);
    search_time(names[grids][1], slope::all_methods(), fill);
  }
  polyline_throughput(section, circles);
  noncircular_time("non-circular, Spencer", {slope::Method::spencer}, section);
  noncircular_time("non-circular, all methods", slope::all_methods(), section);
  return 0;
}
