#include "generate/grading.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dem {

double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

GradingCurve::GradingCurve(std::vector<double> diameters_m, std::vector<double> percent_finer, Basis basis)
    : d_(std::move(diameters_m)), P_(std::move(percent_finer)), basis_(basis) {
  if (d_.size() < 2 || d_.size() != P_.size())
    throw std::invalid_argument("grading: need at least two (diameter, percent) points of equal count");
  for (std::size_t k = 0; k + 1 < d_.size(); ++k)
    if (!(d_[k + 1] > d_[k]) || P_[k + 1] < P_[k])
      throw std::invalid_argument("grading: diameters must increase strictly and percent_finer must not decrease");
  if (!(d_.front() > 0) || P_.front() != 0 || P_.back() != 100)
    throw std::invalid_argument("grading: diameters must be positive, percent_finer must start at 0 and end at 100");
  // Segment k holds mass fraction m_k = (P_{k+1} - P_k)/100 spread uniformly in d, i.e. mass
  // density c = m_k / (b - a). Number density ~ c / d^3, so the number in the segment is
  // proportional to c (1/a^2 - 1/b^2) / 2.
  for (std::size_t k = 0; k + 1 < d_.size(); ++k) {
    const double a = d_[k], b = d_[k + 1], c = (P_[k + 1] - P_[k]) / 100.0 / (b - a);
    segment_number_weight_.push_back(basis_ == Basis::Mass ? 0.5 * c * (1 / (a * a) - 1 / (b * b))
                                                           : (P_[k + 1] - P_[k]) / 100.0);
  }
}

double GradingCurve::sample(std::mt19937_64& rng) const {
  double total = 0;
  for (double w : segment_number_weight_) total += w;
  double u = uniform01(rng) * total;
  std::size_t k = 0;
  while (k + 1 < segment_number_weight_.size() && u >= segment_number_weight_[k]) u -= segment_number_weight_[k++];
  const double a = d_[k], b = d_[k + 1];
  const double f = std::min(1.0, u / segment_number_weight_[k]);
  if (basis_ == Basis::Number) return std::clamp(a + f * (b - a), a, b);
  // Within the segment, the number CDF is (1/a^2 - 1/d^2) / (1/a^2 - 1/b^2).
  const double inv_d2 = 1 / (a * a) - f * (1 / (a * a) - 1 / (b * b));
  return std::clamp(1 / std::sqrt(inv_d2), a, b);
}

double GradingCurve::mass_fraction_finer(double diameter_m) const {
  if (diameter_m <= d_.front()) return 0;
  if (diameter_m >= d_.back()) return 1;
  std::size_t k = 0;
  while (diameter_m > d_[k + 1]) ++k;
  const double t = (diameter_m - d_[k]) / (d_[k + 1] - d_[k]);
  return (P_[k] + t * (P_[k + 1] - P_[k])) / 100.0;
}

void make_lattice(const LatticeLayout& layout, const GradingCurve& grading, double density_kg_per_m3, Particles& particles,
                  PeriodicCell& cell) {
  if (grading.diameters().back() > layout.spacing_m) {
    std::ostringstream msg;
    msg << "lattice spacing " << layout.spacing_m << " m is smaller than the largest diameter "
        << grading.diameters().back() << " m: spheres would overlap";
    throw std::invalid_argument(msg.str());
  }
  std::mt19937_64 rng(layout.seed);
  particles = Particles{};
  for (int a = 0; a < layout.n[0]; ++a)
    for (int b = 0; b < layout.n[1]; ++b)
      for (int c = 0; c < layout.n[2]; ++c) {
        const Vec3 s((a + 0.5) / layout.n[0], (b + 0.5) / layout.n[1], (c + 0.5) / layout.n[2]);
        particles.add(s, 0.5 * grading.sample(rng), density_kg_per_m3);
      }
  cell = PeriodicCell(Vec3(layout.n[0], layout.n[1], layout.n[2]) * layout.spacing_m);
}

}  // namespace dem
