#include <pkg/dem/BoxFactory.hpp>
#include <stdexcept>

namespace yade {

Vector3r BoxFactory::pickRandomPosition(Real) {
    Vector3r p;
    for (int k = 0; k < 3; ++k) p[k] = center[k] + (2 * uniform01() - 1) * extents[k];
    return p;
}

void BoxFactory::checkRegion() const {
    if (!isFinite(extents)) throw std::invalid_argument("BoxFactory.extents is not set (NaN): give the half-sizes of the region.");
    if (!isFinite(center)) throw std::invalid_argument("BoxFactory.center is not set (NaN): give the center of the region.");
}

void BoxFactory::regionBounds(Vector3r& lo, Vector3r& hi) const {
    lo = center - extents.cwiseAbs();
    hi = center + extents.cwiseAbs();
}

} // namespace yade
