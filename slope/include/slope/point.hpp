#pragma once
// A point of a cross-section (limit equilibrium).

namespace slope {

struct Point {
  double x = 0.0;  // m
  double y = 0.0;  // m
};

}  // namespace slope
