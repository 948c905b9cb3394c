// Newmark's rigid-block displacement (slope/newmark.hpp) against closed forms.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "slope/newmark.hpp"

namespace {

constexpr double g = 9.81;

// A rectangular pulse of A g from t = 0 to T, sampled every T / n, then n samples of 0.
slope::AccelerationRecord pulse(double A, double T, int n) {
  slope::AccelerationRecord r;
  r.time_step = T / n;
  for (int i = 0; i <= n; ++i) r.acceleration.push_back(A);
  for (int i = 0; i < n; ++i) r.acceleration.push_back(0.0);
  return r;
}

}  // namespace

TEST_CASE("Newmark: a rectangular pulse against the closed form d = (A - k_c) A g T^2 / (2 k_c)",
          "[slope][seismic][closed_form]") {
  // Newmark (1965): a rectangular pulse of A g over T on a block of yield coefficient k_c < A: the relative velocity
  // grows at (A - k_c) g to (A - k_c) g T, then falls at k_c g to zero, at t = T A / k_c. The sampled pulse falls
  // from A to 0 over one time step (the record is linear between samples), which lengthens it by half a step: an
  // error of first order in T / n.
  const double A = 0.4, kc = 0.1, T = 1.0;
  const double exact = (A - kc) * A * g * T * T / (2.0 * kc);
  const slope::NewmarkResult fine = slope::newmark_displacement(pulse(A, T, 4000), kc);
  const slope::NewmarkResult coarse = slope::newmark_displacement(pulse(A, T, 1000), kc);
  CHECK(fine.displacement == Approx(exact).epsilon(5e-4));
  CHECK(fine.peak_velocity == Approx((A - kc) * g * T).epsilon(5e-4));
  CHECK(fine.sliding_time == Approx(T * A / kc).epsilon(5e-4));
  CHECK(fine.sliding_episodes == 1);
  // first order: four times the steps, a quarter of the error
  const double ratio = (coarse.displacement - exact) / (fine.displacement - exact);
  CHECK(ratio == Approx(4.0).epsilon(0.05));
  // The other way round the pulse pushes the block upslope: no downslope displacement.
  CHECK(slope::newmark_displacement(pulse(A, T, 1000), kc, -1.0).displacement == 0.0);
  // A pulse below k_c moves nothing; a scale of 2 is a pulse of 2 A.
  CHECK(slope::newmark_displacement(pulse(0.09, T, 100), kc).displacement == 0.0);
  CHECK(slope::newmark_displacement(pulse(0.2, T, 4000), kc, 2.0).displacement ==
        Approx(fine.displacement).epsilon(1e-12));
}

TEST_CASE("Newmark: a linear ramp is integrated exactly, whatever the sampling", "[slope][seismic][closed_form]") {
  // a(t) = 2 k_c t / T over [0, T], then the ground at rest: sliding from T/2, where a = k_c, with relative
  // velocity g k_c (t - T/2)^2 / T, v(T) = g k_c T / 4 and x(T) = g k_c T^2 / 24; then v^2 / (2 k_c g) = g k_c T^2 / 32
  // more. d = 7 g k_c T^2 / 96 and 3 T / 4 of sliding: exact for a record linear between its samples.
  const double kc = 0.15, T = 2.0;
  for (int n : {1, 7, 100}) {
    INFO(n << " steps");
    slope::AccelerationRecord r;
    r.time_step = T / n;
    for (int i = 0; i <= n; ++i) r.acceleration.push_back(2.0 * kc * i / n);
    const slope::NewmarkResult out = slope::newmark_displacement(r, kc);
    CHECK(out.displacement == Approx(7.0 * g * kc * T * T / 96.0).epsilon(1e-12));
    CHECK(out.sliding_time == Approx(0.75 * T).epsilon(1e-12));
    CHECK(out.peak_velocity == Approx(g * kc * T / 4.0).epsilon(1e-12));
  }
}

TEST_CASE("Newmark: the block stops between pulses and starts again", "[slope][seismic]") {
  // Two rectangular pulses 3 s apart, each rising from 0 over one step and moving the block as the single pulse
  // does (it stops after about T A / k_c = 2 s): twice the displacement, two episodes.
  const double A = 0.3, kc = 0.15, T = 1.0;
  slope::AccelerationRecord r = pulse(A, T, 1000);
  r.acceleration.insert(r.acceleration.begin(), 0.0);
  const double single = slope::newmark_displacement(r, kc).displacement;
  slope::AccelerationRecord two = r;
  for (int i = 0; i < 2000; ++i) two.acceleration.push_back(0.0);
  two.acceleration.insert(two.acceleration.end(), r.acceleration.begin(), r.acceleration.end());
  const slope::NewmarkResult out = slope::newmark_displacement(two, kc);
  CHECK(out.sliding_episodes == 2);
  CHECK(out.displacement == Approx(2.0 * single).epsilon(1e-9));
}

TEST_CASE("Newmark: a record without a positive time step or with a non-finite sample is refused",
          "[slope][seismic]") {
  slope::AccelerationRecord r;
  r.time_step = 0.01;
  r.acceleration = {0.0, 0.1};
  CHECK(slope::record_error(r).empty());
  r.time_step = 0.0;
  CHECK(slope::record_error(r).find("time step") != std::string::npos);
  r.time_step = 0.01;
  r.acceleration = {0.0};
  CHECK(slope::record_error(r).find("two samples") != std::string::npos);
  r.acceleration = {0.0, std::nan("")};
  CHECK(slope::record_error(r).find("sample 2") != std::string::npos);
}
