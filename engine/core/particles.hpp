#pragma once
// Particles as a struct of arrays: each loop streams only the fields it reads.
//
// Positions are stored in *fractional* cell coordinates s in [0,1)^3; the real position is
// x = L (.) s (component-wise product with the cell lengths). A particle at rest in s therefore
// follows the homogeneous deformation of the cell, and `v` is the fluctuating velocity relative to
// that affine field (the total velocity is v + Ldot/L (.) x).
#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace dem {

struct Particles {
  std::vector<Vec3> s;          // fractional position [-], wrapped into [0,1)
  std::vector<Vec3> v;          // fluctuating velocity [m/s]
  std::vector<Vec3> omega;      // angular velocity [rad/s]
  std::vector<double> radius;   // [m]
  std::vector<double> mass;     // [kg]
  std::vector<double> inertia;  // moment of inertia of a solid sphere, 2/5 m r^2 [kg m^2]

  std::size_t size() const { return radius.size(); }

  // Appends a solid sphere of density rho [kg/m^3] at rest.
  void add(const Vec3& fractional_position, double radius_m, double density_kg_per_m3);
};

double sphere_volume(double radius_m);
double total_solid_volume(const Particles& p);  // sum of sphere volumes [m^3], overlaps not subtracted

}  // namespace dem
