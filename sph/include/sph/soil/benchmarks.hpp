#pragma once
// Reference problems shared by the tests and the benchmark program (no file I/O, no slopes).
#include "sph/soil/model.hpp"

namespace sph::soil {

// Granular column collapse of Bui et al. (2008), IJNAMG 32:1537, aluminium bars:
// column `length` x `height` (0.2 m x 0.1 m) resting on a rigid floor against a back wall at x = 0,
// released at once from its vertical right face. rho = 2650 kg/m^3, E = 0.84 MPa, nu = 0.3,
// phi = 19.8 deg, c = 0, psi = 0; gravity applied at once.
struct ColumnCollapseCase {
  double dx = 0.005;
  double h_over_dx = 1.2;
  double length = 0.2, height = 0.1;
  double floor_length = 0.6;  // inner box length (run-out space)
  double end_time = 1.0;
  KernelType kernel = KernelType::cubic_spline;
  WallSlip wall_slip = WallSlip::no_slip;
};

// The aluminium bars of that case (rho = 2650 kg/m^3, E = 0.84 MPa, nu = 0.3, phi = 19.8 deg, c = 0, psi = 0).
Material aluminium_bars();

Model make_column_collapse(const ColumnCollapseCase& c);

struct DepositShape {
  double runout = 0;  // furthest soil extent from the back wall [m] (particle centre + dx/2)
  double height = 0;  // highest soil extent above the floor [m] (particle centre + dx/2)
};

// Deposit extent; particles with fewer than 2 soil neighbours within 1.5 dx (isolated splashes) are ignored.
DepositShape measure_deposit(const Model& model, double floor_y = 0.0, double back_wall_x = 0.0);

}  // namespace sph::soil
