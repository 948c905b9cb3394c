#pragma once
// Checks shared by the limit-equilibrium tests: the factor of safety of a sliced mass, and the one a search found
// for a method; each fails the test (with the method's error) when there is none.
#include <catch2/catch.hpp>

#include "slope/methods.hpp"
#include "slope/search.hpp"

namespace lem_test {

inline double fs_on(const slope::SlipMass& mass, slope::Method m, double* lambda = nullptr) {
  const slope::FsResult r = slope::factor_of_safety(mass, m);
  INFO(slope::method_key(m) << ": " << r.error);
  REQUIRE(r.factor_of_safety);
  if (lambda != nullptr) *lambda = r.lambda;
  return *r.factor_of_safety;
}

inline double searched(const slope::SearchResult& r, slope::Method m) {
  for (const slope::CriticalSurface& c : r.methods) {
    if (c.method != m) continue;
    INFO(slope::method_key(m) << ": " << c.result.error);
    REQUIRE(c.result.factor_of_safety);
    return *c.result.factor_of_safety;
  }
  FAIL("method missing");
  return 0.0;
}

}  // namespace lem_test
