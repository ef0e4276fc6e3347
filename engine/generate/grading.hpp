#pragma once
// Particle generation: a grading curve sampled by mass, and the cubic lattice of docs/method.md#system.
#include <cstdint>
#include <random>
#include <vector>

#include "core/particles.hpp"
#include "cell/periodic_cell.hpp"

namespace dem {

// A mass-based percent-finer curve, piecewise linear through (diameter_k, percent_k); percent
// rises from 0 to 100. Diameters are drawn so that the *mass* distribution follows the curve:
// on a segment where the mass density is the constant c, the number density is proportional to
// c / d^3, whose cumulative distribution is inverted in closed form.
//
// With Basis::Number the curve is read as a percent finer *by count* instead (diameters uniform in
// number within each segment), the other common reading of a grading curve.
class GradingCurve {
 public:
  enum class Basis { Mass, Number };
  GradingCurve(std::vector<double> diameters_m, std::vector<double> percent_finer, Basis basis = Basis::Mass);
  double sample(std::mt19937_64& rng) const;                  // one diameter [m]
  double mass_fraction_finer(double diameter_m) const;        // the curve itself, in [0, 1]
  const std::vector<double>& diameters() const { return d_; }
  const std::vector<double>& percent_finer() const { return P_; }

 private:
  std::vector<double> d_, P_;
  Basis basis_;
  std::vector<double> segment_number_weight_;  // relative number of particles per segment
};

// Uniform double in [0, 1) from 53 random bits (identical on every platform, unlike std::uniform_real_distribution).
double uniform01(std::mt19937_64& rng);

struct LatticeLayout {
  int n[3] = {20, 20, 20};  // lattice points per axis
  double spacing_m = 5e-3;  // centre-to-centre distance; the cell side is n * spacing
  std::uint64_t seed = 1;
};

// Spheres on a simple cubic lattice (one per site, site at the centre of its lattice cube),
// diameters from the grading curve. Throws if a sampled diameter exceeds the spacing (overlap).
void make_lattice(const LatticeLayout& layout, const GradingCurve& grading, double density_kg_per_m3, Particles& particles,
                  PeriodicCell& cell);

}  // namespace dem
