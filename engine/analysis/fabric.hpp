#pragma once
// Contact fabric (docs/method.md#measures; paper Eqs. 8-10) and the invariants used for stresses too.
#include <span>

#include "core/types.hpp"

namespace dem {

// F = (1/Nc) sum_c n (x) n over all contacts (paper Eq. 8); zero for no contacts.
Mat3 fabric_tensor(std::span<const Vec3> normals);

// Strong-contact fabric F^s = (1/Nc) sum_{c strong} n (x) n with the *total* Nc in the denominator
// (paper Eq. 9); strong means f_n > mean f_n over all contacts (Eq. 10).
Mat3 strong_fabric_tensor(std::span<const Vec3> normals, std::span<const double> normal_forces_N);

// Invariants by analogy with p and q of a diagonal-dominant tensor, on its diagonal (the paper's
// axes): m = (T11 + T22 + T33)/3, d = sqrt(((T11-T22)^2 + (T22-T33)^2 + (T11-T33)^2)/2).
double mean_invariant(const Mat3& t);
double deviator_invariant(const Mat3& t);

// pi-plane coordinates of a principal triplet (axis 1 up, axis 2 lower left, axis 3 lower right):
// x = (v3 - v2)/sqrt(2), y = (2 v1 - v2 - v3)/sqrt(6). Divide by p for the normalised stress plane.
Eigen::Vector2d pi_plane(const Vec3& v);

}  // namespace dem
