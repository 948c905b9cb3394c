#pragma once
// Fixed-width text tables for the terminal.
#include <string>

#include "coupling/scene/scene.hpp"
#include "slope/search.hpp"

namespace coupling {

// Fixed-width table of the critical surface per method (FS, centre, radius, entry, exit) and the search totals.
std::string lem_table(const LemAnalysis& analysis, const slope::SearchResult& result);

}  // namespace coupling
