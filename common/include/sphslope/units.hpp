#pragma once
// Constants and unit conversions shared by every library of the project: one spelling of pi, one degree, one g.
// Angles are stored in radians in slope/ and in the scene, and in degrees (fields named *_deg) in sph/'s material,
// which users set and read in degrees; these two functions are the only conversions between them.
#include <numbers>

namespace sphslope {

inline constexpr double pi = std::numbers::pi;
inline constexpr double degree = pi / 180.0;  // one degree in radians

constexpr double radians(double degrees_value) { return degrees_value * degree; }
constexpr double degrees(double radians_value) { return radians_value * 180.0 / pi; }

// Standard gravity [m/s^2], as in the source thesis (densities are unit weight / g).
inline constexpr double standard_gravity = 9.81;

}  // namespace sphslope
