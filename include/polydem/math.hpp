#pragma once
// Vector types shared by every stage: Eigen fixed-size, double precision, SI units.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace polydem {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // unit quaternion, body frame -> world frame

constexpr double kPi = 3.14159265358979323846;

}  // namespace polydem
