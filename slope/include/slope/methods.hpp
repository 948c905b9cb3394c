#pragma once
// Methods of slices: factor of safety of one slip mass.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "slope/slices.hpp"

namespace slope {

enum class Method {
  ordinary,                    // Fellenius / ordinary method of slices (moment)
  bishop,                      // Bishop simplified (moment, horizontal interslice forces)
  janbu,                       // Janbu simplified (force), without correction
  janbu_corrected,             // Janbu simplified times the f0 correction factor
  spencer,                     // Spencer: force and moment, constant interslice angle
  morgenstern_price,           // Morgenstern-Price with the half-sine interslice function
  morgenstern_price_constant,  // Morgenstern-Price with the constant interslice function
};

// Stable key used in scene files and reports ("ordinary", "bishop", ...).
std::string_view method_key(Method method);
std::optional<Method> method_from_key(std::string_view key);
const std::vector<Method>& all_methods();
// Whether the method solves for an interslice-force inclination (Spencer tan(theta), Morgenstern-Price lambda).
bool has_interslice_lambda(Method method);

// Forces on one slice at the solution, per metre of slope width.
struct SliceForces {
  double normal = 0.0;             // N/m, total normal force on the base
  double shear = 0.0;              // N/m, mobilised shear force on the base (available / FS)
  double pore_force = 0.0;         // N/m, u * base length
  double interslice_normal_right = 0.0;  // N/m, E on the right side (0 where the method has none)
  double interslice_shear_right = 0.0;   // N/m, X on the right side
};

struct FsResult {
  std::optional<double> factor_of_safety;  // empty when the method failed on this surface
  std::string error;                       // why it failed (empty on success)
  double lambda = 0.0;                     // Spencer tan(theta) / Morgenstern-Price lambda (0 otherwise)
  int iterations = 0;
  std::vector<SliceForces> forces;         // filled only when asked for
};

FsResult factor_of_safety(const SlipMass& mass, Method method, bool with_forces = false);

}  // namespace slope
