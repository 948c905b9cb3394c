// Rapid drawdown, the three stages of Duncan, Wright & Wong (1990) (slope/drawdown.hpp).
#include "slope/drawdown.hpp"

#include <algorithm>
#include <cmath>

namespace slope {

double drawdown_undrained_strength(double sigma_fc, double tau_fc, double cohesion, double tan_friction,
                                   const ConsolidatedEnvelope& envelope) {
  const double phi = std::atan(tan_friction), s = std::sin(phi), c = std::cos(phi);
  const double at_one = envelope.intercept + sigma_fc * envelope.tan_slope;  // K_c = 1
  const double at_failure = cohesion + sigma_fc * tan_friction;              // K_c = K_f: the drained envelope
  const double sigma_3c = sigma_fc - tau_fc * (1.0 - s) / c;
  const double sigma_3f = (sigma_fc - cohesion * c) * (1.0 - s) / (c * c);
  // a consolidation stress state with no positive minor principal stress: the lower envelope (XSLOPE, DWW)
  if (!(sigma_3c > 0.0) || !(sigma_3f > 0.0) || !(s > 0.0)) return std::max(0.0, std::min(at_one, at_failure));
  const double kc = (sigma_fc + tau_fc * (1.0 + s) / c) / sigma_3c;
  const double kf = (sigma_fc + cohesion * c) * (1.0 + s) / ((sigma_fc - cohesion * c) * (1.0 - s));
  const double k = std::clamp(kc, 1.0, kf);
  return std::max(0.0, ((kf - k) * at_one + (k - 1.0) * at_failure) / (kf - 1.0));
}

namespace {

std::optional<SlipMass> slice(const Section& section, const std::optional<Circle>& circle, const SlipPolyline& polyline,
                              const SliceOptions& options, std::string& why) {
  return circle ? slice_circle(section, *circle, options, &why) : slice_polyline(section, polyline, options, &why);
}

// The stage-1 value at x, linear between the slices' base midpoints (constant beyond the ends).
double at(const std::vector<double>& xs, const std::vector<double>& values, double x) {
  if (x <= xs.front()) return values.front();
  if (x >= xs.back()) return values.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return values[i - 1] + t * (values[i] - values[i - 1]);
}

// sigma' = N'/l of each slice of a solution.
std::vector<double> effective_normal(const SlipMass& mass, const FsResult& r) {
  std::vector<double> out;
  for (std::size_t i = 0; i < mass.slices.size(); ++i)
    out.push_back((r.forces[i].normal - r.forces[i].pore_force) / mass.slices[i].base_length);
  return out;
}

}  // namespace

DrawdownResult rapid_drawdown(const DrawdownInput& in, const std::optional<Circle>& circle,
                              const SlipPolyline& polyline) {
  DrawdownResult out;
  for (const Material& m : in.before.materials)
    if (m.envelope) {
      out.error = "material \"" + m.name + "\" has a non-linear strength envelope (rapid drawdown takes c', phi')";
      return out;
    }
  std::string why;
  const auto first = slice(in.before, circle, polyline, in.slicing, why);
  const auto mass = first ? slice(in.after, circle, polyline, in.slicing, why) : std::nullopt;
  if (!first || !mass) {
    out.error = "not an admissible slip surface: " + why;
    return out;
  }
  // stage 1: the consolidation stresses
  const FsResult one = factor_of_safety(*first, in.method, true);
  out.stage1 = one.factor_of_safety;
  if (!one.factor_of_safety) {
    out.error = "stage 1 (before drawdown) did not converge: " + one.error;
    return out;
  }
  if (*one.factor_of_safety < 1.0) {
    out.error = "stage 1 (before drawdown) has FS < 1: the slope fails before the drawdown";
    return out;
  }
  std::vector<double> xs, sigma, tau;
  const std::vector<double> normal = effective_normal(*first, one);
  for (std::size_t i = 0; i < first->slices.size(); ++i) {
    const Slice& s = first->slices[i];
    xs.push_back(s.base_x);
    sigma.push_back(normal[i]);
    tau.push_back((s.cohesion + std::max(0.0, normal[i]) * s.tan_friction) / *one.factor_of_safety);
  }
  // stage 2: undrained strengths where the material does not drain freely
  SlipMass two = *mass;
  for (Slice& s : two.slices) {
    DrawdownSlice d;
    d.base_x = s.base_x;
    const auto& envelope = in.envelopes[s.base_material];
    d.undrained = envelope.has_value();
    d.consolidation_normal = at(xs, sigma, s.base_x);
    d.consolidation_shear = at(xs, tau, s.base_x);
    if (d.undrained) {
      d.undrained_strength = drawdown_undrained_strength(std::max(0.0, d.consolidation_normal), d.consolidation_shear,
                                                         s.cohesion, s.tan_friction, *envelope);
      s.cohesion = d.undrained_strength;
      s.tan_friction = 0.0;
    }
    out.slices.push_back(d);
  }
  const FsResult second = factor_of_safety(two, in.method, true);
  out.stage2 = second.factor_of_safety;
  if (!second.factor_of_safety) {
    out.error = "stage 2 (undrained, after drawdown) did not converge: " + second.error;
    return out;
  }
  // stage 3: the drained strength where it is lower
  SlipMass three = two;
  const std::vector<double> after = effective_normal(two, second);
  bool switched = false;
  for (std::size_t i = 0; i < three.slices.size(); ++i) {
    DrawdownSlice& d = out.slices[i];
    if (!d.undrained) continue;
    const Slice& drained = mass->slices[i];
    d.drained_strength = drained.cohesion + std::max(0.0, after[i]) * drained.tan_friction;
    if (d.drained_strength < d.undrained_strength) {
      d.drained_governs = switched = true;
      three.slices[i].cohesion = drained.cohesion;
      three.slices[i].tan_friction = drained.tan_friction;
    }
  }
  out.factor_of_safety = out.stage2;
  if (switched) {
    const FsResult third = factor_of_safety(three, in.method);
    out.stage3 = third.factor_of_safety;
    if (third.factor_of_safety) out.factor_of_safety = std::min(*out.stage2, *third.factor_of_safety);
  }
  return out;
}

}  // namespace slope
