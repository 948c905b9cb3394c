#pragma once
// Rapid drawdown by the three-stage procedure of Duncan, Wright & Wong (1990), as XSLOPE and Slide2 document it:
//   1. the slope before drawdown, drained strengths and the water before: each slice base's consolidation stresses
//      sigma'_fc = N'/l and tau_fc = (c' + sigma'_fc tan phi') / F_1;
//   2. the water after drawdown; in each material that does not drain freely, the undrained strength interpolated on
//      K_c = sigma'_1c / sigma'_3c between the K_c = 1 envelope tau = d + sigma'_fc tan psi and the effective-stress
//      envelope (at K_c = K_f): tau_ff = [(K_f - K_c) tau(K_c = 1) + (K_c - 1) tau(K_f)] / (K_f - 1), the base then
//      c = tau_ff, phi = 0;
//   3. where the drained strength under the water after drawdown, c' + sigma' tan phi' with sigma' from stage 2, is
//      lower than tau_ff, the base takes it, and the factor is solved again.
// The factor of safety is the lower of stages 2 and 3. One slip surface throughout, one method for every stage.
#include <optional>
#include <string>
#include <vector>

#include "slope/methods.hpp"

namespace slope {

// The K_c = 1 envelope of a material that does not drain freely: tau_ff = d + sigma'_fc tan(psi).
struct ConsolidatedEnvelope {
  double intercept = 0.0;  // d, Pa
  double tan_slope = 0.0;  // tan(psi)
};

struct DrawdownInput {
  Section before;  // the section with the water before drawdown
  Section after;   // the same with the water after drawdown
  // per material of the sections: its K_c = 1 envelope; empty: free-draining (drained strengths in every stage)
  std::vector<std::optional<ConsolidatedEnvelope>> envelopes;
  Method method = Method::spencer;
  SliceOptions slicing;
};

struct DrawdownSlice {
  double base_x = 0.0;                       // m
  bool undrained = false;                    // in a material that does not drain freely
  double consolidation_normal = 0.0;         // sigma'_fc, Pa
  double consolidation_shear = 0.0;          // tau_fc, Pa
  double undrained_strength = 0.0;           // tau_ff, Pa (undrained slices)
  double drained_strength = 0.0;             // c' + sigma' tan phi' after drawdown (stage 2's sigma'), Pa
  bool drained_governs = false;              // stage 3 took the drained strength
};

struct DrawdownResult {
  std::optional<double> factor_of_safety;  // the lower of stages 2 and 3; empty with `error`
  std::optional<double> stage1, stage2, stage3;  // stage 3 only when a slice took its drained strength
  std::vector<DrawdownSlice> slices;             // of the surface after drawdown (stages 2 and 3)
  std::string error;
};

// The three stages on the slip surface (a circle when `polyline` is empty). Materials with a non-linear strength
// envelope are refused (error).
DrawdownResult rapid_drawdown(const DrawdownInput& input, const std::optional<Circle>& circle,
                              const SlipPolyline& polyline);

// tau_ff of one base from its consolidation stresses and its material's c', phi' and K_c = 1 envelope (Pa).
double drawdown_undrained_strength(double sigma_fc, double tau_fc, double cohesion, double tan_friction,
                                   const ConsolidatedEnvelope& envelope);

}  // namespace slope
