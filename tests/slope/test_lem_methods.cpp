// Methods of slices on given slip surfaces: hand calculations, closed forms and consistency between methods.
#include <catch2/catch.hpp>

#include <cmath>

#include "lem_sections.hpp"
#include "slope/methods.hpp"
#include "slope/slices.hpp"

namespace test_lem_methods {

using Catch::Matchers::Contains;
using namespace lem_test;

namespace {

// A slice whose base chord has its midpoint on the circle of radius `arm` about (0, 0), with base angle alpha
// (mass sliding toward +x): the normal at the base midpoint passes through the centre, as for a real chord.
slope::Slice hand_slice(double alpha, double width, double weight, double cohesion, double tan_phi, double u,
                        double arm) {
  slope::Slice s;
  s.base_angle = alpha;
  s.width = width;
  s.base_length = width / std::cos(alpha);
  s.base_x = -arm * std::sin(alpha);
  s.base_y = -arm * std::cos(alpha);
  s.x_left = s.base_x - 0.5 * width;
  s.x_right = s.base_x + 0.5 * width;
  s.top_y = s.base_y + 3.0;
  s.weight = weight;
  s.cohesion = cohesion;
  s.tan_friction = tan_phi;
  s.pore_pressure = u;
  return s;
}

slope::SlipMass hand_mass(std::vector<slope::Slice> slices) {
  slope::SlipMass m;
  m.circle = slope::Circle{0.0, 0.0, 10.0};
  m.direction = 1;
  m.slices = std::move(slices);
  m.entry = slope::Point{m.slices.front().x_left, 0.0};
  m.exit = slope::Point{m.slices.back().x_right, 0.0};
  return m;
}

double fs(const slope::SlipMass& mass, slope::Method method) {
  const slope::FsResult r = slope::factor_of_safety(mass, method);
  INFO(slope::method_key(method) << ": " << r.error);
  REQUIRE(r.factor_of_safety.has_value());
  return *r.factor_of_safety;
}

// A long uniform slope of angle beta (degrees) and a shallow circle of very large radius through two points of
// its face 100 m apart: the infinite-slope limit (the base angle stays within 1.5 deg of beta).
struct LongSlope {
  slope::Section section;
  slope::Circle circle;
};

LongSlope long_slope(double beta_deg, const slope::Material& soil) {
  const double t = std::tan(radians(beta_deg));
  LongSlope ls;
  ls.section.bottom_y = -100.0;
  ls.section.materials.push_back(soil);
  ls.section.profile_lines.push_back(slope::ProfileLine{0, {{0, 300 * t}, {300, 0}}});
  const slope::Point p{100, 200 * t}, q{200, 100 * t};
  const double radius = 2000.0;
  const double length = std::hypot(q.x - p.x, q.y - p.y);
  const double h = std::sqrt(radius * radius - 0.25 * length * length);
  const double nx = (p.y - q.y) / length, ny = (q.x - p.x) / length;  // unit normal pointing up-right
  ls.circle = slope::Circle{0.5 * (p.x + q.x) + nx * h, 0.5 * (p.y + q.y) + ny * h, radius};
  return ls;
}

}  // namespace

TEST_CASE("method keys round-trip", "[slope][methods]") {
  for (slope::Method m : slope::all_methods()) CHECK(slope::method_from_key(slope::method_key(m)) == m);
  CHECK_FALSE(slope::method_from_key("swedish"));
  CHECK(slope::all_methods().size() == 7);
}

TEST_CASE("one slice checked by hand: Ordinary, Bishop, Janbu", "[slope][methods][hand]") {
  // alpha = 30 deg, b = 2 m, W = 100 kN/m, c' = 10 kPa, phi' = 30 deg, u = 20 kPa, moment arm R = 10 m.
  const double a = radians(30.0), b = 2.0, W = 100e3, c = 10e3, tp = std::tan(radians(30.0)), u = 20e3;
  const slope::SlipMass mass = hand_mass({hand_slice(a, b, W, c, tp, u, 10.0)});
  const double l = b / std::cos(a);
  // Ordinary (Fellenius), N' = W cos a - u l:  F = (c l + (W cos a - u l) tan phi) / (W sin a)
  const double ordinary = (c * l + (W * std::cos(a) - u * l) * tp) / (W * std::sin(a));
  CHECK(ordinary == Approx(0.928542).epsilon(1e-5));  // worked by hand: (23094.0 + 23333.6) / 50000
  CHECK(fs(mass, slope::Method::ordinary) == Approx(ordinary).epsilon(1e-12));
  // Bishop simplified: F = [c b + (W - u b) tan phi] / m_a / (W sin a), m_a = cos a + sin a tan phi / F
  double bishop = 1.0;
  for (int i = 0; i < 200; ++i)
    bishop = (c * b + (W - u * b) * tp) / (std::cos(a) + std::sin(a) * tp / bishop) / (W * std::sin(a));
  CHECK(fs(mass, slope::Method::bishop) == Approx(bishop).epsilon(1e-9));
  // Janbu simplified: F = [c b + (W - u b) tan phi] / (cos a m_a) / (W tan a)
  double janbu = 1.0;
  for (int i = 0; i < 200; ++i)
    janbu = (c * b + (W - u * b) * tp) / (std::cos(a) * (std::cos(a) + std::sin(a) * tp / janbu)) /
            (W * std::tan(a));
  CHECK(fs(mass, slope::Method::janbu) == Approx(janbu).epsilon(1e-9));
  // one slice: Bishop (moment) and Janbu (force) coincide when there is only one slice
  CHECK(bishop == Approx(janbu).epsilon(1e-9));
}

TEST_CASE("m_alpha below 0.2 near the toe is reported, not turned into a number", "[slope][methods][trap]") {
  // Whitman & Bailey (1967): a toe slice at -60 deg in a phi' = 35 deg soil. With a driving slice at +40 deg the
  // balancing F would need m_a = cos a + sin a tan phi / F < 0.2 on the toe slice (F < 2.02): rejected.
  const double tp = std::tan(radians(35.0));
  const slope::SlipMass mass = hand_mass({hand_slice(radians(40.0), 2.0, 400e3, 0.0, tp, 0.0, 10.0),
                                          hand_slice(radians(-60.0), 1.0, 20e3, 0.0, tp, 0.0, 10.0)});
  for (slope::Method method : {slope::Method::bishop, slope::Method::janbu, slope::Method::janbu_corrected}) {
    const slope::FsResult r = slope::factor_of_safety(mass, method);
    INFO(r.error);
    CHECK_FALSE(r.factor_of_safety);
    CHECK_THAT(r.error, Contains("m_alpha"));
    CHECK_THAT(r.error, Contains("Whitman"));
    CHECK_THAT(r.error, Contains("slice 2"));
  }
  CHECK(slope::factor_of_safety(mass, slope::Method::ordinary).factor_of_safety.has_value());
}

TEST_CASE("phi = 0: Bishop equals the Ordinary method on a circle", "[slope][methods][closed-form][validation]") {
  // With tan phi = 0, m_a = cos a and both reduce to F = sum(c l R) / sum(W x) (Bishop 1955).
  slope::Section s = griffiths_lane_1999();
  s.materials[0] = material("clay", 18.0, 40.0, 0.0);
  for (const slope::Circle& circle : {slope::Circle{36.0, 30.0, 20.0}, slope::Circle{30.0, 35.0, 30.0},
                                      slope::Circle{38.0, 26.0, 16.5}}) {
    const auto mass = slope::slice_circle(s, circle, {});
    REQUIRE(mass);
    const double ordinary = fs(*mass, slope::Method::ordinary);
    CHECK(fs(*mass, slope::Method::bishop) == Approx(ordinary).epsilon(1e-12));
    // moment equilibrium alone fixes F when phi = 0, so Spencer's F is the same (its lambda closes the forces)
    const slope::FsResult spencer = slope::factor_of_safety(*mass, slope::Method::spencer);
    INFO(spencer.error);
    REQUIRE(spencer.factor_of_safety);
    CHECK(*spencer.factor_of_safety == Approx(ordinary).epsilon(1e-8));
  }
}

TEST_CASE("infinite-slope limit: a very flat circle in a long uniform slope", "[slope][methods][closed-form][validation]") {
  // Infinite slope, c' = 0 (e.g. Duncan, Wright & Brandon 2014, ch. 6): F = tan(phi') / tan(beta); with pore
  // pressure ratio ru = u / (gamma z): F = (1 - ru sec^2 beta) tan(phi') / tan(beta); with a horizontal seismic
  // coefficient kh: F = (cos beta - kh sin beta) tan(phi') / (sin beta + kh cos beta). Every method tends to it.
  const double beta = 25.0, phi = 35.0;
  const double t = std::tan(radians(phi)) / std::tan(radians(beta));
  LongSlope ls = long_slope(beta, material("sand", 20.0, 0.0, phi));
  const std::vector<slope::Method> methods{slope::Method::ordinary, slope::Method::bishop, slope::Method::janbu,
                                           slope::Method::spencer, slope::Method::morgenstern_price};
  SECTION("dry") {
    const auto mass = slope::slice_circle(ls.section, ls.circle, {});
    REQUIRE(mass);
    for (slope::Method m : methods) {
      INFO(slope::method_key(m));
      CHECK(fs(*mass, m) == Approx(t).epsilon(0.005));
    }
  }
  SECTION("piezometric line at the ground surface (ru = gamma_w / gamma)") {
    ls.section.water = slope::Water{ls.section.profile_lines[0].points, 9810.0};
    const auto mass = slope::slice_circle(ls.section, ls.circle, {});
    REQUIRE(mass);
    const double ru = 9810.0 / 20e3;
    const double expected = (1.0 - ru / std::pow(std::cos(radians(beta)), 2)) * t;
    for (slope::Method m : methods) {
      INFO(slope::method_key(m));
      CHECK(fs(*mass, m) == Approx(expected).epsilon(0.01));
    }
  }
  SECTION("seismic coefficient 0.1") {
    ls.section.seismic_coefficient = 0.1;
    const auto mass = slope::slice_circle(ls.section, ls.circle, {});
    REQUIRE(mass);
    const double b = radians(beta);
    const double expected =
        (std::cos(b) - 0.1 * std::sin(b)) * std::tan(radians(phi)) / (std::sin(b) + 0.1 * std::cos(b));
    for (slope::Method m : methods) {
      INFO(slope::method_key(m));
      CHECK(fs(*mass, m) == Approx(expected).epsilon(0.01));
    }
  }
}

TEST_CASE("a fully submerged slope has the factor of safety of the dry slope with buoyant unit weight",
          "[slope][methods][water]") {
  // Hydrostatics: free water above the ground plus the pore pressure below it act on the mass as buoyancy, so
  // with effective-stress strength F(submerged, gamma) = F(dry, gamma - gamma_w) for methods that take water
  // as boundary pressures (Bishop, Janbu; e.g. Duncan, Wright & Brandon 2014, sec. 6.7).
  slope::Section wet = griffiths_lane_1999();
  wet.water = slope::Water{{{0, 25}, {60, 25}}, 9810.0};  // 5 m above the crest
  slope::Section buoyant = griffiths_lane_1999();
  buoyant.materials[0].unit_weight = 20e3 - 9810.0;
  for (const slope::Circle& circle : {slope::Circle{36.0, 30.0, 20.0}, slope::Circle{33.0, 34.0, 26.0}}) {
    const auto a = slope::slice_circle(wet, circle, slope::SliceOptions{100});
    const auto b = slope::slice_circle(buoyant, circle, slope::SliceOptions{100});
    REQUIRE(a);
    REQUIRE(b);
    for (slope::Method m : {slope::Method::bishop, slope::Method::janbu}) {
      INFO(slope::method_key(m));
      CHECK(fs(*a, m) == Approx(fs(*b, m)).epsilon(1e-3));
    }
  }
}

TEST_CASE("a surcharge adds its moment about the centre (phi = 0, checked from the slices)",
          "[slope][methods][hand]") {
  slope::Section s = griffiths_lane_1999();
  s.materials[0] = material("clay", 18.0, 40.0, 0.0);
  const slope::Circle circle{36.0, 30.0, 20.0};
  const auto bare = slope::slice_circle(s, circle, {});
  s.surcharges.push_back(slope::Surcharge{12.0, 24.0, 30e3});
  const auto loaded = slope::slice_circle(s, circle, {});
  REQUIRE(bare);
  REQUIRE(loaded);
  // F = sum(c l d) / sum(W (xc - x)); the surcharge adds q b (xc - x) on the slices it covers
  double resisting = 0.0, driving = 0.0, extra = 0.0;
  for (const slope::Slice& sl : loaded->slices) {
    const double d = std::hypot(sl.base_x - circle.xc, sl.base_y - circle.yc);
    resisting += sl.cohesion * sl.base_length * d;
    driving += sl.weight * (circle.xc - sl.base_x);
    const double covered = std::max(0.0, std::min(24.0, sl.x_right) - std::max(12.0, sl.x_left));
    CHECK(sl.surcharge_load == Approx(30e3 * covered).epsilon(1e-12).margin(1e-6));
    extra += 30e3 * covered * (circle.xc - sl.base_x);
  }
  CHECK(extra > 0.0);
  CHECK(fs(*loaded, slope::Method::bishop) == Approx(resisting / (driving + extra)).epsilon(1e-10));
  CHECK(fs(*loaded, slope::Method::bishop) < fs(*bare, slope::Method::bishop));
}

TEST_CASE("Janbu's correction factor f0 follows Janbu (1973)", "[slope][methods]") {
  // f0 = 1 + b1 (d/L - 1.4 (d/L)^2), b1 = 0.50 for c-phi soil; for a circle d = R - (distance centre-chord).
  const slope::Section s = griffiths_lane_1999();
  const slope::Circle circle{36.0, 30.0, 20.0};
  const auto mass = slope::slice_circle(s, circle, {});
  REQUIRE(mass);
  const double lx = mass->exit.x - mass->entry.x, ly = mass->exit.y - mass->entry.y;
  const double L = std::hypot(lx, ly);
  const double dist = std::fabs((circle.xc - mass->entry.x) * ly - (circle.yc - mass->entry.y) * lx) / L;
  const double ratio = (circle.radius - dist) / L;
  const double f0 = 1.0 + 0.5 * (ratio - 1.4 * ratio * ratio);
  CHECK(f0 > 1.0);
  CHECK(fs(*mass, slope::Method::janbu_corrected) ==
        Approx(f0 * fs(*mass, slope::Method::janbu)).epsilon(1e-12));
}

TEST_CASE("Spencer equals Morgenstern-Price with f = 1, the forces close every slice", "[slope][methods]") {
  slope::Section s = griffiths_lane_1999();
  s.water = slope::Water{{{0, 16}, {25, 14}, {60, 11}}, 9810.0};
  s.seismic_coefficient = 0.05;
  const slope::Circle circle{36.0, 32.0, 22.0};
  const auto mass = slope::slice_circle(s, circle, {});
  REQUIRE(mass);
  const slope::FsResult spencer = slope::factor_of_safety(*mass, slope::Method::spencer, true);
  const slope::FsResult constant = slope::factor_of_safety(*mass, slope::Method::morgenstern_price_constant, true);
  const slope::FsResult half_sine = slope::factor_of_safety(*mass, slope::Method::morgenstern_price, true);
  REQUIRE(spencer.factor_of_safety);
  REQUIRE(constant.factor_of_safety);
  REQUIRE(half_sine.factor_of_safety);
  CHECK(*spencer.factor_of_safety == *constant.factor_of_safety);
  CHECK(spencer.lambda == constant.lambda);
  CHECK(spencer.lambda > 0.0);  // interslice shear holds the upslope part up
  CHECK(*half_sine.factor_of_safety == Approx(*spencer.factor_of_safety).epsilon(0.01));

  double total_load = 0.0;
  for (const slope::Slice& sl : mass->slices) total_load += sl.weight + sl.surcharge_load + sl.ponded_water_load;
  for (const slope::FsResult* r : {&spencer, &half_sine}) {
    const double F = *r->factor_of_safety;
    REQUIRE(r->forces.size() == mass->slices.size());
    double e_left = 0.0, x_left = 0.0, moment = 0.0, driving = 0.0;
    for (std::size_t i = 0; i < mass->slices.size(); ++i) {
      const slope::Slice& sl = mass->slices[i];
      const slope::SliceForces& f = r->forces[i];
      const double ca = std::cos(sl.base_angle), sa = std::sin(sl.base_angle);
      const double V = sl.weight + sl.surcharge_load + sl.ponded_water_load;
      const double H = sl.seismic_force + sl.water_thrust;
      // the mass slides toward +x: X acts down on the left face, up on the right face
      CHECK(f.normal * ca + f.shear * sa - V - x_left + f.interslice_shear_right ==
            Approx(0.0).margin(1e-9 * total_load));
      CHECK(f.normal * sa - f.shear * ca + H + e_left - f.interslice_normal_right ==
            Approx(0.0).margin(1e-9 * total_load));
      CHECK(f.shear == Approx((sl.cohesion * sl.base_length + (f.normal - f.pore_force) * sl.tan_friction) / F));
      e_left = f.interslice_normal_right;
      x_left = f.interslice_shear_right;
      moment += f.shear * std::hypot(sl.base_x - circle.xc, sl.base_y - circle.yc);
      driving += V * (circle.xc - sl.base_x) + sl.seismic_force * (circle.yc - 0.5 * (sl.base_y + sl.top_y)) +
                 sl.water_thrust * (circle.yc - sl.top_y);
    }
    CHECK(e_left == Approx(0.0).margin(1e-7 * total_load));  // no force left over at the exit
    CHECK(moment == Approx(driving).epsilon(1e-8));                        // moment about the centre
  }
}

TEST_CASE("Bishop's slice forces satisfy vertical equilibrium and the moment about the centre", "[slope][methods]") {
  slope::Section s = griffiths_lane_1999();
  s.water = slope::Water{{{0, 16}, {25, 14}, {60, 11}}, 9810.0};
  const slope::Circle circle{36.0, 32.0, 22.0};
  const auto mass = slope::slice_circle(s, circle, {});
  REQUIRE(mass);
  const slope::FsResult r = slope::factor_of_safety(*mass, slope::Method::bishop, true);
  REQUIRE(r.factor_of_safety);
  double moment = 0.0, driving = 0.0;
  for (std::size_t i = 0; i < mass->slices.size(); ++i) {
    const slope::Slice& sl = mass->slices[i];
    const slope::SliceForces& f = r.forces[i];
    const double V = sl.weight + sl.surcharge_load + sl.ponded_water_load;
    CHECK(f.normal * std::cos(sl.base_angle) + f.shear * std::sin(sl.base_angle) == Approx(V).epsilon(1e-9));
    CHECK(f.pore_force == Approx(sl.pore_pressure * sl.base_length));
    moment += f.shear * std::hypot(sl.base_x - circle.xc, sl.base_y - circle.yc);
    driving += V * (circle.xc - sl.base_x) + sl.water_thrust * (circle.yc - sl.top_y);
  }
  CHECK(moment == Approx(driving).epsilon(1e-9));
}

TEST_CASE("the methods rank as expected on a c-phi slope", "[slope][methods]") {
  // Fredlund & Krahn (1977): Ordinary lowest; Bishop, Spencer, Morgenstern-Price within about 1 %.
  const auto mass = slope::slice_circle(griffiths_lane_1999(), slope::Circle{36.5, 32.5, 22.8}, {});
  REQUIRE(mass);
  const double ordinary = fs(*mass, slope::Method::ordinary);
  const double bishop = fs(*mass, slope::Method::bishop);
  const double spencer = fs(*mass, slope::Method::spencer);
  const double mp = fs(*mass, slope::Method::morgenstern_price);
  CHECK(ordinary < bishop);
  CHECK(spencer == Approx(bishop).epsilon(0.01));
  CHECK(mp == Approx(spencer).epsilon(0.005));
}

}  // namespace test_lem_methods
