#pragma once
// Fixed-width text tables for the terminal.
#include <string>

#include <vector>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/scene/scene.hpp"
#include "slope/search.hpp"

namespace coupling {

// Fixed-width table of the critical surface per method (FS, centre, radius, entry, exit) and the search totals.
std::string lem_table(const LemAnalysis& analysis, const slope::SearchResult& result);

// The non-circular search (analyses.lem.noncircular_search): per method its FS, what the surface is, entry and exit.
std::string noncircular_table(const slope::NonCircularResult& result);
// "critical seismic coefficient (bishop): k_c = 0.2689 (FS 1.927 without k_h; ...)" or why there is none.
std::string critical_coefficient_line(slope::Method method, const slope::CriticalCoefficient& k);
// "Newmark displacement at k_c = 0.2689 under pulse.csv (PGA 0.40 g): 5.89 m (as given), 0.00 m (reversed)".
// "rapid drawdown (spencer, Duncan-Wright-Wong): "name": FS 1.434 (before 2.203, undrained 1.513, ...)" per surface.
std::string drawdown_lines(const DrawdownAnalysis& analysis, const std::vector<DrawdownSurfaceResult>& surfaces);
std::string newmark_line(const AccelerationRecordInput& record, const NewmarkOutcome& newmark, double yield_coefficient);

// One line per given slip surface (analyses.lem.surfaces) and method: FS, or why there is none.
std::string given_surfaces_table(const std::vector<GivenSurfaceResult>& surfaces);

}  // namespace coupling
