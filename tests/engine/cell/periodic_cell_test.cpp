// Periodic images (cell/periodic_cell.hpp with the force kernel): two spheres touching across a
// face, an edge or a corner of the cell feel the contact, along the right direction and with
// magnitude kn*overlap, in a cubic cell and in cells deformed to non-cubic shapes.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "engine/test_support.hpp"

using namespace dem;

namespace {

struct Case {
  std::string name;
  Vec3 s_a;        // fractional position of the first sphere
  Vec3 direction;  // unit vector from the first sphere to the image of the second
};

std::vector<Case> image_cases() {
  const Vec3 low(0.02, 0.03, 0.04), high(0.98, 0.97, 0.96);  // near the origin / the far corner
  const double r2 = 1 / std::sqrt(2.0), r3 = 1 / std::sqrt(3.0);
  return {
      {"face -x", low, Vec3(-1, 0, 0)},       {"face -y", low, Vec3(0, -1, 0)},
      {"face -z", low, Vec3(0, 0, -1)},       {"face +x", high, Vec3(1, 0, 0)},
      {"face +y", high, Vec3(0, 1, 0)},       {"face +z", high, Vec3(0, 0, 1)},
      {"edge -x-y", low, Vec3(-r2, -r2, 0)},  {"edge +y+z", high, Vec3(0, r2, r2)},
      {"edge +x-z", Vec3(0.98, 0.5, 0.04), Vec3(r2, 0, -r2)},
      {"corner -x-y-z", low, Vec3(-r3, -r3, -r3)}, {"corner +x+y+z", high, Vec3(r3, r3, r3)},
      {"corner +x-y+z", Vec3(0.98, 0.03, 0.96), Vec3(r3, -r3, r3)},
  };
}

// Places sphere b at real distance 2r - overlap from sphere a along `direction` (wrapped into the
// cell, so it lies across the boundary), runs one step and checks the contact force and stress.
void check_image_contact(const PeriodicCell& cell, const Case& c) {
  INFO(c.name << ", cell lengths " << cell.lengths().transpose());
  const double r = 1e-3, overlap = 1e-5, kn = 2e5;
  const Vec3 x_a = cell.to_real(c.s_a);
  const Vec3 x_b = x_a + (2 * r - overlap) * c.direction;
  Particles p;
  p.add(c.s_a, r, 2650);
  p.add(test::fractional(cell, x_b), r, 2650);
  // The second sphere really lies across the boundary: every axis the direction has a component on
  // was wrapped (one for a face, two for an edge, three for a corner).
  const Vec3 unwrapped = x_b.cwiseProduct(cell.inverse_lengths());
  for (int k = 0; k < 3; ++k) REQUIRE((unwrapped[k] < 0 || unwrapped[k] >= 1) == (c.direction[k] != 0));
  // Real positions are O(1e-2) m, so the branch vector carries absolute round-off ~1e-18 m, i.e. a
  // relative error ~1e-13 on an overlap of 1e-5 m. We allow 1e-10.
  const Vec3 l = cell.branch(p.s[0], p.s[1]);
  REQUIRE((l - (2 * r - overlap) * c.direction).norm() <= 1e-15);

  Simulation sim(p, cell, test::material(kn), test::no_damping(), 1e-7, 1e-4);
  sim.step(test::fixed_cell(), ServoSettings{});
  REQUIRE(sim.sums().contacts == 1);
  const Vec3 f_b = sim.net_force()[1];  // force on the second sphere: pushed away from the first
  const Vec3 expected = kn * overlap * c.direction;
  REQUIRE((f_b - expected).norm() <= 1e-10 * kn * overlap);
  REQUIRE((sim.net_force()[0] + f_b).norm() <= 1e-15 * kn * overlap);
  // Stress (1/V) f (x) l of the single contact: compression positive along the contact direction.
  const Mat3 sigma = kn * overlap * (2 * r - overlap) * c.direction * c.direction.transpose() / cell.volume();
  REQUIRE((sim.sums().stress_Pa - sigma).norm() <= 1e-10 * sigma.norm());
}

}  // namespace

TEST_CASE("periodic images: contact across faces, edges and corners of a cubic cell", "[cell][periodic]") {
  const PeriodicCell cell(Vec3(0.01, 0.01, 0.01));
  for (const Case& c : image_cases()) check_image_contact(cell, c);
}

TEST_CASE("periodic images: contact across faces, edges and corners of deformed cells", "[cell][periodic]") {
  SECTION("deform: compress x, stretch y, compress z (non-cubic)") {
    PeriodicCell cell(Vec3(0.01, 0.01, 0.01));
    cell.deform(Vec3(300, -200, 100), 1e-3);  // L <- L exp(-rate dt): (7.41, 12.21, 9.05) mm
    REQUIRE(cell.lengths().x() == Approx(0.01 * std::exp(-0.3)).epsilon(1e-15));
    REQUIRE(cell.lengths().y() == Approx(0.01 * std::exp(0.2)).epsilon(1e-15));
    REQUIRE(cell.volume() == Approx(1e-6 * std::exp(-0.2)).epsilon(1e-14));
    REQUIRE(cell.strain().x() == Approx(0.3).epsilon(1e-14));  // true strain, compression positive
    REQUIRE(cell.strain().y() == Approx(-0.2).epsilon(1e-14));
    for (const Case& c : image_cases()) check_image_contact(cell, c);
  }
  SECTION("set_lengths: 6 x 11 x 17 mm") {
    PeriodicCell cell(Vec3(0.01, 0.01, 0.01));
    cell.set_lengths(Vec3(0.006, 0.011, 0.017));
    for (const Case& c : image_cases()) check_image_contact(cell, c);
  }
}

TEST_CASE("periodic cell: spheres at fixed fractional positions follow the deformation affinely", "[cell][periodic]") {
  // A pair across the x face, separated by 2r + gap in the undeformed cell: no contact. Compressing x
  // by the factor lambda shrinks the real branch to lambda (2r + gap); the overlap is then known exactly.
  const double r = 1e-3, gap = 1e-4, kn = 1e5;
  PeriodicCell cell(Vec3(0.01, 0.01, 0.01));
  Particles p;
  p.add(Vec3(0.05, 0.5, 0.5), r, 2650);
  p.add(Vec3(0.05 - (2 * r + gap) / 0.01 + 1.0, 0.5, 0.5), r, 2650);
  REQUIRE(cell.branch(p.s[0], p.s[1]).x() == Approx(-(2 * r + gap)).epsilon(1e-12));
  const double lambda = 0.93;  // compression strain -ln(0.93); overlap 2 mm - 0.93 * 2.1 mm = 47 um
  cell.deform(Vec3(-std::log(lambda), 0, 0), 1.0);
  Simulation sim(p, cell, test::material(kn), test::no_damping(), 1e-7, 1e-4);
  sim.step(test::fixed_cell(), ServoSettings{});
  const double overlap = 2 * r - lambda * (2 * r + gap);
  // Round-off: positions O(1e-2) m against an overlap of 4.7e-5 m, relative ~1e-13; we allow 1e-10.
  REQUIRE(sim.net_force()[1].x() == Approx(-kn * overlap).epsilon(1e-10));
  REQUIRE(sim.net_force()[0].x() == Approx(kn * overlap).epsilon(1e-10));
}
