#pragma once
// Exact comparison of two particle states (determinism and resume tests): every double array of the set (core
// fields and every registered field), the ids, materials and kinds, value by value, bit for bit.
#include <cstddef>
#include <vector>

#include "sph/engine/particle_set.hpp"

namespace same_state {

// The number of values in which `a` and `b` differ; every value counts when the sizes differ.
inline std::size_t differing_values(sph::ParticleSet& a, sph::ParticleSet& b) {
  std::vector<std::vector<double>*> da, db;
  a.for_each_double_array([&](std::vector<double>& v) { da.push_back(&v); });
  b.for_each_double_array([&](std::vector<double>& v) { db.push_back(&v); });
  if (a.size() != b.size() || da.size() != db.size()) return (da.size() + 3) * (a.size() + b.size()) + 1;
  std::size_t different = 0;
  for (std::size_t f = 0; f < da.size(); ++f)
    for (std::size_t i = 0; i < a.size(); ++i) different += (*da[f])[i] != (*db[f])[i];
  for (std::size_t i = 0; i < a.size(); ++i)
    different += (a.id[i] != b.id[i]) + (a.material[i] != b.material[i]) + (a.kind[i] != b.kind[i]);
  return different;
}

}  // namespace same_state
