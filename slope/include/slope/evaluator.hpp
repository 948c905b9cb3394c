#pragma once
// Fast repeated evaluation of trial circles on one section (search loops, benchmarks, coupling studies):
// slicing and factor of safety without allocating per trial once the internal buffers have grown.
// Gives the same numbers as slice_circle() followed by factor_of_safety(). Not thread-safe: one per thread.
#include <memory>
#include <optional>
#include <string>

#include "slope/methods.hpp"
#include "slope/slices.hpp"

namespace slope {

class CircleEvaluator {
 public:
  explicit CircleEvaluator(const Section& section, const SliceOptions& options = {});
  ~CircleEvaluator();
  CircleEvaluator(CircleEvaluator&&) noexcept;
  CircleEvaluator& operator=(CircleEvaluator&&) noexcept;

  // Factor of safety of the mass above `circle` by `method`; empty when the circle is not an admissible slip
  // surface or the method fails on it (last_error() then says why).
  std::optional<double> factor_of_safety(const Circle& circle, Method method);
  // Why the last call returned nothing; empty after a success. (Formats the message on demand.)
  std::string last_error() const;
  // Number of slices of the last admissible circle.
  int last_slice_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace slope
