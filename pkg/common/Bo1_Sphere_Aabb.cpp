#include <pkg/common/Bo1_Sphere_Aabb.hpp>

namespace yade {

void Bo1_Sphere_Aabb::go(const Sphere& s, Aabb& aabb, const State& state, const Body&) {
    const Real r = aabbEnlargeFactor > 0 ? s.radius * aabbEnlargeFactor : s.radius;
    aabb.min = state.pos() - Vector3r::Constant(r);
    aabb.max = state.pos() + Vector3r::Constant(r);
}

} // namespace yade
