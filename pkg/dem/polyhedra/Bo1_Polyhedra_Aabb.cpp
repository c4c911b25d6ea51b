#include <core/State.hpp>
#include <pkg/dem/polyhedra/Bo1_Polyhedra_Aabb.hpp>

namespace yade {

void Bo1_Polyhedra_Aabb::go(const Polyhedra& p, Aabb& aabb, const State& state, const Body&) {
    p.ensureInitialized();
    const Matrix3r R = state.ori().toRotationMatrix();
    Vector3r lo = Vector3r::Constant(INFINITY), hi = Vector3r::Constant(-INFINITY);
    for (const auto& x : p.v) {
        const Vector3r y = R * x;
        lo = lo.cwiseMin(y);
        hi = hi.cwiseMax(y);
    }
    if (aabbEnlargeFactor > 0) {
        const Vector3r mid = (lo + hi) / 2, half = (hi - lo) / 2 * aabbEnlargeFactor;
        lo = mid - half;
        hi = mid + half;
    }
    aabb.min = state.pos() + lo;
    aabb.max = state.pos() + hi;
}

} // namespace yade
