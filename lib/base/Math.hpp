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
using Vector6i = Eigen::Matrix<int, 6, 1>;
using Matrix3r = Eigen::Matrix<Real, 3, 3>;
using Quaternionr = Eigen::Quaternion<Real>;
using AngleAxisr = Eigen::AngleAxis<Real>;

constexpr Real NaN = std::numeric_limits<Real>::quiet_NaN();
constexpr Real Inf = std::numeric_limits<Real>::infinity();
constexpr Real Mathr_PI = 3.14159265358979323846;

inline bool isFinite(const Vector3r& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
// v scaled to unit length, unless it is zero or already of unit length to within a few ulps (so that
// normalizing again, e.g. after a save and load, changes no bit).
inline void normalizeDirection(Vector3r& v) {
    const Real n = v.norm();
    if (n > 0 && std::abs(n - 1) > 4 * std::numeric_limits<Real>::epsilon()) v /= n;
}

} // namespace yade
