// The sums of three products as the reference Yade rounds them, x + (y + z) (found by running it: its
// distances and projections come out so), for the local-frame geometries and laws.
#pragma once
#include <lib/base/Math.hpp>

namespace yade::localframe {

inline Real dot(const Vector3r& a, const Vector3r& b) { return a[0] * b[0] + (a[1] * b[1] + a[2] * b[2]); }
inline Real norm(const Vector3r& a) { return std::sqrt(dot(a, a)); }
inline Vector3r normalized(const Vector3r& a) { return a / norm(a); }
// m·v and mᵀ·v
inline Vector3r times(const Matrix3r& m, const Vector3r& v) {
    return Vector3r(dot(m.row(0), v), dot(m.row(1), v), dot(m.row(2), v));
}
inline Vector3r transposedTimes(const Matrix3r& m, const Vector3r& v) {
    return Vector3r(dot(m.col(0), v), dot(m.col(1), v), dot(m.col(2), v));
}

} // namespace yade::localframe
