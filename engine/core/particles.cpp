#include "core/particles.hpp"

#include <numbers>

namespace dem {

double sphere_volume(double radius_m) { return 4.0 / 3.0 * std::numbers::pi * radius_m * radius_m * radius_m; }

void Particles::add(const Vec3& fractional_position, double radius_m, double density_kg_per_m3) {
  const double m = density_kg_per_m3 * sphere_volume(radius_m);
  s.push_back(fractional_position);
  v.push_back(Vec3::Zero());
  omega.push_back(Vec3::Zero());
  radius.push_back(radius_m);
  mass.push_back(m);
  inertia.push_back(0.4 * m * radius_m * radius_m);
}

double total_solid_volume(const Particles& p) {
  double v = 0;
  for (double r : p.radius) v += sphere_volume(r);
  return v;
}

}  // namespace dem
