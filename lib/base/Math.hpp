// Math types used everywhere: Yade's names for Eigen types (Real = double).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace yade {

using Real = double;
using Vector2r = Eigen::Matrix<Real, 2, 1>;
using Vector2i = Eigen::Matrix<int, 2, 1>;
using Vector3r = Eigen::Matrix<Real, 3, 1>;
using Vector3i = Eigen::Matrix<int, 3, 1>;
using Vector6r = Eigen::Matrix<Real, 6, 1>;
using Matrix3r = Eigen::Matrix<Real, 3, 3>;
using Quaternionr = Eigen::Quaternion<Real>;
using AngleAxisr = Eigen::AngleAxis<Real>;

constexpr Real NaN = std::numeric_limits<Real>::quiet_NaN();
constexpr Real Inf = std::numeric_limits<Real>::infinity();
constexpr Real Mathr_PI = 3.14159265358979323846;

inline bool isFinite(const Vector3r& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

} // namespace yade
