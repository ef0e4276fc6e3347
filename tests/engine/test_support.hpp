#pragma once
// Small helpers shared by the engine unit tests (not a test file itself: no _test suffix).
#include <cmath>
#include <numbers>

#include "cell/periodic_cell.hpp"
#include "control/stress_servo.hpp"
#include "core/particles.hpp"
#include "dynamics/simulation.hpp"

namespace dem::test {

inline constexpr double pi = std::numbers::pi;

// Undamped material; friction 0 selects the frictionless kernel.
inline Material material(double kn, double ks = 0, double mu = 0, double density = 2650) {
  Material m;
  m.density_kg_per_m3 = density;
  m.law = linear_law(kn, ks, mu);
  return m;
}

inline Damping no_damping() {
  Damping d;
  d.form = Damping::Form::Viscous;
  d.translational = 0;
  d.rotational = 0;
  return d;
}

// Fixed cell: every axis strain-rate controlled at rate 0.
inline CellTargets fixed_cell() { return CellTargets{}; }

// Fractional position of real point x in `cell`, wrapped into [0,1).
inline Vec3 fractional(const PeriodicCell& cell, const Vec3& x) {
  Vec3 s = x.cwiseProduct(cell.inverse_lengths());
  PeriodicCell::wrap_any(s);
  return s;
}

// Elastic energy sum_c 1/2 kn overlap^2 over all pairs, by brute force with the minimum image.
inline double elastic_energy(const Particles& p, const PeriodicCell& cell, double kn) {
  double e = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double overlap = p.radius[i] + p.radius[j] - cell.branch(p.s[i], p.s[j]).norm();
      if (overlap > 0) e += 0.5 * kn * overlap * overlap;
    }
  return e;
}

}  // namespace dem::test
