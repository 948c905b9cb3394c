// CircleEvaluator: the search's non-allocating trial path, exposed for benchmarks and studies.
#include "slope/evaluator.hpp"

#include <stdexcept>

#include "method_kernels.hpp"
#include "slice_table.hpp"

namespace slope {

struct CircleEvaluator::Impl {
  explicit Impl(const Section& section, const SliceOptions& o) : slicer(section), options(o) {}
  detail::Slicer slicer;
  SliceOptions options;
  detail::SliceTable table;
  detail::MethodWorkspace workspace;
  detail::Rejection rejection = detail::Rejection::none;
  detail::Outcome outcome;
  Method method = Method::bishop;
};

CircleEvaluator::CircleEvaluator(const Section& section, const SliceOptions& options) {
  if (const std::string error = section_error(section); !error.empty())
    throw std::invalid_argument("slope::CircleEvaluator: invalid section: " + error);
  impl_ = std::make_unique<Impl>(section, options);
}

CircleEvaluator::~CircleEvaluator() = default;
CircleEvaluator::CircleEvaluator(CircleEvaluator&&) noexcept = default;
CircleEvaluator& CircleEvaluator::operator=(CircleEvaluator&&) noexcept = default;

std::optional<double> CircleEvaluator::factor_of_safety(const Circle& circle, Method method) {
  Impl& s = *impl_;
  s.method = method;
  s.outcome = detail::Outcome{};
  s.rejection = s.slicer.slice(circle, s.options.slices, s.table);
  if (s.rejection != detail::Rejection::none) return std::nullopt;
  s.outcome = detail::evaluate_method(s.table, method, s.workspace);
  if (!s.outcome.ok()) return std::nullopt;
  return s.outcome.factor_of_safety;
}

std::string CircleEvaluator::last_error() const {
  const Impl& s = *impl_;
  if (s.rejection != detail::Rejection::none) return detail::rejection_text(s.rejection);
  if (!s.outcome.ok()) return std::string(method_key(s.method)) + ": " + detail::describe_failure(s.outcome, s.table);
  return {};
}

int CircleEvaluator::last_slice_count() const { return impl_->table.count; }

}  // namespace slope
