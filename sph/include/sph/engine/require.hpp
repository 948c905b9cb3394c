#pragma once
// The checks the settings' validate() functions share: a failed one throws std::invalid_argument with its message.

#include <cmath>
#include <stdexcept>
#include <string>

namespace sph {

inline void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

inline bool finite_positive(double v) { return std::isfinite(v) && v > 0; }

}  // namespace sph
