#include <pkg/dem/CircularFactory.hpp>
#include <cmath>
#include <stdexcept>

namespace yade {

Vector3r CircularFactory::pickRandomPosition(Real r) {
    const Vector3r n = normal.normalized();
    const Vector3r e1 = (std::abs(n[0]) < 0.9 ? n.cross(Vector3r::UnitX()) : n.cross(Vector3r::UnitY())).normalized();
    const Vector3r e2 = n.cross(e1);
    const Real angle = 2 * Mathr_PI * uniform01();
    const Real dist = uniform01() * (radius - r); // uniform in the distance to the axis, as the reference
    const Real axial = (uniform01() - 0.5) * length;
    return center + dist * (std::cos(angle) * e1 + std::sin(angle) * e2) + axial * n;
}

void CircularFactory::checkRegion() const {
    if (!std::isfinite(radius) || !(radius > 0)) throw std::invalid_argument("CircularFactory.radius must be positive and finite (the radius of the region).");
    if (!isFinite(center)) throw std::invalid_argument("CircularFactory.center is not set (NaN): give the center of the region.");
    if (!std::isfinite(length)) throw std::invalid_argument("CircularFactory.length must be finite (0: a disc).");
    if (!isFinite(normal) || !(normal.norm() > 0)) throw std::invalid_argument("CircularFactory.normal is not set: give the axis of the disc or cylinder.");
}

void CircularFactory::regionBounds(Vector3r& lo, Vector3r& hi) const {
    const Vector3r half = Vector3r::Constant(radius + std::abs(length) / 2);
    lo = center - half;
    hi = center + half;
}

} // namespace yade
