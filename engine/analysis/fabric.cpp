#include "analysis/fabric.hpp"

#include <cmath>

namespace dem {

Mat3 fabric_tensor(std::span<const Vec3> normals) {
  Mat3 f = Mat3::Zero();
  for (const Vec3& n : normals) f.noalias() += n * n.transpose();
  return normals.empty() ? f : Mat3(f / static_cast<double>(normals.size()));
}

Mat3 strong_fabric_tensor(std::span<const Vec3> normals, std::span<const double> normal_forces_N) {
  Mat3 f = Mat3::Zero();
  if (normals.empty()) return f;
  double mean = 0;
  for (double fn : normal_forces_N) mean += fn;
  mean /= static_cast<double>(normal_forces_N.size());
  // "Greater than the mean" beyond the round-off of the mean itself: in a network of equal forces
  // the rounded mean can fall an ulp below them, and none of them is strong.
  const double threshold = mean * (1 + 1e-12);
  for (std::size_t c = 0; c < normals.size(); ++c)
    if (normal_forces_N[c] > threshold) f.noalias() += normals[c] * normals[c].transpose();
  return f / static_cast<double>(normals.size());
}

double mean_invariant(const Mat3& t) { return t.trace() / 3.0; }

double deviator_invariant(const Mat3& t) {
  const double a = t(0, 0) - t(1, 1), b = t(1, 1) - t(2, 2), c = t(0, 0) - t(2, 2);
  return std::sqrt(0.5 * (a * a + b * b + c * c));
}

Eigen::Vector2d pi_plane(const Vec3& v) {
  return Eigen::Vector2d((v[2] - v[1]) / std::sqrt(2.0), (2 * v[0] - v[1] - v[2]) / std::sqrt(6.0));
}

}  // namespace dem
