#pragma once
// Basic vector types shared by the whole engine. SI units throughout.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace dem {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
}  // namespace dem
