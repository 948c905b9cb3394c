#pragma once
// The figures of an isph run (figures/ in the run folder, docs/scene-format.md): each gauge's surface elevation
// against time, the surge front against time with the scene's references, and particle snapshots coloured by
// pressure.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "coupling/analyses/isph_measures.hpp"
#include "coupling/analyses/monitor_table.hpp"
#include "coupling/scene/tank_scene.hpp"

namespace coupling {

// Every particle at the snapshot's time: the fluid coloured by pressure (kPa, colour bar), the walls grey; equal
// scales on both axes.
std::string isph_snapshot_svg(const IsphSnapshot& snapshot, const std::string& title);

// One line per gauge: its surface elevation relative to still_water [m] against time [s].
std::string isph_gauges_svg(const MonitorTable& monitors, const std::vector<Gauge>& gauges, double still_water,
                            const std::string& title);

// What the front figure draws besides the run's front.
struct FrontFigureReferences {
  std::vector<std::pair<double, double>> points;  // (t [s], x [m]) of a tabulated front
  std::string points_label;
  std::optional<double> ritter_dam_x, ritter_depth, gravity;  // Ritter's front from the dam [m], h0 [m], g [m/s^2]
  std::optional<double> far_wall_x;  // the inner face of the tank's right wall [m]
};

// The front_x_m column against time, with the references.
std::string isph_front_svg(const MonitorTable& monitors, const FrontFigureReferences& references,
                           const std::string& title);

}  // namespace coupling
