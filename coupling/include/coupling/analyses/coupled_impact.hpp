#pragma once
// A coupled run's slide impact (analyses.coupled.impact; docs/coupled.md, "Impact parameters"): the slide's
// parameters when its centroid reaches the still water, read from slide.csv, the impulse wave Heller & Hager (2010)
// predict from them (impulse_waves.hpp), and what the gauges saw against it.
#include <optional>
#include <string>
#include <vector>

#include "coupling/analyses/impulse_waves.hpp"
#include "coupling/analyses/isph_waves.hpp"
#include "coupling/analyses/monitor_table.hpp"
#include "coupling/scene/coupled_analysis.hpp"
#include "coupling/scene/tank_scene.hpp"

namespace coupling {

// slide.csv's column of the slide's largest thickness normal to the ramp [m].
inline constexpr const char* slide_thickness_column = "thickness_normal_to_ramp_m";

struct CelerityCheck {
  std::string from, to;
  double speed = 0;     // the leading crest's distance over its travel time between the gauges [m/s]
  double expected = 0;  // [g (h + a)]^(1/2), a the mean of the two gauges' leading crests [m/s]
};

struct CoupledImpact {
  // why there is no impact (the centroid started below the still water or never reached it); empty when there is
  std::string missing;
  double time = 0;            // when the centroid reached the still water (linear between slide.csv's rows) [s]
  SlideImpact slide;          // v_s, s, m_s / b, alpha, h at that time
  ImpulseWave predicted;      // Heller & Hager (2010) from it
  // what the gauges saw: the largest elevation over every gauge and its distance from the shoreline
  std::string largest_crest_gauge;
  double largest_crest = 0, largest_crest_at = 0, largest_crest_distance = 0;  // [m], [s], [m]
  std::vector<CelerityCheck> celerity;
};

// The impact from slide.csv (centroid_y_m, centroid_speed_m_s, thickness_normal_to_ramp_m) and the gauges'
// records; `mass_per_width` the soil's mass [kg/m], `rho_w` the water's density, g gravity.
CoupledImpact coupled_impact(const MonitorTable& slide, const MonitorTable& monitors, const SlideImpactSetup& setup,
                             const TankMonitors& gauges, const Tank& tank, double mass_per_width, double g,
                             double rho_w);

}  // namespace coupling
